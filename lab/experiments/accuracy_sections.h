#pragma once

// The sections of Section 5.2 (Tables 2-8, Figs. 14-18): every pair from
// its prior, the stand-in of the paper's odometry, scored against
// reference_pairs.json in the paper's axes and units (paper_axes.h).

#include <string>

#include "lab/experiments/report_context.h"

namespace mlndt {
namespace experiments {

std::string Table2Section(const ReportContext& c);  // And Fig. 14.
std::string Table3Section(const ReportContext& c);  // And Fig. 15.
std::string Table4Section(const ReportContext& c);  // And Fig. 16.
std::string Table5Section(const ReportContext& c);
std::string Table6Section(const ReportContext& c);  // And Fig. 18.
std::string Table7Section(const ReportContext& c);
std::string Table8Section(const ReportContext& c);
std::string Fig17Section(const ReportContext& c);

}  // namespace experiments
}  // namespace mlndt
