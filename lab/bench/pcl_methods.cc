#include "lab/bench/pcl_methods.h"

#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/gicp.h>
#include <pcl/registration/ndt.h>

#include <map>
#include <utility>

#include "mlndt/common/timer.h"

namespace mlndt {
namespace {

using PclPoint = pcl::PointXYZ;
using PclCloud = pcl::PointCloud<PclPoint>;

PclCloud::Ptr ToPcl(const PointCloud& cloud) {
  PclCloud::Ptr out(new PclCloud);
  out->reserve(cloud.size());
  for (const Eigen::Vector3d& p : cloud.points()) {
    out->push_back(PclPoint(static_cast<float>(p.x()),
                            static_cast<float>(p.y()),
                            static_cast<float>(p.z())));
  }
  return out;
}

PclCloud::Ptr VoxelFiltered(const PclCloud::Ptr& cloud, double leaf_size_m) {
  pcl::VoxelGrid<PclPoint> voxel_grid;
  const float leaf = static_cast<float>(leaf_size_m);
  voxel_grid.setLeafSize(leaf, leaf, leaf);
  voxel_grid.setInputCloud(cloud);
  PclCloud::Ptr out(new PclCloud);
  voxel_grid.filter(*out);
  return out;
}

// A single-precision PCL transform as an isometry, its rotation
// re-orthonormalised.
Isometry3d ToIsometry(const Eigen::Matrix4f& matrix) {
  Isometry3d estimate = Isometry3d::Identity();
  estimate.matrix() = matrix.cast<double>();
  estimate.linear() =
      Eigen::Quaterniond(estimate.linear()).normalized().toRotationMatrix();
  return estimate;
}

// GICP with its iteration count readable as NDT's (PCL keeps it protected).
class Gicp : public pcl::GeneralizedIterativeClosestPoint<PclPoint, PclPoint> {
 public:
  int getFinalNumIteration() const { return nr_iterations_; }
};

// Filters both clouds, sets them and aligns from `guess`: the time covers
// all of it, align_ms align() alone.
template <typename Registration>
BenchEstimate Align(const PclCloud::Ptr& reference,
                    const PclCloud::Ptr& input,
                    double leaf_size_m,
                    const Eigen::Matrix4f& guess,
                    Registration* registration) {
  const double start = NowSeconds();
  registration->setInputTarget(VoxelFiltered(reference, leaf_size_m));
  registration->setInputSource(VoxelFiltered(input, leaf_size_m));
  PclCloud aligned;
  const double align_start = NowSeconds();
  registration->align(aligned, guess);
  const double end = NowSeconds();
  BenchEstimate e;
  e.reference_from_input = ToIsometry(registration->getFinalTransformation());
  e.usable = registration->hasConverged();
  e.time_ms = (end - start) * 1e3;
  e.align_ms = (end - align_start) * 1e3;
  e.iterations = registration->getFinalNumIteration();
  // PCL also reports convergence when it stops at the iteration cap.
  e.converged = registration->hasConverged() &&
                e.iterations < registration->getMaximumIterations();
  return e;
}

// pcl_ndt or pcl_gicp on the clouds of every pair, converted once
// (converting is part of loading).
class PclMethod : public BenchMethod {
 public:
  PclMethod(const PclBenchOptions& options, bool gicp)
      : options_(options), gicp_(gicp) {}

  bool Prepare(const std::vector<ScanPair>& pairs, std::string*) override {
    std::map<const PointCloud*, PclCloud::Ptr> converted;
    auto get = [&](const PointCloud& cloud) {
      PclCloud::Ptr& out = converted[&cloud];
      if (out == nullptr) out = ToPcl(cloud);
      return out;
    };
    pairs_.clear();
    for (const ScanPair& pair : pairs) {
      pairs_.push_back({get(*pair.reference), get(*pair.input)});
    }
    return true;
  }

  BenchMethodLabels Labels() const override {
    BenchMethodLabels labels;
    labels.method = gicp_ ? "pcl_gicp" : "pcl_ndt";
    labels.sampling =
        "voxel_grid_" +
        BenchFormat("%g",
                    gicp_ ? options_.gicp_leaf_size_m : options_.leaf_size_m);
    return labels;
  }

  BenchEstimate Run(size_t p, const ScanPair& pair) override {
    const Eigen::Matrix4f guess =
        pair.initial_reference_from_input.matrix().cast<float>();
    const PclCloud::Ptr& reference = pairs_[p].first;
    const PclCloud::Ptr& input = pairs_[p].second;
    if (gicp_) {
      Gicp gicp;
      gicp.setMaxCorrespondenceDistance(
          options_.gicp_max_correspondence_distance_m);
      gicp.setMaximumIterations(options_.gicp_max_iterations);
      return Align(reference, input, options_.gicp_leaf_size_m, guess, &gicp);
    }
    pcl::NormalDistributionsTransform<PclPoint, PclPoint> ndt;
    ndt.setTransformationEpsilon(options_.ndt_transformation_epsilon);
    ndt.setStepSize(options_.ndt_step_size_m);
    ndt.setResolution(static_cast<float>(options_.ndt_resolution_m));
    ndt.setMaximumIterations(options_.ndt_max_iterations);
    return Align(reference, input, options_.leaf_size_m, guess, &ndt);
  }

 private:
  PclBenchOptions options_;
  bool gicp_;
  std::vector<std::pair<PclCloud::Ptr, PclCloud::Ptr>> pairs_;
};

}  // namespace

bool PclAvailable() { return true; }

std::unique_ptr<BenchMethod> MakePclNdtMethod(const PclBenchOptions& options) {
  return std::make_unique<PclMethod>(options, false);
}

std::unique_ptr<BenchMethod> MakePclGicpMethod(const PclBenchOptions& options) {
  return std::make_unique<PclMethod>(options, true);
}

}  // namespace mlndt
