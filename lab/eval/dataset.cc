#include "lab/eval/dataset.h"

#include <glog/logging.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "mlndt/cloud/cloud_format.h"
#include "mlndt/cloud/pose_io.h"

namespace mlndt {
namespace {

std::string LowerExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(),
                 extension.end(),
                 extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension;
}

bool IsTextFile(const std::string& path) {
  return LowerExtension(path) == ".txt";
}

bool IsTextCloud(const std::string& path) {
  return IsTextFile(path) || LowerExtension(path) == ".xyz";
}

// Whether the first line of `path` that is not blank or a '#' comment holds
// at least three numbers (an xyz text cloud's "x y z ..."); a stamps file
// (one number a line) or KITTI's calib.txt ("P0: ...") does not.
bool FirstLineIsPoint(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (int k = 0; k < 100 && std::getline(in, line); ++k) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream tokens(line);
    std::string token;
    if (!(tokens >> token) || token[0] == '#') continue;
    int numbers = 0;
    do {
      char* end = nullptr;
      std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0') break;
      ++numbers;
    } while (numbers < 3 && tokens >> token);
    return numbers >= 3;
  }
  return false;
}

// .txt files beside binary scans (.pcd, .ply, .bin, .3d) are stamps, poses,
// calibration or trajectories, not scans: .txt files are scans only in a
// folder of text clouds (.txt, .xyz), and there only those whose first line
// is a point.
void DropTextFilesThatAreNotScans(std::vector<std::string>* paths) {
  const bool all_text =
      std::all_of(paths->begin(), paths->end(), [](const std::string& p) {
        return IsTextCloud(p);
      });
  paths->erase(std::remove_if(paths->begin(),
                              paths->end(),
                              [&](const std::string& p) {
                                return IsTextFile(p) &&
                                       (!all_text || !FirstLineIsPoint(p));
                              }),
               paths->end());
}

}  // namespace

bool ListScanFiles(const std::string& dir,
                   const std::vector<std::string>& exclude,
                   std::vector<std::string>* paths,
                   std::string* error) {
  CHECK(paths != nullptr);
  CHECK(error != nullptr);
  namespace fs = std::filesystem;
  paths->clear();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    *error = dir + ": not a folder";
    return false;
  }
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::error_code file_ec;
    if (!entry.is_regular_file(file_ec)) continue;
    CloudFormat format;
    std::string ignored;
    if (!CloudFormatFromPath(entry.path().string(), &format, &ignored))
      continue;
    const bool excluded =
        std::any_of(exclude.begin(), exclude.end(), [&](const std::string& e) {
          std::error_code eq_ec;
          return !e.empty() && fs::equivalent(entry.path(), e, eq_ec);
        });
    if (!excluded) paths->push_back(entry.path().string());
  }
  if (ec) {
    *error = dir + ": " + ec.message();
    return false;
  }
  DropTextFilesThatAreNotScans(paths);
  std::sort(paths->begin(),
            paths->end(),
            [](const std::string& a, const std::string& b) {
              return fs::path(a).filename() < fs::path(b).filename();
            });
  if (paths->empty()) {
    *error = dir + ": no point-cloud files (.pcd, .ply, .bin, .3d, .xyz, .txt)";
    return false;
  }
  return true;
}

std::vector<Isometry3d> CameraToVelodynePoses(
    const std::vector<Isometry3d>& cam0_poses,
    const Isometry3d& cam0_from_velo) {
  const Isometry3d velo_from_cam0 = cam0_from_velo.inverse();
  std::vector<Isometry3d> velo_poses;
  velo_poses.reserve(cam0_poses.size());
  for (const Isometry3d& pose : cam0_poses) {
    velo_poses.push_back(velo_from_cam0 * pose * cam0_from_velo);
  }
  return velo_poses;
}

bool ReadSequencePoses(const std::string& poses_path,
                       const std::string& calib_path,
                       std::vector<Isometry3d>* poses,
                       std::string* error) {
  CHECK(poses != nullptr);
  CHECK(error != nullptr);
  if (!ReadKittiPoses(poses_path, poses, error)) return false;
  if (calib_path.empty()) return true;
  Isometry3d cam0_from_velo;
  if (!ReadKittiCalibTr(calib_path, &cam0_from_velo, error)) return false;
  *poses = CameraToVelodynePoses(*poses, cam0_from_velo);
  return true;
}

}  // namespace mlndt
