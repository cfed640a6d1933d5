// The tools' own option tables against their flags (tools/cli/
// table_flags.h): every field of every table in ToolTableFlags() (nested
// structs' fields too) has a flag named as the field's path (or as listed),
// registered as the tool's, whose --help is the field's FullHelp and whose
// default is the struct's, or a shared flag of the same option (type, unit,
// range and default); no flag of the tool's table is undescribed; a flag
// given, or its older name, lands in its field; a value out of range is
// refused naming the flag as given. The flags mlndt_sequence, mlndt_suite
// and mlndt_bench still define by hand are listed, each with the reason it
// is not a table flag.

#include <gflags/gflags.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "lab/bench/bench.h"
#include "lab/eval/suite_plan.h"
#include "lab/eval/trajectory_evaluation.h"
#include "lab/runs/adaptive_start_layer.h"
#include "lab/runs/pose_graph.h"
#include "lab/runs/sequence_registration.h"
#include "mlndt/odometry/odometry_options.h"
#include "mlndt/pipeline/localizer.h"
#include "mlndt/pipeline/map_builder.h"
#include "mlndt/pipeline/pipeline_option_tables.h"
#include "tools/cli/bench_flags.h"
#include "tools/cli/localizer_flags.h"
#include "tools/cli/map_build_flags.h"
#include "tools/cli/odometry_flags.h"
#include "tools/cli/option_flags.h"
#include "tools/cli/pose_graph_flags.h"
#include "tools/cli/sequence_flags.h"
#include "tools/cli/tool_main.h"
#include "tools/cli/tool_table_flags.h"
#include "tools/cli/trajectory_evaluation_flags.h"

namespace mlndt {
namespace {

using tools::TableFlags;
using tools::ToolTableFlags;

// gflags writes a double default its own way; compare values.
void ExpectSameDefault(const std::string& flag_default,
                       const TableFlags& flags,
                       const TableFlags::Field& f,
                       const std::string& what) {
  const OptionField& field = *f.field;
  const std::string field_default =
      field.Format(flags.Owner(f.path, flags.table().defaults()));
  if (field.type == OptionType::DOUBLE) {
    EXPECT_EQ(std::stod(flag_default), std::stod(field_default)) << what;
  } else {
    EXPECT_EQ(flag_default, field_default) << what;
  }
}

bool Listed(const TableFlags::Names& names, const std::string& field) {
  for (const auto& [name, flag] : names) {
    if (name == field) return true;
  }
  return false;
}

// A field read from a shared flag is the same option as the flag's.
void ExpectSameOption(const OptionField& field, const std::string& flag) {
  const OptionField& shared = *tools::FlagOfName(flag)->field;
  EXPECT_EQ(shared.type, field.type) << flag;
  EXPECT_EQ(shared.unit, field.unit) << flag;
  EXPECT_EQ(shared.RangeText(), field.RangeText())
      << "--" << flag << " is another option's flag: give " << field.name
      << " another flag name";
}

TEST(ToolOptionFlags, EveryToolTableIsListed) {
  std::set<std::string> tables;
  for (const TableFlags* flags : ToolTableFlags()) {
    tables.insert(flags->table().struct_name());
  }
  EXPECT_EQ(tables,
            (std::set<std::string>{"MapBuildOptions",
                                   "LocalizerOptions",
                                   "OdometryOptions",
                                   "TrajectoryEvaluationOptions",
                                   "PoseGraphOptions",
                                   "AdaptiveStartLayerOptions",
                                   "SequenceOptions",
                                   "SuitePlanOptions",
                                   "BenchOptions"}));
}

TEST(ToolOptionFlags, EveryFieldHasItsFlagHelpAndDefault) {
  for (const TableFlags* flags : ToolTableFlags()) {
    for (const TableFlags::Field& f : flags->fields()) {
      const OptionField& field = *f.field;
      const std::string what = flags->table().struct_name() + "." + f.path;
      const std::string flag = flags->FlagOf(f.path);
      if (flag.empty()) {
        EXPECT_TRUE(Listed(flags->set_by_tool_flag(), f.path)) << what;
        continue;
      }
      if (!Listed(flags->renamed(), f.path)) {
        std::string underscored = f.path;
        std::replace(underscored.begin(), underscored.end(), '.', '_');
        EXPECT_EQ(flag, underscored) << what;
      }
      gflags::CommandLineFlagInfo info;
      ASSERT_TRUE(gflags::GetCommandLineFlagInfo(flag.c_str(), &info))
          << what << ": --" << flag << " is not registered";
      ExpectSameDefault(info.default_value, *flags, f, what);
      if (tools::FlagOfName(flag) != nullptr) {  // Shared: its help.
        ExpectSameOption(field, flag);
        continue;
      }
      EXPECT_EQ(info.description, field.FullHelp()) << what;
      EXPECT_EQ(info.filename, tools::MainFile(flags->tool())) << what;
    }
  }
}

// A tool may have flags from more than one table (mlndt_sequence).
TEST(ToolOptionFlags, NoFlagOfATableIsUndescribed) {
  std::map<std::string, std::set<std::string>> expected;
  for (const TableFlags* flags : ToolTableFlags()) {
    for (const std::string& flag : flags->RegisteredFlags()) {
      expected[flags->tool()].insert(flag);
    }
  }
  std::vector<gflags::CommandLineFlagInfo> all;
  gflags::GetAllFlags(&all);
  for (const auto& [tool, flags] : expected) {
    std::set<std::string> registered;
    for (const gflags::CommandLineFlagInfo& info : all) {
      if (info.filename == tools::MainFile(tool)) {
        registered.insert(info.name);
      }
    }
    EXPECT_EQ(registered, flags) << tool;
  }
}

// A valid value of the field other than its default `current`.
std::string OtherValue(const OptionField& field, const std::string& current) {
  if (field.type == OptionType::BOOL) {
    return current == "true" ? "false" : "true";
  }
  if (field.type == OptionType::ENUM) {
    for (const EnumTable::Name& name : field.enum_table->names()) {
      std::string lower = name.name;
      for (char& c : lower) c = static_cast<char>(std::tolower(c));
      if (lower != current) return lower;
    }
  }
  const double value = std::stod(current);
  for (const double v : {field.range.hi, field.range.lo, value + 1}) {
    if (std::isfinite(v) && v != value &&
        (!field.has_range || field.range.Contains(v))) {
      std::ostringstream out;
      out.precision(17);
      out << v;
      return out.str();
    }
  }
  return "";
}

// One default-constructed struct of each tool table.
struct ToolStructs {
  MapBuildOptions map;
  LocalizerOptions localizer;
  OdometryOptions odometry;
  TrajectoryEvaluationOptions evaluation;
  AdaptiveStartLayerOptions adaptive;
  PoseGraphOptions pose_graph;
  SequenceOptions sequence;
  SuitePlanOptions suite_plan;
  BenchOptions bench;

  void* Of(const std::string& struct_name) {
    if (struct_name == "SequenceOptions") return &sequence;
    if (struct_name == "SuitePlanOptions") return &suite_plan;
    if (struct_name == "BenchOptions") return &bench;
    if (struct_name == "MapBuildOptions") return &map;
    if (struct_name == "LocalizerOptions") return &localizer;
    if (struct_name == "TrajectoryEvaluationOptions") return &evaluation;
    if (struct_name == "AdaptiveStartLayerOptions") return &adaptive;
    if (struct_name == "PoseGraphOptions") return &pose_graph;
    EXPECT_EQ(struct_name, "OdometryOptions");
    return &odometry;
  }
};

// Gives --<flag>=<other value> (or its older name `given`) and expects
// Apply to set field f.
void ExpectFlagSetsField(const TableFlags& flags,
                         const TableFlags::Field& f,
                         const std::string& given) {
  const OptionField& field = *f.field;
  const std::string current =
      field.Format(flags.Owner(f.path, flags.table().defaults()));
  const std::string value = OtherValue(field, current);
  gflags::FlagSaver saver;
  ASSERT_FALSE(
      gflags::SetCommandLineOption(given.c_str(), value.c_str()).empty())
      << given << "=" << value;
  ToolStructs structs;
  void* s = structs.Of(flags.table().struct_name());
  std::string error;
  ASSERT_TRUE(flags.Apply(s, &error)) << error;
  EXPECT_NE(field.Format(flags.Owner(f.path, s)), current)
      << "--" << given << "=" << value << " did not reach " << f.path;
}

TEST(ToolOptionFlags, AGivenFlagSetsItsField) {
  for (const TableFlags* flags : ToolTableFlags()) {
    for (const TableFlags::Field& f : flags->fields()) {
      const std::string flag = flags->FlagOf(f.path);
      if (!flag.empty()) ExpectFlagSetsField(*flags, f, flag);
    }
  }
}

// Version 0.x dropped the flags' older names (issue 46): none of them is
// registered, so a tool refuses each as an unknown flag (exit 2).
TEST(ToolOptionFlags, OlderNamesAreGone) {
  const char* kDropped[] = {
      // Shared registration flags.
      "threads",
      "unmatched",
      "gbs_cell_size",
      "min_eigenvalue",
      "finest_cell_size",
      "max_iterations",
      "linear_solver",
      "trust_region",
      "min_range",
      "max_range",
      "ndt_cell_size",
      "ndt_max_step",
      "retry_yaw_seeds",
      // mlndt_odometry.
      "local_map_keyframes",
      "local_map_radius",
      "keyframe_distance",
      "keyframe_angle",
      "max_uncertainty_m",
      "max_uncertainty_deg",
      "confirm",
      "confirm_fraction",
      "confirm_last_scan",
      // mlndt_eval.
      "max_time_difference",
      "segment_lengths",
      "segment_step",
      // mlndt_posegraph (--joint_one_way was --both_directions=false).
      "joint_point_blocks",
      "odometry_sigma_m",
      "odometry_sigma_deg",
      "joint_one_way",
      // mlndt_sequence.
      "adaptive_max_translation",
      "adaptive_max_rotation",
      "adaptive_fail_rates",
      // mlndt_bench.
      "compare_pcl",
      "max_translation_error",
      "max_rotation_error",
      "pcl_leaf_size",
      "pcl_resolution",
      "pcl_step_size",
      "pcl_transformation_epsilon",
      "pcl_max_iterations",
      "pcl_gicp_max_correspondence_distance"};
  for (const char* name : kDropped) {
    gflags::CommandLineFlagInfo info;
    EXPECT_FALSE(gflags::GetCommandLineFlagInfo(name, &info))
        << "--" << name << " is still registered (" << info.filename << ")";
  }
}

TEST(ToolOptionFlags, ValuesOutOfRangeNameTheFlag) {
  MapBuildOptions options;
  std::string error;
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("voxel_size", "0.3");
    ASSERT_TRUE(tools::MapBuildFlags().Apply(&options, &error)) << error;
    EXPECT_EQ(options.voxel_size_m, 0.3);
    gflags::SetCommandLineOption("voxel_size", "-1");
    EXPECT_FALSE(tools::MapBuildFlags().Apply(&options, &error));
    EXPECT_EQ(error, "--voxel_size must be in [0.001, 1000] or 0 (m), not -1");
  }
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("num_threads", "0");
    EXPECT_FALSE(tools::MapBuildFlags().Apply(&options, &error));
    EXPECT_EQ(error, "--num_threads must be in [1, 256], not 0");
  }
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("motion_model", "kalman");
    LocalizerOptions localizer;
    EXPECT_FALSE(tools::LocalizerFlags().Apply(&localizer, &error));
    EXPECT_EQ(error,
              "--motion_model=kalman: expected constant_velocity or "
              "constant_pose");
  }
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("prediction_max_rotation_deg", "200");
    OdometryOptions odometry;
    EXPECT_FALSE(tools::OdometryFlags().Apply(&odometry, &error));
    EXPECT_EQ(
        error,
        "--prediction_max_rotation_deg must be in [0, 180] (deg), not 200");
    gflags::SetCommandLineOption("prediction_max_rotation_deg", "20");
    ASSERT_TRUE(tools::OdometryFlags().Apply(&odometry, &error)) << error;
    EXPECT_EQ(odometry.prediction.max_rotation_deg, 20.0);
  }
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("max_time_difference_s", "0");
    TrajectoryEvaluationOptions evaluation;
    EXPECT_FALSE(tools::TrajectoryEvaluationFlags().Apply(&evaluation, &error));
    EXPECT_EQ(error, "--max_time_difference_s must be > 0 (s), not 0");
    gflags::SetCommandLineOption("alignment", "affine");
    gflags::SetCommandLineOption("max_time_difference_s", "0.1");
    EXPECT_FALSE(tools::TrajectoryEvaluationFlags().Apply(&evaluation, &error));
    EXPECT_EQ(error,
              "--alignment=affine: expected se3, sim3, first_pose or none");
  }
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("step", "0");
    SequenceOptions sequence;
    EXPECT_FALSE(tools::SequenceFlags().Apply(&sequence, &error));
    EXPECT_EQ(error, "--step must be >= 1, not 0");
    gflags::SetCommandLineOption("pcl_ndt_resolution_m", "0");
    BenchOptions bench;
    EXPECT_FALSE(tools::BenchFlags().Apply(&bench, &error));
    EXPECT_EQ(error, "--pcl_ndt_resolution_m must be in (0, 1e+09] (m), not 0");
  }
}

}  // namespace
}  // namespace mlndt
