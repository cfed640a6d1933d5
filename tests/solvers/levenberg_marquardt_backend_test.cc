// MinimizeLevenbergMarquardt on synthetic least-squares objectives whose
// minimum is known analytically: residuals r(z) of z = J0 (x - x*) with
// J0^T J0 = Q diag(1 2 4 8 16 32) Q^T (ceres' dogleg_strategy_test.cc), score
// |r|^2, gradient 2 J^T r and Gauss-Newton Hessian 2 J^T J. The objective logs
// where it is evaluated, so the tests can read back the damped system of
// every step; and the LevenbergMarquardtBackend on a real layer.

#include "mlndt/solvers/levenberg_marquardt_backend.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/pose.h"
#include "mlndt/grid/layered_grid.h"
#include "tests/testing/eigen_near.h"
#include "tests/testing/street_pair.h"

namespace mlndt {
namespace {

using testing::EigenNear;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A random orthonormal basis of R^6, fixed by the seed.
Matrix6d RandomBasis(uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Matrix6d m;
  for (int i = 0; i < 36; ++i) m.data()[i] = normal(rng);
  return Eigen::HouseholderQR<Matrix6d>(m).householderQ();
}

enum class Residual {
  LINEAR,     // r = z: one Gauss-Newton step solves it.
  QUADRATIC,  // r = z + z.^2 / 5: mildly non-linear, zero at z = 0.
  // r = atan(z): flat far out, so long steps overshoot (Newton on atan
  // diverges beyond |z| = 1.39) and LM rejects some of them.
  ATAN,
};

struct Evaluation {
  Vector6d xi;
  HessianType hessian;
};

class LeastSquaresObjective : public Objective {
 public:
  LeastSquaresObjective(Residual residual, const Vector6d& minimum)
      : residual_(residual), minimum_(minimum) {
    Vector6d d;
    d << 1.0, 2.0, 4.0, 8.0, 16.0, 32.0;
    j0_ = d.cwiseSqrt().asDiagonal() * RandomBasis(11).transpose();
  }

  ScoreEvaluation Evaluate(const Vector6d& xi,
                           HessianType hessian) const override {
    log_.push_back({xi, hessian});
    const Vector6d z = j0_ * (xi - minimum_);
    Vector6d r, dr;
    for (int i = 0; i < 6; ++i) {
      switch (residual_) {
        case Residual::LINEAR:
          r(i) = z(i);
          dr(i) = 1.0;
          break;
        case Residual::QUADRATIC:
          r(i) = z(i) + 0.2 * z(i) * z(i);
          dr(i) = 1.0 + 0.4 * z(i);
          break;
        case Residual::ATAN:
          r(i) = std::atan(z(i));
          dr(i) = 1.0 / (1.0 + z(i) * z(i));
          break;
      }
    }
    const Matrix6d j = dr.asDiagonal() * j0_;
    ScoreEvaluation evaluation;
    evaluation.matched = 6;
    evaluation.score = r.squaredNorm();
    if (hessian != HessianType::NONE) {
      evaluation.gradient = 2.0 * j.transpose() * r;
      evaluation.hessian = 2.0 * j.transpose() * j;
    }
    return evaluation;
  }

  // The pose where z = J0 (x - x*) takes the value `z`.
  Vector6d FromZ(const Vector6d& z) const {
    return minimum_ + j0_.fullPivLu().solve(z);
  }
  const std::vector<Evaluation>& log() const { return log_; }

 private:
  const Residual residual_;
  const Vector6d minimum_;
  Matrix6d j0_;
  mutable std::vector<Evaluation> log_;
};

Vector6d Minimum() {
  Vector6d x;
  x << 1.0, -2.0, 0.5, 0.3, -0.7, 2.0;
  return x;
}

Vector6d StartZ() {
  Vector6d z;
  z << 2.0, -1.5, 1.0, 0.5, -2.5, 0.3;
  return z;
}

StageControl Control(int max_iterations, double step_tolerance = 0.0) {
  StageControl control;
  control.max_iterations = max_iterations;
  control.step_tolerance = step_tolerance;
  return control;
}

// Catches: a wrong step (a sign, a damping that never decreases, so that it
// crawls), no convergence test, evaluations with another Hessian than
// Gauss-Newton (or none, for a candidate's score).
TEST(MinimizeLevenbergMarquardt, ConvergesToTheMinimum) {
  for (const Residual residual : {Residual::LINEAR, Residual::QUADRATIC}) {
    SCOPED_TRACE(static_cast<int>(residual));
    const LeastSquaresObjective objective(residual, Minimum());
    const Vector6d x0 = objective.FromZ(StartZ() / 2);
    Vector6d xi = x0;
    StageSummary summary;
    MinimizeLevenbergMarquardt(objective,
                               LevenbergMarquardtOptions(),
                               Control(30, 1e-10),
                               &xi,
                               &summary);
    EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE)
        << summary.message;
    EXPECT_TRUE(EigenNear(xi, Minimum(), 1e-10));
    EXPECT_LT(summary.final_score, 1e-20);
    // Quadratic convergence from a small initial damping: a few steps.
    EXPECT_LE(summary.iterations(), residual == Residual::LINEAR ? 5 : 8);
    for (const Evaluation& evaluation : objective.log()) {
      EXPECT_NE(evaluation.hessian, HessianType::FULL);
    }
  }
}

// The poses LM evaluated, in order, without the second evaluation of an
// accepted candidate whose normal equations were formed once needed.
std::vector<Evaluation> Candidates(const std::vector<Evaluation>& log) {
  std::vector<Evaluation> candidates;
  for (const Evaluation& evaluation : log) {
    if (!candidates.empty() && candidates.back().xi == evaluation.xi) continue;
    candidates.push_back(evaluation);
  }
  return candidates;
}

// lambda of every step, read back from the damped system the step solved:
// (H + 2 lambda I) delta = -g at the current pose (the last one accepted)
// gives 2 lambda delta = -(g + H delta). Checks that the residual of that
// system is parallel to delta (the damping is lambda I, not lambda diag(H)).
std::vector<double> RecoverLambdas(const LeastSquaresObjective& objective,
                                   const Vector6d& x0,
                                   const StageSummary& summary) {
  const LeastSquaresObjective probe = objective;  // Keeps the log intact.
  const std::vector<Evaluation> log = Candidates(objective.log());
  EXPECT_EQ(log.size(), summary.trace.size() + 1);  // Start + one per step.
  std::vector<double> lambdas;
  Vector6d current = x0;
  for (size_t k = 0; k < summary.trace.size() && k + 1 < log.size(); ++k) {
    const ScoreEvaluation at =
        probe.Evaluate(current, HessianType::GAUSS_NEWTON);
    const Vector6d delta = log[k + 1].xi - current;
    const Vector6d residual = at.gradient + at.hessian * delta;
    const double lambda = -delta.dot(residual) / (2.0 * delta.squaredNorm());
    EXPECT_LE((residual + 2.0 * lambda * delta).norm(), 1e-6 * residual.norm())
        << "step " << k;
    EXPECT_NEAR(summary.trace[k].step_norm, delta.norm(), 1e-9 * delta.norm());
    lambdas.push_back(lambda);
    if (summary.trace[k].step_is_successful) {
      current = summary.trace[k].reference_from_input_xi;
    }
  }
  return lambdas;
}

// The ATAN problem with its minimum at the origin, so that the steps near it
// (differences of poses) keep their relative precision: from StartZ() LM
// rejects 8 of its 21 steps before converging.
Vector6d Origin() { return Vector6d::Zero(); }

// Catches: lambda_0 not 1e-3 mean(diag(J^T J)) (e.g. of diag(H) = 2 J^T J),
// the decrease and increase swapped or hard-wired to 10, no update after a
// rejection, Marquardt's diag(H) scaling instead of lambda I.
TEST(MinimizeLevenbergMarquardt, DampingFollowsThePaperSchedule) {
  LevenbergMarquardtOptions custom;
  custom.initial_lambda_factor = 1e-4;
  custom.lambda_decrease = 3.0;
  custom.lambda_increase = 7.0;
  for (const LevenbergMarquardtOptions& options :
       {LevenbergMarquardtOptions(), custom}) {
    SCOPED_TRACE(options.lambda_decrease);
    const LeastSquaresObjective objective(Residual::ATAN, Origin());
    const Vector6d x0 = objective.FromZ(StartZ());
    Vector6d xi = x0;
    StageSummary summary;
    MinimizeLevenbergMarquardt(
        objective, options, Control(60, 1e-12), &xi, &summary);
    ASSERT_EQ(summary.termination_type, TerminationType::CONVERGENCE)
        << summary.message;
    const std::vector<double> lambdas = RecoverLambdas(objective, x0, summary);
    ASSERT_EQ(lambdas.size(), summary.trace.size());

    const ScoreEvaluation start =
        LeastSquaresObjective(Residual::ATAN, Origin())
            .Evaluate(x0, HessianType::GAUSS_NEWTON);
    const double mean_jtj = start.hessian.diagonal().mean() / 2.0;
    EXPECT_NEAR(lambdas[0],
                options.initial_lambda_factor * mean_jtj,
                1e-6 * lambdas[0]);
    int accepted = 0, rejected = 0;
    for (size_t k = 0; k + 1 < lambdas.size(); ++k) {
      const bool successful = summary.trace[k].step_is_successful;
      (successful ? accepted : rejected) += 1;
      const double expected = successful ? lambdas[k] / options.lambda_decrease
                                         : lambdas[k] * options.lambda_increase;
      EXPECT_NEAR(lambdas[k + 1], expected, 1e-5 * expected) << "step " << k;
    }
    // Both branches ran, so the schedule was tested, not assumed.
    EXPECT_GT(accepted, 2);
    EXPECT_GT(rejected, 2);
  }
}

// LM with the default options from *xi, to convergence or 60 iterations.
StageSummary MinimizeFromStart(const Objective& objective, Vector6d* xi) {
  StageSummary summary;
  MinimizeLevenbergMarquardt(
      objective, LevenbergMarquardtOptions(), Control(60, 1e-12), xi, &summary);
  return summary;
}

// Catches: normal equations formed for every candidate (a rejected one's are
// never used), or a step solved without the normal equations of the pose it
// starts from. A candidate after a taken step gets them with its score (the
// next step is likely taken too); after a rejected one, only once taken.
TEST(MinimizeLevenbergMarquardt, FormsNormalEquationsOnlyWhereTheyAreUsed) {
  const LeastSquaresObjective objective(Residual::ATAN, Origin());
  const Vector6d x0 = objective.FromZ(StartZ());
  Vector6d xi = x0;
  const StageSummary summary = MinimizeFromStart(objective, &xi);
  const std::vector<Evaluation>& log = objective.log();
  ASSERT_FALSE(log.empty());
  EXPECT_EQ(log[0].hessian, HessianType::GAUSS_NEWTON);
  std::vector<Vector6d> formed = {x0};  // Poses with normal equations.
  Vector6d current = x0;
  bool last_taken = true;
  int scores_only = 0;
  size_t i = 1;
  for (const IterationRecord& record : summary.trace) {
    if (i < log.size() && log[i].xi == current) {  // Formed once needed.
      EXPECT_EQ(log[i].hessian, HessianType::GAUSS_NEWTON);
      formed.push_back(log[i++].xi);
    }
    EXPECT_NE(std::find(formed.begin(), formed.end(), current), formed.end());
    ASSERT_LT(i, log.size());
    const Evaluation& candidate = log[i++];
    EXPECT_EQ(candidate.hessian,
              last_taken ? HessianType::GAUSS_NEWTON : HessianType::NONE);
    if (candidate.hessian == HessianType::GAUSS_NEWTON) {
      formed.push_back(candidate.xi);
    } else {
      ++scores_only;
    }
    last_taken = record.step_is_successful;
    if (last_taken) current = candidate.xi;
  }
  EXPECT_EQ(i, log.size());
  EXPECT_GT(scores_only, 2);
}

// Catches: a rejected step that moves the pose or changes the score, an
// accepted step whose score does not decrease.
TEST(MinimizeLevenbergMarquardt, RejectedStepsLeaveThePoseUnchanged) {
  const LeastSquaresObjective objective(Residual::ATAN, Origin());
  const Vector6d x0 = objective.FromZ(StartZ());
  Vector6d xi = x0;
  const StageSummary summary = MinimizeFromStart(objective, &xi);
  Vector6d previous_xi = x0;
  double previous_score = objective.Evaluate(x0, HessianType::NONE).score;
  int rejected = 0;
  for (const IterationRecord& record : summary.trace) {
    if (record.step_is_successful) {
      EXPECT_LT(record.score, previous_score);
      EXPECT_NE(record.reference_from_input_xi, previous_xi);
    } else {
      ++rejected;
      EXPECT_EQ(record.reference_from_input_xi, previous_xi);
      EXPECT_EQ(record.score, previous_score);
    }
    previous_xi = record.reference_from_input_xi;
    previous_score = record.score;
  }
  EXPECT_GT(rejected, 2);
  EXPECT_EQ(xi, previous_xi);
  EXPECT_EQ(summary.final_score, previous_score);
  // r = 0 only at the origin, and the damping lets LM reach it.
  EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE);
  EXPECT_TRUE(EigenNear(xi, Origin(), 1e-12));
}

// Matches points only at the start pose: every candidate matches none.
class MatchesOnlyAt : public Objective {
 public:
  MatchesOnlyAt(const Objective& objective, const Vector6d& xi)
      : objective_(objective), xi_(xi) {}
  ScoreEvaluation Evaluate(const Vector6d& xi,
                           HessianType hessian) const override {
    ScoreEvaluation evaluation = objective_.Evaluate(xi, hessian);
    if (xi != xi_) {
      evaluation.matched = 0;
      evaluation.score = 0.0;  // Lower, but scored against nothing.
    }
    return evaluation;
  }

 private:
  const Objective& objective_;
  const Vector6d xi_;
};

// Catches: accepting a candidate on its score alone.
TEST(MinimizeLevenbergMarquardt, CandidateMatchingNoPointIsRejected) {
  const LeastSquaresObjective linear(Residual::LINEAR, Minimum());
  const Vector6d x0 = Vector6d::Zero();
  Vector6d xi = x0;
  StageSummary summary;
  MinimizeLevenbergMarquardt(MatchesOnlyAt(linear, x0),
                             LevenbergMarquardtOptions(),
                             Control(4),
                             &xi,
                             &summary);
  ASSERT_EQ(summary.iterations(), 4);
  for (const IterationRecord& record : summary.trace) {
    EXPECT_FALSE(record.step_is_successful);
  }
  EXPECT_EQ(xi, x0);
  EXPECT_EQ(summary.termination_type, TerminationType::NO_CONVERGENCE);
  // Each rejection raises lambda, so the steps shrink.
  for (int k = 1; k < 4; ++k) {
    EXPECT_LT(summary.trace[k].step_norm, summary.trace[k - 1].step_norm);
  }
}

// Returns the same evaluation wherever it is asked.
class FixedObjective : public Objective {
 public:
  explicit FixedObjective(const ScoreEvaluation& evaluation)
      : evaluation_(evaluation) {}
  ScoreEvaluation Evaluate(const Vector6d&, HessianType) const override {
    return evaluation_;
  }

 private:
  const ScoreEvaluation evaluation_;
};

// Catches: a non-finite step taken instead of failing, minimising a score no
// point contributes to.
TEST(MinimizeLevenbergMarquardt, NonFiniteStepOrNoMatchFails) {
  ScoreEvaluation nan_gradient;
  nan_gradient.score = 1.0;
  nan_gradient.matched = 10;
  nan_gradient.gradient = Vector6d::Ones();
  nan_gradient.gradient(4) = kNaN;
  nan_gradient.hessian = 2.0 * Matrix6d::Identity();
  ScoreEvaluation no_match = nan_gradient;
  no_match.gradient = Vector6d::Ones();
  no_match.matched = 0;
  const struct {
    ScoreEvaluation evaluation;
    const char* message;
  } cases[] = {{nan_gradient, "not finite"}, {no_match, "no input point"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.message);
    Vector6d xi = Minimum();
    StageSummary summary;
    MinimizeLevenbergMarquardt(FixedObjective(c.evaluation),
                               LevenbergMarquardtOptions(),
                               Control(5),
                               &xi,
                               &summary);
    EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
    EXPECT_NE(summary.message.find(c.message), std::string::npos)
        << summary.message;
    EXPECT_EQ(summary.iterations(), 0);
    EXPECT_EQ(xi, Minimum());
  }
}

TEST(LevenbergMarquardtOptions, IsValidRanges) {
  std::string error;
  EXPECT_TRUE(LevenbergMarquardtOptions().IsValid(&error)) << error;
  struct Case {
    double initial, decrease, increase;
    const char* field;  // nullptr: valid.
  };
  const Case cases[] = {
      {1e-15, 1.0001, 1.0001, nullptr},
      {1e6, 1e6, 1e6, nullptr},
      {0.0, 10, 10, "initial_lambda_factor"},
      {1e-16, 10, 10, "initial_lambda_factor"},
      {1.1e6, 10, 10, "initial_lambda_factor"},
      {kNaN, 10, 10, "initial_lambda_factor"},
      {1e-3, 1.0, 10, "lambda_decrease"},
      {1e-3, 0.5, 10, "lambda_decrease"},
      {1e-3, 1.1e6, 10, "lambda_decrease"},
      {1e-3, kNaN, 10, "lambda_decrease"},
      {1e-3, 10, 1.0, "lambda_increase"},
      {1e-3, 10, 1.1e6, "lambda_increase"},
      {1e-3, 10, kNaN, "lambda_increase"},
  };
  for (const Case& c : cases) {
    LevenbergMarquardtOptions options;
    options.initial_lambda_factor = c.initial;
    options.lambda_decrease = c.decrease;
    options.lambda_increase = c.increase;
    error.clear();
    SCOPED_TRACE(::testing::Message()
                 << c.initial << " " << c.decrease << " " << c.increase);
    if (c.field == nullptr) {
      EXPECT_TRUE(options.IsValid(&error)) << error;
    } else {
      EXPECT_FALSE(options.IsValid(&error));
      EXPECT_NE(error.find(c.field), std::string::npos) << error;
    }
  }
}

using testing::Street;
using testing::StreetPair;

// Catches: a backend that ignores point_stride, thins from another offset or
// with another stride, or minimises another objective than MlNdtObjective.
TEST(LevenbergMarquardtBackend, PointStrideMatchesMinimizeOnThinnedPoints) {
  const StreetPair& street = Street();
  const NdtLayer& layer = street.map.layer(street.map.num_layers() - 1);
  const ObjectiveOptions objective;
  StageControl control = Control(6);
  control.point_stride = 3;

  LevenbergMarquardtBackend backend{LevenbergMarquardtOptions()};
  backend.SetProblem(street.input, objective, 1);
  Vector6d strided = Vector6d::Zero();
  StageSummary strided_summary;
  backend.SolveStage(layer, control, &strided, &strided_summary);

  std::vector<Eigen::Vector3d> thinned;
  for (size_t i = 0; i < street.input.size(); i += 3) {
    thinned.push_back(street.input[i]);
  }
  Vector6d direct = Vector6d::Zero();
  StageSummary direct_summary;
  control.point_stride = 1;
  MinimizeLevenbergMarquardt(MlNdtObjective(layer, thinned, objective, 1),
                             LevenbergMarquardtOptions(),
                             control,
                             &direct,
                             &direct_summary);

  ASSERT_NE(strided_summary.termination_type, TerminationType::FAILURE)
      << strided_summary.message;
  EXPECT_GT(strided.head<3>().norm(), 0.1);  // The stage moved the pose.
  EXPECT_EQ(strided, direct);
  EXPECT_EQ(strided_summary.final_score, direct_summary.final_score);
  EXPECT_EQ(strided_summary.iterations(), direct_summary.iterations());
}

TEST(LevenbergMarquardtBackendDeathTest, StageBeforeSetProblemDies) {
  const NdtLayer& layer = Street().map.layer(1);  // Built outside the child.
  LevenbergMarquardtBackend backend{LevenbergMarquardtOptions()};
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  EXPECT_DEATH(backend.SolveStage(layer, Control(1), &xi, &summary),
               "SetProblem");
}

}  // namespace
}  // namespace mlndt
