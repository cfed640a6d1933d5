#pragma once

// Reading and writing trajectories in the KITTI and TUM text formats.
// Readers return false with *error ("<path>: line <n>: <problem>") on bad
// input; writers replace the file atomically (a reader never sees half a
// file) and return false with *error naming the file on failure.

#include <string>

#include "lab/eval/trajectory.h"

namespace mlndt {

enum class TrajectoryFormat {
  // KITTI odometry poses/NN.txt: one pose per line, 12 numbers = the first
  // three rows of the row-major 4x4 world_from_sensor matrix; no timestamps
  // (the line index is the time). Read with ReadKittiPoses (pose_io.h): a
  // 3x3 part that is not a rotation within 1e-3 is an error.
  KITTI,
  // TUM RGB-D benchmark: "timestamp tx ty tz qx qy qz qw" per line, seconds,
  // metres and a unit quaternion (Hamilton, w last); lines starting with '#'
  // are comments. Timestamps must increase strictly, and |q| must be 1
  // within kTumQuaternionNormTolerance (q is then normalised).
  TUM,
};

const char* TrajectoryFormatToString(TrajectoryFormat format);
bool StringToTrajectoryFormat(std::string value, TrajectoryFormat* format);

// How far |q| of a TUM line may be from 1 (files print 4-9 digits).
constexpr double kTumQuaternionNormTolerance = 1e-3;

// The format of a trajectory file: ".kitti" -> KITTI, ".tum" -> TUM (case
// does not matter); any other extension (".txt" is used for both) is decided
// by the first line that is neither blank nor a '#' comment: 12 numbers ->
// KITTI, 8 -> TUM. False with *error when the file cannot be read or that
// line fits neither.
bool DetectTrajectoryFormat(const std::string& path,
                            TrajectoryFormat* format,
                            std::string* error);

// Reads `path` in `format` into *trajectory (cleared first).
bool ReadTrajectory(const std::string& path,
                    TrajectoryFormat format,
                    Trajectory* trajectory,
                    std::string* error);
// Detects the format (DetectTrajectoryFormat), then reads the file.
bool ReadTrajectory(const std::string& path,
                    Trajectory* trajectory,
                    std::string* error);

// The comment WriteTrajectory's callers put first in a TUM file whose time
// stamps are scan indices (no times were known), and whether the file at
// `path` starts with it: such a file is associated by index, not by time.
constexpr char kTumIndexStampsComment[] =
    "time stamps: scan indices (0, 1, 2, ...), not times";
bool TumStampsAreScanIndices(const std::string& path);

// Writes with 17 significant digits, so every number reads back as the same
// double. KITTI drops the timestamps. TUM writes a '#' header line and the
// quaternion of each rotation with w >= 0.
bool WriteTrajectory(const std::string& path,
                     TrajectoryFormat format,
                     const Trajectory& trajectory,
                     std::string* error);
// The same; TUM files start with "# <comment>" when `comment` (one line) is
// not empty: where the time stamps come from (a times file, bag header
// stamps) or that they are scan indices.
bool WriteTrajectory(const std::string& path,
                     TrajectoryFormat format,
                     const Trajectory& trajectory,
                     const std::string& comment,
                     std::string* error);

}  // namespace mlndt
