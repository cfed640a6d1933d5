#include "lab/eval/nees.h"

#include <glog/logging.h>

#include <Eigen/Cholesky>

namespace mlndt {
namespace {

bool CheckCovariances(const std::vector<Vector6d>& errors,
                      const std::vector<Matrix6d>& covariances,
                      std::string* error) {
  if (errors.size() != covariances.size()) {
    *error = "NEES: " + std::to_string(errors.size()) + " errors but " +
             std::to_string(covariances.size()) + " covariances";
    return false;
  }
  if (errors.empty()) {
    *error = "NEES: no samples";
    return false;
  }
  for (size_t k = 0; k < covariances.size(); ++k) {
    const Matrix6d& c = covariances[k];
    const double asymmetry = (c - c.transpose()).cwiseAbs().maxCoeff();
    if (!c.allFinite() || !errors[k].allFinite() ||
        asymmetry > 1e-9 * c.cwiseAbs().maxCoeff() ||
        c.llt().info() != Eigen::Success) {
      *error = "NEES: sample " + std::to_string(k) +
               ": the covariance is not finite, symmetric and positive "
               "definite (or the error is not finite)";
      return false;
    }
  }
  return true;
}

void Summarise(const std::vector<Vector6d>& errors,
               const std::vector<Matrix6d>& covariances,
               double expected,
               NeesSummary* summary) {
  double sum = 0.0;
  for (size_t k = 0; k < errors.size(); ++k) {
    summary->nees.push_back(Nees(errors[k], covariances[k]));
    sum += summary->nees.back();
  }
  summary->mean = sum / static_cast<double>(errors.size());
  summary->expected = expected;
  summary->scale_factor = NeesScaleFactor(summary->mean, expected);
}

}  // namespace

double Nees(const Vector6d& error, const Matrix6d& covariance) {
  return error.dot(covariance.ldlt().solve(error));
}

double ExpectedNeesAboutMean(size_t num_samples) {
  CHECK_GE(num_samples, 1u);
  return kPoseDimension * static_cast<double>(num_samples - 1) /
         static_cast<double>(num_samples);
}

double NeesScaleFactor(double mean_nees, double expected_nees) {
  return mean_nees / expected_nees;
}

bool ComputeNees(const std::vector<Vector6d>& errors,
                 const std::vector<Matrix6d>& covariances,
                 NeesSummary* summary,
                 std::string* error) {
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  *summary = NeesSummary();
  if (!CheckCovariances(errors, covariances, error)) return false;
  Summarise(errors, covariances, kPoseDimension, summary);
  return true;
}

bool ComputeNeesAboutMean(const std::vector<Vector6d>& samples,
                          const std::vector<Matrix6d>& covariances,
                          NeesSummary* summary,
                          std::string* error) {
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  *summary = NeesSummary();
  if (!CheckCovariances(samples, covariances, error)) return false;
  if (samples.size() < 2) {
    *error = "NEES about the mean: 1 sample, at least 2 needed";
    return false;
  }
  Vector6d mean = Vector6d::Zero();
  for (const Vector6d& x : samples) mean += x;
  mean /= static_cast<double>(samples.size());
  std::vector<Vector6d> errors;
  for (const Vector6d& x : samples) errors.push_back(x - mean);
  Summarise(
      errors, covariances, ExpectedNeesAboutMean(samples.size()), summary);
  return true;
}

}  // namespace mlndt
