#include "lab/sim/seed_list.h"

#include <gtest/gtest.h>

namespace mlndt {
namespace sim {
namespace {

TEST(ParseSeedList, RangesAndSingles) {
  std::vector<uint64_t> seeds;
  std::string error;
  ASSERT_TRUE(ParseSeedList("1000-1003,7", &seeds, &error)) << error;
  EXPECT_EQ(seeds, (std::vector<uint64_t>{1000, 1001, 1002, 1003, 7}));
  ASSERT_TRUE(ParseSeedList("0", &seeds, &error));
  EXPECT_EQ(seeds, std::vector<uint64_t>{0});
  for (const char* bad : {"",
                          "5-3",
                          "a",
                          "1,",
                          "1-",
                          "-1",
                          "1,,2",
                          "0-100000",
                          "18446744073709551615-18446744073709551615x"}) {
    EXPECT_FALSE(ParseSeedList(bad, &seeds, &error)) << bad;
    EXPECT_TRUE(seeds.empty()) << bad;
  }
  ASSERT_TRUE(ParseSeedList(
      "18446744073709551614-18446744073709551615", &seeds, &error))
      << error;
  EXPECT_EQ(seeds.size(), 2u);
}

TEST(ParseNameList, CommaSeparated) {
  std::vector<std::string> names;
  std::string error;
  ASSERT_TRUE(ParseNameList("vlp16,avia", &names, &error));
  EXPECT_EQ(names, (std::vector<std::string>{"vlp16", "avia"}));
  for (const char* bad : {"", ",", "a,", "a,,b", ",a"}) {
    EXPECT_FALSE(ParseNameList(bad, &names, &error)) << bad;
  }
}

}  // namespace
}  // namespace sim
}  // namespace mlndt
