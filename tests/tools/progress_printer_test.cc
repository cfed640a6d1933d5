// The tools' one progress printer (tools/cli/progress_printer.h): with
// stderr not a terminal (as under ctest), one line per event, "label
// done/total [name] status [times]", the item's name from the list given.

#include "tools/cli/progress_printer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace mlndt {
namespace {

TEST(ProgressPrinter, OneLinePerEventWithTheItemsName) {
  ::testing::internal::CaptureStderr();
  {
    tools::ProgressPrinter printer("mlndt_x", {"a.pcd", "b.pcd"});
    printer({0, 1, 2, "CONVERGENCE, 3 it"});
    printer({1, 2, 2, ""});
  }
  const std::string err = ::testing::internal::GetCapturedStderr();
  const size_t first = err.find("mlndt_x 1/2 a.pcd CONVERGENCE, 3 it [");
  const size_t second = err.find("\nmlndt_x 2/2 b.pcd [");
  ASSERT_NE(first, std::string::npos) << err;
  ASSERT_NE(second, std::string::npos) << err;
  EXPECT_EQ(first, 0u) << err;
  EXPECT_LT(first, second);
  EXPECT_NE(err.find(", ETA 0 s]\n", second), std::string::npos) << err;
}

TEST(ProgressPrinter, WithoutNamesTheStatusAlone) {
  ::testing::internal::CaptureStderr();
  tools::ProgressPrinter printer("mlndt_y");
  printer({4, 5, 9, "pair 4->5 CONVERGENCE"});
  printer.Finish();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(err.rfind("mlndt_y 5/9 pair 4->5 CONVERGENCE [", 0), 0u) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

}  // namespace
}  // namespace mlndt
