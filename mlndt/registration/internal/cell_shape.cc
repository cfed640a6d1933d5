#include "mlndt/registration/internal/cell_shape.h"

#include <utility>
#include <vector>

namespace mlndt {
namespace internal {

Eigen::Array<bool, 3, 1> ThinCellDirections(const NdtCell& cell) {
  // Row i of W is v_i^T / sqrt(lambda_i) (ndt_cell.h).
  const Eigen::Vector3d variances =
      cell.whitening.rowwise().squaredNorm().cwiseInverse();
  return variances.array() < kThinCellDirection * variances.maxCoeff();
}

NdtLayer WithoutLineCells(const NdtLayer& layer) {
  std::vector<NdtCell> cells;
  std::vector<int64_t> keys;
  cells.reserve(layer.cells().size());
  keys.reserve(layer.cells().size());
  for (size_t i = 0; i < layer.cells().size(); ++i) {
    if (ThinCellDirections(layer.cells()[i]).count() == 2) continue;
    cells.push_back(layer.cells()[i]);
    keys.push_back(layer.keys()[i]);
  }
  return NdtLayer(layer.origin(),
                  layer.cell_size(),
                  layer.dims(),
                  std::move(cells),
                  std::move(keys));
}

}  // namespace internal
}  // namespace mlndt
