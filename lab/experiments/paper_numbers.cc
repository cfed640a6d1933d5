#include "lab/experiments/paper_numbers.h"

#include <limits>

namespace mlndt {
namespace experiments {
namespace {
constexpr double kNa = std::numeric_limits<double>::quiet_NaN();
}  // namespace

const PaperTable& PaperTable2Odometry() {
  static const PaperTable kTable = {{{77.52, 22.91, 178.61},
                                     {kNa, kNa, kNa},
                                     {16.96, 12.678, 53.938},
                                     {kNa, kNa, kNa},
                                     {0.50, 0.61541, 2.5508},
                                     {kNa, kNa, kNa}}};
  return kTable;
}

const PaperTable& PaperTable3NdtGbs() {
  static const PaperTable kTable = {{{19.83, 28.45, 125.26},
                                     {-0.76, 2.92, 7.59},
                                     {1.87, 11.68, 42.59},
                                     {0.09, 0.40, 1.32},
                                     {0.19, 0.72, 2.70},
                                     {0.19, 0.57, 2.46}}};
  return kTable;
}

const PaperTable& PaperTable4MlndtGbs() {
  static const PaperTable kTable = {{{0.97, 17.17, 90.89},
                                     {2.00, 4.60, 17.68},
                                     {-2.25, 12.91, 33.39},
                                     {0.09, 0.49, 1.32},
                                     {0.072, 0.42, 1.01},
                                     {0.19, 0.64, 2.83}}};
  return kTable;
}

const PaperTable& PaperTable6MlndtRandom() {
  static const PaperTable kTable = {{{5.90, 42.89, 303.22},
                                     {12.77, 22.70, 28.76},
                                     {1.87, 28.75, 166.66},
                                     {0.09, 1.21, 9.42},
                                     {0.28, 2.99, 28.69},
                                     {0.77, 4.62, 41.30}}};
  return kTable;
}

const PaperTable& PaperTable7NdtRandom() {
  static const PaperTable kTable = {{{34.82, 24.57, 132.45},
                                     {2.49, 1.72, 6.15},
                                     {26.39, 19.44, 82.41},
                                     {0.39, 0.31, 1.38},
                                     {1.13, 1.07, 4.98},
                                     {0.55, 0.44, 2.22}}};
  return kTable;
}

}  // namespace experiments
}  // namespace mlndt
