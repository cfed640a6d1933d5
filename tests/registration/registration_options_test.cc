// Every option has a finite, sane range: absurd values are refused by name
// before any work (a NaN score or an overflowing cell count reported as a
// result was the alternative), by IsValid and by Register alike.

#include "mlndt/registration/registration_options.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "mlndt/registration/registration.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Case {
  const char* field;  // Named in the error.
  std::function<void(RegistrationOptions*)> set;
};

TEST(RegistrationOptions, AbsurdValuesAreRefusedByName) {
  const std::vector<Case> cases = {
      {"loss_scale",
       [](RegistrationOptions* o) { o->objective.loss_scale = 1e300; }},
      {"loss_scale",
       [](RegistrationOptions* o) { o->objective.loss_scale = 1e-300; }},
      {"loss_scale",
       [](RegistrationOptions* o) { o->objective.loss_scale = kInf; }},
      {"loss_scale",
       [](RegistrationOptions* o) { o->objective.loss_scale = std::nan(""); }},
      {"min_eigenvalue_m2",
       [](RegistrationOptions* o) {
         o->grid.regularization.min_eigenvalue_m2 = kInf;
       }},
      {"finest_cell_size_m",
       [](RegistrationOptions* o) { o->grid.finest_cell_size_m = 1e-300; }},
      {"finest_cell_size_m",
       [](RegistrationOptions* o) { o->grid.finest_cell_size_m = kInf; }},
      {"cell_size_m",
       [](RegistrationOptions* o) { o->grid.cell_size_m = kInf; }},
      {"num_threads", [](RegistrationOptions* o) { o->num_threads = 100000; }},
      {"num_threads", [](RegistrationOptions* o) { o->num_threads = 0; }},
      {"unmatched_policy",
       [](RegistrationOptions* o) {
         o->objective.unmatched_policy = static_cast<UnmatchedPolicy>(7);
       }},
      {"loss",
       [](RegistrationOptions* o) {
         o->objective.loss = static_cast<LossType>(-1);
       }},
      {"type",
       [](RegistrationOptions* o) {
         o->backend.type = static_cast<BackendType>(9);
       }},
      {"coarse_weighting",
       [](RegistrationOptions* o) {
         o->grid.coarse_weighting = static_cast<CoarseWeighting>(5);
       }},
      {"step_tolerance",
       [](RegistrationOptions* o) { o->schedule.step_tolerance = 0.0; }},
      {"max_final_iterations",
       [](RegistrationOptions* o) {
         o->schedule.max_final_iterations = 1000000;
       }},
      {"min_range_m",
       [](RegistrationOptions* o) { o->range_filter.min_range_m = kInf; }},
      {"translation_m",
       [](RegistrationOptions* o) {
         o->initial_uncertainty.given = true;
         o->initial_uncertainty.translation_m = std::nan("");
       }},
      {"yaw_seeds_deg",
       [](RegistrationOptions* o) {
         o->retry.yaw_seeds_deg = {45, 720};
       }},
      {"max_mean_score",
       [](RegistrationOptions* o) { o->quality_check.max_mean_score = kInf; }},
  };
  const PointCloud scene = testing::StreetScene(3000, 0.02, 3);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.field);
    RegistrationOptions options;
    c.set(&options);
    std::string error;
    EXPECT_FALSE(options.IsValid(&error));
    EXPECT_NE(error.find(c.field), std::string::npos) << error;
    RegistrationSummary summary;
    Register(options, scene, scene, Isometry3d::Identity(), &summary);
    EXPECT_EQ(summary.termination_type, TerminationType::FAILURE);
    EXPECT_NE(summary.message.find(c.field), std::string::npos)
        << summary.message;
  }
}

TEST(RegistrationOptions, DefaultsAndThePaperPresetAreValid) {
  std::string error;
  EXPECT_TRUE(RegistrationOptions().IsValid(&error)) << error;
  const RegistrationOptions paper = PaperRegistrationOptions();
  EXPECT_TRUE(paper.IsValid(&error)) << error;
  // The paper's configuration (Sections 4-5), not the library's.
  EXPECT_EQ(paper.grid.finest_cell_size_m, 0.0);
  EXPECT_EQ(paper.grid.num_layers, 4);
  EXPECT_EQ(paper.schedule.start_layer, 2);
  EXPECT_EQ(paper.schedule.iterations_per_layer, 3);
  EXPECT_EQ(paper.schedule.max_coarse_point_stride, 1);
  EXPECT_EQ(paper.objective.loss, LossType::NONE);
  EXPECT_EQ(paper.objective.unmatched_policy, UnmatchedPolicy::ZERO_RESIDUAL);
  EXPECT_EQ(paper.backend.type, BackendType::NEWTON);
  EXPECT_TRUE(paper.retry.yaw_seeds_deg.empty());
  EXPECT_NE(RegistrationOptions().grid, paper.grid);
}

}  // namespace
}  // namespace mlndt
