#include "lab/experiments/experiment_plan.h"

#include <algorithm>

#include "glog/logging.h"

namespace mlndt {
namespace experiments {
namespace {

std::vector<std::string> Limit(std::vector<std::string> keys, size_t max) {
  if (max > 0 && keys.size() > max) keys.resize(max);
  return keys;
}

// Pairs of the smallest step of the data set (a single pair otherwise).
std::vector<std::string> SmallestStepPairs(const ExperimentDataset& set,
                                           size_t max) {
  const std::vector<std::string> all = set.PairsByStep();
  if (all.empty()) return {};
  const ReferencePair& first = set.pairs.at(all.front());
  return Limit(set.PairsWithStep(first.input_index - first.reference_index),
               max);
}

// Table 9 wants large motions: the largest steps first.
std::vector<std::string> LargestStepPairs(const ExperimentDataset& set,
                                          size_t max) {
  std::vector<std::string> all = set.PairsByStep();
  std::stable_sort(all.begin(), all.end(), [&](const auto& a, const auto& b) {
    const ReferencePair& pa = set.pairs.at(a);
    const ReferencePair& pb = set.pairs.at(b);
    return pa.input_index - pa.reference_index >
           pb.input_index - pb.reference_index;
  });
  return Limit(all, max);
}

void AddJob(const std::string& experiment,
            const Configuration& config,
            size_t dataset,
            std::vector<SuiteRun> runs,
            double parameter,
            std::vector<Job>* jobs) {
  if (runs.empty()) return;
  Job job;
  job.experiment = experiment;
  job.config = config;
  job.dataset = dataset;
  job.runs = std::move(runs);
  job.parameter = parameter;
  jobs->push_back(std::move(job));
}

}  // namespace

ExperimentPlan MakePlan(bool quick) {
  ExperimentPlan plan;
  plan.quick = quick;
  std::string offsets = "x:0.1,0.25,0.5,1,2,5,10,15,20,25;yaw:5,10,15,30,45";
  plan.fractions = {0.01, 0.02, 0.05, 0.1, 0.2, 0.3};
  if (quick) {
    plan.max_accuracy_pairs = 3;
    plan.max_reach_pairs = 3;
    plan.max_table9_pairs = 2;
    plan.max_sampling_pairs = 2;
    offsets = "x:0.25,1,5,10;yaw:15,45";
    plan.fractions = {0.02, 0.1, 0.3};
    plan.table9_c = {0.6, 0.0};
  }
  std::string error;
  CHECK(ParseStartOffsets(offsets, &plan.offsets, &error)) << error;
  return plan;
}

std::string StartLayerLabel(int start_layer) {
  return start_layer == 0 ? "n" : "n" + std::to_string(start_layer);
}

std::vector<Configuration> AccuracyConfigurations(const ExperimentPlan& plan) {
  const Configuration ndt = NdtConfiguration();
  const Configuration paper = PaperConfiguration();
  const Configuration defaults = DefaultConfiguration();
  Configuration known = defaults;
  known.key = "defaults_known";
  known.label = "defaults, prior uncertainty given";
  InitialGuessUncertainty& u = known.options.mlndt.initial_uncertainty;
  u.given = true;
  u.translation_m = plan.prior_uncertainty_m;
  u.rotation_deg = plan.prior_uncertainty_deg;
  return {ndt,
          WithRandomSampling(ndt, plan.random_fraction),
          paper,
          WithRandomSampling(paper, plan.random_fraction),
          defaults,
          WithRandomSampling(defaults, plan.random_fraction),
          known};
}

std::vector<Job> MakeJobs(const ExperimentPlan& plan,
                          const std::vector<ExperimentDataset>& datasets) {
  std::vector<Job> jobs;
  for (size_t d = 0; d < datasets.size(); ++d) {
    const ExperimentDataset& set = datasets[d];
    // accuracy: every pair (by step) from its prior.
    std::vector<SuiteRun> prior_runs;
    for (const std::string& pair :
         Limit(set.PairsByStep(), plan.max_accuracy_pairs)) {
      if (set.pairs.at(pair).prior_from_input)
        prior_runs.push_back(PriorStart(d, set, pair));
    }
    for (const Configuration& c : AccuracyConfigurations(plan))
      AddJob("accuracy", c, d, prior_runs, NAN, &jobs);

    // reach: the smallest-step pairs from offsets of the reference.
    std::vector<SuiteRun> offset_runs;
    for (const std::string& pair :
         SmallestStepPairs(set, plan.max_reach_pairs)) {
      for (size_t o = 0; o < plan.offsets.size(); ++o) {
        offset_runs.push_back(
            OffsetStart(d, set, pair, plan.offsets[o], static_cast<int>(o)));
      }
    }
    AddJob("reach", NdtConfiguration(), d, offset_runs, NAN, &jobs);
    for (const Configuration& c : AblationConfigurations())
      AddJob("reach", c, d, offset_runs, NAN, &jobs);

    // table9: start layer x initialisation, largest motions first.
    std::vector<SuiteRun> scaled_runs;
    for (const std::string& pair :
         LargestStepPairs(set, plan.max_table9_pairs)) {
      for (const double c : plan.table9_c)
        scaled_runs.push_back(ScaledStart(d, set, pair, c));
    }
    for (Configuration c : {PaperConfiguration(), DefaultConfiguration()}) {
      for (const int layer : plan.table9_start_layers) {
        Configuration with_layer = c;
        with_layer.options.mlndt.schedule.start_layer = layer;
        AddJob("table9", with_layer, d, scaled_runs, layer, &jobs);
      }
    }

    // sampling: random fractions, from the identity and from the prior.
    std::vector<SuiteRun> sweep_runs;
    for (const std::string& pair :
         SmallestStepPairs(set, plan.max_sampling_pairs)) {
      sweep_runs.push_back(IdentityStart(d, set, pair));
      if (set.pairs.at(pair).prior_from_input)
        sweep_runs.push_back(PriorStart(d, set, pair));
    }
    for (const double f : plan.fractions) {
      for (const Configuration& c :
           {NdtConfiguration(), PaperConfiguration(), DefaultConfiguration()}) {
        Configuration sampled = WithRandomSampling(c, f);
        sampled.key = c.key;  // The fraction is the job's parameter.
        AddJob("sampling", sampled, d, sweep_runs, f, &jobs);
      }
    }
  }
  return jobs;
}

}  // namespace experiments
}  // namespace mlndt
