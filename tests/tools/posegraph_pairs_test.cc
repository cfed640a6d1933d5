// ParseScanPairs: mlndt_posegraph --pairs.

#include "tools/cli/posegraph_pairs.h"

#include <gtest/gtest.h>

namespace mlndt {
namespace tools {
namespace {

TEST(ParseScanPairs, ReadsPairsAndQuotesTheBadEntry) {
  std::vector<std::pair<int, int>> pairs;
  std::string error;
  ASSERT_TRUE(ParseScanPairs("4:249,3:245", &pairs, &error)) << error;
  EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{4, 249}, {3, 245}}));
  ASSERT_TRUE(ParseScanPairs("", &pairs, &error));
  EXPECT_TRUE(pairs.empty());
  for (const std::string bad : {"4-249", "4:", ":3", "-1:2", "1:2:3", "a:b"}) {
    EXPECT_FALSE(ParseScanPairs("0:1," + bad, &pairs, &error)) << bad;
    EXPECT_EQ(error, "'" + bad + "': expected i:j (0-based scan indices)");
  }
  EXPECT_FALSE(ParseScanPairs("0:1,", &pairs, &error));
  EXPECT_EQ(error, "'0:1,': trailing comma");
}

}  // namespace
}  // namespace tools
}  // namespace mlndt
