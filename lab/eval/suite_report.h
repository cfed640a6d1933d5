#pragma once

// The tables of a scored suite (suite_score.h) as markdown text, the way
// the mlndt_suite tool prints them (docs/suite.md explains how to read
// them). Undefined numbers (NaN: nothing to average or take a share of)
// print as "–".

#include <string>

#include "lab/eval/suite_score.h"

namespace mlndt {

// 1. Rows right/wrong (the pose), columns every TerminationType (the
//    verdict), with totals; then the precision
//    and recall of CONVERGENCE and of usable (CONVERGENCE or
//    NO_CONVERGENCE), and the success share.
std::string FormatSuiteConfusion(const ConfusionTable& confusion);

// 2. Per data set × start kind: runs, right, right %, reported
//    CONVERGENCE, wrong but CONVERGENCE, pairs skipped.
std::string FormatSuiteStarts(const SuiteScore& score);

// 3. Accuracy of the right runs from the identity and the prior per data
//    set: RMS translation error [cm], mean along-track error [cm], RMS
//    rotation error [deg], median registration time [ms].
std::string FormatSuiteAccuracy(const SuiteScore& score);

// 4. Reach: per offset, right/runs per data set and over all ("–": no
//    run); then per family the reach (suite_score.h): the last offset's
//    values, "none" when the first misses. Empty without offsets.
std::string FormatSuiteReach(const SuiteScore& score);

// All four, each under a heading line.
std::string FormatSuiteReport(const SuiteScore& score);

}  // namespace mlndt
