#pragma once

// Reading and writing the pose files that come with the point clouds:
// KITTI ground-truth poses and calibration, and 3DTK .pose files.
// Readers return false with *error ("<path>: <problem>") on bad input.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace mlndt {

// ---- KITTI ------------------------------------------------------------------

// KITTI poses (odometry poses/NN.txt): one line per pose, 12 numbers = the
// first 3 rows of a 4x4 row-major matrix "r11 r12 r13 tx r21 ... r33 tz",
// metres. Pose i maps points of frame i into the frame of the first frame of
// the sequence (world_from_frame). The numbers are kept as written (not
// re-orthonormalised); a rotation part that is not a rotation within 1e-3, a
// line without exactly 12 numbers, or a file without poses is an error.
// Blank lines are skipped.
bool ReadKittiPoses(const std::string& path,
                    std::vector<Eigen::Isometry3d>* poses,
                    std::string* error);
// Writes the same layout with 17 significant digits, so reading it back gives
// exactly the same doubles. Written with WriteFileAtomically
// (mlndt/common/atomic_file.h), like WritePointCloud (io.h).
bool WriteKittiPoses(const std::string& path,
                     const std::vector<Eigen::Isometry3d>& poses,
                     std::string* error);

// KITTI odometry calib.txt: lines "P0: ...", ..., "Tr: <12 numbers>". The Tr
// line is the row-major 3x4 velo-to-cam0 transform, i.e. cam0_from_velo.
bool ReadKittiCalibTr(const std::string& path,
                      Eigen::Isometry3d* cam0_from_velo,
                      std::string* error);

// ---- 3DTK -------------------------------------------------------------------
//
// 3DTK works in centimetres in a left-handed frame with x right, y up and z
// forward. mlndt uses metres in a right-handed frame with x forward, y left,
// z up (io.h reads .3d scans into it). The axis mapping is
//     p_r = P p_l / 100,   P = [0 0 1; -1 0 0; 0 1 0],   det(P) = -1,
// i.e. x_r = z_l, y_r = -x_l, z_r = y_l (the inverse of 3DTK's own import of
// right-handed data, ScanDataTransform_xyz in src/scanio/helper.cc).
//
// A 3DTK .pose file holds two lines: position x y z [cm] and Euler angles
// θx θy θz [deg] (3DTK reads six numbers with operator>> and converts the
// angles to radians: readPoseHelper in src/scanio/helper.cc). 3DTK turns them
// into a matrix with EulerToMatrix4(rPos, rPosTheta, alignxf) in
// include/slam6d/globals.icc (3DTK/3DTK). That matrix is stored column-major
// (OpenGL order) and is applied to a scan's points as
// p_world = R_l p_scan + t_l (Point::transform in include/slam6d/point.icc),
// with t_l = (x, y, z) and, reading alignxf[0..10] back into rows,
//     R_l = [ cy*cz            -cy*sz             sy
//             sx*sy*cz + cx*sz  -sx*sy*sz + cx*cz  -sx*cy
//            -cx*sy*cz + sx*sz   cx*sy*sz + sx*cz   cx*cy ]
//         = Rx(θx) * Ry(θy) * Rz(θz)
// (s/c = sin/cos of the angle about that axis; Rx, Ry, Rz are the usual
// right-hand-rule matrices, applied to the left-handed coordinates). The
// pose is world_from_scan. In the metric right-handed frame it becomes
//     R_r = P R_l P^-1,   t_r = P t_l / 100,
// so that Convert3dtkPose(...) * Convert3dtkPoint(p) equals
// Convert3dtkPoint(R_l p + t_l). det(R_r) = det(R_l) = +1, so R_r is a proper
// rotation. Example: a 3DTK rotation by +θ about y (up) turns forward (+z_l)
// towards +x_l (right), which is a rotation by -θ about z_r.

// Maps a 3DTK point [cm, left-handed, y up] into metres, right-handed, z up.
Eigen::Vector3d Convert3dtkPoint(const Eigen::Vector3d& point_3dtk);

// Converts a 3DTK pose (position [cm], Euler angles θx θy θz [deg], as in a
// .pose file) into world_from_scan in the metric right-handed frame.
Eigen::Isometry3d Convert3dtkPose(const Eigen::Vector3d& position_cm,
                                  const Eigen::Vector3d& euler_deg);

// Reads a 3DTK .pose file (exactly six numbers; line breaks and blank lines
// do not matter) and returns Convert3dtkPose of it.
bool Read3dtkPose(const std::string& path,
                  Eigen::Isometry3d* world_from_scan,
                  std::string* error);

}  // namespace mlndt
