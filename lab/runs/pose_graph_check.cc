#include "lab/runs/pose_graph_check.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"

namespace mlndt {
namespace {

double WrapAngle(double angle) { return std::remainder(angle, 2.0 * M_PI); }

bool AllFinite(const std::vector<Isometry3d>& poses) {
  return std::all_of(poses.begin(), poses.end(), [](const Isometry3d& p) {
    return p.matrix().allFinite();
  });
}

// Scan j onto scan i's map from the joint relative pose.
PoseGraphPairCheck CheckPair(const RegistrationOptions& registration,
                             double information_scale,
                             const std::vector<LayeredGrid>& maps,
                             const std::vector<PointCloud>& scans,
                             const std::vector<Isometry3d>& joint,
                             int i,
                             int j) {
  PoseGraphPairCheck check;
  check.map_scan = i;
  check.point_scan = j;
  const Isometry3d joint_relative = joint[i].inverse() * joint[j];
  RegistrationSummary summary;
  Register(registration, maps[i], scans[j], joint_relative, &summary);
  check.termination = TerminationTypeToString(summary.termination_type);
  // A DEGENERATE pair still holds along the directions it constrains: its
  // Hessian is ~0 along the free ones, so the NEES judges the others.
  check.usable = summary.IsSolutionUsable() ||
                 summary.termination_type == TerminationType::DEGENERATE;
  Vector6d e = IsometryToPoseVector(joint_relative) -
               IsometryToPoseVector(summary.reference_from_input);
  for (int k = 3; k < 6; ++k) e[k] = WrapAngle(e[k]);
  check.nees = information_scale * 0.5 * e.dot(summary.hessian * e);
  check.translation_m =
      TranslationErrorM(joint_relative, summary.reference_from_input);
  check.rotation_deg =
      RotationErrorRad(joint_relative, summary.reference_from_input) *
      kRadToDeg;
  return check;
}

double OdometryChi2(const Isometry3d& measured_i_from_j,
                    const OdometryNoise& noise,
                    const Isometry3d& pose_i,
                    const Isometry3d& pose_j) {
  const Isometry3d error =
      measured_i_from_j.inverse() * (pose_i.inverse() * pose_j);
  const Eigen::AngleAxisd rotation(error.linear());
  const double sigma_rad = noise.sigma_deg * kDegToRad;
  return error.translation().squaredNorm() / (noise.sigma_m * noise.sigma_m) +
         rotation.angle() * rotation.angle() / (sigma_rad * sigma_rad);
}

std::string Describe(const PoseGraphPairCheck& c) {
  std::ostringstream out;
  out << "pair " << c.map_scan << ":" << c.point_scan;
  if (!c.usable) {
    out << " is " << c.termination << " at the joint poses";
  } else {
    out << ": the joint relative pose is " << c.translation_m << " m, "
        << c.rotation_deg << " deg from the pair's own optimum (NEES " << c.nees
        << " > " << kPairNeesGate << ")";
  }
  return out.str();
}

// The first pair or factor that does not fit, or "".
std::string FirstMisfit(const PoseGraphCheck& check,
                        const OdometryNoise& noise) {
  for (const PoseGraphPairCheck& c : check.pairs) {
    if (!c.usable || !(c.nees <= kPairNeesGate)) {
      return Describe(c);
    }
  }
  for (size_t i = 0; i < check.odometry_chi2.size(); ++i) {
    const double gate = OdometryChi2Gate(check.odometry_chi2.size());
    if (!(check.odometry_chi2[i] <= gate)) {
      std::ostringstream out;
      out << "odometry factor " << i << ":" << i + 1 << ": the joint poses are "
          << std::sqrt(check.odometry_chi2[i]) << " stated sigmas ("
          << noise.sigma_m << " m, " << noise.sigma_deg
          << " deg) from the odometry (chi-square " << check.odometry_chi2[i]
          << " > " << gate << ")";
      return out.str();
    }
  }
  return "";
}

}  // namespace

double OdometryChi2Gate(size_t factors) {
  // Survival function of chi-square with 6 degrees of freedom.
  const auto survival = [](double x) {
    const double h = 0.5 * x;
    return std::exp(-h) * (1.0 + h + 0.5 * h * h);
  };
  const double alpha =
      0.001 / static_cast<double>(std::max<size_t>(1, factors));
  double lo = 0.0, hi = 1000.0;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (survival(mid) > alpha ? lo : hi) = mid;
  }
  return lo;
}

PoseGraphCheck CheckJointPoses(
    const RegistrationOptions& registration,
    double information_scale,
    const std::vector<LayeredGrid>& maps,
    const std::vector<PointCloud>& scans,
    const std::vector<std::pair<int, int>>& extra_pairs,
    const std::vector<Isometry3d>& odometry,
    const OdometryNoise& noise,
    const std::vector<Isometry3d>& joint,
    double final_cost) {
  PoseGraphCheck check;
  if (!std::isfinite(final_cost) || !AllFinite(joint)) {
    check.verdict = "FAILURE";
    check.message =
        "the joint solve ended at a cost or pose that is not "
        "finite";
    return check;
  }
  const int n = static_cast<int>(joint.size());
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i + 1 < n; ++i) pairs.emplace_back(i, i + 1);
  pairs.insert(pairs.end(), extra_pairs.begin(), extra_pairs.end());
  for (const auto& [i, j] : pairs) {
    check.pairs.push_back(
        CheckPair(registration, information_scale, maps, scans, joint, i, j));
  }
  for (int i = 0; !odometry.empty() && i + 1 < n; ++i) {
    check.odometry_chi2.push_back(
        OdometryChi2(odometry[i].inverse() * odometry[i + 1],
                     noise,
                     joint[i],
                     joint[i + 1]));
  }
  check.message = FirstMisfit(check, noise);
  check.verdict = check.message.empty() ? "CONVERGENCE" : "LOW_QUALITY";
  return check;
}

}  // namespace mlndt
