#pragma once

// The conventional NDT path of Register() (Method::NDT), kept apart from the
// ML-NDT layer schedule: build the single grid of the reference scan, then
// minimise the Gaussian score (ML-NDT Eq. 4, Magnusson's outlier mixture)
// over the sampled input points with MinimizeNewton. Input checks, sampling,
// logging and the matched-fraction check stay in registration.cc.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/ndt_layer.h"
#include "mlndt/registration/registration.h"

namespace mlndt {
namespace internal {

// The single grid of `reference`: cell edge options.ndt.cell_size_m (0: the
// paper's layer-2 cell), min points and regularisation from options.grid.
// False with *error on unusable input (see BuildSingleGrid).
bool BuildNdtGrid(const RegistrationOptions& options,
                  const PointCloud& reference,
                  NdtLayer* grid,
                  std::string* error);

// Minimises the Gaussian score of `sampled_points` on `grid` from
// `initial_xi` with Newton for up to options.ndt.max_iterations, and fills
// *summary: trace (layer 1), iterations_per_layer = {n}, num_layers =
// start_layer = 1, scores, pose, counts, Hessian, covariance, solve time,
// termination. Returns false with *error when Newton fails (then only the
// trace and iteration counts are filled). `start_time_s` anchors the trace
// times. options must be valid.
bool RegisterOnNdtGrid(const RegistrationOptions& options,
                       const NdtLayer& grid,
                       const std::vector<Eigen::Vector3d>& sampled_points,
                       const Vector6d& initial_xi,
                       double start_time_s,
                       RegistrationSummary* summary,
                       std::string* error);

}  // namespace internal
}  // namespace mlndt
