// Tests of SolveWithLayerSchedule (problem_schedule.h) on a caller's
// ceres::Problem: KITTI scans 0, 1, 2 (data/kitti), two pairs bound through
// LayerBindings and a prior on scan 0, scheduled coarse to fine in place.

#include "mlndt/schedule/problem_schedule.h"

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/range_filter.h"
#include "mlndt/common/pose.h"
#include "mlndt/cost/add_pair_residuals.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// world_from_scan as Ceres blocks.
struct PoseBlocks {
  double rotation[4] = {0.0, 0.0, 0.0, 1.0};  // x, y, z, w.
  double translation[3] = {0.0, 0.0, 0.0};
  Isometry3d ToIsometry() const {
    Isometry3d out = Isometry3d::Identity();
    out.linear() = Eigen::Map<const Eigen::Quaterniond>(rotation)
                       .normalized()
                       .toRotationMatrix();
    out.translation() = Eigen::Map<const Vector3d>(translation);
    return out;
  }
};

// A prior holding a pose at the identity: 1 mm and ~0.06 deg sigmas.
struct IdentityPrior {
  template <typename T>
  bool operator()(const T* rotation, const T* translation, T* r) const {
    for (int k = 0; k < 3; ++k) {
      r[k] = translation[k] / T(1e-3);
      r[3 + k] = T(2.0) * rotation[k] / T(1e-3);
    }
    return true;
  }
};

// Scan k of data/kitti: range-filtered as Register filters, its map, and
// its samples.
struct Scan {
  LayeredGrid map;
  std::vector<Eigen::Vector3d> samples;
};

const std::vector<Scan>& Scans() {
  static const std::vector<Scan>* scans = [] {
    auto* out = new std::vector<Scan>(3);
    for (int k = 0; k < 3; ++k) {
      PointCloud raw, sampled;
      std::string error;
      const std::string path = testing::BundledDataPath(
          "kitti/pcd/00000" + std::to_string(k) + ".pcd");
      EXPECT_TRUE(ReadPointCloud(path, &raw, nullptr, &error)) << error;
      const PointCloud cloud =
          FilterByRange(RangeFilterOptions(), raw, nullptr);
      EXPECT_TRUE(LayeredGrid::Build(
          LayeredGridOptions(), cloud, &(*out)[k].map, &error))
          << error;
      EXPECT_TRUE(
          SamplePoints(SamplingOptions(), cloud, &sampled, nullptr, &error))
          << error;
      (*out)[k].samples = sampled.points();
    }
    return out;
  }();
  return *scans;
}

Isometry3d Reference(const std::string& key) {
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  EXPECT_TRUE(ReadReferencePairs(
      testing::BundledDataPath("kitti/reference_pairs.json"), &pairs, &error))
      << error;
  return pairs.at(key).reference_from_input;
}

// Three poses at the identity, pairs 0 <- 1 and 1 <- 2 bound to maps 0 and
// 1 (per-point blocks, or one block per pair), and the prior on pose 0.
struct ThreeScanProblem {
  std::vector<PoseBlocks> poses = std::vector<PoseBlocks>(3);
  LayerBinding binding_0{Scans()[0].map.layer(1)};
  LayerBinding binding_1{Scans()[1].map.layer(1)};
  ceres::Problem problem;
  std::vector<ceres::ResidualBlockId> ids;

  explicit ThreeScanProblem(bool one_block_per_pair = false) {
    PairResidualOptions options;
    options.one_block_per_pair = one_block_per_pair;
    const auto add = [&](LayerBinding& binding, int i, int j) {
      const std::vector<ceres::ResidualBlockId> added =
          AddMlNdtPairResiduals(binding,
                                Scans()[j].samples,
                                options,
                                poses[i].rotation,
                                poses[i].translation,
                                poses[j].rotation,
                                poses[j].translation,
                                &problem);
      ids.insert(ids.end(), added.begin(), added.end());
    };
    add(binding_0, 0, 1);
    add(binding_1, 1, 2);
    ids.push_back(problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<IdentityPrior, 6, 4, 3>(
            new IdentityPrior),
        nullptr,
        poses[0].rotation,
        poses[0].translation));
  }
  std::vector<ScheduledBinding> Bindings() {
    return {{&binding_0, &Scans()[0].map}, {&binding_1, &Scans()[1].map}};
  }
  Isometry3d Relative(int i, int j) const {
    return poses[i].ToIsometry().inverse() * poses[j].ToIsometry();
  }
};

// At the start of every stage's Solve: the Problem's residual blocks and the
// cell edge map 0's binding reads.
class StageRecorder : public ceres::IterationCallback {
 public:
  StageRecorder(const ceres::Problem* problem, const LayerBinding* binding)
      : problem_(problem), binding_(binding) {}
  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& s) override {
    if (s.iteration == 0) {
      std::vector<ceres::ResidualBlockId> ids;
      problem_->GetResidualBlocks(&ids);
      block_ids.push_back(ids);
      num_blocks.push_back(problem_->NumResidualBlocks());
      cell_sizes.push_back(binding_->layer().cell_size());
    }
    return ceres::SOLVER_CONTINUE;
  }
  std::vector<std::vector<ceres::ResidualBlockId>> block_ids;
  std::vector<int> num_blocks;
  std::vector<double> cell_sizes;

 private:
  const ceres::Problem* problem_;
  const LayerBinding* binding_;
};

ceres::Solver::Options DenseSolver() {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  options.logging_type = ceres::SILENT;
  return options;
}

// Per-point blocks (false) or one block per pair (true).
class SolveWithLayerScheduleForms : public ::testing::TestWithParam<bool> {};

TEST_P(SolveWithLayerScheduleForms,
       TwoPairsAndAPriorLandOnTheReferencesInPlace) {
  ThreeScanProblem p(GetParam());
  const int n = Scans()[0].map.num_layers();
  ASSERT_GE(n, 3) << "the schedule needs coarse layers to be tested";
  StageRecorder recorder(&p.problem, &p.binding_0);
  ceres::Solver::Options solver = DenseSolver();
  solver.callbacks.push_back(&recorder);
  ProblemScheduleSummary summary;
  std::string error;
  ASSERT_TRUE(SolveWithLayerSchedule(LayerScheduleOptions(),
                                     solver,
                                     p.Bindings(),
                                     &p.problem,
                                     &summary,
                                     &error))
      << error;
  EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE)
      << summary.message;

  // Layers 1..n, coarse to fine, every stage on the same blocks.
  ASSERT_EQ(summary.stages.size(), static_cast<size_t>(n));
  ASSERT_EQ(recorder.block_ids.size(), static_cast<size_t>(n));
  const size_t points = Scans()[1].samples.size() + Scans()[2].samples.size();
  EXPECT_EQ(p.ids.size(), GetParam() ? 3u : points + 1);
  std::vector<ceres::ResidualBlockId> added = p.ids;
  std::sort(added.begin(), added.end());
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(summary.stages[k].layers, std::vector<int>({k + 1, k + 1}));
    EXPECT_EQ(recorder.num_blocks[k], static_cast<int>(p.ids.size()));
    std::vector<ceres::ResidualBlockId> ids = recorder.block_ids[k];
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, added) << "stage " << k + 1 << " has other blocks";
    if (k > 0) EXPECT_LT(recorder.cell_sizes[k], recorder.cell_sizes[k - 1]);
  }
  EXPECT_EQ(&p.binding_0.layer(), &Scans()[0].map.layer(n));

  // From the identity (0.69 m and 1.4 m off) to the references.
  const std::pair<int, int> edges[] = {{0, 1}, {1, 2}, {0, 2}};
  for (const auto& [i, j] : edges) {
    const Isometry3d reference =
        Reference(std::to_string(i) + "_" + std::to_string(j));
    EXPECT_LT(TranslationErrorM(reference, p.Relative(i, j)), 0.03)
        << i << "_" << j;
    EXPECT_LT(RotationErrorRad(reference, p.Relative(i, j)) * kRadToDeg, 0.2)
        << i << "_" << j;
  }
  EXPECT_LT(p.poses[0].ToIsometry().translation().norm(), 1e-3);
}

INSTANTIATE_TEST_SUITE_P(PairForms,
                         SolveWithLayerScheduleForms,
                         ::testing::Values(false, true));

TEST(SolveWithLayerSchedule, FinestLayerAloneDoesNotReachTheReferences) {
  // The same Problem without the coarse stages (start on layer n): from the
  // identity the finest cells are too small, which is why the schedule
  // exists.
  ThreeScanProblem p;
  LayerScheduleOptions finest_only;
  finest_only.start_layer = 0;
  ProblemScheduleSummary summary;
  std::string error;
  ASSERT_TRUE(SolveWithLayerSchedule(
      finest_only, DenseSolver(), p.Bindings(), &p.problem, &summary, &error))
      << error;
  EXPECT_EQ(summary.stages.size(), 1u);
  EXPECT_GT(TranslationErrorM(Reference("1_2"), p.Relative(1, 2)), 0.1);
}

TEST(SolveWithLayerSchedule, RefusesBadInputBeforeTouchingABinding) {
  ThreeScanProblem p;
  const NdtLayer* before = &p.binding_0.layer();
  ProblemScheduleSummary summary;
  std::string error;
  LayerScheduleOptions bad;
  bad.iterations_per_layer = 0;
  EXPECT_FALSE(SolveWithLayerSchedule(
      bad, DenseSolver(), p.Bindings(), &p.problem, &summary, &error));
  EXPECT_EQ(error.rfind("schedule: ", 0), 0u) << error;
  EXPECT_NE(error.find("iterations_per_layer"), std::string::npos) << error;
  std::vector<ScheduledBinding> bindings = p.Bindings();
  bindings[1].map = nullptr;
  EXPECT_FALSE(SolveWithLayerSchedule(LayerScheduleOptions(),
                                      DenseSolver(),
                                      bindings,
                                      &p.problem,
                                      &summary,
                                      &error));
  EXPECT_EQ(error, "bindings[1]: null binding or map");
  EXPECT_FALSE(SolveWithLayerSchedule(
      LayerScheduleOptions(), DenseSolver(), {}, &p.problem, &summary, &error));
  EXPECT_NE(error.find("bindings: none given"), std::string::npos) << error;
  EXPECT_EQ(&p.binding_0.layer(), before);
  EXPECT_TRUE(summary.stages.empty());
}

}  // namespace
}  // namespace mlndt
