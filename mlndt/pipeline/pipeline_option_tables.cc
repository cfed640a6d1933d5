#include "mlndt/pipeline/pipeline_option_tables.h"

#include "mlndt/pipeline/localizer.h"
#include "mlndt/pipeline/map_builder.h"

namespace mlndt {

const OptionTable& MapBuildOwnOptionsTable() {
  using S = MapBuildOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("MapBuildOptions")
          .Double("voxel_size_m",
                  &S::voxel_size_m,
                  "m",
                  ClosedOrZero(1e-3, 1e3),
                  "Voxel edge of the filter of the merged cloud (one "
                  "centroid per voxel); 0 = no filter.")
          .Uint64("max_memory_bytes",
                  &S::max_memory_bytes,
                  "Memory the build may hold at once [bytes]: the merged "
                  "cloud plus the voxel filter's or the map build's working "
                  "memory; 0 = no limit.")
          .Int("num_threads",
               &S::num_threads,
               Closed(1, 256),
               "Threads of the map build (LayeredGrid::Build).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

const OptionTable& LocalizerOwnOptionsTable() {
  using S = LocalizerOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("LocalizerOptions")
          .Enum("motion_model",
                &S::motion_model,
                MotionModelTable(),
                "Initial guess of scan k > 0: constant_velocity (pose_{k-1} "
                "moved by the last relative motion) or constant_pose "
                "(pose_{k-1}).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

}  // namespace mlndt
