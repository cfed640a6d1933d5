#include "lab/programs/scaling_output.h"

#include <cstdio>
#include <iostream>
#include <string>

#include "lab/experiments/scaling_report.h"

namespace mlndt {
namespace lab {

void PrintScalingTable(const std::vector<SizeResult>& results) {
  std::printf("%s", ScalingTableText(results).c_str());
}

std::vector<double> PrintScalingSlopes(const std::vector<size_t>& sizes,
                                       const std::vector<SizeResult>& results) {
  const std::vector<double> slopes = ScalingSlopes(sizes, results);
  std::printf("%s", ScalingSlopesText(sizes, results, slopes).c_str());
  return slopes;
}

void PrintBrokenSolves(const std::vector<SizeResult>& results,
                       double max_translation_error_m,
                       double max_rotation_error_deg) {
  for (const std::string& line : BrokenSolveLines(
           results, max_translation_error_m, max_rotation_error_deg)) {
    std::cerr << "mlndt_scaling: " << line << std::endl;
  }
}

}  // namespace lab
}  // namespace mlndt
