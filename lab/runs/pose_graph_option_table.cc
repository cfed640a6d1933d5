#include "lab/runs/pose_graph_option_table.h"

#include "lab/runs/pose_graph.h"
#include "lab/runs/pose_graph_factors.h"

namespace mlndt {
namespace {

// Below these, 1 / sigma^2 makes the odometry factors' cost overflow or
// swamp every pair (--odometry_noise_sigma_m=1e-300 gave a cost of inf and
// 0 iterations "CONVERGENCE").
constexpr double kMinOdometrySigmaM = 1e-4;
constexpr double kMinOdometrySigmaDeg = 1e-4;

}  // namespace

const OptionTable& OdometryNoiseTable() {
  using S = OdometryNoise;
  static const OptionTable table =
      OptionTableBuilder<S>("OdometryNoise")
          .Double("sigma_m",
                  &S::sigma_m,
                  "m",
                  Closed(kMinOdometrySigmaM, 1e3),
                  "Stated noise of each odometry step, per translation axis "
                  "(at least 0.1 mm: below it the factors' weights overflow "
                  "the solve).")
          .Double("sigma_deg",
                  &S::sigma_deg,
                  "deg",
                  Closed(kMinOdometrySigmaDeg, 180.0),
                  "Stated noise of each odometry step, per rotation axis (at "
                  "least 0.0001 deg).")
          .Build();
  return table;
}

const OptionTable& PoseGraphOwnOptionsTable() {
  using S = PoseGraphOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("PoseGraphOptions")
          .Int("neighbors",
               &S::neighbors,
               AtLeast(1),
               "Edges i -> i+1 .. i+neighbors in the joint problem.")
          .Int("joint_layers",
               &S::joint_layers,
               Closed(1, 2),
               "Finest map layers the joint solve uses, coarse to fine: 1 "
               "(finest only) or 2.")
          .Int("max_iterations",
               &S::max_iterations,
               AtLeast(1),
               "Ceres iteration cap per joint stage.")
          .Bool("both_directions",
                &S::both_directions,
                "Score each pair both ways (else scan j's points against "
                "scan i's map only).")
          .Bool("point_blocks",
                &S::point_blocks,
                "One Ceres residual block per sampled point instead of one "
                "per directed pair (the same normal equations, "
                "mlndt_pair_factor.h).")
          .Double("information_scale",
                  &S::information_scale,
                  "",
                  LeftOpen(0.0, 1e3),
                  "Weight w of every pair's information against the odometry "
                  "factors (calibrated default, docs/embedding.md).")
          .Struct("odometry_noise",
                  &S::odometry_noise,
                  OdometryNoiseTable(),
                  "The odometry factors' stated noise.")
          .Bool("init_from_odometry",
                &S::init_from_odometry,
                "Start from the odometry poses instead of the chained "
                "registrations.")
          .Build();
  return table;
}

}  // namespace mlndt
