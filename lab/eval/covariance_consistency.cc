#include "lab/eval/covariance_consistency.h"

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

Vector6d Mean(const std::vector<StartResult>& runs) {
  Vector6d mean = Vector6d::Zero();
  for (const StartResult& run : runs) mean += run.xi;
  return mean / static_cast<double>(runs.size());
}

}  // namespace

// Sums over the pair's runs into *sum (divide by the run count later).
void Accumulate(const PairRuns& pair, Consistency* sum) {
  const size_t n = pair.runs.size();
  if (n < 2) return;
  const Vector6d mean = Mean(pair.runs);
  Matrix6d spread = Matrix6d::Zero();
  Matrix6d predicted = Matrix6d::Zero();
  for (const StartResult& run : pair.runs) {
    const Vector6d about_mean = run.xi - mean;
    const Vector6d about_reference = run.xi - pair.reference_xi;
    spread += about_mean * about_mean.transpose();
    predicted += run.covariance;
    sum->nees_mean += Nees(about_mean, run.covariance);
    sum->nees_reference += Nees(about_reference, run.covariance);
    sum->nees_mean_sigma2 += Nees(about_mean, run.sigma2 * run.covariance);
    sum->nees_reference_sigma2 +=
        Nees(about_reference, run.sigma2 * run.covariance);
    sum->sigma2 += run.sigma2;
    sum->nees_mean_expected += ExpectedNeesAboutMean(n);
  }
  spread /= static_cast<double>(n - 1);
  predicted /= static_cast<double>(n);
  // Squares now, square roots in Finish (RMS over pairs when pooled).
  sum->spread_std += static_cast<double>(n) * spread.diagonal();
  sum->predicted_std += static_cast<double>(n) * predicted.diagonal();
  sum->bias += static_cast<double>(n) * (mean - pair.reference_xi);
  sum->runs += static_cast<int>(n);
}

Consistency Finish(Consistency sum) {
  if (sum.runs == 0) return sum;
  const double n = sum.runs;
  sum.nees_mean /= n;
  sum.nees_mean_expected /= n;
  sum.nees_reference /= n;
  sum.nees_mean_sigma2 /= n;
  sum.nees_reference_sigma2 /= n;
  sum.sigma2 /= n;
  sum.spread_std = (sum.spread_std / n).cwiseSqrt();
  sum.predicted_std = (sum.predicted_std / n).cwiseSqrt();
  sum.bias /= n;
  return sum;
}

}  // namespace mlndt
