// SequenceOptions::IsValid and AdaptiveStartLayerOptions::IsValid: the
// ranges of their option tables (step >= 1; the adaptive limits > 0, the
// fail rates in [0, 1]) and the rates ascending, each refused naming the
// field.

#include "lab/runs/sequence_option_table.h"

#include <gtest/gtest.h>

#include "lab/runs/adaptive_start_layer_option_table.h"
#include "lab/runs/sequence_registration.h"

namespace mlndt {
namespace {

TEST(SequenceOptions, IsValidChecksTheTableRanges) {
  std::string error;
  EXPECT_TRUE(SequenceOptions().IsValid(&error)) << error;
  SequenceOptions options;
  options.step = 0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error, "invalid option: step = 0; it must be >= 1");
  options.step = 3;
  options.adaptive.max_rotation_deg = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error, "invalid option: max_rotation_deg = 0; it must be > 0");
  EXPECT_EQ(SequenceOwnOptionsTable().Find("step")->RangeText(), ">= 1.");
}

TEST(AdaptiveStartLayerOptions, IsValidChecksRangesAndOrder) {
  std::string error;
  EXPECT_TRUE(AdaptiveStartLayerOptions().IsValid(&error)) << error;
  AdaptiveStartLayerOptions options;
  options.max_translation_m = -1.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error, "invalid option: max_translation_m = -1; it must be > 0");
  options = AdaptiveStartLayerOptions();
  options.fail_rate_thresholds = {0.05, 1.5};
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error,
            "invalid option: fail_rate_thresholds[1] = 1.5; it must be in "
            "[0, 1]");
  options.fail_rate_thresholds = {0.2, 0.05};
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error, "invalid option: fail_rate_thresholds must be ascending");
  // The table hands the struct's IsValid to its callers.
  EXPECT_FALSE(AdaptiveStartLayerOptionsTable().is_valid()(&options, &error));
}

}  // namespace
}  // namespace mlndt
