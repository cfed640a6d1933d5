#include "mlndt/cloud/pose_io.h"

#include <glog/logging.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/rigid_transform.h"

namespace mlndt {
namespace {

// Parses 12 tokens of a row-major 3x4 matrix into *transform, checked and
// re-orthonormalised by ToRigidTransform (rigid_transform.h). Returns false
// with *problem when a token is not a number or the matrix is not a rigid
// transform (non-finite, not a rotation, absurd translation).
bool MatrixFromTokens(const std::vector<std::string_view>& tokens,
                      Eigen::Isometry3d* transform,
                      std::string* problem) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (int i = 0; i < 12; ++i) {
    if (!internal::ParseDouble(tokens[i], &m(i / 4, i % 4))) {
      *problem = "cannot parse number '" + std::string(tokens[i]) + "'";
      return false;
    }
  }
  return ToRigidTransform(m, transform, problem);
}

}  // namespace

bool ReadKittiPoses(const std::string& path,
                    std::vector<Eigen::Isometry3d>* poses,
                    std::string* error) {
  CHECK(poses != nullptr);
  CHECK(error != nullptr);
  poses->clear();
  std::string data;
  if (!internal::ReadFileToString(path, &data, error)) return false;
  internal::LineCursor cursor(data);
  std::string_view line;
  while (cursor.Next(&line)) {
    const std::vector<std::string_view> tokens = internal::SplitTokens(line);
    if (tokens.empty()) continue;
    const std::string line_tag =
        path + ": line " + std::to_string(cursor.line_number());
    if (tokens.size() != 12) {
      *error = line_tag + ": expected 12 numbers (3x4 row-major pose), found " +
               std::to_string(tokens.size());
      poses->clear();
      return false;
    }
    Eigen::Isometry3d pose;
    std::string problem;
    if (!MatrixFromTokens(tokens, &pose, &problem)) {
      *error = line_tag + ": " + problem;
      poses->clear();
      return false;
    }
    poses->push_back(pose);
  }
  if (poses->empty()) {
    *error = path + ": no poses in file";
    return false;
  }
  return true;
}

bool WriteKittiPoses(const std::string& path,
                     const std::vector<Eigen::Isometry3d>& poses,
                     std::string* error) {
  CHECK(error != nullptr);
  std::string text;
  char number[32];
  for (const Eigen::Isometry3d& pose : poses) {
    for (int i = 0; i < 12; ++i) {
      // %.17g round-trips every double exactly.
      std::snprintf(
          number, sizeof(number), "%.17g", pose.matrix()(i / 4, i % 4));
      if (i > 0) text += ' ';
      text += number;
    }
    text += '\n';
  }
  return WriteFileAtomically(path, text, error);
}

bool ReadKittiCalibTr(const std::string& path,
                      Eigen::Isometry3d* cam0_from_velo,
                      std::string* error) {
  CHECK(cam0_from_velo != nullptr);
  CHECK(error != nullptr);
  std::string data;
  if (!internal::ReadFileToString(path, &data, error)) return false;
  internal::LineCursor cursor(data);
  std::string_view line;
  while (cursor.Next(&line)) {
    std::vector<std::string_view> tokens = internal::SplitTokens(line);
    if (tokens.empty() || tokens[0] != "Tr:") continue;
    tokens.erase(tokens.begin());
    const std::string line_tag =
        path + ": line " + std::to_string(cursor.line_number());
    if (tokens.size() != 12) {
      *error = line_tag + ": the Tr: line has " +
               std::to_string(tokens.size()) + " numbers, expected 12";
      return false;
    }
    std::string problem;
    if (!MatrixFromTokens(tokens, cam0_from_velo, &problem)) {
      *error = line_tag + ": Tr: " + problem;
      return false;
    }
    return true;
  }
  *error = path + ": no 'Tr:' line (expected a KITTI odometry calib.txt)";
  return false;
}

Eigen::Vector3d Convert3dtkPoint(const Eigen::Vector3d& point_3dtk) {
  return Eigen::Vector3d(point_3dtk.z(), -point_3dtk.x(), point_3dtk.y()) /
         100.0;
}

Eigen::Isometry3d Convert3dtkPose(const Eigen::Vector3d& position_cm,
                                  const Eigen::Vector3d& euler_deg) {
  const Eigen::Vector3d theta = euler_deg * (M_PI / 180.0);
  // R_l = Rx(θx) Ry(θy) Rz(θz): EulerToMatrix4 in 3DTK
  // include/slam6d/globals.icc.
  const Eigen::Matrix3d rotation_3dtk =
      (Eigen::AngleAxisd(theta.x(), Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(theta.y(), Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(theta.z(), Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  // P: x_r = z_l, y_r = -x_l, z_r = y_l; P is orthogonal, so P^-1 = P^T.
  Eigen::Matrix3d axes;
  // clang-format off
  axes << 0, 0, 1,
         -1, 0, 0,
          0, 1, 0;
  // clang-format on
  Eigen::Isometry3d world_from_scan = Eigen::Isometry3d::Identity();
  world_from_scan.linear() = axes * rotation_3dtk * axes.transpose();
  world_from_scan.translation() = Convert3dtkPoint(position_cm);
  return world_from_scan;
}

bool Read3dtkPose(const std::string& path,
                  Eigen::Isometry3d* world_from_scan,
                  std::string* error) {
  CHECK(world_from_scan != nullptr);
  CHECK(error != nullptr);
  std::string data;
  if (!internal::ReadFileToString(path, &data, error)) return false;
  // 3DTK reads six numbers with operator>>, so line breaks do not matter.
  std::vector<std::string_view> numbers;
  internal::LineCursor cursor(data);
  std::string_view line;
  while (cursor.Next(&line)) {
    for (std::string_view token : internal::SplitTokens(line)) {
      numbers.push_back(token);
    }
  }
  if (numbers.size() != 6) {
    *error = path +
             ": expected 6 numbers (x y z [cm], then θx θy θz [deg]), found " +
             std::to_string(numbers.size());
    return false;
  }
  double values[6];
  for (int i = 0; i < 6; ++i) {
    if (!internal::ParseDouble(numbers[i], &values[i]) ||
        !std::isfinite(values[i])) {
      *error = path + ": cannot parse number '" + std::string(numbers[i]) + "'";
      return false;
    }
  }
  *world_from_scan =
      Convert3dtkPose(Eigen::Vector3d(values[0], values[1], values[2]),
                      Eigen::Vector3d(values[3], values[4], values[5]));
  return true;
}

}  // namespace mlndt
