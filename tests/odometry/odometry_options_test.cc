// OdometryOptions::IsValid: the own fields' ranges come from
// OdometryOwnOptionsTable, each value out of range refused with the message
// the checks beside it wrote (or its range whole); the nested structs by
// their own IsValid.

#include "mlndt/odometry/odometry_options.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace mlndt {
namespace {

TEST(OdometryOptions, IsValidRefusesEachOwnFieldOutOfRange) {
  std::string error;
  ASSERT_TRUE(OdometryOptions().IsValid(&error)) << error;
  const std::vector<
      std::pair<std::function<void(OdometryOptions*)>, std::string>>
      cases = {
          {[](OdometryOptions* o) { o->gate_factor = 0.5; },
           "invalid option: gate_factor = 0.5; it must be >= 1"},
          {[](OdometryOptions* o) { o->recovery.max_search_starts = 6; },
           "invalid option: max_search_starts = 6; it must be <= 5"},
          {[](OdometryOptions* o) { o->max_flatness = 0.0; },
           "invalid option: max_flatness = 0; it must be in (0, 1]"},
          {[](OdometryOptions* o) { o->max_flatness = 1.5; },
           "invalid option: max_flatness = 1.5; it must be in (0, 1]"},
          {[](OdometryOptions* o) {
             o->max_flatness = std::numeric_limits<double>::quiet_NaN();
           },
           "invalid option: max_flatness = nan; it must be in (0, 1]"},
          {[](OdometryOptions* o) { o->weak_direction_rounds = 17; },
           "invalid option: weak_direction_rounds = 17; it must be in [0, "
           "16]"},
          {[](OdometryOptions* o) { o->weak_direction_rounds = -1; },
           "invalid option: weak_direction_rounds = -1; it must be in [0, "
           "16]"},
          {[](OdometryOptions* o) { o->local_map.max_keyframes = 0; },
           "invalid option: max_keyframes = 0; it must be >= 1"},
      };
  for (const auto& [spoil, message] : cases) {
    OdometryOptions options;
    spoil(&options);
    EXPECT_FALSE(options.IsValid(&error)) << message;
    EXPECT_EQ(error, message);
  }
  OdometryOptions options;
  options.max_flatness = 1.0;  // The upper end is valid (off).
  options.weak_direction_rounds = 16;
  EXPECT_TRUE(options.IsValid(&error)) << error;
}

}  // namespace
}  // namespace mlndt
