#include "mlndt/grid/grid_io.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <type_traits>

namespace mlndt {
namespace {

constexpr char kMagic[8] = {'M', 'L', 'N', 'D', 'T', 'M', 'A', 'P'};
constexpr uint32_t kVersion = 1;

uint64_t Fnv1a(const std::string& bytes) {
  uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

class Writer {
 public:
  template <typename T>
  void Put(const T& value) {
    static_assert(std::is_trivially_copyable<T>::value, "plain data only");
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  std::string* bytes() { return &bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  bool Get(T* value) {
    if (bytes_.size() - offset_ < sizeof(T)) return false;
    std::memcpy(value, bytes_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return true;
  }
  size_t remaining() const { return bytes_.size() - offset_; }

 private:
  const std::string& bytes_;
  size_t offset_ = 0;
};

bool Fail(const std::string& path,
          const std::string& problem,
          std::string* error) {
  *error = path + ": " + problem;
  return false;
}

}  // namespace

bool SaveLayeredGrid(const std::string& path,
                     const LayeredGrid& grid,
                     std::string* error) {
  Writer w;
  w.bytes()->append(kMagic, sizeof(kMagic));
  w.Put(kVersion);
  const LayeredGridOptions& o = grid.options();
  w.Put(int32_t{o.division_constant});
  w.Put(int32_t{grid.num_layers()});
  w.Put(int32_t{o.min_points_per_cell});
  w.Put(o.regularization.min_eigenvalue_ratio);
  w.Put(o.regularization.min_eigenvalue_m2);
  for (int a = 0; a < 3; ++a) w.Put(grid.bounds().min()(a));
  for (int a = 0; a < 3; ++a) w.Put(grid.bounds().max()(a));
  w.Put(uint64_t{grid.num_points()});
  for (int i = 1; i <= grid.num_layers(); ++i) {
    const NdtLayer& layer = grid.layer(i);
    for (int a = 0; a < 3; ++a) w.Put(layer.origin()(a));
    w.Put(layer.cell_size());
    for (int a = 0; a < 3; ++a) w.Put(int32_t{layer.dims()(a)});
    w.Put(uint64_t{layer.cells().size()});
    for (size_t c = 0; c < layer.cells().size(); ++c) {
      const NdtCell& cell = layer.cells()[c];
      w.Put(int64_t{layer.keys()[c]});
      w.Put(int32_t{cell.count});
      for (int a = 0; a < 3; ++a) w.Put(cell.mean(a));
      for (int r = 0; r < 3; ++r) {
        for (int s = r; s < 3; ++s) w.Put(cell.covariance(r, s));
      }
    }
  }
  w.Put(Fnv1a(*w.bytes()));

  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return Fail(path, "cannot open for writing", error);
    out.write(w.bytes()->data(),
              static_cast<std::streamsize>(w.bytes()->size()));
    if (!out) {
      std::remove(temporary.c_str());
      return Fail(path, "write failed", error);
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return Fail(path, "cannot rename the temporary file into place", error);
  }
  return true;
}

bool LoadLayeredGrid(const std::string& path,
                     LayeredGrid* grid,
                     std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return Fail(
        path, "cannot open the map file (missing or unreadable)", error);
  const std::string bytes((std::istreambuf_iterator<char>(in)),
                          std::istreambuf_iterator<char>());
  if (bytes.size() < sizeof(kMagic) ||
      std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) {
    return Fail(path, "not an mlndt map file (bad magic)", error);
  }
  if (bytes.size() < sizeof(kMagic) + sizeof(uint32_t) + sizeof(uint64_t)) {
    return Fail(path, "truncated map file", error);
  }
  const std::string body = bytes.substr(0, bytes.size() - sizeof(uint64_t));
  uint64_t stored_checksum = 0;
  std::memcpy(&stored_checksum, bytes.data() + body.size(), sizeof(uint64_t));

  Reader r(body);
  char magic[8];
  for (char& c : magic) r.Get(&c);
  uint32_t version = 0;
  r.Get(&version);
  if (version != kVersion) {
    return Fail(path,
                "unsupported map version " + std::to_string(version) +
                    " (this build reads " + std::to_string(kVersion) + ")",
                error);
  }
  if (Fnv1a(body) != stored_checksum) {
    return Fail(
        path, "checksum mismatch: the map file is corrupt or truncated", error);
  }
  // The file stores n itself, not the finest cell it was derived from.
  LayeredGridOptions options = PaperLayeredGridOptions();
  int32_t q = 0, n = 0, min_points = 0;
  CellRegularization& regularization = options.regularization;
  Eigen::Vector3d lo, hi;
  uint64_t num_points = 0;
  bool ok = r.Get(&q) && r.Get(&n) && r.Get(&min_points) &&
            r.Get(&regularization.min_eigenvalue_ratio) &&
            r.Get(&regularization.min_eigenvalue_m2);
  for (int a = 0; a < 3; ++a) ok = ok && r.Get(&lo(a));
  for (int a = 0; a < 3; ++a) ok = ok && r.Get(&hi(a));
  ok = ok && r.Get(&num_points);
  options.division_constant = q;
  options.num_layers = n;
  options.max_num_layers = 16;
  options.min_points_per_cell = min_points;
  std::string option_error;
  if (!ok || !options.IsValid(&option_error)) {
    return Fail(path, "bad map header " + option_error, error);
  }

  std::vector<NdtLayer> layers;
  std::vector<LayerInfo> info;
  for (int i = 1; i <= n; ++i) {
    Eigen::Vector3d origin;
    double cell_size = 0;
    Eigen::Vector3i dims;
    uint64_t num_cells = 0;
    for (int a = 0; a < 3; ++a) ok = ok && r.Get(&origin(a));
    ok = ok && r.Get(&cell_size);
    for (int a = 0; a < 3; ++a) ok = ok && r.Get(&dims(a));
    ok = ok && r.Get(&num_cells);
    constexpr size_t kCellBytes =
        sizeof(int64_t) + sizeof(int32_t) + 9 * sizeof(double);
    if (!ok || !origin.allFinite() || !(cell_size > 0) ||
        (dims.array() < 1).any() || (dims.array() > 1000000).any() ||
        num_cells > r.remaining() / kCellBytes) {
      return Fail(path, "bad header of layer " + std::to_string(i), error);
    }
    const int64_t grid_cells = int64_t{dims.x()} * dims.y() * dims.z();
    std::vector<NdtCell> cells;
    std::vector<int64_t> keys;
    CellIndex seen(grid_cells);
    for (uint64_t c = 0; c < num_cells; ++c) {
      int64_t key = 0;
      int32_t count = 0;
      Eigen::Vector3d mean;
      Eigen::Matrix3d covariance;
      ok = r.Get(&key) && r.Get(&count);
      for (int a = 0; a < 3; ++a) ok = ok && r.Get(&mean(a));
      for (int a = 0; a < 3; ++a) {
        for (int b = a; b < 3; ++b) {
          ok = ok && r.Get(&covariance(a, b));
          covariance(b, a) = covariance(a, b);
        }
      }
      NdtCell cell;
      if (!ok || key < 0 || key >= grid_cells ||
          seen.FindOrInsert(key, static_cast<int32_t>(c)) !=
              static_cast<int32_t>(c) ||
          !MakeNdtCell(count, mean, covariance, regularization, &cell)) {
        return Fail(
            path,
            "bad cell " + std::to_string(c) + " in layer " + std::to_string(i),
            error);
      }
      cells.push_back(cell);
      keys.push_back(key);
    }
    LayerInfo layer_info;
    layer_info.layer = i;
    layer_info.cell_size_m = cell_size;
    layer_info.dims = dims;
    layer_info.occupied_cells = cells.size();
    info.push_back(layer_info);
    layers.emplace_back(
        origin, cell_size, dims, std::move(cells), std::move(keys));
  }
  if (r.remaining() != 0)
    return Fail(path, "trailing bytes after the last layer", error);
  *grid = LayeredGrid(options,
                      Eigen::AlignedBox3d(lo, hi),
                      num_points,
                      std::move(layers),
                      std::move(info));
  return true;
}

}  // namespace mlndt
