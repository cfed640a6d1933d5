// mlndt_posegraph: odometry by chained pairwise ML-NDT registrations, then a
// joint refinement of all scan poses in one ceres::Problem built from ML-NDT
// pair residuals (the embedding API, mlndt/cost/add_pair_residuals.h).
//
//   mlndt_posegraph --scans=DIR [--gt_poses=poses.txt] [--neighbors=2]
//                   [--output_dir=DIR] [--output_json=FILE] [registration
//                   flags]
//
// (a) Chained: scan i+1 is registered onto scan i with mlndt::Register, the
//     previous relative estimate as the initial guess; world_from_scan poses
//     are the product of the relative ones (scan 0 = world).
// (b) Joint: one Problem with a quaternion + translation block per scan
//     (scan 0 held constant), initialised from (a). For every edge i -> j,
//     j = i+1..i+neighbors, the sampled points of scan j are scored against
//     scan i's map and, unless --joint_one_way, the points of scan i against
//     scan j's map. Each scan's map is built once and its points sampled once
//     (the registration flags' sampling); the Problem is solved on the finest
//     layer of each map (--joint_layers=2: the last two, coarse to fine), with
//     the registration loss and unmatched-point policy. Each directed pair is
//     one residual block (MlNdtPairFactor: the pair's points summed into the
//     same normal equations), unless --joint_point_blocks; the raw scans are
//     freed before the joint solve (maps and samples are all it needs).
//
// Writes trajectory_chained.txt and trajectory_joint.txt (KITTI 12-number
// lines, world_from_scan) into --output_dir when given, and one JSON object
// to stdout (and --output_json). With --gt_poses (KITTI format, the scans'
// own frame, one line per scan in file-name order) the JSON has
//   ate_{chained,joint}_m: RMSE of the translation error over all scans after
//       aligning the first poses (estimate_k -> gt_0 est_0^-1 est_k; no
//       rotation, translation or scale fit beyond that; ComputeAte with
//       FIRST_POSE, lab/eval/trajectory_metrics.h);
//   rpe_{chained,joint}: mean over consecutive scans of the relative pose
//       error gt_{k,k+1}^-1 est_{k,k+1} (ComputeRpe, delta 1):
//       {"translation_m", "rotation_deg"}.

#include <ceres/ceres.h>
#include <gflags/gflags.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "lab/eval/dataset.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/cost/add_pair_residuals.h"
#include "mlndt/cost/robust_loss.h"
#include "tools/common/json_output.h"
#include "tools/common/output_files.h"
#include "tools/common/pose_flags.h"
#include "tools/common/posegraph_metrics.h"
#include "tools/common/progress.h"
#include "tools/common/registration_flags.h"
#include "tools/common/start_layer_check.h"
#include "tools/common/tool_main.h"

// clang-format off
DEFINE_string(scans, "", "Folder of scans (files with a cloud extension, sorted by name)");
DEFINE_string(gt_poses, "", "Optional KITTI-format ground truth (world_from_scan, scan frame)");
DEFINE_int32(neighbors, 2, "Edges i -> i+1 .. i+neighbors in the joint problem; >= 1");
DEFINE_int32(joint_layers, 1,
             "Finest map layers used by the joint solve, coarse to fine: 1 (finest only) or 2. "
             "The chained poses already sit at a finest-layer optimum; on KITTI 0-7 a stage on "
             "layer n-1 first moved them away (joint cost 1023435 vs 1023387, twice the time)");
DEFINE_int32(joint_max_iterations, 50, "Ceres iteration cap per joint stage; >= 1");
DEFINE_bool(joint_one_way, false,
            "Only score scan j's points against scan i's map (default: both directions)");
DEFINE_bool(joint_point_blocks, false,
            "One Ceres residual block per sampled point (the previous form: ~1.2 kB each, "
            "1.18 GB peak on the 21 MulRan KAIST03 keyframes) instead of one block per "
            "directed pair with the same normal equations (mlndt_pair_factor.h)");
DEFINE_string(output_dir, "", "Folder for trajectory_chained.txt and trajectory_joint.txt");
DEFINE_string(output_json, "", "Also write the JSON result to this file");
// clang-format on

namespace mlndt {
namespace {

int Fail(const std::string& message) {
  std::cerr << "mlndt_posegraph: " << message << std::endl;
  return tools::kExitFailed;
}

// A flag, argument or input refused before any work (tool_main.h).
int Refuse(const std::string& message) {
  std::cerr << "mlndt_posegraph: " << message << std::endl;
  return tools::kExitUsage;
}

// A world_from_scan pose in the layout Ceres optimises.
struct PoseBlocks {
  double rotation[4] = {0.0, 0.0, 0.0, 1.0};  // Eigen quaternion x, y, z, w.
  double translation[3] = {0.0, 0.0, 0.0};    // [m].

  static PoseBlocks From(const Isometry3d& world_from_scan) {
    PoseBlocks blocks;
    Eigen::Map<Eigen::Quaterniond>(blocks.rotation) =
        Eigen::Quaterniond(world_from_scan.linear()).normalized();
    Eigen::Map<Vector3d>(blocks.translation) = world_from_scan.translation();
    return blocks;
  }
  Isometry3d ToIsometry() const {
    Isometry3d out = Isometry3d::Identity();
    out.linear() = Eigen::Map<const Eigen::Quaterniond>(rotation)
                       .normalized()
                       .toRotationMatrix();
    out.translation() = Eigen::Map<const Vector3d>(translation);
    return out;
  }
};

// SPARSE_NORMAL_CHOLESKY when Ceres was built with a sparse library (Debian's
// 2.1 has SuiteSparse and CXSparse), else DENSE_QR: a pose-only problem has no
// point blocks to eliminate, so the Schur solvers bring nothing here.
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

struct JointResult {
  int residual_blocks = 0;    // Of the last stage.
  int directed_pairs = 0;     // (map of i, points of j) terms.
  int iterations = 0;         // Over all stages.
  double initial_cost = 0.0;  // First stage, at the chained poses.
  double final_cost = 0.0;    // Last stage.
  double chained_cost_last_stage =
      0.0;  // Last stage's objective at the chained poses.
  std::string termination;
  std::string linear_solver;
};

// Adds the pair residuals of every edge on layer `finest - offset` of each
// map. `poses` must stay in place while the Problem lives.
int AddEdges(const std::vector<LayeredGrid>& maps,
             const std::vector<PointCloud>& samples,
             const RegistrationOptions& options,
             int layer_offset,
             std::vector<PoseBlocks>* poses,
             ceres::Problem* problem) {
  const int n = static_cast<int>(maps.size());
  int directed_pairs = 0;
  const auto add = [&](int map_scan, int point_scan) {
    const LayeredGrid& map = maps[map_scan];
    const int layer = std::max(1, map.num_layers() - layer_offset);
    PoseBlocks& pose_i = (*poses)[map_scan];
    PoseBlocks& pose_j = (*poses)[point_scan];
    PairResidualOptions residuals;
    residuals.objective = options.objective;
    residuals.one_block_per_pair = !FLAGS_joint_point_blocks;
    AddMlNdtPairResiduals(map.layer(layer),
                          samples[point_scan].points(),
                          residuals,
                          pose_i.rotation,
                          pose_i.translation,
                          pose_j.rotation,
                          pose_j.translation,
                          problem);
    ++directed_pairs;
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j <= std::min(n - 1, i + FLAGS_neighbors); ++j) {
      add(i, j);
      if (!FLAGS_joint_one_way) add(j, i);
    }
  }
  return directed_pairs;
}

// Sum of the stage's cost at the given poses (the Problem's own objective).
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

// The joint solve's iterations on a progress bar whose total is the
// iteration cap of all stages (a stage that converges ends early).
class JointProgress : public ceres::IterationCallback {
 public:
  // `progress` must outlive the callback.
  JointProgress(tools::Progress* progress, size_t before, std::string stage)
      : progress_(progress), before_(before), stage_(std::move(stage)) {}

  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& summary) override {
    char cost[64];
    std::snprintf(cost, sizeof(cost), " cost %.6g", summary.cost);
    progress_->Update(before_ + static_cast<size_t>(summary.iteration),
                      stage_ + cost);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  tools::Progress* progress_;
  size_t before_;
  std::string stage_;
};

JointResult SolveJointly(const std::vector<LayeredGrid>& maps,
                         const std::vector<PointCloud>& samples,
                         const RegistrationOptions& options,
                         std::vector<PoseBlocks>* poses) {
  JointResult result;
  const std::vector<PoseBlocks> chained = *poses;
  const size_t stage_iterations =
      static_cast<size_t>(FLAGS_joint_max_iterations);
  tools::Progress progress(
      "mlndt_posegraph joint",
      static_cast<size_t>(FLAGS_joint_layers) * stage_iterations);
  for (int offset = FLAGS_joint_layers - 1; offset >= 0; --offset) {
    ceres::Problem problem;
    result.directed_pairs =
        AddEdges(maps, samples, options, offset, poses, &problem);
    problem.SetParameterBlockConstant((*poses)[0].rotation);
    problem.SetParameterBlockConstant((*poses)[0].translation);
    ceres::Solver::Options solver_options;
    ChooseLinearSolver(&solver_options);
    solver_options.max_num_iterations = FLAGS_joint_max_iterations;
    solver_options.num_threads = options.num_threads;
    const size_t stage = static_cast<size_t>(FLAGS_joint_layers - 1 - offset);
    JointProgress callback(&progress,
                           stage * stage_iterations,
                           "layer n-" + std::to_string(offset));
    solver_options.callbacks.push_back(&callback);
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options, &problem, &summary);
    progress.Finish();
    LOG(INFO) << "joint stage, layer n-" << offset << ": "
              << summary.BriefReport();
    if (offset == FLAGS_joint_layers - 1)
      result.initial_cost = summary.initial_cost;
    result.final_cost = summary.final_cost;
    result.iterations += static_cast<int>(summary.iterations.size()) - 1;
    result.residual_blocks = problem.NumResidualBlocks();
    result.termination =
        ceres::TerminationTypeToString(summary.termination_type);
    result.linear_solver =
        ceres::LinearSolverTypeToString(summary.linear_solver_type_used);
    if (offset == 0)
      result.chained_cost_last_stage = CostAt(&problem, poses, chained);
  }
  return result;
}

// trajectory_chained.txt and trajectory_joint.txt into `dir`.
bool WriteTrajectories(const std::string& dir,
                       const std::vector<Isometry3d>& chained,
                       const std::vector<Isometry3d>& joint,
                       std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    *error = dir + ": " + ec.message();
    return false;
  }
  return WriteKittiPoses(dir + "/trajectory_chained.txt", chained, error) &&
         WriteKittiPoses(dir + "/trajectory_joint.txt", joint, error);
}

// The settings and the joint problem's facts.
// stdout and --output_json (docs/json_schema.md, "mlndt_posegraph").
tools::Json JointJson(size_t num_scans,
                      const JointResult& joint_result,
                      int chained_failures) {
  using tools::Number;
  tools::Json json = tools::ToolJson("mlndt_posegraph");
  json["scans"] = num_scans;
  json["neighbors"] = FLAGS_neighbors;
  json["joint_layers"] = FLAGS_joint_layers;
  json["joint_both_directions"] = !FLAGS_joint_one_way;
  json["joint_point_blocks"] = FLAGS_joint_point_blocks;
  json["directed_pairs"] = joint_result.directed_pairs;
  json["residual_blocks"] = joint_result.residual_blocks;
  json["linear_solver"] = joint_result.linear_solver;
  json["chained_failures"] = chained_failures;
  json["joint_iterations"] = joint_result.iterations;
  json["joint_termination"] = joint_result.termination;
  json["joint_initial_cost"] = Number(joint_result.initial_cost);
  json["joint_cost_at_chained"] = Number(joint_result.chained_cost_last_stage);
  json["joint_final_cost"] = Number(joint_result.final_cost);
  return json;
}

// Reads every scan, builds its map once and samples its points once.
bool LoadScans(const RegistrationOptions& options,
               const std::vector<std::string>& paths,
               std::vector<PointCloud>* scans,
               std::vector<LayeredGrid>* maps,
               std::vector<PointCloud>* samples,
               std::string* error) {
  for (size_t i = 0; i < paths.size(); ++i) {
    if (!ReadPointCloud(paths[i], &(*scans)[i], nullptr, error)) return false;
    if (!LayeredGrid::Build(options.grid, (*scans)[i], &(*maps)[i], error)) {
      *error = paths[i] + ": map: " + *error;
      return false;
    }
    if (!SamplePoints(
            options.sampling, (*scans)[i], &(*samples)[i], nullptr, error)) {
      *error = paths[i] + ": sampling: " + *error;
      return false;
    }
  }
  return true;
}

// (a): scan i+1 registered onto scan i from the previous relative estimate;
// world_from_scan poses, scan 0 = world. A failed pair keeps the previous
// relative pose and is counted in *failures.
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
    LOG(INFO) << "scan " << i + 1 << " onto " << i << ": "
              << summary.BriefReport();
  }
  return chained;
}

int Run() {
  if (FLAGS_scans.empty()) return Refuse("--scans is required");
  if (FLAGS_neighbors < 1) return Refuse("--neighbors must be >= 1");
  if (FLAGS_joint_layers < 1 || FLAGS_joint_layers > 2)
    return Refuse("--joint_layers: 1 or 2");
  if (FLAGS_joint_max_iterations < 1)
    return Refuse("--joint_max_iterations must be >= 1");
  RegistrationOptions options;
  std::string error;
  if (!tools::RegistrationOptionsFromFlags(&options, &error)) {
    return Refuse(error +
                  " (the joint problem is built from ML-NDT residuals)");
  }
  if (!tools::CheckStartLayerBeforeMap(options, &error)) return Refuse(error);

  if (!tools::CheckOutputFile("output_json", FLAGS_output_json, &error)) {
    return Refuse(error);
  }
  if (!FLAGS_output_dir.empty() &&
      !tools::PrepareOutputDir(
          "output_dir",
          FLAGS_output_dir,
          {"trajectory_chained.txt", "trajectory_joint.txt"},
          &error)) {
    return Refuse(error);
  }
  std::vector<std::string> paths;
  if (!ListScanFiles(
          FLAGS_scans, {FLAGS_gt_poses, FLAGS_calib}, &paths, &error)) {
    return Refuse(error);
  }
  if (paths.size() < 2) return Refuse(FLAGS_scans + ": fewer than 2 scans");
  if (!tools::CheckCameraPoseFlags(
          "--gt_poses", !FLAGS_gt_poses.empty(), &error)) {
    return Refuse(error);
  }
  std::vector<Isometry3d> truth;
  if (!FLAGS_gt_poses.empty()) {
    if (!ReadSequencePoses(FLAGS_gt_poses, FLAGS_calib, &truth, &error)) {
      return Refuse(error);
    }
    if (truth.size() < paths.size()) {
      return Refuse(FLAGS_gt_poses + " has " + std::to_string(truth.size()) +
                    " poses for " + std::to_string(paths.size()) + " scans");
    }
    truth.resize(paths.size());
  }
  const size_t n = paths.size();
  const double start = NowSeconds();

  // Scans, maps (built once, shared by both stages) and samples.
  std::vector<PointCloud> scans(n), samples(n);
  std::vector<LayeredGrid> maps(n);
  if (!LoadScans(options, paths, &scans, &maps, &samples, &error)) {
    return Fail(error);
  }
  const double maps_done = NowSeconds();

  // (a) Chained pairwise registrations.
  int chained_failures = 0;
  const std::vector<Isometry3d> chained =
      ChainRegistrations(options, maps, scans, &chained_failures);
  const double chained_done = NowSeconds();
  std::vector<PointCloud>().swap(scans);  // The joint solve needs none.

  // (b) Joint refinement from the chained poses.
  std::vector<PoseBlocks> blocks;
  for (const Isometry3d& pose : chained)
    blocks.push_back(PoseBlocks::From(pose));
  const JointResult joint_result =
      SolveJointly(maps, samples, options, &blocks);
  std::vector<Isometry3d> joint;
  for (const PoseBlocks& b : blocks) joint.push_back(b.ToIsometry());
  const double joint_done = NowSeconds();

  if (!FLAGS_output_dir.empty() &&
      !WriteTrajectories(FLAGS_output_dir, chained, joint, &error)) {
    return Fail(error);
  }
  tools::Json json = JointJson(n, joint_result, chained_failures);
  if (!truth.empty() &&
      !tools::AddTrajectoryMetrics(chained, joint, truth, &json, &error)) {
    return Fail(error);
  }
  json["time_ms"] = {{"total", (joint_done - start) * 1e3},
                     {"maps", (maps_done - start) * 1e3},
                     {"chained", (chained_done - maps_done) * 1e3},
                     {"joint", (joint_done - chained_done) * 1e3}};
  std::cout << tools::JsonText(json);
  if (!FLAGS_output_json.empty() &&
      !tools::WriteJsonFile(FLAGS_output_json, json, &error)) {
    return Fail(error);
  }
  if (chained_failures > 0) {
    return Fail(std::to_string(chained_failures) +
                " chained registration(s) were not usable (they kept the "
                "previous relative pose): the trajectories are not to be "
                "used");
  }
  return tools::kExitOk;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Chained ML-NDT odometry and a joint refinement of all scan "
          "poses.\n"
          "  mlndt_posegraph --scans=DIR [--gt_poses=FILE] [--neighbors=2] "
          "[--output_dir=DIR]\n"
          "Exit 1 when a chained registration was not usable (LOW_QUALITY, "
          "DEGENERATE or FAILURE), after writing every file.",
          false,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
