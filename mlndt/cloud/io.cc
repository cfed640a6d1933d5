#include "mlndt/cloud/io.h"

#include <glog/logging.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <utility>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"
#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace internal {

bool ReadFileToString(const std::string& path,
                      std::string* data,
                      std::string* error) {
  CHECK(data != nullptr);
  CHECK(error != nullptr);
  data->clear();
  struct stat status;
  if (::stat(path.c_str(), &status) != 0) {
    *error = path + ": cannot open file: " + std::strerror(errno);
    return false;
  }
  if (S_ISDIR(status.st_mode)) {
    *error = path + ": cannot open file: it is a directory";
    return false;
  }
  if (!S_ISREG(status.st_mode)) {
    *error = path + ": cannot open file: not a regular file";
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    *error = path + ": cannot open file: " + std::strerror(errno);
    return false;
  }
  // Size from stat; the read below tells us if the file shrank meanwhile.
  data->resize(static_cast<size_t>(status.st_size));
  file.read(data->data(), static_cast<std::streamsize>(data->size()));
  if (static_cast<size_t>(file.gcount()) != data->size()) {
    *error = path + ": read error";
    data->clear();
    return false;
  }
  return true;
}

}  // namespace internal

bool ReadPointCloud(const std::string& path,
                    PointCloud* cloud,
                    ReadCloudInfo* info,
                    std::string* error) {
  CHECK(cloud != nullptr);
  CHECK(error != nullptr);
  *cloud = PointCloud();
  ReadCloudInfo local_info;
  if (info == nullptr) info = &local_info;
  *info = ReadCloudInfo();

  if (!CloudFormatFromPath(path, &info->format, error)) return false;
  std::string data;
  if (!internal::ReadFileToString(path, &data, error)) return false;

  std::vector<Eigen::Vector3d> points;
  std::string problem;
  bool ok = false;
  switch (info->format) {
    case CloudFormat::PCD:
      ok = internal::ParsePcd(data, &points, &problem);
      break;
    case CloudFormat::PLY:
      ok = internal::ParsePly(data, &points, &problem);
      break;
    case CloudFormat::KITTI_BIN:
      ok = internal::ParseKittiBin(data, &points, &problem);
      break;
    case CloudFormat::UOS_3D:
      ok = internal::ParseUos3d(data, &points, &problem);
      break;
    case CloudFormat::XYZ:
      ok = internal::ParseXyzText(data, &points, &problem);
      break;
  }
  if (!ok) {
    *error = path + ": " + problem;
    return false;
  }
  info->points_in_file = points.size();
  *cloud = PointCloud(std::move(points));
  info->dropped_non_finite = RemoveNonFinite(cloud);
  return true;
}

bool CanWritePointCloud(const std::string& path, std::string* error) {
  CHECK(error != nullptr);
  CloudFormat format;
  if (!CloudFormatFromPath(path, &format, error)) return false;
  if (format == CloudFormat::PCD || format == CloudFormat::PLY) return true;
  *error = path + ": writing " + std::string(CloudFormatToString(format)) +
           " is not supported (write .pcd or .ply)";
  return false;
}

bool WritePointCloud(const std::string& path,
                     const PointCloud& cloud,
                     std::string* error) {
  CHECK(error != nullptr);
  if (!CanWritePointCloud(path, error)) return false;
  CloudFormat format;
  if (!CloudFormatFromPath(path, &format, error)) return false;
  std::string bytes;
  switch (format) {
    case CloudFormat::PCD:
      bytes = internal::EncodePcdBinary(cloud);
      break;
    case CloudFormat::PLY:
      bytes = internal::EncodePlyBinary(cloud);
      break;
    default:
      *error = path + ": writing " + CloudFormatToString(format) +
               " is not supported (write .pcd or .ply)";
      return false;
  }
  return WriteFileAtomically(path, bytes, error);
}

}  // namespace mlndt
