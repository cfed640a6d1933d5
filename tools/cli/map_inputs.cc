#include "tools/cli/map_inputs.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "lab/eval/dataset.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/rigid_transform.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/list_flags.h"
#include "tools/cli/matrix_text.h"
#include "tools/cli/pose_flags.h"

namespace mlndt {
namespace tools {

namespace {

// Reads world_from_sensor poses from a KITTI or TUM file, in file order
// (TUM timestamps are not used). With a non-empty `calib` (KITTI
// calib.txt), they are KITTI camera poses and are converted into the
// Velodyne frame (CameraToVelodynePoses).
bool ReadPoseFile(const std::string& path,
                  bool detect,
                  TrajectoryFormat format,
                  const std::string& calib,
                  std::vector<Isometry3d>* poses,
                  std::string* error) {
  Trajectory trajectory;
  const bool ok = detect ? ReadTrajectory(path, &trajectory, error)
                         : ReadTrajectory(path, format, &trajectory, error);
  if (!ok) return false;
  *poses = trajectory.poses();
  if (calib.empty()) return true;
  Isometry3d cam0_from_velo;
  if (!ReadKittiCalibTr(calib, &cam0_from_velo, error)) return false;
  *poses = CameraToVelodynePoses(*poses, cam0_from_velo);
  return true;
}

// A scan list: one path per line; blank lines and lines starting with '#'
// are skipped; relative paths are relative to the list file's folder.
bool ReadScanList(const std::string& path,
                  std::vector<std::string>* paths,
                  std::string* error) {
  namespace fs = std::filesystem;
  paths->clear();
  std::ifstream in(path);
  if (!in) {
    *error = path + ": cannot open the scan list";
    return false;
  }
  const fs::path folder = fs::path(path).parent_path();
  std::string line;
  while (std::getline(in, line)) {
    const size_t begin = line.find_first_not_of(" \t\r");
    if (begin == std::string::npos || line[begin] == '#') continue;
    const size_t end = line.find_last_not_of(" \t\r");
    const fs::path entry = line.substr(begin, end - begin + 1);
    paths->push_back(
        (entry.is_absolute() ? entry : folder / entry).lexically_normal());
  }
  if (paths->empty()) {
    *error = path + ": the scan list names no scans";
    return false;
  }
  return true;
}

// mlndt_map --cloud: the scan flags (poses, calibration, range filter) do
// not apply to one cloud in the world frame; false with *error naming the
// first one given.
bool RefuseScanFlagsWithCloud(std::string* error) {
  return RefuseGivenFlags(
      {"poses",
       "poses_format",
       "calib",
       "poses_are_camera",
       "max_scans",
       "min_range_m",
       "max_range_m",
       "saturated_range_fraction"},
      "does not apply to --cloud (one cloud in the world frame, no "
      "sensor origin)",
      error);
}

// The scans of --scans=DIR (ListScanFiles: the cloud files in DIR sorted by
// name, without the files in `exclude`) or of --scan_list=FILE, exactly one
// of them; the first `max_scans` when > 0; every listed file must exist.
// Messages name the flags.
bool ScanPathsFromFlags(const std::string& scans_dir,
                        const std::string& scan_list,
                        const std::vector<std::string>& exclude,
                        size_t max_scans,
                        std::vector<std::string>* paths,
                        std::string* error) {
  if (!scans_dir.empty() && !scan_list.empty()) {
    *error = "give --scans=DIR or --scan_list=FILE, not both";
    return false;
  }
  if (!scan_list.empty()) {
    if (!ReadScanList(scan_list, paths, error)) {
      *error = "--scan_list: " + *error;
      return false;
    }
  } else if (!ListScanFiles(scans_dir, exclude, paths, error)) {
    *error = "--scans: " + *error;
    return false;
  }
  if (max_scans > 0 && paths->size() > max_scans) paths->resize(max_scans);
  // Every listed scan exists before any work (a missing one would stop the
  // run after the others were read).
  for (size_t k = 0; !scan_list.empty() && k < paths->size(); ++k) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file((*paths)[k], ec)) {
      *error = "--scan_list=" + scan_list + ": scan " + std::to_string(k) +
               " (" + (*paths)[k] + ") is not a readable file";
      return false;
    }
  }
  return true;
}

}  // namespace

bool ParseTrajectoryFormatFlag(const std::string& flag,
                               const std::string& value,
                               bool* detect,
                               TrajectoryFormat* format,
                               std::string* error) {
  *detect = value == "auto";
  if (*detect || StringToTrajectoryFormat(value, format)) return true;
  *error = "--" + flag + "=" + value + ": expected auto, kitti or tum";
  return false;
}

bool ParseInitialPose(const std::string& guess,
                      const std::string& matrix,
                      Isometry3d* pose,
                      bool* given,
                      std::string* error) {
  *pose = Isometry3d::Identity();
  *given = !guess.empty() || !matrix.empty();
  if (!guess.empty() && !matrix.empty()) {
    *error = "give --initial_guess or --initial_matrix, not both";
    return false;
  }
  std::vector<double> v;
  if (!guess.empty()) {
    if (!ParseNumberList(guess, &v) || v.size() != 6) {
      *error = "--initial_guess=" + guess +
               ": expected 6 comma-separated numbers tx,ty,tz,alpha,beta,gamma "
               "(m, deg)";
      return false;
    }
    // Angles beyond a full turn and translations beyond kMaxCoordinateM
    // (1e8 m) are typing errors or corrupt numbers, not poses.
    for (int a = 3; a < 6; ++a) {
      if (std::abs(v[static_cast<size_t>(a)]) > 360.0) {
        *error = "--initial_guess=" + guess +
                 ": angles must be within [-360, 360] deg";
        return false;
      }
    }
    std::string problem;
    if (!ToRigidTransform(
            PoseVectorToIsometry(
                PoseVectorFromDegrees(v[0], v[1], v[2], v[3], v[4], v[5]))
                .matrix(),
            pose,
            &problem)) {
      *error = "--initial_guess=" + guess + ": " + problem;
      return false;
    }
    return true;
  }
  if (!matrix.empty()) {
    if (!ParseNumberList(matrix, &v)) v.clear();
    return RowMajorToRigidTransform(v, "--initial_matrix", pose, error);
  }
  return true;
}

bool InitialPoseFromFlags(const std::string& guess,
                          const std::string& matrix,
                          const std::string& poses_path,
                          const std::string& poses_format,
                          const std::string& calib,
                          Isometry3d* pose,
                          std::string* error) {
  bool given = false;
  if (!ParseInitialPose(guess, matrix, pose, &given, error)) return false;
  if (poses_path.empty()) return true;
  bool detect = true;
  TrajectoryFormat format = TrajectoryFormat::KITTI;
  std::vector<Isometry3d> poses;
  if (!ParseTrajectoryFormatFlag(
          "initial_poses_format", poses_format, &detect, &format, error) ||
      !ReadPoseFile(poses_path, detect, format, calib, &poses, error)) {
    *error = "--initial_poses: " + *error;
    return false;
  }
  *pose = poses.front();
  return true;
}

bool ScanInputFromScanListFlags(const std::string& scans_dir,
                                const std::string& scan_list,
                                const std::vector<std::string>& other_inputs,
                                size_t max_scans,
                                ScanInput* input,
                                std::string* error) {
  const auto list_folder = [&](std::vector<std::string>* paths,
                               std::string* list_error) {
    return ScanPathsFromFlags(
        scans_dir, scan_list, other_inputs, 0, paths, list_error);
  };
  return ScanInputFromFlags(!scans_dir.empty() || !scan_list.empty(),
                            list_folder,
                            max_scans,
                            input,
                            error);
}

bool MapScansFromFlags(const std::string& scans_dir,
                       const std::string& scan_list,
                       const std::string& poses_path,
                       const std::string& poses_format,
                       int max_scans,
                       ScanInput* input,
                       std::vector<Isometry3d>* poses,
                       std::string* error) {
  bool detect = true;
  TrajectoryFormat format = TrajectoryFormat::KITTI;
  if (!ParseTrajectoryFormatFlag(
          "poses_format", poses_format, &detect, &format, error) ||
      !ScanInputFromScanListFlags(scans_dir,
                                  scan_list,
                                  {poses_path, FLAGS_calib},
                                  static_cast<size_t>(max_scans),
                                  input,
                                  error)) {
    return false;
  }
  if (!ReadPoseFile(poses_path, detect, format, FLAGS_calib, poses, error)) {
    *error = "--poses: " + *error;
    return false;
  }
  return CheckPoseCount(
      "--poses=" + poses_path, poses->size(), input->size(), max_scans, error);
}

bool CheckMapSourceFlags(bool from_scans,
                         const std::string& cloud,
                         const std::string& poses_path,
                         std::string* error) {
  if (!from_scans && cloud.empty()) {
    *error =
        "give --scans=DIR (or --scan_list=FILE, or --bag=FILE --topic=NAME) "
        "with --poses, or --cloud";
    return false;
  }
  if (!FLAGS_times.empty()) {
    *error = "--times does not apply to mlndt_map (a map has no time)";
    return false;
  }
  if (from_scans && !cloud.empty()) {
    *error = "give --cloud or --scans/--scan_list/--bag, not both";
    return false;
  }
  if (!cloud.empty() && !RefuseScanFlagsWithCloud(error)) {
    return false;
  }
  if (from_scans && poses_path.empty()) {
    *error =
        "--scans and --scan_list need --poses (world_from_scan of every "
        "scan)";
    return false;
  }
  return CheckCameraPoseFlags("--poses", !poses_path.empty(), error);
}

bool CheckInitialPoseFlags(const std::string& guess,
                           const std::string& matrix,
                           const std::string& poses_path,
                           std::string* error) {
  if (!guess.empty() + !matrix.empty() + !poses_path.empty() > 1) {
    *error =
        "give one of --initial_guess, --initial_matrix and --initial_poses";
    return false;
  }
  return CheckCameraPoseFlags("--initial_poses", !poses_path.empty(), error);
}

bool CheckMapFile(const std::string& path, std::string* error) {
  if (std::filesystem::is_regular_file(path)) return true;
  *error = "--map=" + path +
           (std::filesystem::is_directory(path)
                ? ": it is a directory (give the map file mlndt_map wrote)"
                : ": no such file");
  return false;
}

}  // namespace tools
}  // namespace mlndt
