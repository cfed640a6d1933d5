#pragma once

// mlndt_covariance's measure (its report: lab/programs/covariance_output.h):
// how well the registration covariance P predicts the spread of many
// registrations of one pair (NEES about the runs' mean and about the reference
// pose, lab/eval/nees.h), per pair and pooled over a data set.

#include <string>
#include <vector>

#include "lab/eval/nees.h"
#include "mlndt/common/types.h"

namespace mlndt {

// One usable registration.
struct StartResult {
  Vector6d xi = Vector6d::Zero();
  Matrix6d covariance = Matrix6d::Zero();
  double sigma2 = 1.0;  // final_score / (3 matched - 6).
};

struct PairRuns {
  std::string dataset;
  std::string name;
  Vector6d reference_xi = Vector6d::Zero();
  std::vector<StartResult> runs;  // Usable, non-outlier runs.
  int failures = 0;               // Not usable (FAILURE) or singular H.
  int outliers = 0;               // Far from the median estimate.
};

// Consistency of a set of runs (one pair, or a data set pooled).
struct Consistency {
  int runs = 0;
  double nees_mean = 0.0;           // Mean NEES about the pair means.
  double nees_mean_expected = 0.0;  // 6 (n - 1) / n, averaged over pairs.
  double nees_reference = 0.0;      // Mean NEES about the reference pose.
  double nees_mean_sigma2 = 0.0;    // With sigma2 P.
  double nees_reference_sigma2 = 0.0;
  double sigma2 = 0.0;                     // Mean residual variance estimate.
  Vector6d spread_std = Vector6d::Zero();  // sqrt diag S (pooled: RMS).
  Vector6d predicted_std = Vector6d::Zero();  // sqrt diag mean P.
  Vector6d bias = Vector6d::Zero();           // mean - reference (pair only).

  // k = mean NEES / its expectation (lab/eval/nees.h).
  double k_spread() const {
    return NeesScaleFactor(nees_mean, nees_mean_expected);
  }
  double k_reference() const {
    return NeesScaleFactor(nees_reference, kPoseDimension);
  }
  double k_spread_sigma2() const {
    return NeesScaleFactor(nees_mean_sigma2, nees_mean_expected);
  }
  double k_reference_sigma2() const {
    return NeesScaleFactor(nees_reference_sigma2, kPoseDimension);
  }
};

// Adds the pair's runs (when it has at least 2) to the sums in *sum; call
// Finish once all pairs are in.
void Accumulate(const PairRuns& pair, Consistency* sum);

// The sums of Accumulate turned into means (and RMS standard deviations).
Consistency Finish(Consistency sum);

}  // namespace mlndt
