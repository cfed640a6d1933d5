#pragma once

// Basic types shared by every module of mlndt.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace mlndt {

using Vector3d = Eigen::Vector3d;
using Matrix3d = Eigen::Matrix3d;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
// A rigid transform; the variable name says which frames it maps between,
// e.g. `reference_from_input` maps input points into the reference frame.
using Isometry3d = Eigen::Isometry3d;

// How a solve or a registration ended (names follow ceres::TerminationType).
enum class TerminationType {
  CONVERGENCE,     // A convergence tolerance was met.
  NO_CONVERGENCE,  // The iteration cap was reached first.
  FAILURE,         // Invalid options or unusable input; see the message.
};

const char* TerminationTypeToString(TerminationType type);
bool StringToTerminationType(std::string value, TerminationType* type);

}  // namespace mlndt
