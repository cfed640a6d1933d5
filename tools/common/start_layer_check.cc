#include "tools/common/start_layer_check.h"

#include "mlndt/cloud/range_filter.h"
#include "mlndt/grid/layered_grid.h"
#include "tools/common/flag_utils.h"

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

bool CheckStartLayerForReference(const RegistrationOptions& options,
                                 const PointCloud& reference,
                                 std::string* error) {
  if (!FlagGiven("start_layer")) return true;
  const PointCloud kept =
      FilterByRange(options.range_filter, reference, nullptr);
  if (kept.empty()) return true;  // Register() reports it.
  const int num_layers = static_cast<int>(
      LayerCellSizes(options.grid, BoundingBox(kept).sizes()).size());
  if (num_layers == 0) return true;  // Invalid options: IsValid reports them.
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
