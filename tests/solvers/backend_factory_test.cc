// CreateBackend makes the backend its options name, and refuses invalid
// options with an error naming the field; the BackendType strings round trip.

#include "mlndt/solvers/backend_factory.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace mlndt {
namespace {

constexpr BackendType kAllTypes[] = {
    BackendType::CERES,
    BackendType::NEWTON,
    BackendType::LEVENBERG_MARQUARDT,
};

BackendOptions OptionsFor(BackendType type) {
  BackendOptions options;
  options.type = type;
  return options;
}

// Catches: a switch case returning another backend's kind, or nullptr.
TEST(CreateBackend, MakesTheBackendOfEveryType) {
  for (const BackendType type : kAllTypes) {
    SCOPED_TRACE(BackendTypeToString(type));
    std::string error;
    const std::unique_ptr<Backend> backend =
        CreateBackend(OptionsFor(type), &error);
    ASSERT_NE(backend, nullptr) << error;
    EXPECT_EQ(dynamic_cast<CeresBackend*>(backend.get()) != nullptr,
              type == BackendType::CERES);
    EXPECT_EQ(dynamic_cast<NewtonBackend*>(backend.get()) != nullptr,
              type == BackendType::NEWTON);
    EXPECT_EQ(
        dynamic_cast<LevenbergMarquardtBackend*>(backend.get()) != nullptr,
        type == BackendType::LEVENBERG_MARQUARDT);
  }
}

// Catches: an unchecked enum falling through the switch, options of a backend
// not checked, an error that does not say which field is wrong.
TEST(CreateBackend, InvalidOptionsGiveNullAndNameTheField) {
  struct Case {
    const char* what;
    BackendOptions options;
    const char* field;  // Expected in the error.
  };
  Case out_of_range{"type 7", OptionsFor(BackendType::CERES), "type = 7"};
  out_of_range.options.type = static_cast<BackendType>(7);
  // Ceres' own check names the field.
  Case dogleg{"DOGLEG + ITERATIVE_SCHUR",
              OptionsFor(BackendType::CERES),
              "trust_region_strategy_type"};
  dogleg.options.ceres.trust_region_strategy_type = ceres::DOGLEG;
  dogleg.options.ceres.linear_solver_type = ceres::ITERATIVE_SCHUR;
  Case newton{"line search steps",
              OptionsFor(BackendType::NEWTON),
              "max_line_search_steps"};
  newton.options.newton.max_line_search_steps = 0;
  Case lm{"lambda decrease",
          OptionsFor(BackendType::LEVENBERG_MARQUARDT),
          "lambda_decrease"};
  lm.options.levenberg_marquardt.lambda_decrease = 1.0;
  // Every backend's options are checked, whichever backend is made.
  Case other{"other backend's options",
             OptionsFor(BackendType::CERES),
             "min_eigenvalue_ratio"};
  other.options.newton.min_eigenvalue_ratio = 0.0;

  for (const Case& c : {out_of_range, dogleg, newton, lm, other}) {
    SCOPED_TRACE(c.what);
    std::string error;
    EXPECT_FALSE(c.options.IsValid(&error));
    error.clear();
    EXPECT_EQ(CreateBackend(c.options, &error), nullptr);
    EXPECT_NE(error.find(c.field), std::string::npos) << error;
  }
}

// Catches: a missing or misspelt name, a parser that is case-sensitive or
// does not know "lm", a parser that accepts anything.
TEST(BackendType, StringsRoundTrip) {
  for (const BackendType type : kAllTypes) {
    BackendType parsed = BackendType::CERES;
    const std::string name = BackendTypeToString(type);
    EXPECT_NE(name, "UNKNOWN");
    ASSERT_TRUE(StringToBackendType(name, &parsed)) << name;
    EXPECT_EQ(parsed, type);
  }
  const struct {
    const char* text;
    BackendType type;
  } aliases[] = {{"lm", BackendType::LEVENBERG_MARQUARDT},
                 {"LM", BackendType::LEVENBERG_MARQUARDT},
                 {"levenberg_marquardt", BackendType::LEVENBERG_MARQUARDT},
                 {"Newton", BackendType::NEWTON},
                 {"ceres", BackendType::CERES}};
  for (const auto& alias : aliases) {
    BackendType parsed = BackendType::CERES;
    if (alias.type == BackendType::CERES) parsed = BackendType::NEWTON;
    ASSERT_TRUE(StringToBackendType(alias.text, &parsed)) << alias.text;
    EXPECT_EQ(parsed, alias.type) << alias.text;
  }
  EXPECT_STREQ(BackendTypeToString(static_cast<BackendType>(7)), "UNKNOWN");
  for (const char* bad : {"", "gauss_newton", "l m", "NEWTONS"}) {
    BackendType parsed = BackendType::NEWTON;
    EXPECT_FALSE(StringToBackendType(bad, &parsed)) << bad;
    EXPECT_EQ(parsed, BackendType::NEWTON) << bad;  // Left unchanged.
  }
}

}  // namespace
}  // namespace mlndt
