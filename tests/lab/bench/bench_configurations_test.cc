#include "lab/bench/bench_configurations.h"

#include <gtest/gtest.h>

namespace mlndt {
namespace {

TEST(ParseBenchConfigurations, TheDefaultGridIsOneRowPerBackend) {
  std::vector<BenchConfiguration> configurations;
  std::string error;
  ASSERT_TRUE(ParseBenchConfigurations(BenchGrid(), &configurations, &error))
      << error;
  ASSERT_EQ(configurations.size(), 3u);
  EXPECT_EQ(configurations[0].backend, BackendType::CERES);
  EXPECT_EQ(configurations[1].backend, BackendType::NEWTON);
  EXPECT_EQ(configurations[2].backend, BackendType::LEVENBERG_MARQUARDT);
  // The current defaults, as RegistrationOptions() has them.
  const RegistrationOptions options = configurations[2].Options(1);
  EXPECT_EQ(options.grid.finest_cell_size_m,
            RegistrationOptions().grid.finest_cell_size_m);
  EXPECT_EQ(options.backend.type, BackendType::LEVENBERG_MARQUARDT);
}

// Ceres: minimizers x Jacobians, the trust region also x linear solvers x
// strategies; a loss without scale is one row; defaults outermost.
TEST(ParseBenchConfigurations, GridSizeFollowsTheAxes) {
  BenchGrid grid;
  grid.backends = {"ceres", "lm"};
  grid.minimizers = {"trust_region", "lbfgs"};
  grid.jacobians = {"autodiff", "analytic"};
  grid.linear_solvers = {"dense_normal_cholesky", "dense_qr"};
  grid.losses = {"none", "cauchy"};
  grid.loss_scales = {1.0, 2.0};
  grid.defaults = {"current", "previous"};
  std::vector<BenchConfiguration> configurations;
  std::string error;
  ASSERT_TRUE(ParseBenchConfigurations(grid, &configurations, &error)) << error;
  // Ceres: (trust region 2 Jacobians x 2 solvers + lbfgs 2 Jacobians) x
  // 3 losses = 18; lm: 3 losses. Twice for the defaults.
  EXPECT_EQ(configurations.size(), 2u * (18u + 3u));
  EXPECT_EQ(configurations.front().defaults, BenchDefaults::CURRENT);
  EXPECT_EQ(configurations.back().defaults, BenchDefaults::PREVIOUS);
  EXPECT_EQ(configurations.back().Options(1).grid.finest_cell_size_m, 2.0);
}

// Issue 41 item 5: without --loss_scales each defaults keeps its own Cauchy
// scale (the previous defaults' 3, not the current 1.5); given scales apply
// to both.
TEST(ParseBenchConfigurations, PreviousDefaultsKeepTheirOwnLossScale) {
  BenchGrid grid;
  grid.backends = {"lm"};
  grid.defaults = {"current", "previous"};
  std::vector<BenchConfiguration> configurations;
  std::string error;
  ASSERT_TRUE(ParseBenchConfigurations(grid, &configurations, &error)) << error;
  ASSERT_EQ(configurations.size(), 2u);
  const RegistrationOptions current = configurations[0].Options(1);
  const RegistrationOptions previous = configurations[1].Options(1);
  EXPECT_EQ(current.objective.loss_scale, ObjectiveOptions().loss_scale);
  EXPECT_EQ(previous.objective.loss_scale, 3.0);
  EXPECT_EQ(previous.grid.finest_cell_size_m, 2.0);
  EXPECT_EQ(previous.schedule.step_tolerance, 1e-4);
  EXPECT_EQ(previous.objective.loss, LossType::CAUCHY);

  grid.loss_scales = {2.0};
  ASSERT_TRUE(ParseBenchConfigurations(grid, &configurations, &error)) << error;
  ASSERT_EQ(configurations.size(), 2u);
  EXPECT_EQ(configurations[0].Options(1).objective.loss_scale, 2.0);
  EXPECT_EQ(configurations[1].Options(1).objective.loss_scale, 2.0);
}

TEST(ParseBenchConfigurations, RefusesBadItemsAndEmptyAxesNamingTheFlag) {
  struct Case {
    const char* flag;
    void (*set)(BenchGrid*);
  };
  const Case cases[] = {
      {"--backends: 'foo'",
       [](BenchGrid* g) {
         g->backends = {"lm", "foo"};
       }},
      {"--backends: expected", [](BenchGrid* g) { g->backends = {}; }},
      {"--defaults: 'old'", [](BenchGrid* g) { g->defaults = {"old"}; }},
      {"--samplings: 'none'", [](BenchGrid* g) { g->samplings = {"none"}; }},
      {"--gbs_cell_sizes: expected",
       [](BenchGrid* g) { g->gbs_cell_sizes = {}; }},
      {"--start_layers: expected", [](BenchGrid* g) { g->start_layers = {}; }},
      {"--threads: expected", [](BenchGrid* g) { g->threads = {}; }},
      {"--linear_solvers: 'cholesky'",
       [](BenchGrid* g) { g->linear_solvers = {"cholesky"}; }},
      {"--trust_regions: 'newton'",
       [](BenchGrid* g) { g->trust_regions = {"newton"}; }},
      {"--minimizers: 'newton'",
       [](BenchGrid* g) { g->minimizers = {"newton"}; }},
      {"--jacobians: 'numeric'",
       [](BenchGrid* g) { g->jacobians = {"numeric"}; }},
      {"--losses: 'tukey'", [](BenchGrid* g) { g->losses = {"tukey"}; }},
      {"invalid configuration", [](BenchGrid* g) { g->threads = {0}; }},
      {"invalid configuration",
       [](BenchGrid* g) { g->gbs_cell_sizes = {0.0}; }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.flag);
    BenchGrid grid;
    c.set(&grid);
    std::vector<BenchConfiguration> configurations;
    std::string error;
    EXPECT_FALSE(ParseBenchConfigurations(grid, &configurations, &error));
    EXPECT_EQ(error.rfind(c.flag, 0), 0u) << error;
  }
}

TEST(BenchConfigurationNames, FlagSpellings) {
  EXPECT_EQ(BackendFlagName(BackendType::LEVENBERG_MARQUARDT), "lm");
  EXPECT_EQ(BackendFlagName(BackendType::NEWTON), "newton");
  BenchConfiguration c;
  c.minimizer = ceres::LINE_SEARCH;
  c.line_search_direction = ceres::BFGS;
  EXPECT_EQ(MinimizerFlagName(c), "bfgs");
  c.backend = BackendType::NEWTON;
  EXPECT_EQ(MinimizerFlagName(c), "");
  EXPECT_EQ(LowerCase("DENSE_QR"), "dense_qr");
}

}  // namespace
}  // namespace mlndt
