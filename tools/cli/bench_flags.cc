#include "tools/cli/bench_flags.h"

#include "lab/bench/bench_option_tables.h"

namespace mlndt {
namespace tools {
namespace {

// mlndt_bench does not link the shared registration flags.
const TableFlags kBenchFlags(
    BenchOptionsTable(),
    "mlndt_bench",
    {{"pairs.max_pairs", "max_pairs"},
     {"rounds.repetitions", "repetitions"},
     {"rounds.warmup", "warmup"},
     {"rounds.thresholds.max_translation_error_m", "max_translation_error_m"},
     {"rounds.thresholds.max_rotation_error_deg", "max_rotation_error_deg"}},
    {},
    {{"compare_pcl", "compare_pcl_ndt"},
     {"max_translation_error", "max_translation_error_m"},
     {"max_rotation_error", "max_rotation_error_deg"},
     {"pcl_leaf_size", "pcl_leaf_size_m"},
     {"pcl_resolution", "pcl_ndt_resolution_m"},
     {"pcl_step_size", "pcl_ndt_step_size_m"},
     {"pcl_transformation_epsilon", "pcl_ndt_transformation_epsilon"},
     {"pcl_max_iterations", "pcl_ndt_max_iterations"},
     {"pcl_gicp_max_correspondence_distance",
      "pcl_gicp_max_correspondence_distance_m"}},
    nullptr);

}  // namespace

const TableFlags& BenchFlags() { return kBenchFlags; }

}  // namespace tools
}  // namespace mlndt
