// The nodes' parameters are the tools' flags: same names, same defaults,
// same meaning, and bad values are refused at start naming the parameter.
#include <gflags/gflags.h>
#include <gtest/gtest.h>

#include "integrations/ros/core/localizer_parameters.h"
#include "integrations/ros/core/odometry_parameters.h"
#include "tools/cli/odometry_flags.h"

namespace mlndt {
namespace ros_core {
namespace {

bool IsNodeSetting(const OptionParameter& p) {
  return p.targets.front().root == 2;
}

// Every option parameter of the odometry node is a flag of mlndt_odometry
// (registered with gflags by the tools' code this test links) with the
// same default (the tables' defaults: the registration's; the odometry's
// OdometryRegistrationOptions() differs in --max_flatness,
// --weak_direction_rounds and --max_mean_score, which mlndt_odometry shows
// at start with ShowRegistrationDefaults and the node starts from); and
// every flag made from the tables is a parameter.
TEST(OdometryParameters, AreMlndtOdometrysFlagsWithTheirDefaults) {
  const OptionParameters& parameters = OdometryOptionParameters();
  const tools::TableFlags& own = tools::OdometryFlags();
  size_t checked = 0;
  for (const OptionParameter& p : parameters.parameters()) {
    if (IsNodeSetting(p)) {
      gflags::CommandLineFlagInfo info;
      EXPECT_FALSE(gflags::GetCommandLineFlagInfo(p.name.c_str(), &info))
          << p.name << " is a node setting and a flag";
      continue;
    }
    gflags::CommandLineFlagInfo info;
    ASSERT_TRUE(gflags::GetCommandLineFlagInfo(p.name.c_str(), &info))
        << "~" << p.name << " is no flag of the tools";
    if (p.field->type == OptionType::DOUBLE) {
      EXPECT_EQ(std::stod(parameters.DefaultText(p)),
                std::stod(info.default_value))
          << p.name;
    } else {
      EXPECT_EQ(parameters.DefaultText(p), info.default_value) << p.name;
    }
    ++checked;
  }
  for (const std::string& flag : own.RegisteredFlags()) {
    EXPECT_NE(parameters.Find(flag), nullptr) << flag;
  }
  for (const char* flag : {"sampling",
                           "backend",
                           "newton_line_search",
                           "finest_cell_size_m",
                           "gate_factor",
                           "local_map_max_keyframes",
                           "max_flatness"}) {
    EXPECT_NE(parameters.Find(flag), nullptr) << flag;
  }
  EXPECT_GT(checked, 60u);
}

TEST(OdometryParameters, SetTheFieldsTheFlagsSet) {
  MapParameterSource source({{"gate_factor", "4.5"},
                             {"local_map_max_keyframes", "4"},
                             {"finest_cell_size_m", "0.75"},
                             {"max_flatness", "0.5"},
                             {"sampling", "random"},
                             {"yaw_seeds_deg", "90,-90"},
                             {"local_map_period_s", "0"},
                             {"odom_frame", "world"}});
  OdometryNodeOptions options;
  std::string error;
  ASSERT_TRUE(OdometryNodeOptionsFromParameters(source, &options, &error))
      << error;
  const OdometryOptions& o = options.odometry;
  EXPECT_EQ(o.gate_factor, 4.5);
  EXPECT_EQ(o.local_map.max_keyframes, 4);
  // The grid parameters shape the local map, as --finest_cell_size_m does.
  EXPECT_EQ(o.registration.grid.finest_cell_size_m, 0.75);
  EXPECT_EQ(o.local_map.grid.finest_cell_size_m, 0.75);
  // --max_flatness sets the registration's field.
  EXPECT_EQ(o.registration.quality_check.max_flatness, 0.5);
  EXPECT_EQ(o.registration.sampling.method, SamplingMethod::RANDOM);
  EXPECT_EQ(o.registration.retry.yaw_seeds_deg,
            (std::vector<double>{90.0, -90.0}));
  EXPECT_EQ(options.node.local_map_period_s, 0.0);
  EXPECT_EQ(options.odom_frame, "world");
  EXPECT_EQ(options.sensor_frame, "");

  // Nothing given: the library's and the tool's defaults.
  OdometryNodeOptions defaults;
  ASSERT_TRUE(OdometryNodeOptionsFromParameters(
      MapParameterSource(), &defaults, &error))
      << error;
  // The registration's: the odometry's preset (OdometryRegistrationOptions).
  EXPECT_EQ(defaults.odometry.registration.quality_check.max_flatness,
            OdometryRegistrationOptions().quality_check.max_flatness);
  EXPECT_EQ(defaults.odometry.registration.quality_check.max_mean_score,
            OdometryRegistrationOptions().quality_check.max_mean_score);
  EXPECT_EQ(defaults.odometry.registration.num_threads, 1);
  EXPECT_EQ(defaults.odom_frame, "odom");
}

// Each bad parameter stops the start with a message naming it.
TEST(OdometryParameters, RefuseBadValuesNamingTheParameter) {
  const std::vector<std::pair<std::map<std::string, std::string>, std::string>>
      cases = {
          {{{"gate_factor", "0.5"}}, "~gate_factor=0.5: must be"},
          {{{"gate_factor", "fast"}}, "~gate_factor=fast: expected"},
          {{{"sampling", "sideways"}}, "~sampling=sideways"},
          {{{"local_map_max_keyframes", "0"}}, "~local_map_max_keyframes=0"},
          {{{"queue_size", "0"}}, "~queue_size=0: must be"},
          {{{"local_map_period_s", "-1"}}, "~local_map_period_s=-1"},
          {{{"gate_factr", "3"}}, "~gate_factr is not a parameter"},
          {{{"method", "ndt"}}, "~method is not a parameter"},
          {{{"preset", "fast"}}, "~preset=fast: expected default or paper"},
          {{{"odom_frame", ""}}, "~odom_frame must be"},
      };
  for (const auto& [values, expected] : cases) {
    OdometryNodeOptions options;
    std::string error;
    EXPECT_FALSE(OdometryNodeOptionsFromParameters(
        MapParameterSource(values), &options, &error))
        << expected;
    EXPECT_NE(error.find(expected), std::string::npos)
        << "got: " << error << "\nexpected: " << expected;
  }
}

TEST(LocalizerParameters, AreMlndtLocalizesFlagsButTheMaps) {
  MapParameterSource source({{"map", "/maps/campus.mlndt"},
                             {"motion_model", "constant_pose"},
                             {"initial_guess", "1,2,0.5,0,0,90"},
                             {"initial_uncertainty", "0.5,5"},
                             {"preset", "paper"},
                             {"max_final_iterations", "12"},
                             {"tf_timeout_s", "0.25"},
                             {"odom_frame", ""}});
  LocalizerNodeOptions options;
  std::string error;
  ASSERT_TRUE(LocalizerNodeOptionsFromParameters(source, &options, &error))
      << error;
  const LocalizerOptions& o = options.localizer;
  EXPECT_EQ(options.map_path, "/maps/campus.mlndt");
  EXPECT_EQ(o.motion_model, MotionModel::CONSTANT_POSE);
  ASSERT_TRUE(options.has_initial_pose);
  EXPECT_TRUE(options.initial_map_from_sensor.translation().isApprox(
      Eigen::Vector3d(1, 2, 0.5)));
  EXPECT_NEAR(options.initial_map_from_sensor.linear()(1, 0), 1.0, 1e-12);
  EXPECT_TRUE(o.registration.initial_uncertainty.given);
  EXPECT_EQ(o.registration.initial_uncertainty.rotation_deg, 5.0);
  // The paper preset, then the parameters over it.
  RegistrationOptions paper = PaperRegistrationOptions();
  EXPECT_EQ(o.registration.schedule.start_layer, paper.schedule.start_layer);
  EXPECT_EQ(o.registration.schedule.max_final_iterations, 12);
  EXPECT_EQ(options.node.tf_timeout_s, 0.25);
  EXPECT_EQ(options.odom_frame, "");
  EXPECT_FALSE(options.start_layer_given);
  for (const OptionParameter& p : LocalizerOptionParameters().parameters()) {
    EXPECT_NE(p.targets.front().path.rfind("grid.", 0), 0u) << p.name;
  }
}

TEST(LocalizerParameters, RefuseTheMapsParametersAndBadValues) {
  const std::vector<std::pair<std::map<std::string, std::string>, std::string>>
      cases = {
          {{}, "~map is not set"},
          {{{"map", "m"}, {"finest_cell_size_m", "0.5"}},
           "~finest_cell_size_m does not apply: the map file fixes the "
           "cells"},
          {{{"map", "m"}, {"initial_guess", "1,2,3"}},
           "~initial_guess=1,2,3: expected 6 comma-separated numbers"},
          {{{"map", "m"}, {"initial_uncertainty", "0.5"}},
           "~initial_uncertainty=0.5: expected translation_m,rotation_deg"},
          {{{"map", "m"}, {"initial_uncertainty", "0.5,500"}},
           "~initial_uncertainty=0.5,500"},
          {{{"map", "m"}, {"motion_model", "teleport"}},
           "~motion_model=teleport"},
          {{{"map", "m"}, {"tf_timeout_s", "0"}}, "~tf_timeout_s=0: must be"},
          {{{"map", "m"}, {"map_frame", "odom"}}, "~map_frame must be"},
      };
  for (const auto& [values, expected] : cases) {
    LocalizerNodeOptions options;
    std::string error;
    EXPECT_FALSE(LocalizerNodeOptionsFromParameters(
        MapParameterSource(values), &options, &error))
        << expected;
    EXPECT_NE(error.find(expected), std::string::npos)
        << "got: " << error << "\nexpected: " << expected;
  }
}

}  // namespace
}  // namespace ros_core
}  // namespace mlndt
