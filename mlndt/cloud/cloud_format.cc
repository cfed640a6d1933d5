#include "mlndt/cloud/cloud_format.h"

#include <glog/logging.h>

#include <filesystem>

#include "mlndt/common/enum_table.h"
#include "mlndt/common/internal/enum_strings.h"

namespace mlndt {

const EnumTable& CloudFormatTable() {
  static const EnumTable table({
      {static_cast<int>(CloudFormat::PCD), "PCD"},
      {static_cast<int>(CloudFormat::PLY), "PLY"},
      {static_cast<int>(CloudFormat::KITTI_BIN), "KITTI_BIN"},
      {static_cast<int>(CloudFormat::UOS_3D), "UOS_3D"},
      {static_cast<int>(CloudFormat::XYZ), "XYZ"},
  });
  return table;
}

const char* CloudFormatToString(CloudFormat format) {
  return EnumToString(CloudFormatTable(), format);
}

bool StringToCloudFormat(std::string value, CloudFormat* format) {
  return StringToEnum(CloudFormatTable(), std::move(value), format);
}

bool CloudFormatFromPath(const std::string& path,
                         CloudFormat* format,
                         std::string* error) {
  CHECK(format != nullptr);
  CHECK(error != nullptr);
  std::string extension = std::filesystem::path(path).extension().string();
  std::string upper = extension;
  UpperCase(&upper);
  if (upper == ".PCD") {
    *format = CloudFormat::PCD;
  } else if (upper == ".PLY") {
    *format = CloudFormat::PLY;
  } else if (upper == ".BIN") {
    *format = CloudFormat::KITTI_BIN;
  } else if (upper == ".3D") {
    *format = CloudFormat::UOS_3D;
  } else if (upper == ".XYZ" || upper == ".TXT") {
    *format = CloudFormat::XYZ;
  } else {
    *error = path + ": " +
             (extension.empty() ? std::string("no file extension")
                                : "unknown extension '" + extension + "'") +
             " (known point cloud extensions: .pcd, .ply, .bin (KITTI), "
             ".3d (3DTK), .xyz, .txt)";
    return false;
  }
  return true;
}

}  // namespace mlndt
