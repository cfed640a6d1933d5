#pragma once

// Which registrations the report runs (the jobs of run_batch.h), in its
// full size on the shared data or in the --quick size on the bundled data.
//
//   accuracy  Tables 2-8, Figs. 14-18: every pair from its prior (the
//             odometry stand-in) with NDT and ML-NDT (paper preset and
//             defaults), GBS and random sampling.
//   reach     Section 5.1 and the ablation: the step-1 pairs from the
//             reference pushed off along x and in yaw, NDT and every
//             ablation step.
//   table9    Table 9: start layer n-2, n-1, n x Z_i = c Z_ref.
//   sampling  The sampling-fraction sweep (random sampling, 1-30 %).

#include <vector>

#include "lab/eval/suite_plan.h"
#include "lab/experiments/datasets.h"
#include "lab/experiments/run_batch.h"

namespace mlndt {
namespace experiments {

struct ExperimentPlan {
  bool quick = false;
  // Per data set at most this many pairs in each experiment (0: all).
  size_t max_accuracy_pairs = 0;
  size_t max_reach_pairs = 10;
  size_t max_table9_pairs = 30;
  size_t max_sampling_pairs = 10;
  std::vector<StartOffset> offsets;  // reach; families "x" and "yaw".
  std::vector<double> fractions;     // sampling.
  std::vector<double> table9_c = {0.9, 0.6, 0.3, 0.0};
  std::vector<int> table9_start_layers = {-2, -1, 0};  // n-2, n-1, n.
  double random_fraction = 0.15;  // accuracy: the random-sampling runs.
  // accuracy: the bound of the priors' error passed to the defaults as the
  // initial uncertainty in one more configuration (the largest prior error
  // of the shared references is 0.73 m / 1.8 deg).
  double prior_uncertainty_m = 1.0;
  double prior_uncertainty_deg = 2.0;
};

// The full plan, or the quick one (fewer pairs, offsets and fractions).
ExperimentPlan MakePlan(bool quick);

// "n-2", "n-1", "n".
std::string StartLayerLabel(int start_layer);

// The configurations of the accuracy experiment, in table order: NDT, NDT
// random, paper, paper random, defaults, defaults random, and the defaults
// told the priors' uncertainty.
std::vector<Configuration> AccuracyConfigurations(const ExperimentPlan& plan);

std::vector<Job> MakeJobs(const ExperimentPlan& plan,
                          const std::vector<ExperimentDataset>& datasets);

}  // namespace experiments
}  // namespace mlndt
