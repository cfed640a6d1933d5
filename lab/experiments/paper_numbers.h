#pragma once

// The paper's numbers (Ulaş & Temeltaş 2013, Section 5), as printed: the
// Hannover 1 scans 1-100, in 3DTK's axes (paper_axes.h), translations in
// cm, angles in degrees. Each table column holds mean, std and max.

#include <array>
#include <string>

namespace mlndt {
namespace experiments {

// Mean, std, max of one column; NaN where the paper prints "N.A".
struct PaperColumn {
  double mean, std, max;
};
using PaperTable = std::array<PaperColumn, 6>;  // tx, ty, tz, α, β, γ.

const PaperTable& PaperTable2Odometry();     // Table 2.
const PaperTable& PaperTable3NdtGbs();       // Table 3.
const PaperTable& PaperTable4MlndtGbs();     // Table 4.
const PaperTable& PaperTable6MlndtRandom();  // Table 6.
const PaperTable& PaperTable7NdtRandom();    // Table 7.

// Success rates [%] under the paper's rule (< 50 cm) stated in the text of
// Sections 5.2.1-5.2.2 (Table 8 itself is a qualitative illustration).
constexpr double kPaperSuccessNdtGbs = 90.0;
constexpr double kPaperSuccessMlndtGbs = 98.0;
constexpr double kPaperSuccessMlndtRandom = 94.0;
constexpr double kPaperSuccessNdtRandom = 64.0;

// Table 5: mean and std of the computation time [s] and mean iterations.
struct PaperTiming {
  double mean_s, std_s, iterations;
};
constexpr PaperTiming kPaperTable5Ndt = {39.81, 9.39, 25.0};
constexpr PaperTiming kPaperTable5Mlndt = {9.43, 3.90, 12.77};

// Section 5.1: the reach without initialisation. Translations in the
// paper's "units", most likely cm (3DTK stores cm), so 0.10 m and 0.25 m.
constexpr double kPaperNdtReachM = 0.10;
constexpr double kPaperNdtReachDeg = 5.0;
constexpr double kPaperMlndtReachM = 0.25;
constexpr double kPaperMlndtReachDeg = 15.0;

// Table 9: one row per initialisation c (0.9, 0.6, 0.3, 0) and working
// layers (2-4, 3-4, 4): fail rate [%], time [s], error norm [cm].
struct PaperTable9Row {
  double c;
  int start_layer;  // 2, 3 or 4 of n = 4.
  double fail_percent, time_s, error_cm;
};
constexpr std::array<PaperTable9Row, 12> kPaperTable9 = {{
    {0.9, 2, 7, 21.65, 5.53},
    {0.9, 3, 2, 16.05, 3.18},
    {0.9, 4, 1, 9.59, 4.22},
    {0.6, 2, 11, 20.88, 4.57},
    {0.6, 3, 4, 16.63, 3.90},
    {0.6, 4, 2, 12.58, 3.58},
    {0.3, 2, 15, 21.13, 4.66},
    {0.3, 3, 9, 21.37, 3.47},
    {0.3, 4, 17, 13.70, 4.86},
    {0.0, 2, 17, 21.23, 6.61},
    {0.0, 3, 18, 17.83, 3.29},
    {0.0, 4, 45, 14.00, 4.31},
}};

}  // namespace experiments
}  // namespace mlndt
