#pragma once

// Consistency of pose covariances with the errors they describe: the
// normalised estimation error squared (NEES, Bar-Shalom, Li & Kirubarajan,
// "Estimation with Applications to Tracking and Navigation", 2001, Sec. 5.4).
//
// For an error e (6-vector in the pose vector of ML-NDT Eq. 11: t [m],
// Euler angles [rad]) drawn from N(0, C), NEES = e^T C^-1 e is chi-square
// with 6 degrees of freedom: its expectation is 6. When the errors are taken
// about the mean of n samples instead of about the truth, the expectation
// is 6 (n - 1) / n. A mean NEES above its expectation means the covariances
// are too small: k = mean NEES / expectation is the factor that makes k C
// consistent (the mean NEES of k C equals the expectation).

#include <cstddef>
#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

constexpr int kPoseDimension = 6;

// e^T C^-1 e, solved with LDL^T. C must be symmetric positive definite (not
// checked here; ComputeNees checks).
double Nees(const Vector6d& error, const Matrix6d& covariance);

// The expected NEES of errors about the mean of n samples: 6 (n - 1) / n.
double ExpectedNeesAboutMean(size_t num_samples);

// k = mean_nees / expected_nees: scaling the covariances by k makes the
// mean NEES equal to its expectation.
double NeesScaleFactor(double mean_nees, double expected_nees);

struct NeesSummary {
  std::vector<double> nees;   // One per sample.
  double mean = 0.0;          // Mean NEES.
  double expected = 0.0;      // Its expectation if the covariances are right.
  double scale_factor = 0.0;  // NeesScaleFactor(mean, expected).
};

// Errors against the truth (expected 6). False with *error when the sizes
// differ, there are no samples, or a covariance is not finite, symmetric
// and positive definite.
bool ComputeNees(const std::vector<Vector6d>& errors,
                 const std::vector<Matrix6d>& covariances,
                 NeesSummary* summary,
                 std::string* error);

// Samples of one quantity without a truth (repeated estimates): errors about
// their mean, expected ExpectedNeesAboutMean(n); needs n >= 2.
bool ComputeNeesAboutMean(const std::vector<Vector6d>& samples,
                          const std::vector<Matrix6d>& covariances,
                          NeesSummary* summary,
                          std::string* error);

}  // namespace mlndt
