// The shell both hand-written backends share (hand_written_backend.h):
// SolveStage before SetProblem is a programming error naming the backend,
// and the Newton backend thins the points by control.point_stride before it
// minimises (the LM backend's test checks the same for LM), so that one
// shell serves both.

#include "mlndt/solvers/hand_written_backend.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/pose.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/solvers/levenberg_marquardt_backend.h"
#include "mlndt/solvers/newton_backend.h"
#include "tests/testing/street_pair.h"

namespace mlndt {
namespace {

using testing::Street;
using testing::StreetPair;

StageControl Control(int max_iterations) {
  StageControl control;
  control.max_iterations = max_iterations;
  return control;
}

TEST(HandWrittenBackendDeathTest, StageBeforeSetProblemNamesTheBackend) {
  const NdtLayer& layer = Street().map.layer(1);
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  NewtonBackend newton{NewtonOptions()};
  EXPECT_DEATH(newton.SolveStage(layer, Control(3), &xi, &summary),
               "NewtonBackend: SetProblem first");
  LevenbergMarquardtBackend lm{LevenbergMarquardtOptions()};
  EXPECT_DEATH(lm.SolveStage(layer, Control(3), &xi, &summary),
               "LevenbergMarquardtBackend: SetProblem first");
}

// The stride and thread counts of the Newton backend's stage; the
// minimiser runs on the same threads.
struct StrideCase {
  int stride;
  int threads;
};

void PrintTo(const StrideCase& c, std::ostream* os) {
  *os << "stride " << c.stride << ", " << c.threads << " thread(s)";
}

class NewtonStride : public ::testing::TestWithParam<StrideCase> {};

// Catches: a shell that ignores point_stride, thins from another offset or
// with another stride, or hands the minimiser another objective than
// MlNdtObjective.
TEST_P(NewtonStride, MatchesMinimizeNewtonOnThinnedPoints) {
  const StrideCase c = GetParam();
  const StreetPair& street = Street();
  const NdtLayer& layer = street.map.layer(street.map.num_layers() - 1);
  const ObjectiveOptions objective;
  StageControl control = Control(6);
  control.point_stride = c.stride;

  NewtonBackend backend{NewtonOptions()};
  backend.SetProblem(street.input, objective, c.threads);
  Vector6d strided = Vector6d::Zero();
  StageSummary strided_summary;
  backend.SolveStage(layer, control, &strided, &strided_summary);

  std::vector<Eigen::Vector3d> thinned;
  for (size_t i = 0; i < street.input.size();
       i += static_cast<size_t>(c.stride)) {
    thinned.push_back(street.input[i]);
  }
  control.point_stride = 1;
  Vector6d direct = Vector6d::Zero();
  StageSummary direct_summary;
  MinimizeNewton(MlNdtObjective(layer, thinned, objective, c.threads),
                 NewtonOptions(),
                 control,
                 &direct,
                 &direct_summary);

  ASSERT_NE(strided_summary.termination_type, TerminationType::FAILURE)
      << strided_summary.message;
  EXPECT_GT(strided.head<3>().norm(), 0.1);  // The stage moved the pose.
  EXPECT_EQ(strided, direct);
  EXPECT_EQ(strided_summary.final_score, direct_summary.final_score);
  EXPECT_EQ(strided_summary.iterations(), direct_summary.iterations());
  EXPECT_EQ(strided_summary.trace.size(), direct_summary.trace.size());
  EXPECT_EQ(strided_summary.message, direct_summary.message);
}

INSTANTIATE_TEST_SUITE_P(HandWrittenBackend,
                         NewtonStride,
                         ::testing::Values(StrideCase{2, 1}, StrideCase{4, 2}),
                         [](const ::testing::TestParamInfo<StrideCase>& info) {
                           return "stride" + std::to_string(info.param.stride) +
                                  "_threads" +
                                  std::to_string(info.param.threads);
                         });

}  // namespace
}  // namespace mlndt
