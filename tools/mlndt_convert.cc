// mlndt_convert: converts a point cloud between the formats mlndt reads and
// writes (reads PCD, PLY, KITTI .bin, 3DTK .3d, xyz text; writes binary PCD
// with x y z as float, or binary PLY). Non-finite points are dropped.
//
//   mlndt_convert --input=000000.bin --output=000000.pcd [--voxel_size=0.2]

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <iostream>

#include "mlndt/cloud/io.h"
#include "mlndt/sampling/point_sampler.h"
#include "tools/common/tool_main.h"

DEFINE_string(input, "", "Input cloud (any format mlndt reads)");
DEFINE_string(output, "", "Output cloud (.pcd or .ply)");
DEFINE_double(voxel_size,
              0.0,
              "When > 0, keep one centroid per voxel of this edge [m]");

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Converts a point cloud: mlndt_convert --input=A --output=B",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  if (FLAGS_input.empty() || FLAGS_output.empty()) {
    std::cerr << "mlndt_convert: give --input=FILE and --output=FILE\n";
    return mlndt::tools::kExitUsage;
  }
  if (!(FLAGS_voxel_size >= 0.0)) {
    std::cerr << "mlndt_convert: --voxel_size must be >= 0\n";
    return mlndt::tools::kExitUsage;
  }
  mlndt::PointCloud cloud;
  mlndt::ReadCloudInfo info;
  std::string error;
  if (!mlndt::ReadPointCloud(FLAGS_input, &cloud, &info, &error)) {
    std::cerr << "mlndt_convert: " << error << "\n";
    return mlndt::tools::kExitUsage;
  }
  if (FLAGS_voxel_size > 0.0)
    cloud = mlndt::VoxelDownsample(cloud, FLAGS_voxel_size);
  if (!mlndt::WritePointCloud(FLAGS_output, cloud, &error)) {
    std::cerr << "mlndt_convert: " << error << "\n";
    return mlndt::tools::kExitFailed;
  }
  std::cout << FLAGS_input << " (" << info.points_in_file << " points, "
            << info.dropped_non_finite << " non-finite dropped) -> "
            << FLAGS_output << " (" << cloud.size() << " points)\n";
  return mlndt::tools::kExitOk;
}
