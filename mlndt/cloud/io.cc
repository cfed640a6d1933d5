#include "mlndt/cloud/io.h"

#include <fcntl.h>
#include <glog/logging.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <utility>
#include <vector>

#include "mlndt/internal/cloud_readers.h"

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

namespace {

// Writes all of `bytes` to `fd`, retrying short writes.
bool WriteAll(int fd, const std::string& bytes) {
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n =
        ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    written += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

bool WriteFileAtomically(const std::string& path,
                         const std::string& bytes,
                         std::string* error) {
  CHECK(error != nullptr);
  // A name no other writer uses: pid plus a per-process counter. O_EXCL makes
  // sure we never write into someone else's file. Mode 0666 goes through the
  // umask like a normal file would.
  static std::atomic<unsigned> counter{0};
  std::string temp_path;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temp_path = path + ".tmp." + std::to_string(::getpid()) + "." +
                std::to_string(counter.fetch_add(1));
    fd = ::open(
        temp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) {
    *error = path + ": cannot create temporary file " + temp_path + ": " +
             std::strerror(errno);
    return false;
  }
  // fsync before the rename, so that after a crash `path` holds either the
  // old or the complete new contents.
  int failure = 0;
  if (!WriteAll(fd, bytes) || ::fsync(fd) != 0) failure = errno;
  if (::close(fd) != 0 && failure == 0) failure = errno;
  if (failure != 0) {
    ::unlink(temp_path.c_str());
    *error = path + ": write failed: " + std::strerror(failure);
    return false;
  }
  if (std::rename(temp_path.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlink(temp_path.c_str());
    *error = path + ": cannot rename temporary file onto it: " +
             std::strerror(rename_errno);
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

bool WritePointCloud(const std::string& path,
                     const PointCloud& cloud,
                     std::string* error) {
  CHECK(error != nullptr);
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
  return internal::WriteFileAtomically(path, bytes, error);
}

}  // namespace mlndt
