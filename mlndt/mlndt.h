#pragma once

// mlndt: 3D LiDAR scan matching with the Multi-Layered Normal Distribution
// Transform (Ulas & Temeltas, J Intell Robot Syst 71:85-108, 2013).
// The umbrella header: includes the whole public API.

#include "mlndt/cloud/cloud_format.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/point_cloud.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/types.h"
#include "mlndt/cost/add_pair_residuals.h"
#include "mlndt/cost/add_residuals.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/layer_binding.h"
#include "mlndt/cost/mlndt_pair_cost.h"
#include "mlndt/cost/mlndt_point_cost.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/cost/score.h"
#include "mlndt/grid/grid_io.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"
#include "mlndt/ndt/gaussian_score.h"
#include "mlndt/ndt/ndt_registration.h"
#include "mlndt/registration/registration.h"
#include "mlndt/registration/registration_options.h"
#include "mlndt/registration/registration_summary.h"
#include "mlndt/sampling/point_sampler.h"
#include "mlndt/schedule/layer_scheduler.h"
#include "mlndt/solvers/backend.h"
#include "mlndt/solvers/backend_factory.h"
