#include "lab/programs/covariance_output.h"

#include <cmath>
#include <cstdio>

#include "mlndt/common/pose.h"
#include "tools/cli/list_flags.h"

namespace mlndt {
namespace lab {
namespace {

// Translation [m] and angles [deg] of a pose-vector quantity, for printing.
std::vector<double> InDegrees(const Vector6d& v) {
  return {
      v(0), v(1), v(2), v(3) * kRadToDeg, v(4) * kRadToDeg, v(5) * kRadToDeg};
}

}  // namespace

tools::Json ConsistencyJson(const Consistency& c) {
  const auto numbers = [](const std::vector<double>& values) {
    tools::Json array = tools::Json::array();
    for (const double v : values) array.push_back(tools::Number(v));
    return array;
  };
  return {{"runs", c.runs},
          {"nees_about_mean", tools::Number(c.nees_mean)},
          {"nees_about_mean_expected", tools::Number(c.nees_mean_expected)},
          {"k_spread", tools::Number(c.k_spread())},
          {"nees_about_reference", tools::Number(c.nees_reference)},
          {"k_reference", tools::Number(c.k_reference())},
          {"sigma2", tools::Number(c.sigma2)},
          {"k_spread_sigma2", tools::Number(c.k_spread_sigma2())},
          {"k_reference_sigma2", tools::Number(c.k_reference_sigma2())},
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

bool ParseCovarianceDatasets(const std::string& text,
                             std::vector<std::string>* datasets,
                             std::string* error) {
  if (!tools::SplitList(text, datasets)) {
    *error = "--datasets: expected a comma-separated list of kitti, koide3";
    return false;
  }
  for (const std::string& dataset : *datasets) {
    if (dataset != "kitti" && dataset != "koide3") {
      *error = "--datasets: unknown '" + dataset + "' (kitti, koide3)";
      return false;
    }
  }
  return true;
}

size_t CovarianceRegistrations(const std::vector<std::string>& datasets,
                               int starts) {
  size_t pairs = 0;
  for (const std::string& dataset : datasets) {
    pairs += dataset == "kitti" ? 7 : 1;
  }
  return pairs * static_cast<size_t>(starts);
}

std::string CovarianceCsvHeader() {
  return "dataset,pair,start,usable,tx,ty,tz,alpha,beta,gamma,sd_tx,sd_ty,sd_"
         "tz,sd_alpha,"
         "sd_beta,sd_gamma,final_score,matched\n";
}

void AppendCovarianceCsvRow(const PairRuns& pair,
                            int start,
                            const RegistrationSummary& summary,
                            bool usable,
                            std::ostringstream* csv) {
  *csv << pair.dataset << "," << pair.name << "," << start << "," << usable;
  for (int a = 0; a < 6; ++a) *csv << "," << summary.reference_from_input_xi(a);
  for (int a = 0; a < 6; ++a) {
    *csv << "," << std::sqrt(summary.covariance(a, a));
  }
  *csv << "," << summary.final_score << "," << summary.matched_points << "\n";
}

void ReportConsistency(const std::vector<std::string>& datasets,
                       const std::vector<PairRuns>& pairs,
                       tools::Json* json) {
  tools::Json pair_list = tools::Json::array();
  for (const std::string& dataset : datasets) {
    Consistency pooled;
    int failures = 0, outliers = 0;
    for (const PairRuns& pair : pairs) {
      if (pair.dataset != dataset) continue;
      Consistency one;
      Accumulate(pair, &one);
      Accumulate(pair, &pooled);
      failures += pair.failures;
      outliers += pair.outliers;
      const Consistency result = Finish(one);
      PrintRow(dataset + " " + pair.name, result);
      pair_list.push_back({{"dataset", dataset},
                           {"pair", pair.name},
                           {"failures", pair.failures},
                           {"outliers", pair.outliers},
                           {"consistency", ConsistencyJson(result)}});
    }
    const Consistency result = Finish(pooled);
    PrintRow(dataset + " (all)", result);
    std::printf("\n");
    (*json)[dataset] = {{"failures", failures},
                        {"outliers", outliers},
                        {"consistency", ConsistencyJson(result)}};
  }
  (*json)["pairs"] = pair_list;
}

}  // namespace lab
}  // namespace mlndt
