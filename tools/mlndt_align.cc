// mlndt_align: registers one input scan onto a reference scan with ML-NDT
// (or, with --method=ndt, the conventional single-grid NDT baseline) and
// reports the pose, a per-iteration trace and timings (README's main job).
//
//   mlndt_align REF IN [--initial_guess=tx,ty,tz,a,b,g] [--output_json=FILE]
//   mlndt_align --reference=REF --input=IN ...
//
// Without a reference and an input it aligns the Velodyne pair bundled in
// data/ and compares the result with the reference result shipped with it.
// stdout ends with the result's reference_from_input as a 4x4 matrix (4
// lines of 4 numbers). --output_json (docs/json_schema.md) is written for
// every registration that ran, trusted or not; --output_cloud only for an
// accepted result. A FAILURE prints no matrix (its pose is no estimate),
// and a cloud with fewer points than one NDT cell needs is refused. Exit
// codes (tool_main.h): 0 the result is accepted (verdict_flags.h), 1
// FAILURE or a result not to be trusted, 2 a flag or an input refused
// before any work.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "lab/runs/matcher.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "tools/cli/align_output.h"
#include "tools/cli/json_output.h"
#include "tools/cli/map_inputs.h"
#include "tools/cli/matrix_text.h"
#include "tools/cli/output_files.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/start_layer_check.h"
#include "tools/cli/tool_main.h"
#include "tools/cli/tool_utils.h"
#include "tools/cli/verdict_flags.h"

// clang-format off
DEFINE_string(reference, "",
              "Reference scan (any format mlndt reads; or the first positional argument); "
              "default: the bundled pair");
DEFINE_string(input, "",
              "Input scan, registered onto the reference (or the second positional argument); "
              "default: the bundled pair");
DEFINE_string(initial_guess, "",
              "Initial reference_from_input: tx,ty,tz,alpha,beta,gamma (m, deg; R = Rx Ry Rz, "
              "ML-NDT Eq. 7)");
DEFINE_string(initial_matrix, "",
              "Initial reference_from_input: 12 comma-separated numbers, a row-major 3x4 matrix");
DEFINE_string(expected_matrix_file, "",
              "Optional 3x4/4x4 text matrix to compare the result with (reference_from_input)");
DEFINE_string(output_json, "",
              "Write the result as JSON to this file (docs/json_schema.md, mlndt_align)");
DEFINE_string(output_cloud, "",
              "Write the input, moved into the reference frame (.pcd/.ply); only for an "
              "accepted result (exit 0)");
DEFINE_bool(trace, false, "Print the per-iteration trace");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_align";
constexpr char kBundledReference[] = "koide3/251370668.pcd";
constexpr char kBundledInput[] = "koide3/251371071.pcd";
constexpr char kBundledExpected[] = "koide3/T_target_source.txt";

// The bundled pair's folder: share/mlndt/data beside the executable's
// folder (tools/CMakeLists.txt puts it there in the build tree and in the
// installation).
std::string BundledDataDir() {
  std::error_code error;  // Without /proc: relative to the working folder.
  const std::filesystem::path exe =
      std::filesystem::read_symlink("/proc/self/exe", error);
  return (exe.parent_path().parent_path() / "share/mlndt/data/").string();
}

struct Inputs {
  std::string reference;
  std::string input;
  std::string expected;
};

// REF IN as positional arguments or as --reference/--input; the bundled
// pair (and its expected result) without either.
bool InputsFromCommandLine(int argc, char** argv, Inputs* in, std::string* e) {
  if (argc > 1 && (!FLAGS_reference.empty() || !FLAGS_input.empty())) {
    *e = "give the scans as REF IN or as --reference/--input, not both";
    return false;
  }
  if (argc > 3) {
    *e = std::string("unexpected argument '") + argv[3] +
         "' (usage: mlndt_align REF IN [--flags])";
    return false;
  }
  if (argc == 2) {
    *e = "give both the reference and the input (REF IN), or neither (to "
         "align the bundled pair)";
    return false;
  }
  in->reference = argc == 3 ? argv[1] : FLAGS_reference;
  in->input = argc == 3 ? argv[2] : FLAGS_input;
  if (in->reference.empty() != in->input.empty()) {
    *e = "give both --reference and --input, or neither (to align the "
         "bundled pair)";
    return false;
  }
  in->expected = FLAGS_expected_matrix_file;
  if (in->reference.empty()) {
    const std::string data_dir = BundledDataDir();
    in->reference = data_dir + kBundledReference;
    in->input = data_dir + kBundledInput;
    if (in->expected.empty()) in->expected = data_dir + kBundledExpected;
  }
  return true;
}

// The flags and files checked before the clouds are read: the matcher,
// the start pose, the outputs and the expected matrix.
bool CheckFlags(MatcherOptions* options,
                Isometry3d* initial,
                Isometry3d* expected,
                const Inputs& in,
                std::string* error) {
  if (!tools::MatcherOptionsFromFlags(options, error)) return false;
  if (options->method == Method::MLNDT &&
      !tools::CheckStartLayerBeforeMap(options->mlndt, error)) {
    return false;
  }
  bool guess_given = false;
  if (!tools::ParseInitialPose(FLAGS_initial_guess,
                               FLAGS_initial_matrix,
                               initial,
                               &guess_given,
                               error) ||
      !tools::CheckOutputFile("output_json", FLAGS_output_json, error) ||
      !tools::CheckOutputFile("output_cloud", FLAGS_output_cloud, error)) {
    return false;
  }
  if (!FLAGS_output_cloud.empty() &&
      !CanWritePointCloud(FLAGS_output_cloud, error)) {
    *error = "--output_cloud: " + *error;
    return false;
  }
  return in.expected.empty() ||
         tools::ReadMatrixFile(in.expected, expected, error);
}

int Run(int argc, char** argv) {
  Inputs in;
  MatcherOptions options;
  Isometry3d initial = Isometry3d::Identity();
  Isometry3d expected = Isometry3d::Identity();
  std::string error;
  if (!InputsFromCommandLine(argc, argv, &in, &error) ||
      !CheckFlags(&options, &initial, &expected, in, &error)) {
    return tools::Refuse(kTool, error);
  }

  PointCloud reference, input;
  if (!ReadPointCloud(in.reference, &reference, nullptr, &error) ||
      !ReadPointCloud(in.input, &input, nullptr, &error)) {
    return tools::Refuse(kTool, error);
  }
  if (!tools::CheckCloudSizes(
          options, in.reference, reference, in.input, input, &error) ||
      (options.method == Method::MLNDT &&
       !tools::CheckStartLayerForReference(options.mlndt, reference, &error))) {
    return tools::Refuse(kTool, error);
  }

  RegistrationSummary summary;
  RegisterWithMatcher(options, reference, input, initial, &summary);
  // The map's layer count is known now; a start layer beyond it was
  // clamped by the library: refuse the result instead.
  if (options.method == Method::MLNDT && summary.num_layers > 0 &&
      !tools::CheckStartLayerForMap(
          options.mlndt.schedule, summary.num_layers, &error)) {
    return tools::Refuse(kTool, error + " (nothing written)");
  }

  const double peak_bytes = tools::PeakResidentBytes();
  double translation_error = NAN, rotation_error_deg = NAN;
  tools::PrintAlignResult(in.reference,
                          reference.size(),
                          in.input,
                          input.size(),
                          summary,
                          peak_bytes,
                          FLAGS_trace,
                          in.expected,
                          expected,
                          &translation_error,
                          &rotation_error_deg);
  if (!FLAGS_output_json.empty() &&
      !tools::WriteJsonFile(FLAGS_output_json,
                            tools::AlignResultJson(in.reference,
                                                   in.input,
                                                   in.expected,
                                                   options.method,
                                                   summary,
                                                   peak_bytes,
                                                   translation_error,
                                                   rotation_error_deg),
                            &error)) {
    return tools::Fail(kTool, error);
  }
  if (!tools::AcceptedResult(summary.termination_type)) {
    return tools::Fail(
        kTool, tools::UnacceptedResultMessage(summary, FLAGS_output_cloud));
  }
  if (!FLAGS_output_cloud.empty() &&
      !WritePointCloud(FLAGS_output_cloud,
                       TransformCloud(summary.reference_from_input, input),
                       &error)) {
    return tools::Fail(kTool, error);
  }
  return tools::kExitOk;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  const std::string usage =
      std::string(
          "registers the input scan onto the reference with ML-NDT "
          "(--method=mlndt) or NDT (--method=ndt) and prints the pose, "
          "ending with reference_from_input as a 4x4 matrix.\n\n"
          "Usage:\n"
          "  mlndt_align REF IN [--initial_guess=tx,ty,tz,a,b,g] "
          "[--output_json=FILE] [--output_cloud=FILE] [registration flags]\n"
          "  mlndt_align --reference=REF --input=IN [...]\n"
          "  mlndt_align   (the bundled koide3 pair, compared with its "
          "reference result)\n\n") +
      mlndt::tools::kExitCodesHelp;
  mlndt::tools::RefuseUnreadFlags(
      {"bag", "topic", "times", "calib", "poses_are_camera"},
      "does not apply to mlndt_align (it registers two clouds: give them as "
      "REF IN)");
  if (!mlndt::tools::StartTool(usage.c_str(), false, &argc, &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run(argc, argv);
}
