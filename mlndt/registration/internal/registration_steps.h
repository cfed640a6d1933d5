#pragma once

// Steps every registration entry point shares (ML-NDT's Register, the NDT
// baseline's RegisterNdt): failing with a message, checking and sampling the
// input, the map's facts and the matched-fraction check.

#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/cloud/range_filter.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/prepared_input.h"
#include "mlndt/registration/registration_summary.h"
#include "mlndt/sampling/point_sampler.h"

namespace mlndt {
namespace internal {

// FAILURE with `message`, logged (LOG(ERROR)) under `entry_point`'s name.
void Fail(const char* entry_point,
          const std::string& message,
          RegistrationSummary* summary);

// Checks the input and that the initial guess is finite and rigid (a
// rotation, not a reflection or a scaled matrix), drops the returns the range
// filter rejects and samples the rest (Section 4.3), filling the counts and the
// sampling time. False (and the message in *error) when nothing usable is
// left. `buffer` (optional) holds the range filter's output: its memory
// is reused (Register passes the filtered reference's, no longer needed once
// the map exists). CheckInput, then CheckInitialGuess, then FilterAndSample.
bool SampleInput(const RangeFilterOptions& range_filter,
                 const SamplingOptions& options,
                 const PointCloud& input,
                 const Isometry3d& initial_reference_from_input,
                 PointCloud* sampled,
                 RegistrationSummary* summary,
                 std::string* error,
                 PointCloud* buffer = nullptr);

// SampleInput's first step: false with *error for an empty input or one with
// a non-finite point.
bool CheckInput(const PointCloud& input, std::string* error);

// SampleInput's second step: false with *error for a guess that is not
// finite or not a rigid transform.
bool CheckInitialGuess(const Isometry3d& initial_reference_from_input,
                       std::string* error);

// SampleInput's last step: the range filter, then the sampling; fills
// summary's input_points, range_filtered_points, sampled_points and
// sampling_time_s (as far as it got). False with *error when nothing is
// left.
bool FilterAndSample(const RangeFilterOptions& range_filter,
                     const SamplingOptions& options,
                     const PointCloud& input,
                     PointCloud* sampled,
                     RegistrationSummary* summary,
                     std::string* error,
                     PointCloud* buffer = nullptr);

// PrepareInput's work (prepared_input.h) with the range filter's output in
// `buffer` (optional; as SampleInput's): CheckInput, then FilterAndSample,
// then the samples about their centroid. Returns prepared->ok().
bool FilterSampleAndCentre(const RangeFilterOptions& range_filter,
                           const SamplingOptions& options,
                           const PointCloud& input,
                           PreparedInput* prepared,
                           PointCloud* buffer = nullptr);

// The reference scan without the returns the range filter rejects; false
// with *error when none is left.
bool FilterReference(const RangeFilterOptions& range_filter,
                     const PointCloud& reference,
                     PointCloud* filtered,
                     std::string* error);

// False with *error for a map without layers or occupied cells.
bool CheckMap(const LayeredGrid& map, std::string* error);

// Fills the map's layer count, finest cell, occupied cells and bytes.
void DescribeMap(const LayeredGrid& map, RegistrationSummary* summary);

// An error message when fewer than `min_fraction` of the sampled points are
// matched at the solution, else "".
std::string CheckMatchedFraction(double min_fraction,
                                 const RegistrationSummary& summary);

}  // namespace internal
}  // namespace mlndt
