#include "lab/runs/pose_graph.h"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <algorithm>

#include "lab/runs/pose_graph_option_table.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/timer.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration.h"
#include "mlndt/sampling/point_sampler.h"

namespace mlndt {
namespace {

// What the joint problem is built from: each scan's map and samples.
struct GraphInputs {
  std::vector<LayeredGrid> maps;
  std::vector<PointCloud> samples;
};

// SPARSE_NORMAL_CHOLESKY when Ceres has a sparse library, else DENSE_QR: a
// pose-only problem has no point blocks to eliminate.
void ChooseLinearSolver(ceres::Solver::Options* options) {
  for (const ceres::SparseLinearAlgebraLibraryType library :
       {ceres::SUITE_SPARSE, ceres::EIGEN_SPARSE, ceres::CX_SPARSE}) {
    if (ceres::IsSparseLinearAlgebraLibraryTypeAvailable(library)) {
      options->linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
      options->sparse_linear_algebra_library_type = library;
      return;
    }
  }
  options->linear_solver_type = ceres::DENSE_QR;
}

// The (map scan, point scan) terms: neighbours, extra pairs, both ways.
std::vector<std::pair<int, int>> DirectedPairs(const PoseGraphOptions& o,
                                               int n) {
  std::vector<std::pair<int, int>> edges;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j <= std::min(n - 1, i + o.neighbors); ++j) {
      edges.emplace_back(i, j);
    }
  }
  edges.insert(edges.end(), o.extra_pairs.begin(), o.extra_pairs.end());
  std::vector<std::pair<int, int>> directed;
  for (const auto& [i, j] : edges) {
    directed.emplace_back(i, j);
    if (o.both_directions) directed.emplace_back(j, i);
  }
  return directed;
}

// Pair residuals on layer `finest - offset` of each map, and the odometry
// factors. `poses` must stay in place while the Problem lives.
void BuildProblem(const PoseGraphOptions& o,
                  const GraphInputs& in,
                  int layer_offset,
                  std::vector<PoseBlocks>* poses,
                  ceres::Problem* problem,
                  PoseGraphSummary* summary) {
  const int n = static_cast<int>(in.maps.size());
  PairResidualOptions residuals;
  residuals.objective = o.registration.objective;
  residuals.one_block_per_pair = !o.point_blocks;
  residuals.information_scale = o.information_scale;
  const std::vector<std::pair<int, int>> directed = DirectedPairs(o, n);
  for (const auto& [map_scan, point_scan] : directed) {
    const LayeredGrid& map = in.maps[map_scan];
    const int layer = std::max(1, map.num_layers() - layer_offset);
    PoseBlocks& pose_i = (*poses)[map_scan];
    PoseBlocks& pose_j = (*poses)[point_scan];
    AddMlNdtPairResiduals(map.layer(layer),
                          in.samples[point_scan].points(),
                          residuals,
                          pose_i.rotation,
                          pose_i.translation,
                          pose_j.rotation,
                          pose_j.translation,
                          problem);
  }
  summary->directed_pairs = static_cast<int>(directed.size());
  summary->odometry_factors = 0;
  for (int i = 0; !o.odometry.empty() && i + 1 < n; ++i) {
    AddOdometryFactor(o.odometry[i].inverse() * o.odometry[i + 1],
                      o.odometry_noise,
                      &(*poses)[i],
                      &(*poses)[i + 1],
                      problem);
    ++summary->odometry_factors;
  }
}

// Sum of the Problem's cost at the given poses.
double CostAt(ceres::Problem* problem,
              std::vector<PoseBlocks>* poses,
              const std::vector<PoseBlocks>& at) {
  const std::vector<PoseBlocks> saved = *poses;
  *poses = at;
  double cost = 0.0;
  problem->Evaluate(
      ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr);
  *poses = saved;
  return cost;
}

// Forwards Ceres' iterations of one joint stage to PoseGraphOptions::progress,
// numbered after the `before` iterations of the earlier stages.
class IterationForwarder : public ceres::IterationCallback {
 public:
  IterationForwarder(const PoseGraphOptions& options,
                     std::string stage,
                     size_t before)
      : options_(options), stage_(std::move(stage)), before_(before) {}
  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& summary) override {
    const size_t done = before_ + static_cast<size_t>(summary.iteration);
    ReportProgress(options_.progress,
                   {done,
                    done,
                    static_cast<size_t>(options_.joint_layers) *
                        static_cast<size_t>(options_.max_iterations),
                    stage_ + " cost " + std::to_string(summary.cost)});
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const PoseGraphOptions& options_;
  std::string stage_;
  size_t before_ = 0;
};

void SolveJointly(const PoseGraphOptions& o,
                  const GraphInputs& in,
                  std::vector<PoseBlocks>* poses,
                  PoseGraphSummary* summary) {
  const std::vector<PoseBlocks> initial = *poses;
  for (int offset = o.joint_layers - 1; offset >= 0; --offset) {
    ceres::Problem problem;
    BuildProblem(o, in, offset, poses, &problem, summary);
    problem.SetParameterBlockConstant((*poses)[0].rotation);
    problem.SetParameterBlockConstant((*poses)[0].translation);
    ceres::Solver::Options solver;
    ChooseLinearSolver(&solver);
    solver.max_num_iterations = o.max_iterations;
    solver.num_threads = o.registration.num_threads;
    const std::string stage = "layer n-" + std::to_string(offset);
    IterationForwarder callback(
        o,
        stage,
        static_cast<size_t>((o.joint_layers - 1 - offset) * o.max_iterations));
    solver.callbacks.push_back(&callback);
    ceres::Solver::Summary report;
    ceres::Solve(solver, &problem, &report);
    LOG(INFO) << "joint stage, " << stage << ": " << report.BriefReport();
    if (offset == o.joint_layers - 1) {
      summary->initial_cost = report.initial_cost;
    }
    summary->final_cost = report.final_cost;
    summary->iterations += static_cast<int>(report.iterations.size()) - 1;
    summary->residual_blocks = problem.NumResidualBlocks();
    summary->termination =
        ceres::TerminationTypeToString(report.termination_type);
    summary->linear_solver =
        ceres::LinearSolverTypeToString(report.linear_solver_type_used);
    if (offset == 0) {
      summary->cost_at_initial = CostAt(&problem, poses, initial);
    }
  }
}

// Reads every scan, builds its map once and samples its points once.
bool LoadScans(const RegistrationOptions& options,
               const std::vector<std::string>& paths,
               std::vector<PointCloud>* scans,
               GraphInputs* in,
               std::string* error) {
  const size_t n = paths.size();
  scans->resize(n);
  in->maps.resize(n);
  in->samples.resize(n);
  for (size_t i = 0; i < n; ++i) {
    if (!ReadPointCloud(paths[i], &(*scans)[i], nullptr, error)) return false;
    if (!LayeredGrid::Build(options.grid, (*scans)[i], &in->maps[i], error)) {
      *error = paths[i] + ": map: " + *error;
      return false;
    }
    if (!SamplePoints(
            options.sampling, (*scans)[i], &in->samples[i], nullptr, error)) {
      *error = paths[i] + ": sampling: " + *error;
      return false;
    }
  }
  return true;
}

// Scan i+1 onto scan i from the previous relative estimate; scan 0 = world.
// A failed pair keeps the previous relative pose and is counted.
std::vector<Isometry3d> ChainRegistrations(const RegistrationOptions& options,
                                           const std::vector<LayeredGrid>& maps,
                                           const std::vector<PointCloud>& scans,
                                           int* failures) {
  std::vector<Isometry3d> chained(scans.size(), Isometry3d::Identity());
  Isometry3d relative = Isometry3d::Identity();
  for (size_t i = 0; i + 1 < scans.size(); ++i) {
    RegistrationSummary summary;
    Register(options, maps[i], scans[i + 1], relative, &summary);
    if (summary.IsSolutionUsable()) {
      relative = summary.reference_from_input;
    } else {
      ++*failures;
      LOG(WARNING) << "scan " << i + 1 << " onto " << i << ": "
                   << summary.message << "; keeping the previous relative pose";
    }
    chained[i + 1] = chained[i] * relative;
  }
  return chained;
}

// The odometry moved so that scan 0 is the world.
std::vector<Isometry3d> FromFirst(const std::vector<Isometry3d>& odometry,
                                  size_t n) {
  std::vector<Isometry3d> poses;
  const Isometry3d first_inverse = odometry[0].inverse();
  for (size_t i = 0; i < n; ++i) poses.push_back(first_inverse * odometry[i]);
  return poses;
}

}  // namespace

bool PoseGraphOptions::IsValid(size_t num_scans, std::string* error) const {
  const auto fail = [error](const std::string& message) {
    *error = message;
    return false;
  };
  // The ranges of PoseGraphOwnOptionsTable (the odometry noise's too), then
  // what needs the number of scans.
  if (!PoseGraphOwnOptionsTable().Check(*this, error)) return false;
  const int n = static_cast<int>(num_scans);
  for (const auto& [i, j] : extra_pairs) {
    if (i < 0 || j < 0 || i >= n || j >= n || i == j) {
      return fail("pair " + std::to_string(i) + ":" + std::to_string(j) +
                  ": scans are 0.." + std::to_string(n - 1) +
                  " and a pair needs two of them");
    }
  }
  if (!odometry.empty() && odometry.size() < num_scans) {
    return fail("odometry has " + std::to_string(odometry.size()) +
                " poses for " + std::to_string(num_scans) + " scans");
  }
  if (init_from_odometry && odometry.empty()) {
    return fail("initialising from the odometry needs odometry poses");
  }
  return registration.IsValid(error);
}

bool RunPoseGraph(const PoseGraphOptions& options,
                  const std::vector<std::string>& paths,
                  PoseGraphSummary* summary,
                  std::string* error) {
  *summary = PoseGraphSummary();
  if (paths.size() < 2) return (*error = "fewer than 2 scans", false);
  if (!options.IsValid(paths.size(), error)) return false;
  const double start = NowSeconds();
  std::vector<PointCloud> scans;
  GraphInputs in;
  if (!LoadScans(options.registration, paths, &scans, &in, error)) {
    return false;
  }
  const double maps_done = NowSeconds();
  summary->initial_is_chained = !options.init_from_odometry;
  summary->initial = options.init_from_odometry
                         ? FromFirst(options.odometry, paths.size())
                         : ChainRegistrations(options.registration,
                                              in.maps,
                                              scans,
                                              &summary->chained_failures);
  const double chained_done = NowSeconds();
  std::vector<PoseBlocks> blocks;
  for (const Isometry3d& pose : summary->initial) {
    blocks.push_back(PoseBlocks::From(pose));
  }
  SolveJointly(options, in, &blocks, summary);
  for (const PoseBlocks& b : blocks) summary->joint.push_back(b.ToIsometry());
  summary->check = CheckJointPoses(options.registration,
                                   // The calibrated weight, whatever the
                                   // pairs' weight in the joint problem.
                                   kCalibratedPairInformationScale,
                                   in.maps,
                                   scans,
                                   options.extra_pairs,
                                   options.odometry,
                                   options.odometry_noise,
                                   summary->joint,
                                   summary->final_cost);
  const double done = NowSeconds();
  summary->maps_s = maps_done - start;
  summary->chained_s = chained_done - maps_done;
  summary->joint_s = done - chained_done;
  summary->total_s = done - start;
  return true;
}

}  // namespace mlndt
