#include "mlndt/grid/grid_io.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <utility>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"
#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace {

constexpr char kMagic[8] = {'M', 'L', 'N', 'D', 'T', 'M', 'A', 'P'};
// Version 2 adds the cell rules (grid_io.h); a map that scores every cell
// with its whole covariance is still written as version 1.
constexpr uint32_t kVersion = 2;

// Byte counts of the fixed parts (grid_io.h).
constexpr size_t kHeaderBytes = 8 + 4 + 3 * 4 + 2 * 8 + 6 * 8 + 8;  // 96, v1
constexpr size_t kLayerHeaderBytes = 3 * 8 + 8 + 3 * 4 + 8;         // 52
constexpr size_t kCellBytes = 8 + 4 + 3 * 8 + 6 * 8;                // 84
constexpr size_t kChecksumBytes = 8;
static_assert(kHeaderBytes == 96 && kLayerHeaderBytes == 52 && kCellBytes == 84,
              "the layout documented in grid_io.h");

// Limits a map must respect (grid_io.h).
constexpr int kMaxLayers = 16;
constexpr int32_t kMaxDimsPerAxis = 1000000;
constexpr int64_t kMaxDenseIndexCells = 3 * CellIndex::kMaxDenseCells;

uint64_t Fnv1a(const char* bytes, size_t size) {
  uint64_t hash = 14695981039346656037ull;
  for (size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 1099511628211ull;
  }
  return hash;
}

// Appends fields in little-endian byte order, whatever the host's.
class Writer {
 public:
  void Raw(const char* bytes, size_t size) { bytes_.append(bytes, size); }
  void U32(uint32_t value) { Unsigned(value, 4); }
  void I32(int32_t value) { Unsigned(static_cast<uint32_t>(value), 4); }
  void U64(uint64_t value) { Unsigned(value, 8); }
  void I64(int64_t value) { Unsigned(static_cast<uint64_t>(value), 8); }
  // IEEE 754 binary64, the bits in little-endian order.
  void F64(double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof(bits));
    Unsigned(bits, 8);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  void Unsigned(uint64_t value, int size) {
    for (int i = 0; i < size; ++i) {
      bytes_.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
    }
  }
  std::string bytes_;
};

// Reads little-endian fields from [data, data + size); every getter returns
// false (and reads nothing) when fewer bytes are left than it needs.
class Reader {
 public:
  Reader(const char* data, size_t size) : data_(data), size_(size) {}
  bool U32(uint32_t* value) {
    uint64_t v;
    if (!Unsigned(4, &v)) return false;
    *value = static_cast<uint32_t>(v);
    return true;
  }
  bool I32(int32_t* value) {
    uint32_t v;
    if (!U32(&v)) return false;
    *value = static_cast<int32_t>(v);
    return true;
  }
  bool U64(uint64_t* value) { return Unsigned(8, value); }
  bool I64(int64_t* value) {
    uint64_t v;
    if (!Unsigned(8, &v)) return false;
    *value = static_cast<int64_t>(v);
    return true;
  }
  bool F64(double* value) {
    uint64_t bits;
    if (!Unsigned(8, &bits)) return false;
    std::memcpy(value, &bits, sizeof(bits));
    return true;
  }
  // Skips `bytes`; false when fewer are left.
  bool Skip(uint64_t bytes) {
    if (remaining() < bytes) return false;
    offset_ += static_cast<size_t>(bytes);
    return true;
  }
  size_t remaining() const { return size_ - offset_; }

 private:
  bool Unsigned(int size, uint64_t* value) {
    if (remaining() < static_cast<size_t>(size)) return false;
    *value =
        internal::LoadUnsigned(data_ + offset_, size, /*big_endian=*/false);
    offset_ += static_cast<size_t>(size);
    return true;
  }
  const char* data_;
  size_t size_;
  size_t offset_ = 0;
};

bool Fail(const std::string& path,
          const std::string& problem,
          std::string* error) {
  *error = path + ": " + problem;
  return false;
}

std::string Str(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// One layer's header as read, checked against the map header and the bytes
// left before anything is allocated for it.
struct LayerHeader {
  Eigen::Vector3d origin;
  double cell_size = 0.0;
  Eigen::Vector3i dims;
  uint64_t num_cells = 0;
  int64_t grid_cells = 0;
};

bool CheckLayerHeader(const LayerHeader& h,
                      const Eigen::AlignedBox3d& bounds,
                      double coarser_cell_size,
                      size_t bytes_left,
                      std::string* problem) {
  if (!h.origin.allFinite() || !std::isfinite(h.cell_size) ||
      !(h.cell_size > 0.0)) {
    *problem = "origin or cell size not finite and positive";
    return false;
  }
  if ((h.dims.array() < 1).any() || (h.dims.array() > kMaxDimsPerAxis).any()) {
    *problem = "dims outside 1.." + std::to_string(kMaxDimsPerAxis);
    return false;
  }
  if (coarser_cell_size > 0.0 && !(h.cell_size < coarser_cell_size)) {
    *problem = "cell size " + Str(h.cell_size) +
               " m is not smaller than the coarser layer's " +
               Str(coarser_cell_size) + " m";
    return false;
  }
  // The grid covers the bounding box from its min corner with at most one
  // spare cell per axis (LayeredGrid::Build: origin = min corner, dims =
  // floor(extent / cell size) + 1).
  const Eigen::Vector3d extent = bounds.sizes();
  for (int a = 0; a < 3; ++a) {
    const double slack =
        1e-6 * (std::abs(bounds.min()(a)) + extent(a) + h.cell_size);
    const double covered = h.dims(a) * h.cell_size;
    if (std::abs(h.origin(a) - bounds.min()(a)) > slack ||
        covered < extent(a) - slack ||
        (h.dims(a) - 2) * h.cell_size > extent(a) + slack) {
      *problem = "dims " + std::to_string(h.dims(a)) + " of " +
                 Str(h.cell_size) + " m cells on axis " + std::to_string(a) +
                 " do not fit the " + Str(extent(a)) + " m bounding box";
      return false;
    }
  }
  if (h.num_cells > static_cast<uint64_t>(h.grid_cells)) {
    *problem = std::to_string(h.num_cells) + " cells in a grid of " +
               std::to_string(h.grid_cells) + " cells";
    return false;
  }
  if (h.num_cells > bytes_left / kCellBytes) {
    *problem = std::to_string(h.num_cells) + " cells need " +
               std::to_string(h.num_cells) + " * " +
               std::to_string(kCellBytes) + " bytes, the file has " +
               std::to_string(bytes_left) + " left";
    return false;
  }
  return true;
}

// The mean of a cell's points lies in the cell (up to rounding: a
// thousandth of the cell edge).
bool MeanInsideCell(const LayerHeader& h,
                    int64_t key,
                    const Eigen::Vector3d& mean) {
  const int64_t ijk[3] = {key % h.dims.x(),
                          key / h.dims.x() % h.dims.y(),
                          key / (int64_t{h.dims.x()} * h.dims.y())};
  const double slack = 1e-3 * h.cell_size;
  for (int a = 0; a < 3; ++a) {
    const double low = h.origin(a) + static_cast<double>(ijk[a]) * h.cell_size;
    if (!(mean(a) >= low - slack && mean(a) <= low + h.cell_size + slack)) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool SaveLayeredGrid(const std::string& path,
                     const LayeredGrid& grid,
                     std::string* error) {
  CHECK(error != nullptr);
  Writer w;
  w.Raw(kMagic, sizeof(kMagic));
  const LayeredGridOptions& o = grid.options();
  const CellRegularization& g = o.regularization;
  const bool cell_rules = g.line_ratio != 0.0 || g.plane_ratio != 0.0;
  w.U32(cell_rules ? kVersion : 1);
  w.I32(o.division_constant);
  w.I32(grid.num_layers());
  w.I32(o.min_points_per_cell);
  w.F64(g.min_eigenvalue_ratio);
  w.F64(g.min_eigenvalue_m2);
  if (cell_rules) {
    w.F64(g.line_ratio);
    w.F64(g.plane_ratio);
    w.F64(g.in_plane_variance_scale);
  }
  for (int a = 0; a < 3; ++a) w.F64(grid.bounds().min()(a));
  for (int a = 0; a < 3; ++a) w.F64(grid.bounds().max()(a));
  w.U64(grid.num_points());
  for (int i = 1; i <= grid.num_layers(); ++i) {
    const NdtLayer& layer = grid.layer(i);
    for (int a = 0; a < 3; ++a) w.F64(layer.origin()(a));
    w.F64(layer.cell_size());
    for (int a = 0; a < 3; ++a) w.I32(layer.dims()(a));
    w.U64(layer.cells().size());
    for (size_t c = 0; c < layer.cells().size(); ++c) {
      const NdtCell& cell = layer.cells()[c];
      w.I64(layer.keys()[c]);
      w.I32(cell.count);
      for (int a = 0; a < 3; ++a) w.F64(cell.mean(a));
      for (int r = 0; r < 3; ++r) {
        for (int s = r; s < 3; ++s) w.F64(cell.covariance(r, s));
      }
    }
  }
  w.U64(Fnv1a(w.bytes().data(), w.bytes().size()));
  return WriteFileAtomically(path, w.bytes(), error);
}

namespace {

// The map header: options, bounds and point count.
struct MapHeader {
  LayeredGridOptions options = PaperLayeredGridOptions();
  Eigen::AlignedBox3d bounds;
  uint64_t num_points = 0;
};

// Magic, version and checksum (FNV-1a of everything before it).
bool CheckPreamble(const std::string& path,
                   const std::string& bytes,
                   uint32_t* version,
                   std::string* error) {
  if (bytes.size() < sizeof(kMagic) ||
      std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) {
    return Fail(path, "not an mlndt map file (bad magic)", error);
  }
  if (bytes.size() < sizeof(kMagic) + 4 + kChecksumBytes) {
    return Fail(path, "truncated map file", error);
  }
  const size_t body_size = bytes.size() - kChecksumBytes;
  Reader(bytes.data() + sizeof(kMagic), 4).U32(version);
  if (*version != 1 && *version != kVersion) {
    return Fail(path,
                "unsupported map version " + std::to_string(*version) +
                    " (this build reads 1 and " + std::to_string(kVersion) +
                    ")",
                error);
  }
  const uint64_t stored_checksum = internal::LoadUnsigned(
      bytes.data() + body_size, kChecksumBytes, /*big_endian=*/false);
  if (Fnv1a(bytes.data(), body_size) != stored_checksum) {
    return Fail(
        path, "checksum mismatch: the map file is corrupt or truncated", error);
  }
  return true;
}

// The map header. The file stores n itself, not the finest cell it was
// derived from.
bool ReadMapHeader(const std::string& path,
                   uint32_t version,
                   Reader* r,
                   MapHeader* header,
                   std::string* error) {
  LayeredGridOptions& options = header->options;
  int32_t q = 0, n = 0, min_points = 0;
  CellRegularization& regularization = options.regularization;
  Eigen::Vector3d lo, hi;
  bool ok = r->I32(&q) && r->I32(&n) && r->I32(&min_points) &&
            r->F64(&regularization.min_eigenvalue_ratio) &&
            r->F64(&regularization.min_eigenvalue_m2);
  if (ok && version >= 2) {  // Version 1: whole covariances (the header's).
    ok = r->F64(&regularization.line_ratio) &&
         r->F64(&regularization.plane_ratio) &&
         r->F64(&regularization.in_plane_variance_scale);
  }
  for (int a = 0; a < 3; ++a) ok = ok && r->F64(&lo(a));
  for (int a = 0; a < 3; ++a) ok = ok && r->F64(&hi(a));
  ok = ok && r->U64(&header->num_points);
  if (!ok) return Fail(path, "truncated map header", error);
  if (n < 1 || n > kMaxLayers) {
    return Fail(path,
                "bad map header: " + std::to_string(n) + " layers (1 to " +
                    std::to_string(kMaxLayers) + " allowed)",
                error);
  }
  options.division_constant = q;
  options.num_layers = n;
  options.max_num_layers = kMaxLayers;
  options.min_points_per_cell = min_points;
  std::string option_error;
  if (!options.IsValid(&option_error)) {
    return Fail(path, "bad map header: " + option_error, error);
  }
  if (!lo.allFinite() || !hi.allFinite() || (lo.array() > hi.array()).any()) {
    return Fail(
        path, "bad map header: bounding box not finite or inverted", error);
  }
  if (r->remaining() / kLayerHeaderBytes < static_cast<size_t>(n)) {
    return Fail(path,
                "truncated map file: " + std::to_string(n) +
                    " layers need at least " +
                    std::to_string(n * kLayerHeaderBytes) + " bytes, " +
                    std::to_string(r->remaining()) + " left",
                error);
  }
  header->bounds = Eigen::AlignedBox3d(lo, hi);
  return true;
}

// Pass 1: every layer header, checked, before anything is allocated (the
// cells of each layer are skipped; their bytes were checked to exist).
bool ReadLayerHeaders(const std::string& path,
                      const MapHeader& map,
                      Reader* r,
                      std::vector<LayerHeader>* headers,
                      std::string* error) {
  const int n = map.options.num_layers;
  headers->resize(static_cast<size_t>(n));
  double coarser_cell_size = 0.0;
  int64_t dense_index_cells = 0;
  for (int i = 1; i <= n; ++i) {
    const std::string layer_tag = "layer " + std::to_string(i);
    LayerHeader& h = (*headers)[static_cast<size_t>(i - 1)];
    bool ok = true;
    for (int a = 0; a < 3; ++a) ok = ok && r->F64(&h.origin(a));
    ok = ok && r->F64(&h.cell_size);
    for (int a = 0; a < 3; ++a) ok = ok && r->I32(&h.dims(a));
    ok = ok && r->U64(&h.num_cells);
    if (!ok) return Fail(path, "truncated header of " + layer_tag, error);
    std::string problem;
    h.grid_cells = 0;
    if ((h.dims.array() >= 1).all() &&
        (h.dims.array() <= kMaxDimsPerAxis).all()) {
      h.grid_cells = int64_t{h.dims.x()} * h.dims.y() * h.dims.z();
    }
    if (!CheckLayerHeader(
            h, map.bounds, coarser_cell_size, r->remaining(), &problem)) {
      return Fail(path, "bad header of " + layer_tag + ": " + problem, error);
    }
    // Layers of at most CellIndex::kMaxDenseCells grid cells get a dense
    // index of 4 bytes a grid cell when built (ndt_layer.h); bound the sum.
    if (h.grid_cells <= CellIndex::kMaxDenseCells) {
      dense_index_cells += h.grid_cells;
      if (dense_index_cells > kMaxDenseIndexCells) {
        return Fail(path,
                    "bad header of " + layer_tag +
                        ": the dense cell index of the layers so far would "
                        "take " +
                        std::to_string(dense_index_cells * 4 / (1 << 20)) +
                        " MiB (at most " +
                        std::to_string(kMaxDenseIndexCells * 4 / (1 << 20)) +
                        " MiB allowed)",
                    error);
      }
    }
    coarser_cell_size = h.cell_size;
    r->Skip(h.num_cells * kCellBytes);  // Cannot fail: checked above.
  }
  if (r->remaining() != 0) {
    return Fail(
        path,
        std::to_string(r->remaining()) + " trailing bytes after the last layer",
        error);
  }
  return true;
}

// One cell record; an empty `problem` when it is usable. `points_in_cells`
// sums the counts read so far.
void ReadCell(const LayerHeader& h,
              const MapHeader& map,
              Reader* r,
              uint64_t* points_in_cells,
              int64_t* key,
              NdtCell* cell,
              std::string* problem) {
  int32_t count = 0;
  Eigen::Vector3d mean;
  Eigen::Matrix3d covariance;
  bool ok = r->I64(key) && r->I32(&count);
  for (int a = 0; a < 3; ++a) ok = ok && r->F64(&mean(a));
  for (int a = 0; a < 3; ++a) {
    for (int b = a; b < 3; ++b) {
      ok = ok && r->F64(&covariance(a, b));
      covariance(b, a) = covariance(a, b);
    }
  }
  *points_in_cells += count > 0 ? static_cast<uint64_t>(count) : 0;
  if (!ok) {
    *problem = "truncated";
  } else if (*key < 0 || *key >= h.grid_cells) {
    *problem = "key " + std::to_string(*key) + " outside the grid";
  } else if (count < 1) {
    *problem = "point count " + std::to_string(count);
  } else if (*points_in_cells > map.num_points) {
    *problem = "the cells hold more points than the map's " +
               std::to_string(map.num_points) + " points";
  } else if (!MeanInsideCell(h, *key, mean)) {
    *problem = "mean outside its cell";
  } else if (!MakeNdtCell(
                 count, mean, covariance, map.options.regularization, cell)) {
    *problem = "no usable mean and covariance";
  }
}

// Pass 2: the cells of layer i (1-based), the reader at its header.
bool ReadLayerCells(const std::string& path,
                    const MapHeader& map,
                    const LayerHeader& h,
                    int i,
                    Reader* r,
                    std::vector<NdtCell>* cells,
                    std::vector<int64_t>* keys,
                    std::string* error) {
  const std::string layer_tag = "layer " + std::to_string(i);
  r->Skip(kLayerHeaderBytes);
  // Cells: bounded by the bytes of the file (checked in pass 1).
  cells->reserve(h.num_cells);
  keys->reserve(h.num_cells);
  uint64_t points_in_cells = 0;
  for (uint64_t c = 0; c < h.num_cells; ++c) {
    int64_t key = 0;
    NdtCell cell;
    std::string cell_problem;
    ReadCell(h, map, r, &points_in_cells, &key, &cell, &cell_problem);
    if (!cell_problem.empty()) {
      return Fail(path,
                  "bad cell " + std::to_string(c) + " in " + layer_tag + ": " +
                      cell_problem,
                  error);
    }
    cells->push_back(cell);
    keys->push_back(key);
  }
  // Unique keys (NdtLayer CHECKs it); sorting a copy costs 8 bytes a cell,
  // not a table over the whole grid.
  std::vector<int64_t> sorted = *keys;
  std::sort(sorted.begin(), sorted.end());
  const auto duplicate = std::adjacent_find(sorted.begin(), sorted.end());
  if (duplicate != sorted.end()) {
    return Fail(path,
                "bad cells in " + layer_tag + ": key " +
                    std::to_string(*duplicate) + " appears twice",
                error);
  }
  return true;
}

}  // namespace

bool LoadLayeredGrid(const std::string& path,
                     LayeredGrid* grid,
                     std::string* error) {
  CHECK(grid != nullptr);
  CHECK(error != nullptr);
  std::string bytes;
  if (!internal::ReadFileToString(path, &bytes, error)) return false;
  uint32_t version = 0;
  if (!CheckPreamble(path, bytes, &version, error)) return false;
  const size_t body_size = bytes.size() - kChecksumBytes;
  Reader r(bytes.data() + sizeof(kMagic) + 4, body_size - sizeof(kMagic) - 4);
  MapHeader map;
  if (!ReadMapHeader(path, version, &r, &map, error)) return false;
  const Reader cells_start = r;
  std::vector<LayerHeader> headers;
  if (!ReadLayerHeaders(path, map, &r, &headers, error)) return false;

  r = cells_start;
  std::vector<NdtLayer> layers;
  std::vector<LayerInfo> info;
  for (int i = 1; i <= map.options.num_layers; ++i) {
    const LayerHeader& h = headers[static_cast<size_t>(i - 1)];
    std::vector<NdtCell> cells;
    std::vector<int64_t> keys;
    if (!ReadLayerCells(path, map, h, i, &r, &cells, &keys, error)) {
      return false;
    }
    LayerInfo layer_info;
    layer_info.layer = i;
    layer_info.cell_size_m = h.cell_size;
    layer_info.dims = h.dims;
    layer_info.occupied_cells = cells.size();
    info.push_back(layer_info);
    layers.emplace_back(
        h.origin, h.cell_size, h.dims, std::move(cells), std::move(keys));
  }
  *grid = LayeredGrid(map.options,
                      map.bounds,
                      map.num_points,
                      std::move(layers),
                      std::move(info));
  return true;
}

}  // namespace mlndt
