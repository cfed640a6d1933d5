// The conventional single-grid NDT baseline (RegisterNdt): summary, failures,
// convergence on the synthetic street scene and the bundled KITTI pairs, and
// the paper's long-range claim against ML-NDT.

#include "mlndt/ndt/ndt_registration.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "lab/runs/matcher.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "mlndt/ndt/gaussian_score.h"
#include "mlndt/ndt/ndt_objective.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/synthetic_scene.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

NdtOptions Ndt(double cell_size_m,
               NdtNeighbors neighbors = NdtOptions().neighbors) {
  NdtOptions options;
  options.cell_size_m = cell_size_m;
  options.neighbors = neighbors;
  return options;
}

void Register(const NdtOptions& options,
              const PointCloud& reference,
              const PointCloud& input,
              const Isometry3d& initial,
              RegistrationSummary* summary) {
  RegisterNdt(options, reference, input, initial, summary);
}

// Registers a second sampling of the street scene, seen from a sensor at
// `reference_from_input`, from the identity (NDT or ML-NDT options).
template <typename Options>
RegistrationSummary RegisterStreet(const Isometry3d& reference_from_input,
                                   const Options& options) {
  const PointCloud reference = testing::StreetScene(60000, 0.02, 1);
  const PointCloud input = TransformCloud(reference_from_input.inverse(),
                                          testing::StreetScene(60000, 0.02, 2));
  RegistrationSummary summary;
  Register(options, reference, input, Isometry3d::Identity(), &summary);
  return summary;
}

TEST(NdtBaseline, ObjectiveIsTheGaussianScore) {
  const PointCloud reference = testing::StreetScene(20000, 0.02, 1);
  const PointCloud input = testing::StreetScene(5000, 0.02, 2);
  LayeredGridOptions grid_options;
  grid_options.cell_size_m = 2.0;
  LayeredGrid map;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(grid_options, reference, &map, &error))
      << error;
  const NdtLayer& grid = map.layer(1);
  GaussianScoreOptions score_options;
  const NdtGaussianObjective objective(grid, input.points(), score_options);
  const Vector6d xi = PoseVectorFromDegrees(0.1, -0.1, 0.0, 0.5, 0.0, 1.0);
  for (HessianType h :
       {HessianType::NONE, HessianType::GAUSS_NEWTON, HessianType::FULL}) {
    score_options.hessian = h;
    const ScoreEvaluation direct =
        EvaluateGaussianScore(grid, input.points(), xi, score_options);
    const ScoreEvaluation via = objective.Evaluate(xi, h);
    EXPECT_EQ(via.score, direct.score);
    EXPECT_EQ(via.gradient, direct.gradient);
    EXPECT_EQ(via.hessian, direct.hessian);
    EXPECT_EQ(via.matched, direct.matched);
  }
}

// Small motions the Gaussian score's basin holds with 1 m cells. DIRECT1's
// basin is narrow on this scene (about 0.1 m and 0.3 deg: a 0.15 m shift
// along the street, where only boxes, poles and recesses constrain x, or a
// 0.5 deg yaw, 0.35 m at the scene's ends, is not recovered); DIRECT7
// widens it to 1 m and 4 deg.
struct SmallTransformCase {
  NdtNeighbors neighbors;
  double tx, ty, tz, alpha_deg, beta_deg, gamma_deg;
};

class NdtSmallTransform : public ::testing::TestWithParam<SmallTransformCase> {
};

TEST_P(NdtSmallTransform, RecoversKnownTransformWithOneMetreCells) {
  const SmallTransformCase& c = GetParam();
  const Isometry3d truth = PoseVectorToIsometry(PoseVectorFromDegrees(
      c.tx, c.ty, c.tz, c.alpha_deg, c.beta_deg, c.gamma_deg));
  const RegistrationSummary s = RegisterStreet(truth, Ndt(1.0, c.neighbors));
  ASSERT_TRUE(s.IsSolutionUsable()) << s.message;
  EXPECT_LT(TranslationErrorM(truth, s.reference_from_input), 0.02)
      << s.FullReport();
  EXPECT_LT(RotationErrorRad(truth, s.reference_from_input) * kRadToDeg, 0.1)
      << s.FullReport();
}

INSTANTIATE_TEST_SUITE_P(
    Synthetic,
    NdtSmallTransform,
    ::testing::Values(
        SmallTransformCase{NdtNeighbors::DIRECT1, 0.05, 0.05, 0, 0, 0, 0.3},
        SmallTransformCase{
            NdtNeighbors::DIRECT1, 0.05, 0.1, 0.05, 0.2, 0.1, 0.3},
        SmallTransformCase{
            NdtNeighbors::DIRECT1, 0.03, -0.1, 0.03, 0.3, -0.2, -0.3},
        SmallTransformCase{NdtNeighbors::DIRECT7, 0.3, 0.2, 0, 0, 0, 2},
        SmallTransformCase{NdtNeighbors::DIRECT7, 0.5, -0.3, 0.05, 0.5, 0, 3}));

TEST(NdtBaseline, SummaryIsComplete) {
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(0.2, 0.1, 0, 0, 0, 1));
  const RegistrationSummary s = RegisterStreet(truth, Ndt(2.0));
  ASSERT_TRUE(s.IsSolutionUsable()) << s.message;
  EXPECT_EQ(s.algorithm, "NDT");
  EXPECT_EQ(s.BriefReport().rfind("NDT registration", 0), 0u)
      << s.BriefReport();
  EXPECT_NE(s.FullReport().find("start 1 of 1 (finest cell 2.00 m)"),
            std::string::npos)
      << s.FullReport();
  EXPECT_EQ(s.finest_cell_size_m, 2.0);
  EXPECT_GT(s.map_occupied_cells, 0u);
  EXPECT_EQ(s.num_layers, 1);
  EXPECT_EQ(s.start_layer, 1);
  ASSERT_EQ(s.iterations_per_layer.size(), 1u);
  EXPECT_EQ(s.iterations_per_layer[0], s.num_iterations);
  EXPECT_EQ(static_cast<int>(s.trace.size()), s.num_iterations);
  ASSERT_FALSE(s.trace.empty());
  for (size_t i = 0; i < s.trace.size(); ++i) {
    EXPECT_EQ(s.trace[i].layer, 1);
    EXPECT_EQ(s.trace[i].iteration, static_cast<int>(i) + 1);
    if (i > 0) EXPECT_GE(s.trace[i].time_s, s.trace[i - 1].time_s);
  }
  EXPECT_LE(s.num_iterations, NdtOptions().max_iterations);
  EXPECT_GT(s.sampled_points, 0u);
  EXPECT_EQ(s.matched_points + s.unmatched_points, s.sampled_points);
  EXPECT_GT(s.map_time_s, 0.0);
  EXPECT_GT(s.solve_time_s, 0.0);
  EXPECT_GE(s.total_time_s, s.map_time_s + s.sampling_time_s + s.solve_time_s);
  // Gaussian scores are negative and lower is better.
  EXPECT_LT(s.final_score, 0.0);
  EXPECT_LT(s.final_score, s.initial_score);
  EXPECT_EQ(s.final_score, s.trace.back().score);
  // At a minimum the full Newton Hessian is positive definite, and the
  // covariance is its inverse.
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(s.hessian);
  EXPECT_GT(solver.eigenvalues().minCoeff(), 0.0);
  EXPECT_LT(
      (s.covariance * s.hessian - Matrix6d::Identity()).cwiseAbs().maxCoeff(),
      1e-6);
  EXPECT_LT(std::sqrt(s.covariance(0, 0)), 0.05);
}

TEST(NdtBaseline, DefaultCellIsThePapersLayerTwoCell) {
  const PointCloud reference = testing::StreetScene(60000, 0.02, 1);
  const RegistrationSummary s =
      RegisterStreet(Isometry3d::Identity(), Ndt(0.0));
  ASSERT_TRUE(s.IsSolutionUsable()) << s.message;
  LayeredGrid paper_map;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(
      PaperLayeredGridOptions(), reference, &paper_map, &error))
      << error;
  EXPECT_EQ(s.finest_cell_size_m, paper_map.layer(2).cell_size());
}

TEST(NdtBaseline, PrebuiltMapGivesWhatTheCloudOverloadGives) {
  const PointCloud reference = testing::StreetScene(20000, 0.02, 1);
  const PointCloud input = testing::StreetScene(20000, 0.02, 2);
  for (double cell : {0.0, 1.5}) {
    SCOPED_TRACE(cell);
    const PointCloud kept =
        FilterByRange(Ndt(cell).range_filter, reference, nullptr);
    LayeredGridOptions grid_options;
    LayeredGrid map;
    std::string error;
    ASSERT_TRUE(NdtGridOptions(Ndt(cell), kept, &grid_options, &error));
    ASSERT_TRUE(LayeredGrid::Build(grid_options, kept, &map, &error)) << error;
    RegistrationSummary on_map, on_cloud;
    RegisterNdt(Ndt(cell), map, input, Isometry3d::Identity(), &on_map);
    RegisterNdt(Ndt(cell), reference, input, Isometry3d::Identity(), &on_cloud);
    ASSERT_TRUE(on_map.IsSolutionUsable()) << on_map.message;
    EXPECT_EQ(on_map.reference_from_input_xi, on_cloud.reference_from_input_xi);
    EXPECT_EQ(on_map.final_score, on_cloud.final_score);
    EXPECT_EQ(on_map.num_iterations, on_cloud.num_iterations);
    EXPECT_EQ(on_map.map_time_s, 0.0);
  }
  // The matcher dispatches to the same entry points.
  MatcherOptions matcher;
  matcher.method = Method::NDT;
  matcher.ndt = Ndt(1.5);
  RegistrationSummary via_matcher, direct;
  RegisterWithMatcher(
      matcher, reference, input, Isometry3d::Identity(), &via_matcher);
  RegisterNdt(Ndt(1.5), reference, input, Isometry3d::Identity(), &direct);
  EXPECT_EQ(via_matcher.reference_from_input_xi,
            direct.reference_from_input_xi);
}

TEST(NdtBaseline, InvalidOptionsAndBadInputGiveFailure) {
  const PointCloud cloud = testing::StreetScene(5000, 0.02, 1);
  RegistrationSummary s;
  NdtOptions options = Ndt(1.0);
  options.outlier_ratio = 1.0;
  Register(options, cloud, cloud, Isometry3d::Identity(), &s);
  EXPECT_EQ(s.termination_type, TerminationType::FAILURE);
  EXPECT_NE(s.message.find("outlier_ratio"), std::string::npos) << s.message;

  options = Ndt(-1.0);
  Register(options, cloud, cloud, Isometry3d::Identity(), &s);
  EXPECT_NE(s.message.find("cell_size_m"), std::string::npos) << s.message;

  options = Ndt(1.0);
  options.max_iterations = 0;
  Register(options, cloud, cloud, Isometry3d::Identity(), &s);
  EXPECT_NE(s.message.find("max_iterations"), std::string::npos) << s.message;

  options = Ndt(1.0);
  options.max_step_norm = -0.1;
  Register(options, cloud, cloud, Isometry3d::Identity(), &s);
  EXPECT_NE(s.message.find("max_step_norm"), std::string::npos) << s.message;

  Register(Ndt(1.0), PointCloud(), cloud, Isometry3d::Identity(), &s);
  EXPECT_EQ(s.termination_type, TerminationType::FAILURE);
  EXPECT_NE(s.message.find("reference"), std::string::npos) << s.message;

  Register(Ndt(1.0), cloud, PointCloud(), Isometry3d::Identity(), &s);
  EXPECT_NE(s.message.find("input cloud is empty"), std::string::npos)
      << s.message;

  PointCloud nan_input = cloud;
  nan_input.Add(
      Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0));
  Register(Ndt(1.0), cloud, nan_input, Isometry3d::Identity(), &s);
  EXPECT_NE(s.message.find("non-finite"), std::string::npos) << s.message;

  // Clouds 1 km apart: no sampled point lies in an occupied cell.
  Register(Ndt(1.0),
           cloud,
           TransformCloud(
               PoseVectorToIsometry(PoseVectorFromDegrees(1000, 0, 0, 0, 0, 0)),
               cloud),
           Isometry3d::Identity(),
           &s);
  EXPECT_EQ(s.termination_type, TerminationType::FAILURE);
  EXPECT_NE(s.message.find("occupied cell"), std::string::npos) << s.message;
}

TEST(NdtBaseline, LongRangeStartFailsWhereMlNdtSucceeds) {
  // The paper's long-range claim (Section 5.3): from the identity, 5 m and
  // 20 deg away, ML-NDT converges; single-grid NDT with the small cells it
  // needs for accuracy does not, and with the paper's comparison cell (one
  // layer-2 cell, 8.5 m here) it ends ~9 cm off where ML-NDT ends ~1 mm off.
  const Isometry3d truth =
      PoseVectorToIsometry(PoseVectorFromDegrees(5, 0, 0, 0, 0, 20));
  const RegistrationSummary mlndt =
      RegisterStreet(truth, RegistrationOptions());
  ASSERT_TRUE(mlndt.IsSolutionUsable()) << mlndt.message;
  EXPECT_LT(TranslationErrorM(truth, mlndt.reference_from_input), 0.05)
      << mlndt.FullReport();
  EXPECT_LT(RotationErrorRad(truth, mlndt.reference_from_input) * kRadToDeg,
            0.3);

  for (const NdtOptions& options : {Ndt(1.0, NdtNeighbors::DIRECT1),
                                    Ndt(1.0, NdtNeighbors::DIRECT7),
                                    Ndt(2.0)}) {
    const RegistrationSummary ndt = RegisterStreet(truth, options);
    const double error_m = TranslationErrorM(truth, ndt.reference_from_input);
    EXPECT_TRUE(!ndt.IsSolutionUsable() || error_m > 1.0)
        << "cell " << options.cell_size_m << " m: " << error_m << " m\n"
        << ndt.FullReport();
  }
  const RegistrationSummary coarse = RegisterStreet(truth, Ndt(0.0));
  EXPECT_GT(TranslationErrorM(truth, coarse.reference_from_input), 0.05)
      << coarse.FullReport();
}

class NdtKittiFrames : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    for (int i = 0; i < 8; ++i) {
      PointCloud cloud;
      std::string error;
      ASSERT_TRUE(
          ReadPointCloud(testing::BundledDataPath("kitti/pcd/00000" +
                                                  std::to_string(i) + ".pcd"),
                         &cloud,
                         nullptr,
                         &error))
          << error;
      scans_.push_back(cloud);
    }
    std::string error;
    ASSERT_TRUE(ReadKittiPoses(
        testing::BundledDataPath("kitti/poses_velo.txt"), &poses_, &error))
        << error;
    ASSERT_EQ(poses_.size(), 8u);
  }
  // Consecutive pairs from identity within 0.2 m and 1 deg of ground truth.
  // (The scans fit best at ~0.8x the ground-truth translation, so even a
  // perfect result ends 0.1-0.17 m off.)
  static int ConsecutiveSuccesses(const NdtOptions& options,
                                  std::string* report) {
    int successes = 0;
    for (int i = 0; i + 1 < 8; ++i) {
      const Isometry3d truth = poses_[i].inverse() * poses_[i + 1];
      RegistrationSummary s;
      Register(options, scans_[i], scans_[i + 1], Isometry3d::Identity(), &s);
      const double et = TranslationErrorM(truth, s.reference_from_input);
      const double er =
          RotationErrorRad(truth, s.reference_from_input) * kRadToDeg;
      successes += s.IsSolutionUsable() && et < 0.2 && er < 1.0;
      *report += "pair " + std::to_string(i) + ": " + std::to_string(et) +
                 " m, " + std::to_string(er) + " deg, " + s.message + "\n";
    }
    return successes;
  }
  static std::vector<PointCloud> scans_;
  static std::vector<Isometry3d> poses_;
};
std::vector<PointCloud> NdtKittiFrames::scans_;
std::vector<Isometry3d> NdtKittiFrames::poses_;

TEST_F(NdtKittiFrames, ConsecutivePairsFromIdentity) {
  // Issue requirement: >= 70 % of the 7 pairs (5). Measured: 5 of 7 with the
  // paper's cell (~15 m; at the threshold: its coarse model ends 0.2-0.5 m
  // off on the others), 7 of 7 with 2 m cells.
  std::string report;
  EXPECT_GE(ConsecutiveSuccesses(Ndt(0.0), &report), 5) << report;
  report.clear();
  EXPECT_GE(ConsecutiveSuccesses(Ndt(2.0), &report), 5) << report;
}

// The NDT baseline has ML-NDT's verdict (JudgeSolution): started 180 deg
// off, its Newton steps stop wherever the Gaussian score flattens, and
// before the verdict every such stop was CONVERGENCE (5 m off, exit 0).
TEST_F(NdtKittiFrames, AWrongPoseFromAFarStartIsNotCalledConverged) {
  int wrong = 0;
  for (int i = 0; i + 1 < 8; i += 2) {
    const Isometry3d truth = poses_[i].inverse() * poses_[i + 1];
    Isometry3d turned = truth;
    turned.linear() =
        Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()) * truth.linear();
    RegistrationSummary s;
    Register(NdtOptions(), scans_[i], scans_[i + 1], turned, &s);
    const bool right =
        TranslationErrorM(truth, s.reference_from_input) < 0.2 &&
        RotationErrorRad(truth, s.reference_from_input) < 1.0 * kDegToRad;
    wrong += !right;
    if (!right) {
      EXPECT_FALSE(s.IsSolutionUsable()) << "pair " << i << "\n"
                                         << s.FullReport();
    }
  }
  EXPECT_GT(wrong, 0) << "no start ended wrong: the test checks nothing";
}

// A ground plane alone: the fit leaves its in-plane translations and the
// turn about its normal free. The verdict names it, and the covariance is
// infinite along them (it was H^-1 of a near-singular Hessian, or zero).
TEST(NdtBaseline, APlaneIsDegenerateWithAnInfiniteCovariance) {
  const auto plane = [](int n, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> xy(-20.0, 20.0);
    std::normal_distribution<double> noise(0.0, 0.02);
    PointCloud cloud;
    for (int k = 0; k < n; ++k) {
      cloud.Add(Eigen::Vector3d(xy(random), xy(random), noise(random)));
    }
    return cloud;
  };
  RegistrationSummary s;
  Register(
      Ndt(2.0), plane(20000, 1), plane(20000, 2), Isometry3d::Identity(), &s);
  EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE) << s.message;
  EXPECT_NE(s.message.find("translation along"), std::string::npos)
      << s.message;
  EXPECT_TRUE(std::isinf(s.covariance(0, 0)) && std::isinf(s.covariance(1, 1)))
      << s.covariance;
}

// The corridor of issue 22 (40 m of input in a 100 m reference) at 8000 and
// 45000 input points: with the probe of weak directions (on by default)
// the same verdict as ML-NDT's, through the same check, whatever the
// density: the corridor's length is free.
TEST(NdtBaseline, ACorridorIsDegenerateAlongItsLengthAtAnyDensity) {
  for (const int n : {8000, 45000}) {
    Isometry3d truth = Isometry3d::Identity();
    truth.translation() = Eigen::Vector3d(1.0, 0.1, 0.0);
    RegistrationSummary s;
    Register(Ndt(0.0),
             testing::Corridor(50.0, n * 5 / 2, 1),
             TransformCloud(truth.inverse(), testing::Corridor(20.0, n, 2)),
             Isometry3d::Identity(),
             &s);
    EXPECT_EQ(s.termination_type, TerminationType::DEGENERATE)
        << n << " points: " << s.message;
    EXPECT_NE(s.message.find("translation along (1.00, "), std::string::npos)
        << n << " points: " << s.message;
    EXPECT_GE(s.covariance(0, 0), 1.0) << n << " points: " << s.covariance;
  }
}

}  // namespace
}  // namespace mlndt
