#pragma once

// The layered map's flags for a tool that builds maps only to describe them
// (mlndt_info --layers): the shared registration flags of grid.*
// (option_flags.h: --num_layers, --division_constant, --finest_cell_size_m,
// --min_points_per_cell, ...), over a base the tool chooses (and shown as
// their defaults); the other
// shared flags (linked with these) are refused and left out of --help.

#include <string>
#include <vector>

#include "mlndt/grid/layered_grid.h"

namespace mlndt {
namespace tools {

// The shared flags of every other option: call HideFlagsFromHelp on them
// before StartTool.
std::vector<std::string> NonGridFlags();
// Makes `base` the grid flags' defaults (their --help shows them); call
// before StartTool with the base given to ApplyGridFlags.
void SetGridFlagDefaults(const LayeredGridOptions& base);
// Whether any of GridFlags() was given.
bool GridFlagsGiven();

// Sets the fields of *grid from the grid flags given (the others keep
// *grid's values); false with *error naming the flag for a bad value, for
// --num_layers with --finest_cell_size_m > 0, and for any other shared flag
// given (`tool` names the tool in the message).
bool ApplyGridFlags(const std::string& tool,
                    LayeredGridOptions* grid,
                    std::string* error);

}  // namespace tools
}  // namespace mlndt
