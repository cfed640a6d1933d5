#include "mlndt/registration/localizability.h"

#include <Eigen/Eigenvalues>

#include "mlndt/registration/internal/cell_shape.h"
#include "mlndt/registration/quality_check.h"

namespace mlndt {

namespace {

// The unit normals of the planar cells of the inliers among `matches`.
std::vector<Eigen::Vector3d> PlanarNormals(
    const std::vector<PointMatch>& matches, double gate) {
  std::vector<Eigen::Vector3d> normals;
  normals.reserve(matches.size());
  for (const PointMatch& match : matches) {
    if (!match.IsInlier(gate)) continue;
    const Eigen::Array<bool, 3, 1> thin =
        internal::ThinCellDirections(*match.cell);
    if (thin.count() != 1) continue;
    int i = 0;
    thin.maxCoeff(&i);
    // Row i of W is v_i^T / sqrt(lambda_i) (ndt_cell.h): the normal.
    normals.push_back(match.cell->whitening.row(i).transpose().normalized());
  }
  return normals;
}

}  // namespace

Localizability LocalizabilityOf(const std::vector<PointMatch>& matches,
                                double gate,
                                double constraining_cosine) {
  Localizability result;
  const std::vector<Eigen::Vector3d> normals = PlanarNormals(matches, gate);
  result.planar_points = static_cast<int>(normals.size());
  if (normals.empty()) return result;
  Matrix3d information = Matrix3d::Zero();
  for (const Eigen::Vector3d& n : normals) information += n * n.transpose();
  const Eigen::SelfAdjointEigenSolver<Matrix3d> solver(information);
  result.directions = solver.eigenvectors();
  const double count = static_cast<double>(normals.size());
  result.information = solver.eigenvalues().cwiseMax(0.0) / count;
  // The normals that lean on each direction by at least the cosine.
  Eigen::Vector3d constraining = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& n : normals) {
    const Eigen::Vector3d cosines =
        (result.directions.transpose() * n).cwiseAbs();
    constraining +=
        (cosines.array() >= constraining_cosine).cast<double>().matrix();
  }
  result.share = constraining / count;
  return result;
}

}  // namespace mlndt
