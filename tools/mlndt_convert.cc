// mlndt_convert: converts a point cloud between the formats mlndt reads and
// writes (reads PCD, PLY, KITTI .bin, 3DTK .3d, xyz text; writes binary PCD
// with x y z as float, or binary PLY). Non-finite points are dropped.
//
//   mlndt_convert 000000.bin 000000.pcd [--voxel_size=0.2]
//   mlndt_convert --input=000000.bin --output=000000.pcd

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <iostream>

#include "mlndt/cloud/io.h"
#include "mlndt/sampling/point_sampler.h"
#include "tools/cli/input_files.h"
#include "tools/cli/output_files.h"
#include "tools/cli/tool_main.h"

DEFINE_string(
    input,
    "",
    "Input cloud (any format mlndt reads; or the first positional argument)");
DEFINE_string(output,
              "",
              "Output cloud (.pcd or .ply; or the second positional argument)");
DEFINE_double(voxel_size,
              0.0,
              "When > 0, keep one centroid per voxel of this edge [m]");

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool("Converts a point cloud.\n"
                               "  mlndt_convert IN OUT [--voxel_size=0.2]\n"
                               "  mlndt_convert --input=IN --output=OUT",
                               false,
                               &argc,
                               &argv)) {
    return mlndt::tools::kExitUsage;
  }
  if (argc > 1 && (!FLAGS_input.empty() || !FLAGS_output.empty())) {
    std::cerr << "mlndt_convert: give the clouds as IN OUT or as "
                 "--input/--output, not both\n";
    return mlndt::tools::kExitUsage;
  }
  if (argc > 3 || argc == 2) {
    std::cerr << "mlndt_convert: expected IN OUT (usage: mlndt_convert IN OUT "
                 "[--voxel_size=V])\n";
    return mlndt::tools::kExitUsage;
  }
  const std::string input = argc == 3 ? argv[1] : FLAGS_input;
  const std::string output = argc == 3 ? argv[2] : FLAGS_output;
  if (input.empty() || output.empty()) {
    std::cerr << "mlndt_convert: give IN OUT (or --input=FILE and "
                 "--output=FILE)\n";
    return mlndt::tools::kExitUsage;
  }
  std::string error;
  // OUT is an argument too, but only IN is read.
  mlndt::tools::SetToolArguments({input});
  if (!mlndt::tools::CheckOutputFile("output", output, &error)) {
    std::cerr << "mlndt_convert: " << error << "\n";
    return mlndt::tools::kExitUsage;
  }
  // An output format mlndt cannot write is refused before the input is
  // read, as mlndt_align --output_cloud is (exit 2, not 1 after the work).
  if (!mlndt::CanWritePointCloud(output, &error)) {
    std::cerr << "mlndt_convert: " << error << "\n";
    return mlndt::tools::kExitUsage;
  }
  if (!(FLAGS_voxel_size >= 0.0)) {
    std::cerr << "mlndt_convert: --voxel_size must be >= 0\n";
    return mlndt::tools::kExitUsage;
  }
  mlndt::PointCloud cloud;
  mlndt::ReadCloudInfo info;
  if (!mlndt::ReadPointCloud(input, &cloud, &info, &error)) {
    std::cerr << "mlndt_convert: " << error << "\n";
    return mlndt::tools::kExitUsage;
  }
  if (FLAGS_voxel_size > 0.0)
    cloud = mlndt::VoxelDownsample(cloud, FLAGS_voxel_size);
  if (!mlndt::WritePointCloud(output, cloud, &error)) {
    std::cerr << "mlndt_convert: " << error << "\n";
    return mlndt::tools::kExitFailed;
  }
  std::cout << input << " (" << info.points_in_file << " points, "
            << info.dropped_non_finite << " non-finite dropped) -> " << output
            << " (" << cloud.size() << " points)\n";
  return mlndt::tools::kExitOk;
}
