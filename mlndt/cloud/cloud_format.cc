#include "mlndt/cloud/cloud_format.h"

#include <glog/logging.h>

#include <filesystem>

#include "mlndt/common/internal/enum_strings.h"

namespace mlndt {

const char* CloudFormatToString(CloudFormat format) {
  switch (format) {
    case CloudFormat::PCD:
      return "PCD";
    case CloudFormat::PLY:
      return "PLY";
    case CloudFormat::KITTI_BIN:
      return "KITTI_BIN";
    case CloudFormat::UOS_3D:
      return "UOS_3D";
    case CloudFormat::XYZ:
      return "XYZ";
  }
  return "UNKNOWN";
}

bool StringToCloudFormat(std::string value, CloudFormat* result) {
  UpperCase(&value);
  MLNDT_STRING_TO_ENUM(PCD, CloudFormat);
  MLNDT_STRING_TO_ENUM(PLY, CloudFormat);
  MLNDT_STRING_TO_ENUM(KITTI_BIN, CloudFormat);
  MLNDT_STRING_TO_ENUM(UOS_3D, CloudFormat);
  MLNDT_STRING_TO_ENUM(XYZ, CloudFormat);
  return false;
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
