#pragma once

// mlndt's ML-NDT registration (mlndt::Register) as a pcl::Registration, so
// that PCL code written for pcl::NormalDistributionsTransform runs ML-NDT by
// changing one type:
//
//   mlndt::pcl::MultiLayerNdt<pcl::PointXYZ, pcl::PointXYZ> ndt;
//   ndt.setInputTarget(map);     // the ML-NDT map is built once per target
//   ndt.setInputSource(scan);
//   ndt.align(*aligned, guess);  // guess: target_from_source, Matrix4f
//   if (ndt.hasConverged()) use(ndt.getFinalTransformation());
//
// What each PCL call means here:
//  * setInputTarget: the target becomes the ML-NDT reference map, built
//    there and then (as PCL's NDT and ndt_omp build their grids) and kept
//    for every align() until the target changes. Changing an option the
//    map depends on (range_filter, grid: setResolution,
//    setMinPointPerVoxel, setOptions) rebuilds it at the next align(). A
//    map that cannot be built is reported there and then (PCL's console)
//    and by every align() (FAILURE). PCL's k-d tree of the target (for
//    getFitnessScore) is built by pcl::Registration at the first align(),
//    as for PCL's own NDT.
//  * setInputSource / setIndices: the points registered; align()'s output is
//    them moved by getFinalTransformation().
//  * align(output, guess): mlndt::Register(options, map, source, guess). The
//    clouds are converted as mlndt's readers do (conversions.h), so the
//    pose equals, bit for bit, mlndt::Register's on the same points with the
//    same options and the guess cast to double.
//  * hasConverged(): true only when the verdict (getSummary().
//    termination_type) is CONVERGENCE: the last layer met its step
//    tolerance and the result passed the quality check. NO_CONVERGENCE (the
//    iteration cap was reached; the pose passed the quality check),
//    LOW_QUALITY, DEGENERATE and FAILURE give false; the summary says why.
//  * getFinalTransformation(): the registered target_from_source (float);
//    getSummary().reference_from_input holds it in double. On FAILURE (bad
//    options, a target map that cannot be built, no usable points) it is
//    the guess.
//  * getFitnessScore(max_range): PCL's: the mean squared distance [m^2] from
//    each source point, moved by the final transformation, to its nearest
//    target point (pcl::Registration's own code).
//  * setMaximumIterations(n): the cap on the last layer's iterations
//    (options.schedule.max_final_iterations; the coarse layers run
//    schedule.iterations_per_layer each). In [1, 10000].
//  * setTransformationEpsilon(e): PCL's bound on a step's squared
//    translation [m^2]. It tightens the last layer's convergence test to a
//    successful step with ||delta xi|| <= sqrt(e) (metres and radians
//    together) when sqrt(e) is below options.schedule.step_tolerance
//    (default 1e-3); a looser bound is not applied, because CONVERGENCE
//    promises the pose settled to that tolerance (PCL's NDT tutorial's 0.01
//    would stop ML-NDT at 0.1 m steps). To loosen it, set
//    options.schedule.step_tolerance. e <= 0 (PCL's "not set") keeps the
//    options' tolerance; e must be finite and, when positive, >= 1e-24.
//  * setResolution(r): the finest layer's largest cell edge [m]
//    (options.grid.finest_cell_size_m); the coarser layers follow from the
//    target's bounding box (Section 4 of the paper).
//  * setMinPointPerVoxel(n): the points a cell needs to hold a distribution
//    (options.grid.min_points_per_cell, in [4, 1e6]).
//  * setNumThreads(n) (ndt_omp's name): options.num_threads.
//  * setStepSize, setOulierRatio: kept and returned by their getters, with
//    no effect: ML-NDT has no More-Thuente line search and no uniform
//    outlier term (Eq. 10 is a sum of squared whitened distances).
//  * Not used: setTransformationRotationEpsilon, setEuclideanFitnessEpsilon,
//    setMaxCorrespondenceDistance, setRANSAC*, correspondence estimation and
//    rejectors, the visualisation callback.
// Every other option is mlndt's: getOptions() / setOptions() with
// mlndt::RegistrationOptions (the library's defaults unless set).
//
// Point types: any PCL point type with float x, y, z that pcl::Registration
// accepts (PCL_ADD_POINT4D). getFitnessScore needs PointSource ==
// PointTarget (pcl::Registration searches the target's k-d tree with source
// points).
//
// The target goes through options.range_filter as mlndt's reference does
// (points near the origin, a saturated largest range): for a map in a world
// frame set range_filter.min_range_m and saturated_range_fraction to 0.
// Inside namespace mlndt, `pcl::` names this namespace: write `::pcl::`
// there (PCL's PCL_ERROR-style macros do not compile there).

#include <pcl/point_cloud.h>
#include <pcl/registration/registration.h>

#include <cstddef>
#include <memory>
#include <string>

#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration_options.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {
namespace pcl {

template <typename PointSource, typename PointTarget>
class MultiLayerNdt
    : public ::pcl::Registration<PointSource, PointTarget, float> {
 public:
  using Base = ::pcl::Registration<PointSource, PointTarget, float>;
  using Matrix4 = typename Base::Matrix4;
  using PointCloudSource = typename Base::PointCloudSource;
  using PointCloudSourceConstPtr = typename Base::PointCloudSourceConstPtr;
  using PointCloudTarget = typename Base::PointCloudTarget;
  using PointCloudTargetConstPtr = typename Base::PointCloudTargetConstPtr;
  using Ptr = std::shared_ptr<MultiLayerNdt<PointSource, PointTarget>>;
  using ConstPtr =
      std::shared_ptr<const MultiLayerNdt<PointSource, PointTarget>>;

  // mlndt::RegistrationOptions' defaults.
  MultiLayerNdt();
  ~MultiLayerNdt() override = default;

  // ---- pcl::Registration ---------------------------------------------------

  // A refused cloud (empty: pcl::Registration prints why) also clears the
  // result, so a stale hasConverged() never survives it.
  void setInputSource(const PointCloudSourceConstPtr& cloud) override;
  void setInputTarget(const PointCloudTargetConstPtr& cloud) override;

  // ---- pcl::NormalDistributionsTransform's calls (see above) --------------

  void setResolution(float resolution);
  float getResolution() const;
  void setMinPointPerVoxel(unsigned int min_points_per_voxel);
  void setStepSize(double step_size) { step_size_ = step_size; }
  double getStepSize() const { return step_size_; }
  void setOulierRatio(double outlier_ratio) { outlier_ratio_ = outlier_ratio; }
  double getOulierRatio() const { return outlier_ratio_; }
  // Iterations of the reported solution, over all layers.
  int getFinalNumIteration() const { return summary_.num_iterations; }
  void setNumThreads(int num_threads);

  // ---- mlndt ----------------------------------------------------------------

  // The options of the next align(): those set with setOptions, with
  // max_final_iterations and step_tolerance as the PCL setters left them
  // (see setTransformationEpsilon above).
  RegistrationOptions getOptions() const;
  // Sets every option, the two PCL-mapped ones included (the PCL members
  // max_iterations_ and transformation_epsilon_ follow). Checked at align().
  void setOptions(const RegistrationOptions& options);

  // The last align()'s summary: the verdict (termination_type, message), its
  // evidence (quality, constraints), the pose in double, the per-iteration
  // trace, counts and timings. map_time_s is the time of the map build when
  // this align() built it (0 otherwise). Before any align(): FAILURE.
  const RegistrationSummary& getSummary() const { return summary_; }
  TerminationType getTerminationType() const {
    return summary_.termination_type;
  }
  // Covariance of the pose vector xi = (t [m], alpha, beta, gamma [rad]),
  // R = Rx(alpha) Ry(beta) Rz(gamma) (ML-NDT Eqs. 7 and 11), at the
  // solution; infinite along degenerate directions, zero when unknown.
  const Matrix6d& getCovariance() const { return summary_.covariance; }
  // The reference map of the current target (empty when there is none).
  const LayeredGrid& getTargetMap() const { return map_; }
  // Non-finite points dropped from the last align()'s source and from the
  // current target.
  size_t getSourceDroppedNonFinite() const { return source_dropped_; }
  size_t getTargetDroppedNonFinite() const { return target_dropped_; }

 protected:
  using Base::converged_;
  using Base::final_transformation_;
  using Base::input_;
  using Base::max_iterations_;
  using Base::nr_iterations_;
  using Base::previous_transformation_;
  using Base::reg_name_;
  using Base::target_;
  using Base::transformation_;
  using Base::transformation_epsilon_;

  void computeTransformation(PointCloudSource& output,
                             const Matrix4& guess) override;

 private:
  // Builds map_ when the target or the map's options changed since the
  // last build (*built says whether it did); false with *error when there
  // is no map.
  bool UpdateMap(const RegistrationOptions& options,
                 bool* built,
                 std::string* error);
  // The PCL-mapped settings are in mlndt's ranges; false with *error naming
  // the PCL setter otherwise.
  bool CheckPclSettings(std::string* error) const;
  // FAILURE with `message`: the guess as the result, output moved by it.
  void Fail(const std::string& message,
            const Matrix4& guess,
            PointCloudSource* output);
  // Clears the last result (a refused input).
  void ClearResult(const std::string& message);

  RegistrationOptions options_;
  // transformation_epsilon_ as setOptions last wrote it: while it holds
  // this value, options_.schedule.step_tolerance is used as it is.
  double epsilon_from_options_ = 0.0;
  double step_size_ = 0.1;       // PCL NDT's default; no effect.
  double outlier_ratio_ = 0.55;  // PCL NDT's default; no effect.

  LayeredGrid map_;
  bool map_stale_ = true;    // The target changed since map_ was built.
  std::string map_error_;    // Why the last build failed ("" when it did not).
  double map_time_s_ = 0.0;  // The last build's wall time [s].
  RangeFilterOptions map_range_filter_;  // map_'s options.
  LayeredGridOptions map_grid_;

  RegistrationSummary summary_;
  size_t source_dropped_ = 0;
  size_t target_dropped_ = 0;
};

}  // namespace pcl
}  // namespace mlndt

#include "mlndt/pcl/impl/multi_layer_ndt.hpp"
