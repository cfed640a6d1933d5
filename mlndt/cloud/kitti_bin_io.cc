// KITTI Velodyne .bin reading: a headerless array of little-endian float32
// records "x y z intensity" (16 bytes per point), metres, in the Velodyne
// frame (x forward, y left, z up). The KITTI devkit reads it with
// fread(data, sizeof(float), 4 * n, stream).

#include <string>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"

namespace mlndt {
namespace internal {

bool ParseKittiBin(const std::string& data,
                   std::vector<Eigen::Vector3d>* points,
                   std::string* error) {
  constexpr size_t kRecordBytes = 16;
  if (data.empty()) {
    *error = "empty file: no points (KITTI .bin records are 16 bytes each)";
    return false;
  }
  if (data.size() % kRecordBytes != 0) {
    *error = "file size " + std::to_string(data.size()) +
             " bytes is not a multiple of 16 (KITTI .bin records are float32 "
             "x y z intensity)";
    return false;
  }
  const size_t count = data.size() / kRecordBytes;
  points->reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const char* record = data.data() + i * kRecordBytes;
    points->emplace_back(LoadFloat(record, 4, /*big_endian=*/false),
                         LoadFloat(record + 4, 4, /*big_endian=*/false),
                         LoadFloat(record + 8, 4, /*big_endian=*/false));
  }
  return true;
}

}  // namespace internal
}  // namespace mlndt
