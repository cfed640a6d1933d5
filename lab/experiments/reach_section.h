#pragma once

// Section 5.1's reach claim ("NDT up to 10 units and 5 deg, ML-NDT up to 25
// units and 15 deg, without initialisation") and the ablation from the
// paper preset to the defaults: the smallest-step pairs started from the
// reference pushed off along x and in yaw.

#include <string>

#include "lab/experiments/report_context.h"

namespace mlndt {
namespace experiments {

// The share of right runs every offset up to the reach needs.
constexpr double kReachShare = 0.9;

// The reach of `config` on `dataset` ("" = pooled) in offset family
// `family`: the largest offset value such that it and every smaller one of
// the family have at least kReachShare of the runs right (strict rule);
// 0 when the first misses; NaN without runs.
double Reach(const ReportContext& c,
             const std::string& dataset,
             const std::string& config,
             const std::string& family);

std::string ReachSection(const ReportContext& c);

}  // namespace experiments
}  // namespace mlndt
