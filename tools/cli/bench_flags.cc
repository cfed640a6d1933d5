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
    nullptr);

}  // namespace

const TableFlags& BenchFlags() { return kBenchFlags; }

}  // namespace tools
}  // namespace mlndt
