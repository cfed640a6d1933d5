#pragma once

// The point-cloud file formats mlndt reads, and how a file's format is chosen
// from its extension. io.h describes each format in detail.

#include <string>

namespace mlndt {

class EnumTable;

enum class CloudFormat {
  PCD,        // PCL's .pcd (ascii, binary, binary_compressed).
  PLY,        // .ply (ascii, binary_little_endian, binary_big_endian).
  KITTI_BIN,  // KITTI Velodyne .bin: float32 x y z intensity records.
  UOS_3D,     // 3DTK "uos" .3d text: centimetres, left-handed, y up.
  XYZ,        // Plain text .xyz / .txt: x y z per line, metres.
};

// "PCD", "PLY", "KITTI_BIN", "UOS_3D", "XYZ".
// The names of CloudFormat's values (enum_table.h).
const EnumTable& CloudFormatTable();
const char* CloudFormatToString(CloudFormat format);
// Parses the names above, case-insensitively ("pcd" works). Returns false and
// leaves *format unchanged for an unknown name.
bool StringToCloudFormat(std::string value, CloudFormat* format);

// Chooses the format from the extension of `path`, case-insensitively:
//   .pcd -> PCD, .ply -> PLY, .bin -> KITTI_BIN, .3d -> UOS_3D,
//   .xyz and .txt -> XYZ.
// Returns false for any other extension, with *error naming the file and the
// known extensions.
bool CloudFormatFromPath(const std::string& path,
                         CloudFormat* format,
                         std::string* error);

}  // namespace mlndt
