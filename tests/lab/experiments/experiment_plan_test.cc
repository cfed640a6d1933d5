// The plan of mlndt_experiments (lab/experiments/experiment_plan.h,
// datasets.h, configurations.h) on the bundled data (data/: kitti, room,
// koide3): which data sets are found, which jobs and starts the quick plan
// makes, and the configurations it compares. Tested through the tool only
// before (tests/tools/mlndt_experiments_test.cc).

#include "lab/experiments/experiment_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "lab/experiments/configurations.h"
#include "lab/experiments/datasets.h"
#include "lab/experiments/run_batch.h"
#include "mlndt/common/pose.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace experiments {
namespace {

std::vector<ExperimentDataset> BundledDatasets() {
  std::vector<ExperimentDataset> datasets;
  std::vector<std::string> missing;
  std::string error;
  EXPECT_TRUE(
      FindDatasets(testing::BundledDataPath(""), &datasets, &missing, &error))
      << error;
  EXPECT_EQ(missing, (std::vector<std::string>{"mulran", "3dtk"}));
  return datasets;
}

TEST(FindDatasets, FindsTheBundledSetsInReportOrderWithEveryScan) {
  const std::vector<ExperimentDataset> datasets = BundledDatasets();
  ASSERT_EQ(datasets.size(), 3u);
  EXPECT_EQ(datasets[0].name, "kitti");
  EXPECT_EQ(datasets[1].name, "room");
  EXPECT_EQ(datasets[2].name, "koide3");
  for (const ExperimentDataset& set : datasets) {
    ASSERT_FALSE(set.pairs.empty()) << set.name;
    for (const auto& [key, pair] : set.pairs) {
      for (const int64_t scan : {pair.reference_index, pair.input_index}) {
        ASSERT_EQ(set.scan_paths.count(scan), 1u) << set.name << " " << key;
        EXPECT_TRUE(std::filesystem::exists(set.scan_paths.at(scan)));
      }
    }
  }
  // KITTI 0-7: the step-1 pairs are 0_1 ... 6_7, and PairsByStep lists
  // them before any longer step.
  const ExperimentDataset& kitti = datasets[0];
  const std::vector<std::string> step1 = kitti.PairsWithStep(1);
  ASSERT_EQ(step1.size(), 7u);
  EXPECT_EQ(step1.front(), "0_1");
  EXPECT_EQ(step1.back(), "6_7");
  const std::vector<std::string> by_step = kitti.PairsByStep();
  ASSERT_EQ(by_step.size(), kitti.pairs.size());
  EXPECT_EQ(std::vector<std::string>(by_step.begin(), by_step.begin() + 7),
            step1);
}

TEST(FindDatasets, UnreadableReferencesAreAnErrorNamingTheFile) {
  const std::string dir = testing::ScratchPath("broken_data");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/koide3");
  std::ofstream(dir + "/koide3/reference_pairs.json") << "{ not json";
  std::vector<ExperimentDataset> datasets;
  std::vector<std::string> missing;
  std::string error;
  EXPECT_FALSE(FindDatasets(dir, &datasets, &missing, &error));
  EXPECT_NE(error.find("reference_pairs.json"), std::string::npos) << error;
}

TEST(MakeJobs, TheQuickPlanRunsEveryExperimentOnEveryDataSet) {
  const std::vector<ExperimentDataset> datasets = BundledDatasets();
  const ExperimentPlan plan = MakePlan(/*quick=*/true);
  ASSERT_EQ(plan.offsets.size(), 6u);  // x: 4 offsets, yaw: 2.
  const std::vector<Job> jobs = MakeJobs(plan, datasets);
  const size_t per_set = AccuracyConfigurations(plan).size() + 1 +
                         AblationConfigurations().size() +
                         2 * plan.table9_start_layers.size() +
                         3 * plan.fractions.size();
  ASSERT_EQ(jobs.size(), datasets.size() * per_set);
  std::set<std::string> experiments;
  for (const Job& job : jobs) {
    experiments.insert(job.experiment);
    const ExperimentDataset& set = datasets.at(job.dataset);
    ASSERT_FALSE(job.runs.empty()) << job.experiment << " " << set.name;
    for (const SuiteRun& run : job.runs) {
      EXPECT_EQ(run.dataset, job.dataset);
      ASSERT_EQ(set.pairs.count(run.pair_key), 1u) << run.pair_key;
    }
    if (job.experiment == "accuracy") {
      EXPECT_LE(job.runs.size(), plan.max_accuracy_pairs);
      for (const SuiteRun& run : job.runs) EXPECT_EQ(run.start, "prior");
    } else if (job.experiment == "reach") {
      EXPECT_EQ(job.runs.size() % plan.offsets.size(), 0u);
      for (const SuiteRun& run : job.runs)
        EXPECT_LT(run.offset_index, static_cast<int>(plan.offsets.size()));
    } else if (job.experiment == "table9") {
      EXPECT_EQ(job.config.options.mlndt.schedule.start_layer,
                static_cast<int>(job.parameter));
    } else {
      ASSERT_EQ(job.experiment, "sampling");
      EXPECT_NE(
          std::find(
              plan.fractions.begin(), plan.fractions.end(), job.parameter),
          plan.fractions.end());
    }
  }
  EXPECT_EQ(experiments,
            (std::set<std::string>{"accuracy", "reach", "table9", "sampling"}));
}

TEST(Starts, ScaledAndOffsetStartsAreMadeFromTheReference) {
  const std::vector<ExperimentDataset> datasets = BundledDatasets();
  const ExperimentDataset& koide3 = datasets.at(2);
  const std::string pair = koide3.PairsByStep().front();
  const Isometry3d truth =
      ScaledStart(2, koide3, pair, 1.0).reference_from_input;
  // c = 1: the reference itself (through its pose vector: the file's 9
  // digits are not exactly a rotation); c = 0: the identity (Z_i = c Z_gt).
  EXPECT_TRUE(ScaledStart(2, koide3, pair, 1.0)
                  .initial_reference_from_input.isApprox(truth, 1e-6));
  EXPECT_TRUE(ScaledStart(2, koide3, pair, 0.0)
                  .initial_reference_from_input.isApprox(Isometry3d::Identity(),
                                                         1e-12));
  EXPECT_TRUE(IdentityStart(2, koide3, pair)
                  .initial_reference_from_input.isApprox(Isometry3d::Identity(),
                                                         1e-12));
  // An offset of 1 m along x moves the start 1 m from the reference.
  const ExperimentPlan plan = MakePlan(/*quick=*/true);
  const StartOffset& one_m = plan.offsets.at(1);
  ASSERT_EQ(one_m.label, "x=1");
  const SuiteRun run = OffsetStart(2, koide3, pair, one_m, 1);
  EXPECT_EQ(run.offset_index, 1);
  EXPECT_NEAR(
      (run.initial_reference_from_input.translation() - truth.translation())
          .norm(),
      1.0,
      1e-9);
}

TEST(Configurations, TheAblationGoesFromThePaperPresetToTheDefaults) {
  const std::vector<Configuration> steps = AblationConfigurations();
  ASSERT_EQ(steps.size(), 5u);
  EXPECT_EQ(steps.front().key, PaperConfiguration().key);
  EXPECT_EQ(steps.back().key, DefaultConfiguration().key);
  const std::vector<OptionDifference> differences = PaperDefaultDifferences();
  ASSERT_FALSE(differences.empty());
  std::set<std::string> labels;
  for (const Configuration& c : steps) labels.insert(c.label);
  for (const OptionDifference& d : differences) {
    EXPECT_NE(d.paper, d.defaults) << d.option;
    EXPECT_EQ(labels.count(d.step), 1u) << d.option << " " << d.step;
  }
  const Configuration random = WithRandomSampling(DefaultConfiguration(), 0.1);
  EXPECT_EQ(random.key, "defaults_random10");
  EXPECT_EQ(random.options.mlndt.sampling.method, SamplingMethod::RANDOM);
  EXPECT_DOUBLE_EQ(random.options.mlndt.sampling.random_fraction, 0.1);
  EXPECT_EQ(StartLayerLabel(-2), "n-2");
  EXPECT_EQ(StartLayerLabel(0), "n");
}

}  // namespace
}  // namespace experiments
}  // namespace mlndt
