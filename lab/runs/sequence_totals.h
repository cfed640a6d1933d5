#pragma once

// Totals over a sequence run (sequence_registration.h), shared by the
// sequence tool's summary.json and the experiment tables. Error statistics
// are over |component| (the paper's Tables 2-4 layout) in cm and deg.

#include <cstddef>
#include <vector>

#include "lab/eval/pose_error.h"
#include "lab/eval/statistics.h"
#include "lab/runs/sequence_registration.h"

namespace mlndt {

// The error values of a pair in report units, in this order: tx, ty, tz
// [cm], alpha, beta, gamma [deg] (component magnitudes), translation norm
// [cm], rotation angle [deg].
constexpr int kNumErrorValues = 8;

// The names of the error values ("tx_cm", ..., "rotation_deg").
const char* const* ErrorNames();

std::vector<double> ErrorValues(const PoseError& error);

struct SequenceTotals {
  size_t pairs = 0;
  bool has_truth = false;
  size_t successes = 0;              // < 0.5 m.
  size_t strict_successes = 0;       // < 0.2 m and < 1 deg.
  size_t registration_failures = 0;  // termination FAILURE.
  size_t guess_check_failures = 0;   // Adaptive rule's verdict.
  double success_rate_percent = 0.0;
  double strict_success_rate_percent = 0.0;
  // ErrorValues statistics over all pairs, and over successful pairs only.
  std::vector<Stats> errors = std::vector<Stats>(kNumErrorValues);
  std::vector<Stats> errors_successful = std::vector<Stats>(kNumErrorValues);
  Stats time_ms;  // Total per pair (map + registration).
  Stats map_time_ms;
  Stats registration_time_ms;  // Total minus map.
  Stats iterations;
};

SequenceTotals ComputeTotals(const std::vector<PairResult>& results);

}  // namespace mlndt
