#include "mlndt/registration/localizability.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "mlndt/registration/quality_check.h"

namespace mlndt {

namespace {

// The normalised point-to-plane rows u = J / |J| (localizability.h) of the
// inliers on planar cells.
std::vector<Vector6d> PlanarRows(
    const std::vector<Eigen::Vector3d>& input_points,
    const std::vector<PointMatch>& matches,
    const Matrix3d& rotation,
    double rms_range_m,
    double gate) {
  const double inverse_lever = 1.0 / std::max(rms_range_m, 1e-3);
  std::vector<Vector6d> rows;
  rows.reserve(input_points.size());
  for (size_t k = 0; k < input_points.size(); ++k) {
    if (!matches[k].IsInlier(gate)) continue;
    const NdtCell& cell = *matches[k].cell;
    const Eigen::Array<bool, 3, 1> thin = ThinCellDirections(cell);
    if (thin.count() != 1) continue;
    int i = 0;
    thin.maxCoeff(&i);
    // Row i of W is v_i^T / sqrt(lambda_i) (ndt_cell.h): the normal.
    const Eigen::Vector3d n = cell.whitening.row(i).transpose().normalized();
    Vector6d row;
    row << n, (rotation * input_points[k]).cross(n) * inverse_lever;
    rows.push_back(row.normalized());
  }
  return rows;
}

}  // namespace

Localizability LocalizabilityOf(
    const std::vector<Eigen::Vector3d>& input_points,
    const std::vector<PointMatch>& matches,
    const Matrix3d& rotation,
    double rms_range_m,
    double gate,
    double constraining_cosine) {
  Localizability result;
  const std::vector<Vector6d> rows =
      PlanarRows(input_points, matches, rotation, rms_range_m, gate);
  result.planar_points = static_cast<int>(rows.size());
  if (rows.empty()) return result;
  Matrix6d information = Matrix6d::Zero();
  for (const Vector6d& u : rows) {
    information.selfadjointView<Eigen::Lower>().rankUpdate(u);
  }
  information = information.selfadjointView<Eigen::Lower>();
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(information);
  result.directions = solver.eigenvectors();
  const double n = static_cast<double>(rows.size());
  result.information = solver.eigenvalues().cwiseMax(0.0) / n;
  // The points whose row leans on each direction by at least the cosine.
  Vector6d constraining = Vector6d::Zero();
  for (const Vector6d& u : rows) {
    const Vector6d cosines = (result.directions.transpose() * u).cwiseAbs();
    constraining += (cosines.array() >= constraining_cosine).cast<double>().matrix();
  }
  result.share = constraining / n;
  return result;
}

}  // namespace mlndt
