#pragma once

// Basic types shared by every module of mlndt.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace mlndt {

class EnumTable;

using Vector3d = Eigen::Vector3d;
using Matrix3d = Eigen::Matrix3d;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
// A rigid transform; the variable name says which frames it maps between,
// e.g. `reference_from_input` maps input points into the reference frame.
using Isometry3d = Eigen::Isometry3d;

// How a solve or a registration ended (names follow ceres::TerminationType).
// A registration reports CONVERGENCE or NO_CONVERGENCE only when its result
// passes the quality check (registration_options.h); otherwise it says why
// the pose is not to be trusted.
enum class TerminationType {
  CONVERGENCE,     // A convergence tolerance was met.
  NO_CONVERGENCE,  // The iteration cap was reached first.
  FAILURE,         // Invalid options or unusable input; see the message.
  // The solver stopped, but the input does not fit the map at the solution
  // (too few inliers, too high a score per point): most likely a wrong pose.
  LOW_QUALITY,
  // The fit does not constrain every direction of the pose (a plane, a
  // corridor, a line): the pose can slide along the directions the message
  // names, and the covariance is infinite along them.
  DEGENERATE,
};

// The one definition of a result to be used: CONVERGENCE or NO_CONVERGENCE
// (the pose passed the quality check). LOW_QUALITY, DEGENERATE and FAILURE
// are not to be used.
inline bool IsUsableTermination(TerminationType type) {
  return type == TerminationType::CONVERGENCE ||
         type == TerminationType::NO_CONVERGENCE;
}

// The names of TerminationType's values (enum_table.h).
const EnumTable& TerminationTypeTable();
const char* TerminationTypeToString(TerminationType type);
bool StringToTerminationType(std::string value, TerminationType* type);

}  // namespace mlndt
