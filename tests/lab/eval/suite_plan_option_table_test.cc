// SuitePlanOptions::IsValid's ranges come from SuitePlanOptionsTable: each
// single value out of range is refused naming its field; the starts' own
// checks still follow.

#include "lab/eval/suite_plan_option_table.h"

#include <gtest/gtest.h>

#include "lab/eval/suite_plan.h"

namespace mlndt {
namespace {

TEST(SuitePlanOptions, IsValidChecksTheTableRanges) {
  std::string error;
  EXPECT_TRUE(SuitePlanOptions().IsValid(&error)) << error;
  SuitePlanOptions plan;
  plan.perturb_translation_m = 2e4;
  EXPECT_FALSE(plan.IsValid(&error));
  EXPECT_EQ(error,
            "invalid option: perturb_translation_m = 20000; it must be in "
            "[0, 10000]");
  plan = SuitePlanOptions();
  plan.perturb_rotation_deg = -1.0;
  EXPECT_FALSE(plan.IsValid(&error));
  EXPECT_EQ(error,
            "invalid option: perturb_rotation_deg = -1; it must be in [0, "
            "180]");
  plan = SuitePlanOptions();
  plan.perturb_count = 0;
  EXPECT_FALSE(plan.IsValid(&error));
  EXPECT_EQ(error, "invalid option: perturb_count = 0; it must be >= 1");
  plan = SuitePlanOptions();
  plan.steps = {1, 0};
  EXPECT_FALSE(plan.IsValid(&error));
  EXPECT_EQ(error, "a step of 0");
}

}  // namespace
}  // namespace mlndt
