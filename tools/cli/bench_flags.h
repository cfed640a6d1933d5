#pragma once

// mlndt_bench's flags of BenchOptions' single values (table_flags.h, made
// from BenchOptionsTable): --repetitions, --warmup, --max_pairs,
// --max_translation_error_m, --max_rotation_error_deg (the rounds' and the
// pairs' fields by their own names), --compare_pcl_ndt, --compare_pcl_gicp
// and --pcl_<field> of PclBenchOptions. The grid's list flags, --seed and
// the pairs' path and lists stay the tool's (tests/tools/
// tool_option_flags_test.cc lists them with their reasons). Linking this
// file gives a tool these flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& BenchFlags();

}  // namespace tools
}  // namespace mlndt
