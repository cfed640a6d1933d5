// Adds ML-NDT residuals of one scan against a layered map to a
// ceres::Problem that also holds the user's own residual (a weak prior on the
// translation, standing in for odometry), solves it, and prints the pose.
//
//   mlndt_consumer reference.pcd input.pcd

#include <ceres/ceres.h>

#include <iostream>

#include "mlndt/mlndt.h"

// The user's own residual: the translation stays near a prior [m].
struct TranslationPrior {
  explicit TranslationPrior(const Eigen::Vector3d& prior) : prior_(prior) {}
  template <typename T>
  bool operator()(const T* translation, T* residual) const {
    for (int i = 0; i < 3; ++i)
      residual[i] = T(0.1) * (translation[i] - T(prior_(i)));
    return true;
  }
  Eigen::Vector3d prior_;
};

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: mlndt_consumer reference.pcd input.pcd\n";
    return 1;
  }
  mlndt::PointCloud reference, input;
  std::string error;
  if (!mlndt::ReadPointCloud(argv[1], &reference, nullptr, &error) ||
      !mlndt::ReadPointCloud(argv[2], &input, nullptr, &error)) {
    std::cerr << error << "\n";
    return 1;
  }
  mlndt::LayeredGrid map;
  if (!mlndt::LayeredGrid::Build(
          mlndt::LayeredGridOptions(), reference, &map, &error)) {
    std::cerr << error << "\n";
    return 1;
  }
  mlndt::PointCloud samples;
  if (!mlndt::SamplePoints(
          mlndt::SamplingOptions(), input, &samples, nullptr, &error)) {
    std::cerr << error << "\n";
    return 1;
  }

  // The caller's pose blocks: quaternion (x, y, z, w) and translation.
  double rotation[4] = {0.0, 0.0, 0.0, 1.0};
  double translation[3] = {0.0, 0.0, 0.0};
  // One Problem: the ML-NDT residuals read their layer through a binding,
  // which moves them coarse to fine; the prior stays.
  mlndt::LayerBinding layer_binding(map.layer(1));
  ceres::Problem problem;
  mlndt::AddMlNdtResidualsQuaternion(layer_binding,
                                     samples.points(),
                                     mlndt::ObjectiveOptions(),
                                     rotation,
                                     translation,
                                     &problem);
  problem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<TranslationPrior, 3, 3>(
          new TranslationPrior(Eigen::Vector3d::Zero())),
      nullptr,
      translation);
  for (int layer = 1; layer <= map.num_layers(); ++layer) {
    layer_binding.Rebind(map.layer(layer));
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = layer == map.num_layers() ? 30 : 6;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    std::cout << "layer " << layer << ": " << summary.BriefReport() << "\n";
  }
  std::cout << "translation [m]: " << translation[0] << " " << translation[1]
            << " " << translation[2] << "\n";
  return 0;
}
