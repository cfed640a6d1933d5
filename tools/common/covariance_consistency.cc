#include "tools/common/covariance_consistency.h"

#include <cstdio>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace tools {
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

namespace {

// Translation [m] and angles [deg] of a pose-vector quantity, for printing.
std::vector<double> InDegrees(const Vector6d& v) {
  return {
      v(0), v(1), v(2), v(3) * kRadToDeg, v(4) * kRadToDeg, v(5) * kRadToDeg};
}

}  // namespace

Json ConsistencyJson(const Consistency& c) {
  const auto numbers = [](const std::vector<double>& values) {
    Json array = Json::array();
    for (const double v : values) array.push_back(Number(v));
    return array;
  };
  return {{"runs", c.runs},
          {"nees_about_mean", Number(c.nees_mean)},
          {"nees_about_mean_expected", Number(c.nees_mean_expected)},
          {"k_spread", Number(c.k_spread())},
          {"nees_about_reference", Number(c.nees_reference)},
          {"k_reference", Number(c.k_reference())},
          {"sigma2", Number(c.sigma2)},
          {"k_spread_sigma2", Number(c.k_spread_sigma2())},
          {"k_reference_sigma2", Number(c.k_reference_sigma2())},
          {"spread_std_m_deg", numbers(InDegrees(c.spread_std))},
          {"predicted_std_m_deg", numbers(InDegrees(c.predicted_std))},
          {"bias_m_deg", numbers(InDegrees(c.bias))}};
}

void PrintRow(const std::string& label, const Consistency& c) {
  const std::vector<double> spread = InDegrees(c.spread_std);
  const std::vector<double> predicted = InDegrees(c.predicted_std);
  std::printf(
      "%-16s %4d  NEES(mean) %9.3g (exp %4.2f) k %9.3g | NEES(ref) %9.3g k "
      "%9.3g | "
      "sigma2 %6.3f k_s2 %8.3g / %8.3g\n",
      label.c_str(),
      c.runs,
      c.nees_mean,
      c.nees_mean_expected,
      c.k_spread(),
      c.nees_reference,
      c.k_reference(),
      c.sigma2,
      c.k_spread_sigma2(),
      c.k_reference_sigma2());
  std::printf(
      "%-16s       spread std  t [mm] %7.2f %7.2f %7.2f  rot [mdeg] %7.2f "
      "%7.2f %7.2f\n",
      "",
      spread[0] * 1e3,
      spread[1] * 1e3,
      spread[2] * 1e3,
      spread[3] * 1e3,
      spread[4] * 1e3,
      spread[5] * 1e3);
  std::printf(
      "%-16s       predicted   t [mm] %7.2f %7.2f %7.2f  rot [mdeg] %7.2f "
      "%7.2f %7.2f\n",
      "",
      predicted[0] * 1e3,
      predicted[1] * 1e3,
      predicted[2] * 1e3,
      predicted[3] * 1e3,
      predicted[4] * 1e3,
      predicted[5] * 1e3);
}

}  // namespace tools
}  // namespace mlndt
