#pragma once

// Inputs of the map tools (mlndt_map, mlndt_localize): the scans of a
// folder or a list file, pose files in KITTI or TUM format, and an initial
// pose given on the command line.

#include <cstddef>
#include <string>
#include <vector>

#include "lab/eval/trajectory_io.h"
#include "mlndt/common/types.h"
#include "tools/cli/scan_input.h"

namespace mlndt {
namespace tools {

// "auto" (DetectTrajectoryFormat), "kitti" or "tum", for --*_format flags.
// False with *error naming `flag` for another value.
bool ParseTrajectoryFormatFlag(const std::string& flag,
                               const std::string& value,
                               bool* detect,
                               TrajectoryFormat* format,
                               std::string* error);

// An initial pose from --initial_guess=tx,ty,tz,alpha,beta,gamma (m, deg,
// R = Rx Ry Rz) or --initial_matrix= 12 numbers (row-major 3x4, the rotation
// re-orthonormalised); at most one of them. *given tells whether one was.
// Refused: angles beyond +-360 deg, a translation beyond kMaxCoordinateM
// (1e8 m, mlndt/common/rigid_transform.h), a matrix that is not a rotation
// within 1e-3.
bool ParseInitialPose(const std::string& guess,
                      const std::string& matrix,
                      Isometry3d* pose,
                      bool* given,
                      std::string* error);

// The first scan's pose: ParseInitialPose of `guess` or `matrix`, else the
// first pose of `poses_path` (ReadPoseFile, its format from the flag value
// `poses_format`, errors prefixed "--initial_poses: "), else the identity.
bool InitialPoseFromFlags(const std::string& guess,
                          const std::string& matrix,
                          const std::string& poses_path,
                          const std::string& poses_format,
                          const std::string& calib,
                          Isometry3d* pose,
                          std::string* error);

// ScanInputFromFlags for a tool with --scans=DIR and --scan_list=FILE
// (ScanPathsFromFlags; `other_inputs` are left out of the folder).
bool ScanInputFromScanListFlags(const std::string& scans_dir,
                                const std::string& scan_list,
                                const std::vector<std::string>& other_inputs,
                                size_t max_scans,
                                ScanInput* input,
                                std::string* error);

// mlndt_map's scans and their world_from_scan poses (--poses in
// `poses_format`, pose k for scan k): false with *error naming the flag
// when the format, the scans or the poses are refused, or when the counts
// differ (more poses than scans only with `max_scans` > 0).
bool MapScansFromFlags(const std::string& scans_dir,
                       const std::string& scan_list,
                       const std::string& poses_path,
                       const std::string& poses_format,
                       int max_scans,
                       ScanInput* input,
                       std::vector<Isometry3d>* poses,
                       std::string* error);

// mlndt_map's source: scans (`from_scans`: --scans, --scan_list or --bag)
// with --poses, or one --cloud; no --times. False with *error naming the
// flags otherwise.
bool CheckMapSourceFlags(bool from_scans,
                         const std::string& cloud,
                         const std::string& poses_path,
                         std::string* error);

// At most one of --initial_guess, --initial_matrix and --initial_poses,
// and the camera pose flags fit --initial_poses (CheckCameraPoseFlags).
bool CheckInitialPoseFlags(const std::string& guess,
                           const std::string& matrix,
                           const std::string& poses_path,
                           std::string* error);

// --map=`path` names an existing file (not a folder).
bool CheckMapFile(const std::string& path, std::string* error);

}  // namespace tools
}  // namespace mlndt
