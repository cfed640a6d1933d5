#pragma once

// --start_layer against the map's layers. The library clamps a start layer
// beyond the map to its nearest layer (ResolveStartLayer); a tool refuses
// one given on the command line instead, so that the flag is never silently
// changed: s > n, or s <= 0 with n + s < 1 (|s| > 16 is refused with the
// other options, RegistrationOptions::IsValid).

#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {
namespace tools {

// Before any map is built: the layer count the options fix
// (grid.num_layers when grid.finest_cell_size_m is 0), or the most there
// can be (grid.max_num_layers). True when --start_layer was not given.
bool CheckStartLayerBeforeMap(const RegistrationOptions& options,
                              std::string* error);

// Once the reference is read, before the map is built: the layer count of
// the map Register() will build from `reference` (range-filtered, then
// LayerCellSizes over its bounding box). True when --start_layer was not
// given.
bool CheckStartLayerForReference(const RegistrationOptions& options,
                                 const PointCloud& reference,
                                 std::string* error);

// Once the map is known: its `num_layers`. True when --start_layer was not
// given.
bool CheckStartLayerForMap(const LayerScheduleOptions& schedule,
                           int num_layers,
                           std::string* error);

}  // namespace tools
}  // namespace mlndt
