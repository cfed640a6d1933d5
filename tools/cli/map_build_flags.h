#pragma once

// mlndt_map's flags of MapBuildOptions' own fields (table_flags.h, made from
// MapBuildOwnOptionsTable): voxel_size_m is --voxel_size (--voxel_size_m is
// the sampling's, refused by mlndt_map); num_threads is the shared
// --num_threads; max_memory_bytes is set by
// mlndt_map's --max_memory_gb (GB, 10^9 bytes). Linking this file gives a
// tool these flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& MapBuildFlags();

}  // namespace tools
}  // namespace mlndt
