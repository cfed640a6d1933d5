// mlndt on a simulated pair with an exact truth: a dense spinning sensor on
// a street, car steps, registered from the identity with the default
// options, lands within 2 cm and 0.1 deg of the truth.

#include <gtest/gtest.h>

#include "lab/sim/sim_dataset.h"
#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"

namespace mlndt {
namespace sim {
namespace {

TEST(SimRegistration, DenseStreetPairFromTheIdentityLandsOnTheTruth) {
  SimulationOptions options;
  options.sensor = "os1_64";
  options.scene = "street";
  options.trajectory = "car";
  options.seed = 1;  // A training seed.
  options.num_scans = 3;
  options.steps = {1, 2};
  options.car.min_step_m = 1.2;
  options.car.max_step_m = 1.2;
  SimDataset dataset;
  std::string error;
  ASSERT_TRUE(MakeSimDataset(options, &dataset, &error)) << error;
  for (const SimPair& pair : dataset.pairs) {
    ASSERT_TRUE(pair.constraints.free_directions.empty());
    const PointCloud reference(dataset.scans[pair.reference].points);
    const PointCloud input(dataset.scans[pair.input].points);
    RegistrationSummary summary;
    Register(RegistrationOptions(),
             reference,
             input,
             Isometry3d::Identity(),
             &summary);
    const double step = pair.input - pair.reference;
    EXPECT_NEAR(
        pair.reference_from_input.translation().norm(), 1.2 * step, 0.01);
    EXPECT_EQ(summary.termination_type, TerminationType::CONVERGENCE)
        << summary.message;
    EXPECT_LT(TranslationErrorM(pair.reference_from_input,
                                summary.reference_from_input),
              0.02)
        << summary.FullReport();
    EXPECT_LT(RotationErrorRad(pair.reference_from_input,
                               summary.reference_from_input) *
                  kRadToDeg,
              0.1)
        << summary.FullReport();
  }
}

}  // namespace
}  // namespace sim
}  // namespace mlndt
