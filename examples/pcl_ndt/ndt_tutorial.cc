// PCL's NDT tutorial ("How to use Normal Distributions Transform",
// pointclouds.org/documentation/tutorials/normal_distributions_transform),
// written from its text: align room_scan2 onto room_scan1 from the robot's
// odometry guess, the input thinned by an approximate voxel grid.
//
// One source, two programs (CMakeLists.txt): pcl_ndt_tutorial registers
// with pcl::NormalDistributionsTransform, mlndt_ndt_tutorial (compiled with
// MLNDT_NDT_TUTORIAL_USE_MLNDT) with mlndt::pcl::MultiLayerNdt. The type of
// `ndt` is the only difference. The tutorial's viewer is left out (it needs
// a display); the rest is the tutorial's program.
//
//   pcl_ndt_tutorial [DATA_DIR [OUTPUT.pcd]]
//
// DATA_DIR holds room_scan1.pcd and room_scan2.pcd (default: the current
// folder, as in the tutorial); OUTPUT.pcd (default
// room_scan2_transformed.pcd) receives the unfiltered input moved by the
// result. Exit 0 when the registration reports convergence, 1 otherwise.

#include <pcl/filters/approximate_voxel_grid.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <pcl/registration/ndt.h>

#include <iostream>
#include <string>

#ifdef MLNDT_NDT_TUTORIAL_USE_MLNDT
#include "mlndt/pcl/multi_layer_ndt.h"
#endif

int main(int argc, char** argv) {
  const std::string data_dir = argc > 1 ? std::string(argv[1]) + "/" : "";
  const std::string output_path =
      argc > 2 ? argv[2] : "room_scan2_transformed.pcd";

  // Loading first scan of room.
  pcl::PointCloud<pcl::PointXYZ>::Ptr target_cloud(
      new pcl::PointCloud<pcl::PointXYZ>);
  if (pcl::io::loadPCDFile<pcl::PointXYZ>(data_dir + "room_scan1.pcd",
                                          *target_cloud) == -1) {
    PCL_ERROR("Couldn't read file room_scan1.pcd \n");
    return 2;
  }
  std::cout << "Loaded " << target_cloud->size()
            << " data points from room_scan1.pcd" << std::endl;

  // Loading second scan of room from new perspective.
  pcl::PointCloud<pcl::PointXYZ>::Ptr input_cloud(
      new pcl::PointCloud<pcl::PointXYZ>);
  if (pcl::io::loadPCDFile<pcl::PointXYZ>(data_dir + "room_scan2.pcd",
                                          *input_cloud) == -1) {
    PCL_ERROR("Couldn't read file room_scan2.pcd \n");
    return 2;
  }
  std::cout << "Loaded " << input_cloud->size()
            << " data points from room_scan2.pcd" << std::endl;

  // Filtering input scan to roughly 10% of original size to increase speed
  // of registration.
  pcl::PointCloud<pcl::PointXYZ>::Ptr filtered_cloud(
      new pcl::PointCloud<pcl::PointXYZ>);
  pcl::ApproximateVoxelGrid<pcl::PointXYZ> approximate_voxel_filter;
  approximate_voxel_filter.setLeafSize(0.2, 0.2, 0.2);
  approximate_voxel_filter.setInputCloud(input_cloud);
  approximate_voxel_filter.filter(*filtered_cloud);
  std::cout << "Filtered cloud contains " << filtered_cloud->size()
            << " data points from room_scan2.pcd" << std::endl;

  // Initializing Normal Distributions Transform (NDT).
#ifdef MLNDT_NDT_TUTORIAL_USE_MLNDT
  mlndt::pcl::MultiLayerNdt<pcl::PointXYZ, pcl::PointXYZ> ndt;
#else
  pcl::NormalDistributionsTransform<pcl::PointXYZ, pcl::PointXYZ> ndt;
#endif

  // Setting scale dependent NDT parameters.
  // Setting minimum transformation difference for termination condition.
  ndt.setTransformationEpsilon(0.01);
  // Setting maximum step size for More-Thuente line search.
  ndt.setStepSize(0.1);
  // Setting Resolution of NDT grid structure (VoxelGridCovariance).
  ndt.setResolution(1.0);

  // Setting max number of registration iterations.
  ndt.setMaximumIterations(35);

  // Setting point cloud to be aligned.
  ndt.setInputSource(filtered_cloud);
  // Setting point cloud to be aligned to.
  ndt.setInputTarget(target_cloud);

  // Set initial alignment estimate found using robot odometry.
  Eigen::AngleAxisf init_rotation(0.6931, Eigen::Vector3f::UnitZ());
  Eigen::Translation3f init_translation(1.79387, 0.720047, 0);
  Eigen::Matrix4f init_guess = (init_translation * init_rotation).matrix();

  // Calculating required rigid transform to align the input cloud to the
  // target cloud.
  pcl::PointCloud<pcl::PointXYZ>::Ptr output_cloud(
      new pcl::PointCloud<pcl::PointXYZ>);
  ndt.align(*output_cloud, init_guess);

  std::cout << "Normal Distributions Transform has converged:"
            << ndt.hasConverged() << " score: " << ndt.getFitnessScore()
            << std::endl;
  std::cout << "Final transformation:\n"
            << ndt.getFinalTransformation() << std::endl;

  // Transforming unfiltered, input cloud using found transform.
  pcl::transformPointCloud(
      *input_cloud, *output_cloud, ndt.getFinalTransformation());

  // Saving transformed input cloud.
  pcl::io::savePCDFileASCII(output_path, *output_cloud);

  return ndt.hasConverged() ? 0 : 1;
}
