#include "tools/cli/start_layer_check.h"

#include "mlndt/cloud/range_filter.h"
#include "mlndt/grid/map_memory.h"
#include "tools/cli/flag_utils.h"

namespace mlndt {
namespace tools {
namespace {

bool CheckAgainst(int start_layer,
                  int num_layers,
                  const std::string& what,
                  std::string* error) {
  if (!FlagGiven("start_layer")) return true;
  const int resolved = start_layer > 0 ? start_layer : num_layers + start_layer;
  if (resolved >= 1 && resolved <= num_layers) return true;
  *error = "--start_layer=" + std::to_string(start_layer) +
           " is out of range: " + what + " " + std::to_string(num_layers) +
           " layer(s); give 1.." + std::to_string(num_layers) + " or " +
           std::to_string(1 - num_layers) + "..0 (from the finest)";
  return false;
}

}  // namespace

bool CheckStartLayerBeforeMap(const RegistrationOptions& options,
                              std::string* error) {
  const LayeredGridOptions& grid = options.grid;
  if (grid.finest_cell_size_m > 0.0) {
    // n is derived from the extent: only s > max_num_layers is known now.
    return options.schedule.start_layer <= 0 ||
           CheckAgainst(options.schedule.start_layer,
                        grid.max_num_layers,
                        "a map has at most",
                        error);
  }
  return CheckAgainst(options.schedule.start_layer,
                      grid.num_layers,
                      "the map will have (--num_layers)",
                      error);
}

bool ReferenceMapNumLayers(const RegistrationOptions& options,
                           const PointCloud& reference,
                           int* num_layers,
                           std::string* error) {
  const PointCloud kept =
      FilterByRange(options.range_filter, reference, nullptr);
  MapMemoryEstimate estimate;
  if (!EstimateMapMemory(options.grid, kept, 0, &estimate, error)) {
    return false;
  }
  *num_layers = static_cast<int>(estimate.layers.size());
  return true;
}

bool CheckStartLayerForReference(const RegistrationOptions& options,
                                 const PointCloud& reference,
                                 std::string* error) {
  if (!FlagGiven("start_layer")) return true;
  int num_layers = 0;
  std::string refused;
  // Register() reports a reference or options it refuses.
  if (!ReferenceMapNumLayers(options, reference, &num_layers, &refused)) {
    return true;
  }
  return CheckAgainst(options.schedule.start_layer,
                      num_layers,
                      "the reference's map will have",
                      error);
}

bool CheckStartLayerForMap(const LayerScheduleOptions& schedule,
                           int num_layers,
                           std::string* error) {
  return CheckAgainst(schedule.start_layer, num_layers, "the map has", error);
}

}  // namespace tools
}  // namespace mlndt
