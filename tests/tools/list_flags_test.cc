// The tools' list and matrix parsers (tools/cli/list_flags.h,
// tools/cli/matrix_text.h).

#include "tools/cli/list_flags.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <limits>

#include "mlndt/common/pose.h"
#include "tests/testing/scratch_dir.h"
#include "tools/cli/matrix_text.h"

namespace mlndt {
namespace {

using tools::ParseIntList;
using tools::ParseNumberList;
using tools::SplitList;

TEST(SplitList, TrimsItemsAndRejectsEmptyOnes) {
  std::vector<std::string> items;
  ASSERT_TRUE(SplitList(" a, b ,c", &items));
  EXPECT_EQ(items, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_FALSE(SplitList("", &items));
  EXPECT_FALSE(SplitList("a,,b", &items));
  EXPECT_FALSE(SplitList("a,", &items));
  EXPECT_FALSE(SplitList(" ", &items));
}

TEST(ParseNumberList, FiniteNumbersOnly) {
  std::vector<double> v;
  ASSERT_TRUE(ParseNumberList("1, -2.5,3e2 ", &v));
  EXPECT_EQ(v, (std::vector<double>{1.0, -2.5, 300.0}));
  ASSERT_TRUE(ParseNumberList("", &v));  // An empty list.
  EXPECT_TRUE(v.empty());
  EXPECT_FALSE(ParseNumberList("1,x", &v));
  EXPECT_FALSE(ParseNumberList("1,,2", &v));
  EXPECT_FALSE(ParseNumberList("1 2", &v));
  EXPECT_FALSE(ParseNumberList("inf", &v));
  EXPECT_FALSE(ParseNumberList("nan", &v));
}

TEST(ParseIntList, IntegersOnly) {
  std::vector<int> v;
  ASSERT_TRUE(ParseIntList("1, -2,30", &v));
  EXPECT_EQ(v, (std::vector<int>{1, -2, 30}));
  EXPECT_FALSE(ParseIntList("1.5", &v));
  EXPECT_FALSE(ParseIntList("", &v));
  EXPECT_FALSE(ParseIntList("1,", &v));
}

TEST(ParseCountList, WholeNumbersInRangeOnly) {
  std::vector<size_t> v;
  std::string error;
  EXPECT_TRUE(tools::ParseCountList("1, 2,7", 1, 7, &v, &error)) << error;
  EXPECT_EQ(v, (std::vector<size_t>{1, 2, 7}));
  for (const char* bad : {"0",
                          "8",
                          "1e300",
                          "1e0",
                          "1.0",
                          "-1",
                          "+1",
                          "0x2",
                          "18446744073709551615",
                          "18446744073709551616",
                          "99999999999999999999999"}) {
    EXPECT_FALSE(tools::ParseCountList(bad, 1, 7, &v, &error)) << bad;
    EXPECT_NE(error.find(std::string("'") + bad +
                         "' is not a whole number in [1, 7]"),
              std::string::npos)
        << error;
  }
  EXPECT_FALSE(tools::ParseCountList("1,,2", 1, 7, &v, &error));
  EXPECT_FALSE(tools::ParseCountList("", 1, 7, &v, &error));
  const size_t max = std::numeric_limits<size_t>::max();
  EXPECT_TRUE(
      tools::ParseCountList("18446744073709551615", 0, max, &v, &error));
  EXPECT_EQ(v, (std::vector<size_t>{max}));
}

TEST(RowMajorToRigidTransform, ReadsRowsAndChecksTheRotation) {
  const Isometry3d motion =
      PoseVectorToIsometry(PoseVectorFromDegrees(1, 2, 3, 10, -20, 30));
  std::vector<double> v;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) v.push_back(motion.matrix()(r, c));
  }
  Isometry3d parsed;
  std::string error;
  ASSERT_TRUE(tools::RowMajorToRigidTransform(v, "--m", &parsed, &error));
  EXPECT_TRUE(parsed.isApprox(motion, 1e-12));
  v[0] = 2.0;  // Not a rotation.
  EXPECT_FALSE(tools::RowMajorToRigidTransform(v, "--m", &parsed, &error));
  EXPECT_EQ(
      error.rfind("--m: the 3x3 part is not a rotation (|R^T R - I| = ", 0), 0u)
      << error;
  v.pop_back();
  EXPECT_FALSE(tools::RowMajorToRigidTransform(v, "--m", &parsed, &error));
}

TEST(ReadMatrixFile, ReadsTwelveOrSixteenNumbers) {
  const std::string path = testing::ScratchPath("matrix_text.txt");
  {
    std::ofstream out(path);
    out << "1 0 0 5\n0 1 0 6\n0 0 1 7\n0 0 0 1\n";
  }
  Isometry3d transform;
  std::string error;
  ASSERT_TRUE(tools::ReadMatrixFile(path, &transform, &error)) << error;
  EXPECT_EQ(transform.translation(), Eigen::Vector3d(5, 6, 7));
  {
    std::ofstream out(path);
    out << "1 0 0 5\n0 1 0 6\n";
  }
  EXPECT_FALSE(tools::ReadMatrixFile(path, &transform, &error));
  EXPECT_NE(error.find("expected 12 or 16 numbers"), std::string::npos);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace mlndt
