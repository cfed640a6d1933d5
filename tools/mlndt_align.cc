// mlndt_align: registers one input scan onto a reference scan with ML-NDT
// (or, with --method=ndt, the conventional single-grid NDT baseline) and
// reports the pose, a per-iteration trace and timings (README's main job).
//
//   mlndt_align --reference=ref.pcd --input=in.pcd
//   [--initial_guess=tx,ty,tz,a,b,g]
//               [--output_json=result.json]
//
// Without --reference/--input it aligns the Velodyne pair bundled in data/
// and compares the result with the reference result shipped with it.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cstdio>
#include <fstream>
#include <iostream>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "tools/common/json_writer.h"
#include "tools/common/registration_flags.h"
#include "tools/common/tool_utils.h"

DEFINE_string(reference,
              "",
              "Reference scan (any format mlndt reads); default: bundled pair");
DEFINE_string(
    input,
    "",
    "Input scan, registered onto the reference; default: bundled pair");
DEFINE_string(initial_guess,
              "",
              "tx,ty,tz,alpha,beta,gamma: metres and degrees, R = Rx Ry Rz "
              "(ML-NDT Eq. 7)");
DEFINE_string(initial_matrix,
              "",
              "12 comma-separated numbers: row-major 3x4 matrix mapping input "
              "points into the "
              "reference frame");
DEFINE_string(expected_matrix_file,
              "",
              "Optional 3x4/4x4 text matrix to compare the result with "
              "(reference_from_input)");
DEFINE_string(output_json, "", "Write the result as JSON to this file");
DEFINE_string(output_cloud,
              "",
              "Write the input, moved into the reference frame (.pcd/.ply)");
DEFINE_bool(trace, false, "Print the per-iteration trace");

namespace mlndt {
namespace {

constexpr char kBundledReference[] = "koide3/251370668.pcd";
constexpr char kBundledInput[] = "koide3/251371071.pcd";
constexpr char kBundledExpected[] = "koide3/T_target_source.txt";

int Fail(const std::string& message) {
  std::cerr << "mlndt_align: " << message << std::endl;
  return 1;
}

bool InitialGuessFromFlags(Isometry3d* reference_from_input,
                           std::string* error) {
  if (!FLAGS_initial_guess.empty() && !FLAGS_initial_matrix.empty()) {
    *error = "give --initial_guess or --initial_matrix, not both";
    return false;
  }
  std::vector<double> v;
  if (!FLAGS_initial_guess.empty()) {
    if (!tools::ParseNumberList(FLAGS_initial_guess, &v) || v.size() != 6) {
      *error =
          "--initial_guess needs 6 comma-separated numbers "
          "tx,ty,tz,alpha,beta,gamma";
      return false;
    }
    *reference_from_input = PoseVectorToIsometry(
        PoseVectorFromDegrees(v[0], v[1], v[2], v[3], v[4], v[5]));
    return true;
  }
  if (!FLAGS_initial_matrix.empty()) {
    if (!tools::ParseNumberList(FLAGS_initial_matrix, &v) || v.size() != 12) {
      *error =
          "--initial_matrix needs 12 comma-separated numbers (row-major 3x4)";
      return false;
    }
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    for (int i = 0; i < 12; ++i) m(i / 4, i % 4) = v[static_cast<size_t>(i)];
    const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
    if ((r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-3 ||
        r.determinant() < 0) {
      *error = "--initial_matrix: the 3x3 part is not a rotation";
      return false;
    }
    reference_from_input->matrix() = m;
    // Re-orthonormalise the rotation read from text.
    reference_from_input->linear() =
        Eigen::Quaterniond(r).normalized().toRotationMatrix();
    return true;
  }
  *reference_from_input = Isometry3d::Identity();
  return true;
}

std::string MatrixJson(const Isometry3d& t) {
  std::vector<double> v;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) v.push_back(t.matrix()(r, c));
  }
  return tools::JsonArray(v);
}

std::string TraceJson(const RegistrationSummary& summary) {
  std::string out = "[";
  for (size_t i = 0; i < summary.trace.size(); ++i) {
    const IterationRecord& r = summary.trace[i];
    std::vector<double> pose(r.reference_from_input_xi.data(),
                             r.reference_from_input_xi.data() + 6);
    for (int a = 3; a < 6; ++a) pose[static_cast<size_t>(a)] *= kRadToDeg;
    tools::JsonObject o;
    o.AddNumber("iteration", r.iteration)
        .AddNumber("layer", r.layer)
        .AddNumber("score", r.score)
        .AddNumber("step_norm", r.step_norm)
        .AddBool("step_is_successful", r.step_is_successful)
        .Add("pose", tools::JsonArray(pose))
        .AddNumber("time_ms", r.time_s * 1e3);
    out += (i ? ", " : "") + o.str();
  }
  return out + "]";
}

int Run() {
  const bool bundled = FLAGS_reference.empty() && FLAGS_input.empty();
  if (FLAGS_reference.empty() != FLAGS_input.empty()) {
    return Fail(
        "give both --reference and --input, or neither (to align the bundled "
        "pair)");
  }
  const std::string data_dir = MLNDT_DATA_DIR;
  const std::string reference_path =
      bundled ? data_dir + "/" + kBundledReference : FLAGS_reference;
  const std::string input_path =
      bundled ? data_dir + "/" + kBundledInput : FLAGS_input;
  std::string expected_path = FLAGS_expected_matrix_file;
  if (bundled && expected_path.empty())
    expected_path = data_dir + "/" + kBundledExpected;

  RegistrationOptions options;
  std::string error;
  if (!tools::RegistrationOptionsFromFlags(&options, &error))
    return Fail(error);
  Isometry3d initial = Isometry3d::Identity();
  if (!InitialGuessFromFlags(&initial, &error)) return Fail(error);
  Isometry3d expected = Isometry3d::Identity();
  if (!expected_path.empty() &&
      !tools::ReadMatrixFile(expected_path, &expected, &error)) {
    return Fail(error);
  }

  PointCloud reference, input;
  ReadCloudInfo reference_info, input_info;
  if (!ReadPointCloud(reference_path, &reference, &reference_info, &error))
    return Fail(error);
  if (!ReadPointCloud(input_path, &input, &input_info, &error))
    return Fail(error);

  RegistrationSummary summary;
  Register(options, reference, input, initial, &summary);

  std::cout << "reference: " << reference_path << " (" << reference.size()
            << " points)\n"
            << "input:     " << input_path << " (" << input.size()
            << " points)\n"
            << summary.FullReport();
  const double peak_bytes = tools::PeakResidentBytes();
  std::printf(
      "  peak memory:    %.1f MB resident (the process, clouds included)\n",
      peak_bytes / 1e6);
  if (FLAGS_trace) {
    for (const IterationRecord& r : summary.trace) {
      std::printf("  iter %2d layer %d score %12.2f step %.2e %s\n",
                  r.iteration,
                  r.layer,
                  r.score,
                  r.step_norm,
                  r.step_is_successful ? "" : "(rejected)");
    }
  }
  double translation_error = -1, rotation_error_deg = -1;
  if (!expected_path.empty()) {
    translation_error =
        TranslationErrorM(expected, summary.reference_from_input);
    rotation_error_deg =
        RotationErrorRad(expected, summary.reference_from_input) * kRadToDeg;
    std::printf("  vs expected:    %.4f m, %.4f deg (%s)\n",
                translation_error,
                rotation_error_deg,
                expected_path.c_str());
  }

  if (!FLAGS_output_json.empty()) {
    tools::JsonObject json;
    json.AddString("reference", reference_path)
        .AddString("input", input_path)
        .AddString("method", MethodToString(summary.method))
        .Add("reference_from_input", MatrixJson(summary.reference_from_input))
        .AddBool("converged",
                 summary.termination_type == TerminationType::CONVERGENCE)
        .AddString("termination",
                   TerminationTypeToString(summary.termination_type))
        .AddString("message", summary.message)
        .AddNumber("iterations", summary.num_iterations)
        .Add("iterations_per_layer",
             tools::JsonArray(summary.iterations_per_layer))
        .AddNumber("start_layer", summary.start_layer)
        .AddNumber("num_layers", summary.num_layers)
        .AddNumber("score", summary.final_score)
        .AddNumber("initial_score", summary.initial_score)
        .AddNumber("sampled_points",
                   static_cast<double>(summary.sampled_points))
        .AddNumber("matched_points",
                   static_cast<double>(summary.matched_points))
        .AddNumber("unmatched_points",
                   static_cast<double>(summary.unmatched_points))
        .Add("time_ms",
             tools::JsonObject()
                 .AddNumber("total", summary.total_time_s * 1e3)
                 .AddNumber("map", summary.map_time_s * 1e3)
                 .AddNumber("sampling", summary.sampling_time_s * 1e3)
                 .AddNumber("solve", summary.solve_time_s * 1e3)
                 .str())
        .Add("memory",
             tools::JsonObject()
                 .AddNumber("map_bytes", static_cast<double>(summary.map_bytes))
                 .AddNumber("map_occupied_cells",
                            static_cast<double>(summary.map_occupied_cells))
                 .AddNumber("peak_resident_bytes", peak_bytes)
                 .str())
        .Add("covariance",
             tools::JsonArray(std::vector<double>(
                 summary.covariance.data(), summary.covariance.data() + 36)))
        .Add("trace", TraceJson(summary));
    if (!expected_path.empty()) {
      json.AddNumber("translation_error_m", translation_error)
          .AddNumber("rotation_error_deg", rotation_error_deg);
    }
    if (!WriteFileAtomically(FLAGS_output_json, json.str() + "\n", &error)) {
      return Fail(error);
    }
  }
  if (!FLAGS_output_cloud.empty() &&
      !WritePointCloud(FLAGS_output_cloud,
                       TransformCloud(summary.reference_from_input, input),
                       &error)) {
    return Fail(error);
  }
  return summary.IsSolutionUsable()
             ? 0
             : Fail("registration failed: " + summary.message);
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "Registers --input onto --reference with ML-NDT (--method=mlndt) or NDT "
      "(--method=ndt).\n"
      "  mlndt_align --reference=ref.pcd --input=in.pcd "
      "[--initial_guess=tx,ty,tz,a,b,g]");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  google::InitGoogleLogging(argv[0]);
  FLAGS_logtostderr = true;
  if (argc > 1) {
    std::cerr << "mlndt_align: unexpected argument '" << argv[1]
              << "' (flags are --name=value)\n";
    return 1;
  }
  return mlndt::Run();
}
