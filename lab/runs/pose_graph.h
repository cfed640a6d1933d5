#pragma once

// mlndt_posegraph's run: every scan's pose refined jointly in one
// ceres::Problem built from ML-NDT pair residuals (the embedding API,
// mlndt/cost/add_pair_residuals.h), optionally with odometry factors of a
// stated noise between consecutive scans and extra pairs (loop closures).
//
// (a) Initial poses: chained pairwise registrations (scan i+1 onto scan i
//     from the previous relative estimate; scan 0 = world), or the given
//     odometry moved so that scan 0 is the world.
// (b) Joint: a quaternion + translation block per scan (scan 0 constant).
//     For every edge i -> j, j = i+1..i+neighbors, and every extra pair, scan
//     j's sampled points against scan i's map and (both_directions) the
//     reverse; each map is built once and each scan sampled once. Each
//     directed pair is one residual block (MlNdtPairFactor) unless
//     point_blocks; its information is information_scale times the
//     unit-information one. With odometry, one factor per consecutive pair
//     (pose_graph_factors.h). Solved on the finest layer of each map
//     (joint_layers 2: the last two, coarse to fine).
// (c) Verdict: the joint poses against each pair's own optimum and
//     information and against the odometry factors (pose_graph_check.h).

#include <string>
#include <utility>
#include <vector>

#include "lab/runs/pose_graph_check.h"
#include "lab/runs/pose_graph_factors.h"
#include "mlndt/common/progress.h"
#include "mlndt/common/types.h"
#include "mlndt/cost/add_pair_residuals.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {

struct PoseGraphOptions {
  // The maps, sampling, loss and unmatched-point policy of the pairs, and
  // the chained registrations.
  RegistrationOptions registration;
  int neighbors = 2;        // >= 1.
  int joint_layers = 1;     // 1 or 2.
  int max_iterations = 50;  // Per joint stage; >= 1.
  bool both_directions = true;
  bool point_blocks = false;
  // w of PairResidualOptions: the pairs' weight against the odometry
  // factors (a graph of pairs alone has the same optimum for any w).
  double information_scale = kCalibratedPairInformationScale;
  // More ML-NDT pairs (i, j), e.g. loop closures; i != j, both in range.
  std::vector<std::pair<int, int>> extra_pairs;
  // world_from_scan per scan, or empty: no odometry factors.
  std::vector<Isometry3d> odometry;
  OdometryNoise odometry_noise;
  // Start from the odometry instead of the chained registrations.
  bool init_from_odometry = false;
  // Hears of every joint iteration (may be null, not owned): Ceres'
  // iterations of all stages, max_iterations per stage, each status the
  // stage and its cost ("layer n-0 cost 12.5").
  ProgressCallback* progress = nullptr;

  // The ranges of PoseGraphOwnOptionsTable, then (by `num_scans`) the
  // extra pairs and the odometry poses, and the registration's IsValid.
  bool IsValid(size_t num_scans, std::string* error) const;
};

struct PoseGraphSummary {
  std::vector<Isometry3d> initial;  // Chained or from the odometry.
  std::vector<Isometry3d> joint;
  bool initial_is_chained = true;
  int chained_failures = 0;  // Pairs that kept the previous relative pose.
  int directed_pairs = 0;
  int odometry_factors = 0;
  int residual_blocks = 0;       // Of the last stage.
  int iterations = 0;            // Over all stages.
  double initial_cost = 0.0;     // First stage, at the initial poses.
  double cost_at_initial = 0.0;  // Last stage's objective there.
  double final_cost = 0.0;
  std::string termination;  // Ceres' (always CONVERGENCE or NO_CONVERGENCE).
  std::string linear_solver;
  // The verdict on the joint poses (pose_graph_check.h).
  PoseGraphCheck check;
  double maps_s = 0.0, chained_s = 0.0, joint_s = 0.0, total_s = 0.0;
};

// Reads the scans at `paths`, builds their maps, samples them, finds the
// initial poses and solves. False with *error for invalid options or a scan
// that cannot be read or mapped.
bool RunPoseGraph(const PoseGraphOptions& options,
                  const std::vector<std::string>& paths,
                  PoseGraphSummary* summary,
                  std::string* error);

}  // namespace mlndt
