#pragma once

// Flags of the map tools (mlndt_map, mlndt_localize): the layered-map
// options from the shared registration flags (registration_flags.h), and
// refusals of the shared flags a tool does not read, so that a flag given
// on the command line is never silently ignored.

#include <string>
#include <vector>

#include "mlndt/grid/layered_grid.h"
#include "tools/cli/flag_utils.h"

namespace mlndt {
namespace tools {

// The map options of --preset (default | paper) and the map flags given:
// every LayeredGridOptions field's (option_flags.h: --finest_cell_size_m,
// --num_layers, --division_constant, --min_points_per_cell, ...). False
// with *error naming the flag for a bad value, for --num_layers with
// --finest_cell_size_m > 0, and for any other registration flag given
// (`tool` names the tool in the message).
bool GridOptionsFromFlags(const std::string& tool,
                          LayeredGridOptions* grid,
                          std::string* error);

// False with *error naming the first of the map flags above (and
// --coarse_weighting) given on the command line: a tool that loads a map
// file cannot change its cells.
bool RefuseMapFlags(const std::string& tool, std::string* error);

// The shared flags mlndt_map refuses (GridOptionsFromFlags) and those
// mlndt_localize refuses (RefuseMapFlags, and conventional NDT's): their
// --help leaves them out (HideFlagsFromHelp, tool_main.h).
const std::vector<std::string>& MapBuildRefusedFlags();
const std::vector<std::string>& LocalizerRefusedFlags();

}  // namespace tools
}  // namespace mlndt
