#include "mlndt/common/types.h"

#include <gtest/gtest.h>

#include <string>

#include "mlndt/common/internal/check_option.h"

namespace mlndt {
namespace {

TEST(TerminationType, StringRoundTrip) {
  for (const TerminationType type : {TerminationType::CONVERGENCE,
                                     TerminationType::NO_CONVERGENCE,
                                     TerminationType::FAILURE}) {
    TerminationType parsed = type == TerminationType::FAILURE
                                 ? TerminationType::CONVERGENCE
                                 : TerminationType::FAILURE;
    ASSERT_TRUE(StringToTerminationType(TerminationTypeToString(type), &parsed))
        << TerminationTypeToString(type);
    EXPECT_EQ(parsed, type);
  }
  EXPECT_STREQ(TerminationTypeToString(TerminationType::CONVERGENCE),
               "CONVERGENCE");
  EXPECT_STREQ(TerminationTypeToString(TerminationType::NO_CONVERGENCE),
               "NO_CONVERGENCE");
  EXPECT_STREQ(TerminationTypeToString(TerminationType::FAILURE), "FAILURE");
}

TEST(TerminationType, ParsesLowerCaseAndRejectsUnknownNames) {
  TerminationType parsed = TerminationType::FAILURE;
  ASSERT_TRUE(StringToTerminationType("no_convergence", &parsed));
  EXPECT_EQ(parsed, TerminationType::NO_CONVERGENCE);
  ASSERT_TRUE(StringToTerminationType("Convergence", &parsed));
  EXPECT_EQ(parsed, TerminationType::CONVERGENCE);

  parsed = TerminationType::NO_CONVERGENCE;
  EXPECT_FALSE(StringToTerminationType("CONVERGED", &parsed));
  EXPECT_FALSE(StringToTerminationType("", &parsed));
  EXPECT_FALSE(StringToTerminationType("NO CONVERGENCE", &parsed));
  EXPECT_EQ(parsed, TerminationType::NO_CONVERGENCE);  // Untouched on failure.
}

// A tiny Options struct using every check_option.h macro.
struct TinyOptions {
  int max_iterations = 10;  // >= 1.
  double step_size = 0.5;   // > 0.
  double ratio = 0.5;       // <= 1.
  double tolerance = 1e-6;  // < 1.
  struct Nested {
    double scale = 2.0;  // > 0.
  } nested;

  bool IsValid(std::string* error) const {
    MLNDT_OPTION_GE(max_iterations, 1);
    MLNDT_OPTION_GT(step_size, 0.0);
    MLNDT_OPTION_LE(ratio, 1.0);
    MLNDT_OPTION_LT(tolerance, 1.0);
    MLNDT_OPTION_GT(nested.scale, 0.0);
    return true;
  }
};

TEST(CheckOption, ValidOptionsPassAndLeaveErrorUntouched) {
  TinyOptions options;
  std::string error = "untouched";
  EXPECT_TRUE(options.IsValid(&error));
  EXPECT_EQ(error, "untouched");
  // Boundaries: GE and LE accept equality.
  options.max_iterations = 1;
  options.ratio = 1.0;
  EXPECT_TRUE(options.IsValid(&error));
  EXPECT_EQ(error, "untouched");
}

TEST(CheckOption, MessageNamesTheFieldItsValueAndTheBound) {
  std::string error;
  {
    TinyOptions options;
    options.max_iterations = 0;
    EXPECT_FALSE(options.IsValid(&error));
    EXPECT_NE(error.find("max_iterations"), std::string::npos) << error;
    EXPECT_NE(error.find("= 0"), std::string::npos) << error;
    EXPECT_NE(error.find(">= 1"), std::string::npos) << error;
  }
  {
    TinyOptions options;
    options.step_size = 0.0;  // GT rejects equality.
    EXPECT_FALSE(options.IsValid(&error));
    EXPECT_NE(error.find("step_size"), std::string::npos) << error;
    EXPECT_NE(error.find("> 0"), std::string::npos) << error;
    EXPECT_EQ(error.find("max_iterations"), std::string::npos) << error;
  }
  {
    TinyOptions options;
    options.ratio = 1.5;
    EXPECT_FALSE(options.IsValid(&error));
    EXPECT_NE(error.find("ratio"), std::string::npos) << error;
    EXPECT_NE(error.find("1.5"), std::string::npos) << error;
    EXPECT_NE(error.find("<= 1"), std::string::npos) << error;
  }
  {
    TinyOptions options;
    options.tolerance = 1.0;  // LT rejects equality.
    EXPECT_FALSE(options.IsValid(&error));
    EXPECT_NE(error.find("tolerance"), std::string::npos) << error;
    EXPECT_NE(error.find("< 1"), std::string::npos) << error;
  }
  {
    TinyOptions options;
    options.nested.scale = -3.0;
    EXPECT_FALSE(options.IsValid(&error));
    EXPECT_NE(error.find("nested.scale"), std::string::npos) << error;
    EXPECT_NE(error.find("-3"), std::string::npos) << error;
  }
}

TEST(CheckOption, ReportsTheFirstViolatedField) {
  TinyOptions options;
  options.step_size = -1.0;
  options.tolerance = 5.0;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("step_size"), std::string::npos) << error;
  EXPECT_EQ(error.find("tolerance"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
