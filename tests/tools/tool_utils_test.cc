// The tools' shared helpers (tools/common/tool_utils.h): number lists from
// flags, and one end-to-end check that mlndt_align turns a malformed list
// into a clear error and exit code 1.

#include "tools/common/tool_utils.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

TEST(ParseNumberList, CommaSeparatedNumbers) {
  std::vector<double> values;
  ASSERT_TRUE(tools::ParseNumberList("1,-2.5, 3e2 ,+4", &values));
  EXPECT_EQ(values, (std::vector<double>{1, -2.5, 300, 4}));
  ASSERT_TRUE(tools::ParseNumberList("7", &values));
  EXPECT_EQ(values, (std::vector<double>{7}));
  // No text, no numbers (callers check the count they need).
  ASSERT_TRUE(tools::ParseNumberList("", &values));
  EXPECT_TRUE(values.empty());
}

TEST(ParseNumberList, RejectsEmptyItemsAndTrailingCommas) {
  const char* kBad[] = {
      "1,0,0,0,0,1,0,0,0,0,1,0,",  // Trailing comma after 12 numbers.
      "1,2,",
      ",",
      ",1",
      "1,,2",
      "1, ,2",
      " ",
      "1,2,\t",
  };
  for (const char* text : kBad) {
    std::vector<double> values;
    EXPECT_FALSE(tools::ParseNumberList(text, &values)) << "'" << text << "'";
  }
}

TEST(ParseNumberList, RejectsNonNumbersAndNonFinite) {
  for (const char* text : {"1,x", "1,2 3", "nan", "1,inf", "1e999", "--1"}) {
    std::vector<double> values;
    EXPECT_FALSE(tools::ParseNumberList(text, &values)) << "'" << text << "'";
  }
}

TEST(MlndtAlign, TrailingCommaInInitialMatrixIsAnError) {
  const std::string koide3 = testing::BundledDataPath("koide3/");
  const testing::ToolRun run = testing::RunTool(
      "mlndt_align",
      "--reference=" + testing::ShellQuote(koide3 + "251370668.pcd") +
          " --input=" + testing::ShellQuote(koide3 + "251371071.pcd") +
          " --initial_matrix=1,0,0,0,0,1,0,0,0,0,1,0,");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("--initial_matrix needs 12"), std::string::npos)
      << run.err;
}

}  // namespace
}  // namespace mlndt
