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

// The layer count of the map Register() builds from `reference`: the
// range filter, then the layers LayeredGrid::Build chooses, with its
// coverage rule (LayeredGridOptions::min_covered_fraction lowers n while
// too few points lie in finest cells that can hold a distribution,
// mlndt/grid/cell_coverage.h), found by EstimateMapMemory without building
// the map. False when Register() will refuse the reference or the options
// (it reports why); *error then says so.
bool ReferenceMapNumLayers(const RegistrationOptions& options,
                           const PointCloud& reference,
                           int* num_layers,
                           std::string* error);

// Once the reference is read, before the map is built: the layer count of
// the map Register() will build from it (ReferenceMapNumLayers). True when
// --start_layer was not given, or when Register() will refuse the reference
// itself.
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
