#include "lab/eval/trajectory_io.h"

#include <glog/logging.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/internal/enum_strings.h"
#include "mlndt/common/rigid_transform.h"

namespace mlndt {
namespace {

constexpr int kKittiNumbers = 12;
constexpr int kTumNumbers = 8;

// The one place this module writes files: a temporary file next to `path`
// (unique name), fsync, rename. To be swapped for the shared helper in
// mlndt/common once it exists.
bool WriteTextFile(const std::string& path,
                   const std::string& text,
                   std::string* error) {
  return WriteFileAtomically(path, text, error);
}

bool IsCommentOrBlank(std::string_view line) {
  const std::string_view trimmed = internal::Trim(line);
  return trimmed.empty() || trimmed.front() == '#';
}

// Parses one TUM line's 8 tokens. False with *problem (no path, no line).
bool ParseTumLine(const std::vector<std::string_view>& tokens,
                  double* timestamp_s,
                  Isometry3d* world_from_sensor,
                  std::string* problem) {
  double v[kTumNumbers];
  for (int i = 0; i < kTumNumbers; ++i) {
    if (!internal::ParseDouble(tokens[i], &v[i])) {
      *problem = "cannot parse number '" + std::string(tokens[i]) + "'";
      return false;
    }
    if (!std::isfinite(v[i])) {
      *problem = "non-finite number '" + std::string(tokens[i]) + "'";
      return false;
    }
  }
  Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);  // w, x, y, z.
  if (std::abs(q.norm() - 1.0) > kTumQuaternionNormTolerance) {
    char text[96];
    std::snprintf(text,
                  sizeof(text),
                  "quaternion norm %.6g is not 1 (tolerance %g)",
                  q.norm(),
                  kTumQuaternionNormTolerance);
    *problem = text;
    return false;
  }
  *timestamp_s = v[0];
  // The translation bound of every pose read (rigid_transform.h).
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = q.normalized().toRotationMatrix();
  m.topRightCorner<3, 1>() = Vector3d(v[1], v[2], v[3]);
  return ToRigidTransform(m, world_from_sensor, problem);
}

bool ReadTum(const std::string& path,
             Trajectory* trajectory,
             std::string* error) {
  std::string data;
  if (!internal::ReadFileToString(path, &data, error)) return false;
  internal::LineCursor cursor(data);
  std::string_view line;
  size_t previous_line = 0;
  while (cursor.Next(&line)) {
    if (IsCommentOrBlank(line)) continue;
    const std::string line_tag =
        path + ": line " + std::to_string(cursor.line_number());
    const std::vector<std::string_view> tokens = internal::SplitTokens(line);
    if (tokens.size() != kTumNumbers) {
      *error = line_tag +
               ": expected 8 numbers (timestamp tx ty tz qx qy qz qw), found " +
               std::to_string(tokens.size());
      return false;
    }
    double timestamp_s = 0.0;
    Isometry3d pose;
    std::string problem;
    if (!ParseTumLine(tokens, &timestamp_s, &pose, &problem)) {
      *error = line_tag + ": " + problem;
      return false;
    }
    if (!trajectory->empty() &&
        !(timestamp_s > trajectory->timestamps_s().back())) {
      *error = line_tag + ": timestamp " + std::string(tokens[0]) +
               " is not after the one on line " +
               std::to_string(previous_line) +
               " (timestamps must increase strictly)";
      return false;
    }
    trajectory->Add(timestamp_s, pose);
    previous_line = cursor.line_number();
  }
  if (trajectory->empty()) {
    *error = path + ": no poses in file";
    return false;
  }
  return true;
}

std::string FormatTum(const Trajectory& trajectory,
                      const std::string& comment) {
  std::string text;
  if (!comment.empty()) text += "# " + comment + "\n";
  text += "# timestamp tx ty tz qx qy qz qw\n";
  char line[512];
  for (size_t i = 0; i < trajectory.size(); ++i) {
    const Isometry3d& pose = trajectory.world_from_sensor(i);
    Eigen::Quaterniond q(pose.linear());
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    const Vector3d& t = pose.translation();
    std::snprintf(line,
                  sizeof(line),
                  "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
                  trajectory.timestamp_s(i),
                  t.x(),
                  t.y(),
                  t.z(),
                  q.x(),
                  q.y(),
                  q.z(),
                  q.w());
    text += line;
  }
  return text;
}

}  // namespace

const char* TrajectoryFormatToString(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::KITTI:
      return "KITTI";
    case TrajectoryFormat::TUM:
      return "TUM";
  }
  return "UNKNOWN";
}

bool StringToTrajectoryFormat(std::string value, TrajectoryFormat* result) {
  UpperCase(&value);
  MLNDT_STRING_TO_ENUM(KITTI, TrajectoryFormat);
  MLNDT_STRING_TO_ENUM(TUM, TrajectoryFormat);
  return false;
}

bool DetectTrajectoryFormat(const std::string& path,
                            TrajectoryFormat* format,
                            std::string* error) {
  CHECK(format != nullptr);
  CHECK(error != nullptr);
  std::string extension = std::filesystem::path(path).extension().string();
  UpperCase(&extension);
  if (extension == ".KITTI" || extension == ".TUM") {
    return StringToTrajectoryFormat(extension.substr(1), format);
  }
  std::string data;
  if (!internal::ReadFileToString(path, &data, error)) return false;
  internal::LineCursor cursor(data);
  std::string_view line;
  while (cursor.Next(&line)) {
    if (IsCommentOrBlank(line)) continue;
    const size_t count = internal::SplitTokens(line).size();
    if (count == kKittiNumbers || count == kTumNumbers) {
      *format = count == kKittiNumbers ? TrajectoryFormat::KITTI
                                       : TrajectoryFormat::TUM;
      return true;
    }
    *error = path + ": line " + std::to_string(cursor.line_number()) +
             ": cannot tell the trajectory format: " + std::to_string(count) +
             " numbers, expected 12 (KITTI) or 8 (TUM)";
    return false;
  }
  *error = path + ": no poses in file";
  return false;
}

bool ReadTrajectory(const std::string& path,
                    TrajectoryFormat format,
                    Trajectory* trajectory,
                    std::string* error) {
  CHECK(trajectory != nullptr);
  CHECK(error != nullptr);
  *trajectory = Trajectory();
  if (format == TrajectoryFormat::TUM) {
    if (ReadTum(path, trajectory, error)) return true;
    *trajectory = Trajectory();
    return false;
  }
  std::vector<Isometry3d> poses;
  if (!ReadKittiPoses(path, &poses, error)) return false;
  *trajectory = Trajectory(poses);
  return true;
}

bool ReadTrajectory(const std::string& path,
                    Trajectory* trajectory,
                    std::string* error) {
  TrajectoryFormat format;
  if (!DetectTrajectoryFormat(path, &format, error)) return false;
  return ReadTrajectory(path, format, trajectory, error);
}

bool TumStampsAreScanIndices(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
    if (line.find(kTumIndexStampsComment) != std::string::npos) return true;
  }
  return false;
}

bool WriteTrajectory(const std::string& path,
                     TrajectoryFormat format,
                     const Trajectory& trajectory,
                     std::string* error) {
  return WriteTrajectory(path, format, trajectory, "", error);
}

bool WriteTrajectory(const std::string& path,
                     TrajectoryFormat format,
                     const Trajectory& trajectory,
                     const std::string& comment,
                     std::string* error) {
  CHECK(error != nullptr);
  if (format == TrajectoryFormat::KITTI) {
    return WriteKittiPoses(path, trajectory.poses(), error);
  }
  if (comment.find('\n') != std::string::npos) {
    *error = path + ": a TUM header comment must be one line";
    return false;
  }
  return WriteTextFile(path, FormatTum(trajectory, comment), error);
}

}  // namespace mlndt
