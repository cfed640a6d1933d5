#include "tools/cli/map_build_flags.h"

#include "mlndt/pipeline/pipeline_option_tables.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kMapBuildFlags(MapBuildOwnOptionsTable(),
                                "mlndt_map",
                                {{"voxel_size_m", "voxel_size"}},
                                {{"max_memory_bytes", "max_memory_gb"}},
                                &IsSharedFlag);

}  // namespace

const TableFlags& MapBuildFlags() { return kMapBuildFlags; }

}  // namespace tools
}  // namespace mlndt
