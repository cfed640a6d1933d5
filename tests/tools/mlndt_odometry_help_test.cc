// mlndt_odometry's --helpfull shows, for the registration flags whose
// default differs in OdometryRegistrationOptions() (--max_flatness,
// --weak_direction_rounds, --max_mean_score), the odometry's defaults: the
// values the tool uses when they are not given. A registration tool
// (mlndt_align) still shows the registration's.

#include <gtest/gtest.h>

#include <string>

#include "mlndt/odometry/odometry_options.h"
#include "mlndt/registration/registration_options.h"
#include "tests/testing/run_tool.h"

namespace mlndt {
namespace {

// The "default: X" of flag --<name> in gflags' --helpfull text.
std::string HelpDefault(const std::string& help, const std::string& name) {
  const size_t start = help.find("\n    -" + name + " (");
  if (start == std::string::npos) return "(no --" + name + ")";
  const size_t next = help.find("\n    -", start + 1);
  const size_t at = help.find("default: ", start);
  if (at == std::string::npos || (next != std::string::npos && at > next)) {
    return "(no default)";
  }
  const size_t end = help.find('\n', at);
  return help.substr(at + 9, end - at - 9);
}

TEST(MlndtOdometryHelp, SharedFlagsShowTheOdometrysDefaults) {
  const testing::ToolRun odometry =
      testing::RunTool("mlndt_odometry", "--helpfull");
  const RegistrationOptions options = OdometryOptions().registration;
  EXPECT_EQ(std::stod(HelpDefault(odometry.out, "max_flatness")),
            options.quality_check.max_flatness);
  EXPECT_EQ(std::stoi(HelpDefault(odometry.out, "weak_direction_rounds")),
            options.retry.weak_direction_rounds);
  EXPECT_EQ(std::stod(HelpDefault(odometry.out, "max_mean_score")),
            options.quality_check.max_mean_score);
  // They differ from the registration's, or the test would hold anyway.
  const RegistrationOptions registration;
  ASSERT_NE(options.quality_check.max_flatness,
            registration.quality_check.max_flatness);
  ASSERT_NE(options.retry.weak_direction_rounds,
            registration.retry.weak_direction_rounds);
  ASSERT_NE(options.quality_check.max_mean_score,
            registration.quality_check.max_mean_score);

  const testing::ToolRun align = testing::RunTool("mlndt_align", "--helpfull");
  EXPECT_EQ(std::stod(HelpDefault(align.out, "max_flatness")),
            registration.quality_check.max_flatness);
  EXPECT_EQ(std::stoi(HelpDefault(align.out, "weak_direction_rounds")),
            registration.retry.weak_direction_rounds);
}

TEST(MlndtOdometryHelp, HelpShowsTheOdometrysDefaults) {
  const testing::ToolRun run = testing::RunTool("mlndt_odometry", "--help");
  EXPECT_NE(run.out.find("\n  --max_flatness=0.8"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("\n  --weak_direction_rounds=0  (int32)"),
            std::string::npos)
      << run.out;
}

}  // namespace
}  // namespace mlndt
