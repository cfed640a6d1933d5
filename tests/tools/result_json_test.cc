// The JSON made from a result table (tools/cli/result_json.h): one key
// per field named as the field, in the table's order; nested results as
// objects, the trace as an array of objects, matrices as rows; numbers that
// are not finite as null; `trace` left out on request.

#include "tools/cli/result_json.h"

#include <gtest/gtest.h>

#include <limits>

#include "mlndt/registration/registration_summary.h"

namespace mlndt {
namespace tools {
namespace {

TEST(ResultJson, KeysAreTheTablesFieldsInOrderWithNestedObjects) {
  RegistrationSummary s;
  s.termination_type = TerminationType::LOW_QUALITY;
  s.trace.resize(3);
  s.trace[2].layer = 5;
  s.constraints.degenerate_directions.assign(1, Vector6d::Unit(2));
  s.covariance(3, 3) = std::numeric_limits<double>::infinity();
  s.total_time_s = 0.25;
  const Json json = RegistrationSummaryJson(s, true);
  std::vector<std::string> keys;
  for (const auto& item : json.items()) keys.push_back(item.key());
  std::vector<std::string> fields;
  for (const ResultField& f : RegistrationSummaryTable().fields()) {
    fields.push_back(f.name);
  }
  EXPECT_EQ(keys, fields);
  EXPECT_EQ(json["termination_type"], "LOW_QUALITY");
  EXPECT_EQ(json["usable"], false);
  EXPECT_EQ(json["total_time_s"], 0.25);  // Seconds, as the struct.
  ASSERT_EQ(json["trace"].size(), 3u);
  EXPECT_EQ(json["trace"][2]["layer"], 5);
  EXPECT_TRUE(json["trace"][2].contains("reference_from_input_xi"));
  EXPECT_EQ(json["quality"]["points"], 0);
  EXPECT_EQ(json["constraints"]["degenerate_directions"],
            Json::parse("[[0.0, 0.0, 1.0, 0.0, 0.0, 0.0]]"));
  EXPECT_EQ(json["constraints"]["weakest_translations"].size(), 3u);
  EXPECT_TRUE(json["covariance"][3][3].is_null());
  EXPECT_EQ(json["covariance"][3][2], 0.0);
  EXPECT_EQ(json["reference_from_input"][3][3], 1.0);
  EXPECT_EQ(json["reference_from_input_xi"].size(), 6u);

  const Json without = RegistrationSummaryJson(s, false);
  EXPECT_FALSE(without.contains("trace"));
  EXPECT_EQ(without.size(), json.size() - 1);
}

}  // namespace
}  // namespace tools
}  // namespace mlndt
