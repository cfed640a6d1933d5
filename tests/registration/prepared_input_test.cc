#include "mlndt/registration/prepared_input.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/registration/prepared_registration.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// Bit for bit (NaN and infinities included): memcmp of the doubles.
template <typename Matrix>
bool SameBits(const Matrix& a, const Matrix& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, 8) == 0; }

// Everything but the times is the same, bit for bit.
void ExpectSameSummary(const RegistrationSummary& plain,
                       const RegistrationSummary& prepared) {
  EXPECT_EQ(plain.termination_type, prepared.termination_type);
  EXPECT_EQ(plain.message, prepared.message);
  EXPECT_TRUE(SameBits(plain.reference_from_input.matrix(),
                       prepared.reference_from_input.matrix()))
      << plain.reference_from_input.matrix() << "\n"
      << prepared.reference_from_input.matrix();
  EXPECT_TRUE(SameBits(plain.reference_from_input_xi,
                       prepared.reference_from_input_xi));
  EXPECT_TRUE(SameBits(plain.initial_reference_from_input_xi,
                       prepared.initial_reference_from_input_xi));
  EXPECT_TRUE(SameBits(plain.initial_score, prepared.initial_score));
  EXPECT_TRUE(SameBits(plain.final_score, prepared.final_score));
  EXPECT_TRUE(SameBits(plain.hessian, prepared.hessian));
  EXPECT_TRUE(SameBits(plain.covariance, prepared.covariance));
  EXPECT_TRUE(SameBits(plain.quality.inlier_fraction,
                       prepared.quality.inlier_fraction));
  EXPECT_TRUE(SameBits(plain.quality.mean_score, prepared.quality.mean_score));
  EXPECT_EQ(plain.attempts, prepared.attempts);
  EXPECT_EQ(plain.point_iterations, prepared.point_iterations);
  EXPECT_EQ(plain.start_layer, prepared.start_layer);
  EXPECT_EQ(plain.iterations_per_layer, prepared.iterations_per_layer);
  EXPECT_EQ(plain.input_points, prepared.input_points);
  EXPECT_EQ(plain.range_filtered_points, prepared.range_filtered_points);
  EXPECT_EQ(plain.sampled_points, prepared.sampled_points);
  EXPECT_EQ(plain.matched_points, prepared.matched_points);
  ASSERT_EQ(plain.trace.size(), prepared.trace.size());
  for (size_t i = 0; i < plain.trace.size(); ++i) {
    EXPECT_EQ(plain.trace[i].layer, prepared.trace[i].layer);
    EXPECT_TRUE(SameBits(plain.trace[i].score, prepared.trace[i].score)) << i;
    EXPECT_TRUE(SameBits(plain.trace[i].reference_from_input_xi,
                         prepared.trace[i].reference_from_input_xi))
        << i;
  }
}

// The koide3 Velodyne pair: the map of the target, the source prepared once
// and registered from several starts, against Register on the cloud from
// each start.
class PreparedVelodynePair : public ::testing::Test {
 protected:
  void SetUp() override {
    target_ = testing::LoadBundledCloud("koide3/251370668.pcd");
    source_ = testing::LoadBundledCloud("koide3/251371071.pcd");
    std::string error;
    ASSERT_TRUE(LayeredGrid::Build(
        RegistrationOptions().grid, target_, 1, &map_, &error))
        << error;
  }
  // The identity, and starts 0.6 m and 8 deg off it (inside and at the edge
  // of the default schedule's reach).
  static std::vector<Isometry3d> Starts() {
    return {Isometry3d::Identity(),
            PoseVectorToIsometry(PoseVectorFromDegrees(0.6, 0, 0, 0, 0, 0)),
            PoseVectorToIsometry(PoseVectorFromDegrees(0, -0.6, 0, 0, 0, 8)),
            PoseVectorToIsometry(PoseVectorFromDegrees(0.3, 0.3, 0, 0, 0, -8))};
  }
  PointCloud target_, source_;
  LayeredGrid map_;
};

TEST_F(PreparedVelodynePair, SameResultAsRegisterOnTheCloudFromEveryStart) {
  RegistrationOptions options;
  PreparedInput prepared;
  ASSERT_TRUE(PrepareInput(options, source_, &prepared))
      << prepared.input_error << prepared.sampling_error;
  for (const Isometry3d& start : Starts()) {
    RegistrationSummary plain, from_prepared;
    Register(options, map_, source_, start, &plain);
    Register(options, map_, prepared, start, &from_prepared);
    ASSERT_TRUE(plain.IsSolutionUsable()) << plain.message;
    EXPECT_EQ(from_prepared.sampled_points, prepared.points.size());
    ExpectSameSummary(plain, from_prepared);
  }
}

TEST_F(PreparedVelodynePair, SameResultWithAStatedPrior) {
  // As RegisterWithinPrior runs it: the prior picks the start layer and
  // bounds the retries.
  RegistrationOptions options;
  options.initial_uncertainty.given = true;
  options.initial_uncertainty.translation_m = 1.0;
  options.initial_uncertainty.rotation_deg = 15.0;
  PreparedInput prepared;
  ASSERT_TRUE(PrepareInput(options, source_, &prepared));
  // The prepared input registered again from the first start after the
  // others: nothing carries over between runs.
  std::vector<Isometry3d> starts = Starts();
  starts.push_back(starts.front());
  for (const Isometry3d& start : starts) {
    RegistrationSummary plain, from_prepared;
    Register(options, map_, source_, start, &plain);
    Register(options, map_, prepared, start, &from_prepared);
    ExpectSameSummary(plain, from_prepared);
  }
}

TEST_F(PreparedVelodynePair, SamplingIsDeterministic) {
  // What sharing the samples rests on: the same input and options sample
  // the same points, in the same order, every time.
  PreparedInput a, b;
  ASSERT_TRUE(PrepareInput(RegistrationOptions(), source_, &a));
  ASSERT_TRUE(PrepareInput(RegistrationOptions(), source_, &b));
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_GT(a.points.size(), 1000u);
  EXPECT_LT(a.points.size(), source_.size());
  for (size_t i = 0; i < a.points.size(); ++i) {
    ASSERT_TRUE(SameBits(a.points[i], b.points[i])) << i;
  }
  EXPECT_TRUE(SameBits(a.centre, b.centre));
  // Another seed samples other points.
  RegistrationOptions other_seed;
  other_seed.sampling.seed = 2;
  PreparedInput c;
  ASSERT_TRUE(PrepareInput(other_seed, source_, &c));
  EXPECT_FALSE(SameBits(a.centre, c.centre));
}

TEST_F(PreparedVelodynePair, TheSamplingItWasPreparedWithApplies) {
  RegistrationOptions sparse;
  sparse.sampling.method = SamplingMethod::RANDOM;
  sparse.sampling.random_fraction = 0.05;
  PreparedInput prepared;
  ASSERT_TRUE(PrepareInput(sparse, source_, &prepared));
  RegistrationSummary plain, from_prepared;
  Register(sparse, map_, source_, Isometry3d::Identity(), &plain);
  // Registered with the default sampling in the options: the prepared
  // samples are used.
  Register(RegistrationOptions(),
           map_,
           prepared,
           Isometry3d::Identity(),
           &from_prepared);
  ExpectSameSummary(plain, from_prepared);
}

TEST_F(PreparedVelodynePair, SameFailuresInTheSameOrder) {
  RegistrationOptions options;
  const Isometry3d nan_guess = Isometry3d(
      Eigen::Matrix4d::Constant(std::numeric_limits<double>::quiet_NaN()));
  RegistrationOptions too_close;  // Drops every point of the scan.
  too_close.range_filter.min_range_m = 1000.0;
  RegistrationOptions sparse_cells;  // GBS keeps no cell.
  sparse_cells.sampling.gbs_cell_size_m = 0.001;
  struct Case {
    RegistrationOptions options;
    PointCloud input;
    Isometry3d guess;
  };
  const std::vector<Case> cases = {
      {options, PointCloud(), Isometry3d::Identity()},
      {options, PointCloud(), nan_guess},  // The input's problem first.
      {options, source_, nan_guess},
      {too_close, source_, Isometry3d::Identity()},
      {too_close, source_, nan_guess},  // The guess's problem first.
      {sparse_cells, source_, Isometry3d::Identity()},
  };
  for (const Case& c : cases) {
    PreparedInput prepared;
    PrepareInput(c.options, c.input, &prepared);
    RegistrationSummary plain, from_prepared;
    Register(c.options, map_, c.input, c.guess, &plain);
    Register(c.options, map_, prepared, c.guess, &from_prepared);
    EXPECT_EQ(plain.termination_type, TerminationType::FAILURE);
    EXPECT_FALSE(plain.message.empty());
    ExpectSameSummary(plain, from_prepared);
  }
}

TEST_F(PreparedVelodynePair, PreparedWithInvalidOptionsFails) {
  RegistrationOptions invalid;
  invalid.range_filter.min_range_m = -1.0;
  PreparedInput prepared;
  EXPECT_FALSE(PrepareInput(invalid, source_, &prepared));
  RegistrationSummary summary;
  Register(
      RegistrationOptions(), map_, prepared, Isometry3d::Identity(), &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("prepared with invalid options"),
            std::string::npos)
      << summary.message;
}

// PreparedRegistration: one backend for every run, each run as Register on
// the cloud from its start, whatever ran before it (another start, another
// map), for each backend and with the Ceres blocks evaluated by two threads.
TEST_F(PreparedVelodynePair, SharedSetUpGivesRegistersResultFromEveryStart) {
  RegistrationOptions with_prior;
  with_prior.initial_uncertainty.given = true;
  with_prior.initial_uncertainty.translation_m = 1.0;
  with_prior.initial_uncertainty.rotation_deg = 15.0;
  RegistrationOptions lm = with_prior;
  lm.backend.type = BackendType::LEVENBERG_MARQUARDT;
  RegistrationOptions two_threads = with_prior;
  two_threads.num_threads = 2;
  LayeredGrid source_map;  // Another map: the source's own.
  std::string error;
  ASSERT_TRUE(
      LayeredGrid::Build(with_prior.grid, source_, 1, &source_map, &error));
  std::vector<Isometry3d> starts = Starts();
  starts.push_back(starts.front());
  for (const RegistrationOptions& options : {with_prior, lm, two_threads}) {
    PreparedInput prepared;
    ASSERT_TRUE(PrepareInput(options, source_, &prepared));
    PreparedRegistration runs(options, prepared);
    for (const Isometry3d& start : starts) {
      RegistrationSummary plain, shared;
      Register(options, map_, source_, start, &plain);
      runs.Register(map_, start, &shared);
      ASSERT_TRUE(plain.IsSolutionUsable()) << plain.message;
      ExpectSameSummary(plain, shared);
      Register(options, source_map, source_, start, &plain);
      runs.Register(source_map, start, &shared);
      ExpectSameSummary(plain, shared);
    }
  }
}

TEST_F(PreparedVelodynePair, SharedSetUpFailsAsRegister) {
  RegistrationOptions invalid;
  invalid.num_threads = 0;
  RegistrationOptions options;
  PreparedInput prepared, empty;
  ASSERT_TRUE(PrepareInput(options, source_, &prepared));
  PrepareInput(options, PointCloud(), &empty);
  const LayeredGrid no_map;
  const Isometry3d nan_guess = Isometry3d(
      Eigen::Matrix4d::Constant(std::numeric_limits<double>::quiet_NaN()));
  struct Case {
    RegistrationOptions options;
    const PointCloud* input;
    const PreparedInput* prepared;
    const LayeredGrid* map;
    Isometry3d guess;
  };
  const PointCloud no_points;
  const std::vector<Case> cases = {
      {invalid, &source_, &prepared, &map_, Isometry3d::Identity()},
      {options, &source_, &prepared, &no_map, Isometry3d::Identity()},
      {options, &source_, &prepared, &map_, nan_guess},
      {options, &no_points, &empty, &map_, nan_guess},
  };
  for (const Case& c : cases) {
    RegistrationSummary plain, shared;
    Register(c.options, *c.map, *c.input, c.guess, &plain);
    PreparedRegistration(c.options, *c.prepared)
        .Register(*c.map, c.guess, &shared);
    EXPECT_EQ(plain.termination_type, TerminationType::FAILURE);
    ExpectSameSummary(plain, shared);
  }
}

}  // namespace
}  // namespace mlndt
