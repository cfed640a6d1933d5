#pragma once

// Reading and writing point-cloud files. The format comes from the extension
// (cloud_format.h). Only x, y, z are read; every other field is skipped.
// Points come back in metres; points with a NaN or infinite coordinate are
// dropped and counted.
//
// Formats read:
//  * PCD (.pcd), PCL's format, versions 0.7 and 0.6 (0.6 headers have no
//    VERSION line). A text header (FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT,
//    VIEWPOINT, POINTS, DATA; '#' comments) followed by the body:
//      - DATA ascii: one point per line, COUNT values per field.
//      - DATA binary: little-endian records of sum(SIZE*COUNT) bytes.
//      - DATA binary_compressed: uint32 compressed size, uint32 uncompressed
//        size, then LZF data that decompresses to a field-major layout (all
//        x values, then all y values, ...; each field's block is
//        POINTS*SIZE*COUNT bytes).
//    FIELDS may hold anything as long as it has x, y and z with TYPE F and
//    SIZE 4 or 8 and COUNT 1. Other fields, including COUNT > 1 fields and
//    PCL's '_' padding fields, are skipped by SIZE*COUNT bytes (ascii: COUNT
//    values; PCL writes no values for '_' fields in ascii, and both layouts
//    are accepted). POINTS must equal WIDTH*HEIGHT; organised clouds
//    (HEIGHT > 1) are read as a flat list. VIEWPOINT is not applied.
//  * PLY (.ply): format ascii, binary_little_endian or binary_big_endian 1.0.
//    The `element vertex N` must have scalar properties x, y, z of type
//    float/float32 or double/float64; its other scalar properties (any type)
//    are skipped; list properties in the vertex element are not supported.
//    Elements before the vertices are skipped, elements after them (faces)
//    are ignored; comment and obj_info lines are allowed.
//  * KITTI Velodyne (.bin): headerless float32 little-endian records
//    x y z intensity (16 bytes per point), metres, sensor frame.
//  * 3DTK "uos" (.3d): text, one point per line "x y z" (extra columns such
//    as reflectance ignored; blank lines allowed; an optional 3DTK "W x H"
//    header line is skipped). 3DTK stores CENTIMETRES in a LEFT-handed frame
//    with x right, y up and z forward. Points are converted to metres in a
//    right-handed frame with x forward, y left and z up:
//        x_r = z / 100,   y_r = -x / 100,   z_r = y / 100.
//    This is the inverse of the mapping 3DTK itself applies when it imports
//    right-handed "xyz" data (ScanDataTransform_xyz in src/scanio/helper.cc:
//    x_l = -y_r, y_l = z_r, z_l = x_r). pose_io.h converts .pose files into
//    the same frame (Convert3dtkPoint / Convert3dtkPose).
//  * Plain text (.xyz, .txt): one point per line, at least three numbers
//    separated by whitespace and/or commas (extra columns ignored), metres.
//    Blank lines and lines starting with '#' are skipped.
//
// Empty files: a PCD or PLY file whose header declares 0 points reads as an
// empty cloud (WritePointCloud writes such a file for an empty cloud). A
// file without any point in a format that has no header to declare a count
// (.bin, .3d, .xyz/.txt: 0 bytes, or only blank and comment lines) is an
// error, "no points", and so is a 0-byte file in any format.
//
// Formats written: PCD (DATA binary, FIELDS x y z, float32) and PLY
// (binary_little_endian, float x y z). Coordinates are stored as float32, so
// about 7 significant digits survive a round trip.

#include <cstddef>
#include <string>

#include "mlndt/cloud/cloud_format.h"
#include "mlndt/cloud/point_cloud.h"

namespace mlndt {

// What ReadPointCloud found besides the points.
struct ReadCloudInfo {
  CloudFormat format = CloudFormat::PCD;
  // Points stored in the file, including non-finite ones.
  size_t points_in_file = 0;
  // Points dropped because a coordinate was NaN or infinite.
  size_t dropped_non_finite = 0;
};

// Reads a cloud, choosing the format by extension. `info` may be null. On
// failure returns false, leaves *cloud empty (never a partial cloud), and
// *error names the file and the problem, e.g.
// "scan.pcd: truncated binary body: expected 3200 bytes, found 1000".
bool ReadPointCloud(const std::string& path,
                    PointCloud* cloud,
                    ReadCloudInfo* info,
                    std::string* error);

// Writes PCD or PLY, chosen by extension (see above), with
// WriteFileAtomically (mlndt/common/atomic_file.h): a temporary file in the
// same folder, fsynced and renamed onto `path`, so a failure (a full disk
// included) never leaves a half-written file and never damages an existing
// file at `path`; an existing file keeps its mode; a symbolic link, FIFO,
// device or directory at `path` is refused. Returns false with *error for
// other extensions and for I/O failures (naming `path` and the OS reason).
bool WritePointCloud(const std::string& path,
                     const PointCloud& cloud,
                     std::string* error);

// True when WritePointCloud can write `path`'s format (.pcd or .ply); false
// with *error naming the path and the formats otherwise. Tools call it
// before any work.
bool CanWritePointCloud(const std::string& path, std::string* error);

}  // namespace mlndt
