// The CSV made from a result table (tools/cli/result_csv.h): a header of
// the flattened field names (nested results as "outer.inner"), the trace
// left out, one line per result; vectors and matrices as one cell of
// space-separated numbers, numbers to 17 digits, leading columns first and
// strings quoted.

#include "tools/cli/result_csv.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "mlndt/pipeline/localizer.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {
namespace tools {
namespace {

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) lines.push_back(line);
  return lines;
}

size_t IndexOf(const std::vector<std::string>& columns,
               const std::string& name) {
  for (size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return i;
  }
  ADD_FAILURE() << "no column " << name;
  return 0;
}

TEST(ResultCsv, ColumnsAreTheFlattenedFieldNamesWithoutTheTrace) {
  const std::vector<std::string> columns =
      ResultCsvColumns(LocalizationResultTable());
  EXPECT_EQ(columns.front(), "index");
  IndexOf(columns, "registration.termination_type");
  IndexOf(columns, "registration.quality.inlier_fraction");
  IndexOf(columns, "registration.constraints.degenerate_directions");
  for (const std::string& name : columns) {
    EXPECT_EQ(name.find("trace"), std::string::npos) << name;
    EXPECT_NE(name, "registration");
    EXPECT_NE(name, "registration.quality");
  }
  // Every field of every table but the trace, once.
  const size_t registration = RegistrationSummaryTable().fields().size() - 3 +
                              FitQualityTable().fields().size() +
                              ConstraintAnalysisTable().fields().size();
  EXPECT_EQ(columns.size(),
            LocalizationResultTable().fields().size() - 1 + registration);
}

TEST(ResultCsv, OneLinePerResultInTheColumnsOrder) {
  std::vector<LocalizationResult> results(2);
  results[1].index = 1;
  results[1].load_time_s = 0.1;
  results[1].registration.termination_type = TerminationType::CONVERGENCE;
  results[1].registration.message = "done, \"quoted\"";
  results[1].registration.quality.inlier_fraction = 0.75;
  results[1].registration.covariance(0, 1) =
      std::numeric_limits<double>::infinity();
  results[1].registration.trace.resize(4);
  results[1].map_from_scan.translation() << 1.5, -2, 0;
  const std::string csv = ResultCsvOf(
      LocalizationResultTable(), results, {{"file", {"a.pcd", "b,c.pcd"}}});
  const std::vector<std::string> lines = Lines(csv);
  ASSERT_EQ(lines.size(), 3u);
  std::vector<std::string> header = ResultCsvColumns(LocalizationResultTable());
  header.insert(header.begin(), "file");
  std::string expected_header;
  for (const std::string& name : header) {
    expected_header += (expected_header.empty() ? "" : ",") + name;
  }
  EXPECT_EQ(lines[0], expected_header);
  const std::vector<std::string> cells =
      ResultCsvCells(LocalizationResultTable(), &results[1]);
  ASSERT_EQ(cells.size() + 1, header.size());
  EXPECT_EQ(cells[IndexOf(header, "index") - 1], "1");
  EXPECT_EQ(cells[IndexOf(header, "usable") - 1], "true");
  EXPECT_EQ(cells[IndexOf(header, "load_time_s") - 1], "0.10000000000000001");
  EXPECT_EQ(cells[IndexOf(header, "registration.termination_type") - 1],
            "CONVERGENCE");
  EXPECT_EQ(cells[IndexOf(header, "registration.message") - 1],
            "\"done, \"\"quoted\"\"\"");
  EXPECT_EQ(cells[IndexOf(header, "registration.quality.inlier_fraction") - 1],
            "0.75");
  EXPECT_EQ(cells[IndexOf(header, "map_from_scan") - 1],
            "1 0 0 1.5 0 1 0 -2 0 0 1 0 0 0 0 1");
  const std::string covariance =
      cells[IndexOf(header, "registration.covariance") - 1];
  EXPECT_EQ(covariance.substr(0, 6), "0 inf ");
  EXPECT_EQ(
      lines[2], "\"b,c.pcd\"," + [&] {
        std::string row;
        for (const std::string& cell : cells) {
          row += (row.empty() ? "" : ",") + cell;
        }
        return row;
      }());
  EXPECT_EQ(lines[1].substr(0, 8), "a.pcd,0,");
}

}  // namespace
}  // namespace tools
}  // namespace mlndt
