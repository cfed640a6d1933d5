#include "integrations/ros/core/stamp_check.h"

#include <gtest/gtest.h>

namespace mlndt {
namespace ros_core {
namespace {

TEST(StampCheck, RefusesRepeatsNotesGapsAndLearnsTheInterval) {
  StampCheck check;
  std::string refusal, gap;
  ASSERT_TRUE(check.Check(10.0, &refusal, &gap));
  check.Use(10.0);
  ASSERT_TRUE(check.Check(10.1, &refusal, &gap));
  EXPECT_EQ(gap, "");
  check.Use(10.1);
  // A repeated stamp and an older one are refused.
  EXPECT_FALSE(check.Check(10.1, &refusal, &gap));
  EXPECT_NE(refusal.find("not after the last scan's (10.100000 s)"),
            std::string::npos)
      << refusal;
  EXPECT_FALSE(check.Check(10.05, &refusal, &gap));
  // 0.1 s is regular; 0.2 s (a dropped message) is a gap, still accepted.
  ASSERT_TRUE(check.Check(10.3, &refusal, &gap));
  EXPECT_NE(gap.find("gap of 0.200000 s"), std::string::npos) << gap;
  check.Use(10.3);
  // The gap does not become the regular interval.
  ASSERT_TRUE(check.Check(10.4, &refusal, &gap));
  EXPECT_EQ(gap, "");
  check.Use(10.4);
  ASSERT_TRUE(check.Check(10.56, &refusal, &gap));
  EXPECT_NE(gap.find("gap"), std::string::npos);
  // A stamp refused is not used: the next check compares with the last used.
  check.Reset();
  EXPECT_TRUE(check.Check(1.0, &refusal, &gap));
}

}  // namespace
}  // namespace ros_core
}  // namespace mlndt
