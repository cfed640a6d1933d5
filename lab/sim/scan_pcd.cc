#include "lab/sim/scan_pcd.h"

#include <cstring>

#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace sim {
namespace {

template <typename T>
void Append(T value, std::string* bytes) {
  static_assert(sizeof(T) == 4 || sizeof(T) == 2);
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));  // x86-64 and ARM64: little-endian.
  bytes->append(raw, sizeof(T));
}

}  // namespace

std::string SimScanPcd(const SimScan& scan) {
  const std::string n = std::to_string(scan.points.size());
  std::string bytes =
      "# .PCD v0.7 - Point Cloud Data file format\n"
      "VERSION 0.7\n"
      "FIELDS x y z time ring\n"
      "SIZE 4 4 4 4 2\n"
      "TYPE F F F F U\n"
      "COUNT 1 1 1 1 1\n"
      "WIDTH " +
      n +
      "\n"
      "HEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\n"
      "POINTS " +
      n +
      "\n"
      "DATA binary\n";
  bytes.reserve(bytes.size() + 18 * scan.points.size());
  for (size_t k = 0; k < scan.points.size(); ++k) {
    Append(static_cast<float>(scan.points[k].x()), &bytes);
    Append(static_cast<float>(scan.points[k].y()), &bytes);
    Append(static_cast<float>(scan.points[k].z()), &bytes);
    Append(scan.times_s[k], &bytes);
    Append(scan.channels[k], &bytes);
  }
  return bytes;
}

bool WriteSimScanPcd(const std::string& path,
                     const SimScan& scan,
                     std::string* error) {
  return WriteFileAtomically(path, SimScanPcd(scan), error);
}

}  // namespace sim
}  // namespace mlndt
