#pragma once

// mlndt_map's report: the layer table and extent on stdout (a build and
// `mlndt_map info`), and --output_json (docs/json_schema.md, "mlndt_map").

#include <string>
#include <vector>

#include "mlndt/grid/layered_grid.h"
#include "mlndt/pipeline/map_builder.h"
#include "tools/cli/json_output.h"
#include "tools/cli/scan_input.h"

namespace mlndt {
namespace tools {

// `mlndt_map info`: the file, points, extent, options and layers.
void PrintMapInfo(const std::string& path, const LayeredGrid& map);

// A build's points, extent, layers, memory and times.
void PrintMapBuild(const MapBuildOptions& options,
                   const MapBuildSummary& summary,
                   const LayeredGrid& map);

// A warning on stderr for every scan without a finite point.
void WarnScansWithoutPoints(const ScanInput& input,
                            const MapBuildSummary& summary);

// --output_json of a build written to `output`.
Json MapBuildJson(const std::string& output,
                  const MapBuildOptions& options,
                  const MapBuildSummary& s,
                  const LayeredGrid& map);

}  // namespace tools
}  // namespace mlndt
