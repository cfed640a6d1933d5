#pragma once

// Implementation of mlndt::pcl::MultiLayerNdt (multi_layer_ndt.h).
//
// PCL's macros (PCL_ERROR, ...) name `pcl::` unqualified, which inside
// namespace mlndt::pcl means this namespace: this file calls
// ::pcl::console::print instead.

#include <pcl/common/transforms.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <climits>
#include <cmath>

#include "mlndt/cloud/range_filter.h"
#include "mlndt/common/timer.h"
#include "mlndt/pcl/conversions.h"
#include "mlndt/registration/registration.h"

namespace mlndt {
namespace pcl {
namespace internal {

inline bool SameRangeFilter(const RangeFilterOptions& a,
                            const RangeFilterOptions& b) {
  return a.min_range_m == b.min_range_m && a.max_range_m == b.max_range_m &&
         a.saturated_range_fraction == b.saturated_range_fraction;
}

// The points of `target` the range filter keeps, built into *map; false
// with *error when none is left or the map cannot be built.
inline bool BuildTargetMap(const RegistrationOptions& options,
                           const PointCloud& target,
                           LayeredGrid* map,
                           std::string* error) {
  if (target.empty()) {
    *error = "the target has no finite point";
    return false;
  }
  RangeFilterSummary filtered_summary;
  const PointCloud filtered =
      FilterByRange(options.range_filter, target, &filtered_summary);
  if (filtered.empty()) {
    *error = "the range filter dropped every target point: " +
             DescribeDroppedPoints(options.range_filter, filtered_summary);
    return false;
  }
  return LayeredGrid::Build(
      options.grid, filtered, options.num_threads, map, error);
}

}  // namespace internal

template <typename PointSource, typename PointTarget>
MultiLayerNdt<PointSource, PointTarget>::MultiLayerNdt() {
  reg_name_ = "MultiLayerNdt";
  setOptions(RegistrationOptions());
  summary_.message = "align() has not run";
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::setInputSource(
    const PointCloudSourceConstPtr& cloud) {
  if (!cloud || cloud->empty()) {
    ::pcl::console::print(
        ::pcl::console::L_ERROR,
        "[mlndt::pcl::%s::setInputSource] the source cloud is %s\n",
        this->getClassName().c_str(),
        cloud ? "empty" : "null");
    input_.reset();
    ClearResult("setInputSource: the source cloud was refused (empty or null)");
    return;
  }
  Base::setInputSource(cloud);
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::setInputTarget(
    const PointCloudTargetConstPtr& cloud) {
  map_ = LayeredGrid();
  map_stale_ = true;
  map_error_.clear();
  target_dropped_ = 0;
  if (!cloud || cloud->empty()) {
    ::pcl::console::print(
        ::pcl::console::L_ERROR,
        "[mlndt::pcl::%s::setInputTarget] the target cloud is %s\n",
        this->getClassName().c_str(),
        cloud ? "empty" : "null");
    target_.reset();
    ClearResult("setInputTarget: the target cloud was refused (empty or null)");
    return;
  }
  Base::setInputTarget(cloud);
  // Options that are not valid yet are reported by align().
  const RegistrationOptions options = getOptions();
  std::string error;
  bool built = false;
  if (options.IsValid(&error) && !UpdateMap(options, &built, &error)) {
    ::pcl::console::print(::pcl::console::L_ERROR,
                          "[mlndt::pcl::%s::setInputTarget] %s\n",
                          this->getClassName().c_str(),
                          error.c_str());
  }
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::setResolution(float resolution) {
  options_.grid.finest_cell_size_m = static_cast<double>(resolution);
}

template <typename PointSource, typename PointTarget>
float MultiLayerNdt<PointSource, PointTarget>::getResolution() const {
  return static_cast<float>(options_.grid.finest_cell_size_m);
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::setMinPointPerVoxel(
    unsigned int min_points_per_voxel) {
  options_.grid.min_points_per_cell =
      static_cast<int>(std::min<unsigned int>(min_points_per_voxel, INT_MAX));
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::setNumThreads(int num_threads) {
  options_.num_threads = num_threads;
}

template <typename PointSource, typename PointTarget>
RegistrationOptions MultiLayerNdt<PointSource, PointTarget>::getOptions()
    const {
  RegistrationOptions options = options_;
  options.schedule.max_final_iterations = max_iterations_;
  // PCL's epsilon bounds a squared step [m^2], mlndt's tolerance a step
  // norm; a bound looser than the options' is not applied (see the header).
  if (transformation_epsilon_ != epsilon_from_options_ &&
      transformation_epsilon_ > 0.0) {
    options.schedule.step_tolerance = std::min(
        options.schedule.step_tolerance, std::sqrt(transformation_epsilon_));
  }
  return options;
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::setOptions(
    const RegistrationOptions& options) {
  options_ = options;
  max_iterations_ = options.schedule.max_final_iterations;
  transformation_epsilon_ =
      options.schedule.step_tolerance * options.schedule.step_tolerance;
  epsilon_from_options_ = transformation_epsilon_;
}

template <typename PointSource, typename PointTarget>
bool MultiLayerNdt<PointSource, PointTarget>::CheckPclSettings(
    std::string* error) const {
  if (max_iterations_ < 1 || max_iterations_ > 10000) {
    *error = "setMaximumIterations(" + std::to_string(max_iterations_) +
             "): the last layer's iteration cap must be in [1, 10000]";
    return false;
  }
  const double epsilon = transformation_epsilon_;
  if (epsilon != epsilon_from_options_ &&
      (!std::isfinite(epsilon) || (epsilon > 0.0 && epsilon < 1e-24))) {
    *error = "setTransformationEpsilon(" + std::to_string(epsilon) +
             "): the squared step bound [m^2] must be finite and, when "
             "positive, at least 1e-24";
    return false;
  }
  return true;
}

template <typename PointSource, typename PointTarget>
bool MultiLayerNdt<PointSource, PointTarget>::UpdateMap(
    const RegistrationOptions& options, bool* built, std::string* error) {
  *built = map_stale_ || options.grid != map_grid_ ||
           !internal::SameRangeFilter(options.range_filter, map_range_filter_);
  if (*built) {
    map_stale_ = false;
    map_grid_ = options.grid;
    map_range_filter_ = options.range_filter;
    map_ = LayeredGrid();
    map_error_.clear();
    const double start_s = NowSeconds();
    const PointCloud target = ToPointCloud(*target_, &target_dropped_);
    if (!internal::BuildTargetMap(options, target, &map_, &map_error_)) {
      map_ = LayeredGrid();
    }
    map_time_s_ = NowSeconds() - start_s;
  }
  if (map_error_.empty()) return true;
  *error = "target map: " + map_error_;
  return false;
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::ClearResult(
    const std::string& message) {
  converged_ = false;
  nr_iterations_ = 0;
  summary_ = RegistrationSummary();
  summary_.message = message;
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::Fail(const std::string& message,
                                                   const Matrix4& guess,
                                                   PointCloudSource* output) {
  summary_.termination_type = TerminationType::FAILURE;
  summary_.message = message;
  ::pcl::console::print(::pcl::console::L_ERROR,
                        "[mlndt::pcl::%s::align] FAILURE: %s\n",
                        this->getClassName().c_str(),
                        message.c_str());
  converged_ = false;
  final_transformation_ = guess;
  transformation_ = Matrix4::Identity();
  ::pcl::transformPointCloud(*output, *output, final_transformation_);
}

template <typename PointSource, typename PointTarget>
void MultiLayerNdt<PointSource, PointTarget>::computeTransformation(
    PointCloudSource& output, const Matrix4& guess) {
  converged_ = false;
  nr_iterations_ = 0;
  previous_transformation_ = guess;
  summary_ = RegistrationSummary();
  const RegistrationOptions options = getOptions();
  std::string error;
  if (!CheckPclSettings(&error) || !options.IsValid(&error)) {
    return Fail(error, guess, &output);
  }
  bool built = false;
  if (!UpdateMap(options, &built, &error)) return Fail(error, guess, &output);
  const double map_time_s = built ? map_time_s_ : 0.0;
  Isometry3d initial;
  if (!ToIsometry(guess, &initial, &error)) {
    return Fail("the guess: " + error, guess, &output);
  }
  // `output` holds the source points align() registers (setIndices').
  const PointCloud source = ToPointCloud(output, &source_dropped_);
  Register(options, map_, source, initial, &summary_);
  summary_.map_time_s = map_time_s;
  summary_.total_time_s += map_time_s;
  if (summary_.termination_type == TerminationType::FAILURE) {
    const std::string message = summary_.message;
    return Fail(message, guess, &output);
  }
  ::pcl::console::print(::pcl::console::L_DEBUG,
                        "[mlndt::pcl::%s::align] %s\n",
                        this->getClassName().c_str(),
                        summary_.BriefReport().c_str());
  converged_ = summary_.termination_type == TerminationType::CONVERGENCE;
  nr_iterations_ = summary_.num_iterations;
  final_transformation_ = summary_.reference_from_input.matrix().cast<float>();
  // The motion from the guess to the result, in the target frame.
  transformation_ = final_transformation_ * guess.inverse();
  ::pcl::transformPointCloud(output, output, final_transformation_);
}

}  // namespace pcl
}  // namespace mlndt
