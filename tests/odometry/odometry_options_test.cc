// OdometryOptions::IsValid: the own fields' ranges come from
// OdometryOwnOptionsTable, each value out of range refused with the message
// the checks beside it wrote (or its range whole); the nested structs by
// their own IsValid.

#include "mlndt/odometry/odometry_options.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mlndt/common/option_table.h"
#include "mlndt/odometry/odometry_option_tables.h"
#include "mlndt/registration/registration_options.h"

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
          {[](OdometryOptions* o) { o->local_map.max_keyframes = 0; },
           "invalid option: max_keyframes = 0; it must be >= 1"},
      };
  for (const auto& [spoil, message] : cases) {
    OdometryOptions options;
    spoil(&options);
    EXPECT_FALSE(options.IsValid(&error)) << message;
    EXPECT_EQ(error, message);
  }
  // The registration's fields by its own IsValid.
  OdometryOptions options;
  options.registration.quality_check.max_flatness = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("max_flatness"), std::string::npos) << error;
}

// "path=value" of every field of `table` in the struct at `s`.
void Values(const OptionTable& table,
            const void* s,
            const std::string& prefix,
            std::map<std::string, std::string>* values) {
  for (const OptionField& field : table.fields()) {
    if (field.type == OptionType::STRUCT) {
      Values(*field.nested,
             field.locate(const_cast<void*>(s)),
             prefix + field.name + ".",
             values);
    } else {
      (*values)[prefix + field.name] = field.Format(s);
    }
  }
}

// OdometryOptions' registration starts from OdometryRegistrationOptions():
// the library's defaults but the probe of weak directions, the search along
// them, the mean-score check and the localizability test (no shadow fields
// of the odometry's own).
TEST(OdometryOptions, RegistrationDefaultsAreTheOdometryPreset) {
  const RegistrationOptions library;
  const RegistrationOptions preset = OdometryRegistrationOptions();
  const OdometryOptions odometry;
  std::map<std::string, std::string> library_values, preset_values,
      odometry_values;
  Values(RegistrationOptionsTable(), &library, "", &library_values);
  Values(RegistrationOptionsTable(), &preset, "", &preset_values);
  Values(
      RegistrationOptionsTable(), &odometry.registration, "", &odometry_values);
  EXPECT_EQ(odometry_values, preset_values);
  std::vector<std::string> differ;
  for (const auto& [path, value] : preset_values) {
    if (library_values.at(path) != value) differ.push_back(path + "=" + value);
  }
  EXPECT_EQ(differ,
            (std::vector<std::string>{"quality_check.max_flatness=0.8",
                                      "quality_check.max_mean_score=11",
                                      "quality_check.min_localizability=0",
                                      "retry.weak_direction_rounds=0"}));
  EXPECT_EQ(OdometryOwnOptionsTable().Find("max_flatness"), nullptr);
}

}  // namespace
}  // namespace mlndt
