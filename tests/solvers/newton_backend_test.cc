// MinimizeNewton on synthetic objectives whose minimum is known analytically
// (the pattern of ceres' dogleg_strategy_test.cc: a Hessian Q diag(d) Q^T in
// a random orthonormal basis Q, so that nothing is axis-aligned), and the
// NewtonBackend on a real layer (its point stride is tested with the shell,
// hand_written_backend_test.cc). Each test names the wrong implementation it
// catches.

#include "mlndt/solvers/newton_backend.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
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

// A one-dimensional profile phi(u) with phi' and phi''.
struct Profile {
  double value, first, second;
};
using ProfileFunction = Profile (*)(int coordinate, double u);

Profile Quadratic(int, double u) { return {0.5 * u * u, u, 1.0}; }

// u^2/2 + u^4/4: convex, curvature growing away from the minimum.
Profile Quartic(int, double u) {
  return {0.5 * u * u + 0.25 * u * u * u * u, u + u * u * u, 1.0 + 3 * u * u};
}

// log cosh u: convex, but the curvature sech^2 u vanishes far out, so the
// full Newton step -sinh(2u)/2 overshoots the minimum for |u| > 1.09.
Profile LogCosh(int, double u) {
  const double sech = 1.0 / std::cosh(u);
  return {std::log(std::cosh(u)), std::tanh(u), sech * sech};
}

// Coordinate 0 is a double well -u^2/2 + u^4/4 (minima at u = +-1, a
// maximum at 0, negative curvature for |u| < 1/sqrt(3)); the others quartic.
Profile DoubleWell(int coordinate, double u) {
  if (coordinate != 0) return Quartic(coordinate, u);
  return {
      -0.5 * u * u + 0.25 * u * u * u * u, -u + u * u * u, -1.0 + 3 * u * u};
}

// f(x) = sum_i d_i phi(i, u_i) with u = Q^T (x - x*): the gradient is
// Q (d .* phi'(u)), the Hessian Q diag(d .* phi''(u)) Q^T. Logs the Hessian
// type of every evaluation.
class RotatedSeparableObjective : public Objective {
 public:
  RotatedSeparableObjective(ProfileFunction profile,
                            const Vector6d& weights,
                            const Vector6d& minimum,
                            uint32_t seed = 7)
      : profile_(profile),
        weights_(weights),
        minimum_(minimum),
        basis_(RandomBasis(seed)) {}

  ScoreEvaluation Evaluate(const Vector6d& xi,
                           HessianType hessian) const override {
    requests_.push_back(hessian);
    const Vector6d u = ToU(xi);
    ScoreEvaluation evaluation;
    evaluation.matched = 1;
    Vector6d first, second;
    for (int i = 0; i < 6; ++i) {
      const Profile p = profile_(i, u(i));
      evaluation.score += weights_(i) * p.value;
      first(i) = weights_(i) * p.first;
      second(i) = weights_(i) * p.second;
    }
    if (hessian != HessianType::NONE) {
      evaluation.gradient = basis_ * first;
      evaluation.hessian = basis_ * second.asDiagonal() * basis_.transpose();
    }
    return evaluation;
  }

  Vector6d ToU(const Vector6d& xi) const {
    return basis_.transpose() * (xi - minimum_);
  }
  Vector6d FromU(const Vector6d& u) const { return minimum_ + basis_ * u; }
  double Score(const Vector6d& xi) const {
    return Evaluate(xi, HessianType::NONE).score;
  }
  const std::vector<HessianType>& requests() const { return requests_; }

 private:
  const ProfileFunction profile_;
  const Vector6d weights_;
  const Vector6d minimum_;
  const Matrix6d basis_;
  mutable std::vector<HessianType> requests_;
};

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

Vector6d Minimum() {
  Vector6d x;
  x << 1.0, -2.0, 0.5, 0.3, -0.7, 2.0;
  return x;
}

Vector6d Unit(int i) { return Vector6d::Unit(i); }

StageControl Control(int max_iterations, double step_tolerance = 0.0) {
  StageControl control;
  control.max_iterations = max_iterations;
  control.step_tolerance = step_tolerance;
  return control;
}

// Condition 1e3, above the default min_eigenvalue_ratio, so no lift.
Vector6d IllConditionedWeights() {
  Vector6d d;
  d << 1.0, 3.0, 10.0, 30.0, 100.0, 1000.0;
  return d;
}

// Catches: a step other than -H^-1 g (gradient descent, a wrong sign), a lift
// applied to a safely positive definite H (gamma = ratio * largest without
// subtracting the smallest), asking for the Gauss-Newton Hessian.
TEST(MinimizeNewton, OneStepSolvesAQuadratic) {
  const RotatedSeparableObjective quadratic(
      Quadratic, IllConditionedWeights(), Minimum());
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  MinimizeNewton(quadratic, NewtonOptions(), Control(1), &xi, &summary);
  EXPECT_TRUE(EigenNear(xi, Minimum(), 1e-12));
  ASSERT_EQ(summary.iterations(), 1);
  EXPECT_TRUE(summary.trace[0].step_is_successful);
  EXPECT_NEAR(summary.trace[0].step_norm, Minimum().norm(), 1e-12);
  EXPECT_EQ(summary.trace[0].reference_from_input_xi, xi);
  EXPECT_LT(summary.final_score, 1e-20);
  EXPECT_EQ(summary.termination_type, TerminationType::NO_CONVERGENCE);
  for (const HessianType type : quadratic.requests()) {
    EXPECT_NE(type, HessianType::GAUSS_NEWTON);
  }
  EXPECT_EQ(quadratic.requests().front(), HessianType::FULL);
}

// Catches: a stage that does not stop on the update norm, or stops before the
// step that reached the minimum is recorded.
TEST(MinimizeNewton, QuadraticConvergesOnTheSecondIteration) {
  const RotatedSeparableObjective quadratic(
      Quadratic, IllConditionedWeights(), Minimum());
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  MinimizeNewton(quadratic, NewtonOptions(), Control(10, 1e-8), &xi, &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE);
  // Step 1 lands on x*; step 2 is below the tolerance (or finds no decrease
  // left): either way the stage converged after two records.
  ASSERT_EQ(summary.iterations(), 2);
  EXPECT_TRUE(summary.trace[0].step_is_successful);
  EXPECT_LT(summary.trace[1].step_norm, 1e-8);
  EXPECT_TRUE(EigenNear(xi, Minimum(), 1e-12));
}

// Catches: a trace that records the score before the step (or of a rejected
// candidate), a line search accepting a non-decrease, no convergence.
TEST(MinimizeNewton, ConvergesOnANonQuadraticConvexFunction) {
  Vector6d weights;
  weights << 1.0, 2.0, 5.0, 10.0, 20.0, 50.0;
  const RotatedSeparableObjective quartic(Quartic, weights, Minimum());
  Vector6d u0;
  u0 << 2.0, -1.5, 1.0, 3.0, -0.5, 0.8;
  Vector6d xi = quartic.FromU(u0);
  const double initial_score = quartic.Score(xi);
  StageSummary summary;
  MinimizeNewton(quartic, NewtonOptions(), Control(50, 1e-6), &xi, &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE)
      << summary.message;
  EXPECT_EQ(summary.message, "update norm below tolerance");
  EXPECT_TRUE(EigenNear(xi, Minimum(), 1e-10));
  EXPECT_GT(summary.iterations(), 3);  // Not a quadratic: several steps.
  double previous = initial_score;
  for (const IterationRecord& record : summary.trace) {
    ASSERT_TRUE(record.step_is_successful);
    EXPECT_LT(record.score, previous);
    EXPECT_EQ(record.score, quartic.Score(record.reference_from_input_xi));
    previous = record.score;
  }
  EXPECT_EQ(summary.final_score, summary.trace.back().score);
}

// A saddle-like start: along u_0 (weight 1/2) the double well curves down,
// the other directions up. The plain Newton step -H^-1 g heads for the
// maximum at u_0 = 0 (from 0.3 to about -0.07, uphill); the lifted
// H + gamma I is positive definite, so its step descends. With ratio 1/2 the
// lifted curvature along u_0 is 1/2 and the step lands near u_0 = 0.57.
RotatedSeparableObjective SaddleObjective() {
  Vector6d weights = Vector6d::Ones();
  weights(0) = 0.5;
  return RotatedSeparableObjective(DoubleWell, weights, Minimum());
}

NewtonOptions SaddleOptions(bool line_search) {
  NewtonOptions options;
  options.line_search = line_search;
  options.min_eigenvalue_ratio = 0.5;
  return options;
}

// Catches: no lift (gamma = 0), or a lift that leaves H indefinite.
TEST(MinimizeNewton, IndefiniteHessianIsLiftedToADescentStep) {
  const RotatedSeparableObjective saddle = SaddleObjective();
  const Vector6d x0 = saddle.FromU(0.3 * Unit(0));
  const ScoreEvaluation at_x0 = saddle.Evaluate(x0, HessianType::FULL);
  ASSERT_LT(Eigen::SelfAdjointEigenSolver<Matrix6d>(at_x0.hessian)
                .eigenvalues()
                .minCoeff(),
            0.0);
  Vector6d xi = x0;
  StageSummary summary;
  // No line search: the descent must come from the lift alone.
  MinimizeNewton(saddle, SaddleOptions(false), Control(1), &xi, &summary);
  ASSERT_EQ(summary.iterations(), 1);
  EXPECT_LT(summary.trace[0].score, at_x0.score);
  EXPECT_LT((xi - x0).dot(at_x0.gradient), 0.0);
  EXPECT_GT(saddle.ToU(xi)(0), 0.3);  // Away from the maximum.
}

// Catches the same with the line search on: the unlifted direction is uphill,
// every halving fails and the stage stops at the start.
TEST(MinimizeNewton, IndefiniteStartConvergesToAMinimumNotTheSaddle) {
  const RotatedSeparableObjective saddle = SaddleObjective();
  Vector6d xi = saddle.FromU(0.3 * Unit(0));
  StageSummary summary;
  MinimizeNewton(saddle, SaddleOptions(true), Control(50, 1e-9), &xi, &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE)
      << summary.message;
  EXPECT_TRUE(EigenNear(saddle.ToU(xi), Unit(0), 1e-8));
}

// log cosh along u_0 only, from u_0 = start; the other coordinates sit at
// their minimum, so the Newton step is -sinh(2 start)/2 along u_0.
struct LineSearchCase {
  double start;
  int max_line_search_steps;
  double expected_scale;  // Of the step taken, or of the last one tried.
  bool successful;
};

// Hand-computed: from 1.5 the full step reaches -3.51 (log cosh 2.82 >
// 0.86), half of it -1.00 (0.43): scale 1/2. From 2 the full step reaches
// -11.6, half -4.82 (4.13 > 1.33), a quarter -1.41 (0.78): scale 1/4, which
// needs 3 tries; with 2 the step is rejected after trying scale 1/2.
// Catches: no line search, halving past the first decrease, one try too few
// or too many (off by one in max_line_search_steps), a rejected step that
// still moves the pose, a trace step norm other than the last one tried.
TEST(MinimizeNewton, LineSearchHalvesUntilTheScoreDecreases) {
  const LineSearchCase cases[] = {{1.5, 8, 0.5, true},
                                  {2.0, 8, 0.25, true},
                                  {2.0, 3, 0.25, true},
                                  {2.0, 2, 0.5, false}};
  for (const LineSearchCase& c : cases) {
    SCOPED_TRACE(::testing::Message() << "start " << c.start << ", tries "
                                      << c.max_line_search_steps);
    const RotatedSeparableObjective log_cosh(
        LogCosh, Vector6d::Ones(), Minimum());
    const Vector6d x0 = log_cosh.FromU(c.start * Unit(0));
    const double full_step = -std::sinh(2 * c.start) / 2;
    NewtonOptions options;
    options.max_line_search_steps = c.max_line_search_steps;
    Vector6d xi = x0;
    StageSummary summary;
    MinimizeNewton(log_cosh, options, Control(1), &xi, &summary);
    ASSERT_EQ(summary.iterations(), 1);
    EXPECT_NEAR(summary.trace[0].step_norm,
                c.expected_scale * std::abs(full_step),
                1e-12);
    if (c.successful) {
      EXPECT_TRUE(summary.trace[0].step_is_successful);
      const double u = c.start + c.expected_scale * full_step;
      EXPECT_TRUE(EigenNear(xi, log_cosh.FromU(u * Unit(0)), 1e-12));
      EXPECT_LT(summary.trace[0].score, log_cosh.Score(x0));
      EXPECT_EQ(summary.termination_type, TerminationType::NO_CONVERGENCE);
    } else {
      EXPECT_FALSE(summary.trace[0].step_is_successful);
      EXPECT_EQ(xi, x0);
      EXPECT_EQ(summary.trace[0].reference_from_input_xi, x0);
      EXPECT_EQ(summary.final_score, log_cosh.Score(x0));
      EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE);
    }
  }
}

// Catches: a line search that runs although it is off.
TEST(MinimizeNewton, WithoutLineSearchTheFullStepIsTaken) {
  const RotatedSeparableObjective log_cosh(
      LogCosh, Vector6d::Ones(), Minimum());
  const Vector6d x0 = log_cosh.FromU(2.0 * Unit(0));
  NewtonOptions options;
  options.line_search = false;
  Vector6d xi = x0;
  StageSummary summary;
  MinimizeNewton(log_cosh, options, Control(1), &xi, &summary);
  // The derivatives at x0 and the score at the step, no halvings.
  EXPECT_EQ(log_cosh.requests(),
            std::vector<HessianType>({HessianType::FULL, HessianType::NONE}));
  ASSERT_EQ(summary.iterations(), 1);
  const double u = 2.0 - std::sinh(4.0) / 2;
  EXPECT_TRUE(EigenNear(xi, log_cosh.FromU(u * Unit(0)), 1e-9));
  EXPECT_TRUE(summary.trace[0].step_is_successful);
  EXPECT_GT(summary.trace[0].score, log_cosh.Score(x0));  // Overshot.
  EXPECT_EQ(summary.final_score, summary.trace[0].score);
}

// Catches: a non-finite step taken (or looped on) instead of failing.
TEST(MinimizeNewton, NonFiniteDerivativesFail) {
  ScoreEvaluation nan_gradient;
  nan_gradient.score = 1.0;
  nan_gradient.matched = 10;
  nan_gradient.gradient = Vector6d::Ones();
  nan_gradient.gradient(2) = kNaN;
  nan_gradient.hessian = Matrix6d::Identity();
  ScoreEvaluation nan_hessian = nan_gradient;
  nan_hessian.gradient = Vector6d::Ones();
  nan_hessian.hessian(1, 3) = nan_hessian.hessian(3, 1) = kNaN;
  for (const ScoreEvaluation& evaluation : {nan_gradient, nan_hessian}) {
    Vector6d xi = Minimum();
    StageSummary summary;
    MinimizeNewton(
        FixedObjective(evaluation), NewtonOptions(), Control(5), &xi, &summary);
    EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
    EXPECT_NE(summary.message.find("not finite"), std::string::npos)
        << summary.message;
    EXPECT_EQ(summary.iterations(), 0);
    EXPECT_EQ(xi, Minimum());
  }
}

// Catches: minimising a score that no point contributes to.
TEST(MinimizeNewton, NoMatchedPointFails) {
  ScoreEvaluation evaluation;
  evaluation.matched = 0;
  evaluation.unmatched = 100;
  evaluation.gradient = Vector6d::Ones();
  evaluation.hessian = Matrix6d::Identity();
  Vector6d xi = Minimum();
  StageSummary summary;
  MinimizeNewton(
      FixedObjective(evaluation), NewtonOptions(), Control(5), &xi, &summary);
  EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
  EXPECT_NE(summary.message.find("no input point"), std::string::npos)
      << summary.message;
  EXPECT_EQ(summary.iterations(), 0);
  EXPECT_EQ(xi, Minimum());
}

TEST(NewtonOptions, IsValidRanges) {
  std::string error;
  EXPECT_TRUE(NewtonOptions().IsValid(&error)) << error;
  const auto valid = [](int steps, double ratio, std::string* error) {
    NewtonOptions options;
    options.max_line_search_steps = steps;
    options.min_eigenvalue_ratio = ratio;
    return options.IsValid(error);
  };
  EXPECT_TRUE(valid(1, 1e-15, &error)) << error;
  EXPECT_TRUE(valid(60, 1.0, &error)) << error;
  EXPECT_FALSE(valid(0, 1e-6, &error));
  EXPECT_NE(error.find("max_line_search_steps"), std::string::npos) << error;
  EXPECT_FALSE(valid(61, 1e-6, &error));
  EXPECT_NE(error.find("max_line_search_steps"), std::string::npos) << error;
  for (const double ratio : {0.0, 1e-16, 1.5, kNaN}) {
    error.clear();
    EXPECT_FALSE(valid(8, ratio, &error)) << ratio;
    EXPECT_NE(error.find("min_eigenvalue_ratio"), std::string::npos) << error;
  }
}

using testing::Street;

TEST(NewtonBackendDeathTest, StageBeforeSetProblemIsAProgrammingError) {
  const NdtLayer& layer = Street().map.layer(1);  // Built outside the child.
  NewtonBackend backend{NewtonOptions()};
  Vector6d xi = Vector6d::Zero();
  StageSummary summary;
  EXPECT_DEATH(backend.SolveStage(layer, Control(1), &xi, &summary),
               "SetProblem");
}

}  // namespace
}  // namespace mlndt
