#pragma once

// The one check of a rigid transform given from outside (pose files, tool
// flags, Python arrays, initial guesses): finite, last row (0, 0, 0, 1), a
// rotation part R with |R^T R - I| (Frobenius) at most
// kRigidRotationTolerance and det R > 0, and a translation no longer than
// kMaxCoordinateM. What passes is re-orthonormalised (the nearest rotation,
// R = U V^T of the SVD U S V^T), so text with 6 decimals (|R^T R - I| about
// 1e-6) gives an exact rotation; a rotation already exact to 1e-12 is kept
// as it is.

#include <Eigen/Core>
#include <string>

#include "mlndt/common/types.h"

namespace mlndt {

// |R^T R - I| a rotation written as text may have (6 decimals: ~1e-6).
constexpr double kRigidRotationTolerance = 1e-3;
// Largest coordinate magnitude [m] accepted in a pose, a point bound or a
// map: 1e8 m is about eight Earth diameters, far beyond any UTM or ECEF
// coordinate; anything larger (1e300) is a corrupt number, not a place.
constexpr double kMaxCoordinateM = 1e8;

// Checks `matrix` as above and stores the re-orthonormalised transform in
// *rigid. False with *problem (what is wrong, with the numbers) otherwise;
// *rigid is then unchanged.
bool ToRigidTransform(const Eigen::Matrix4d& matrix,
                      Isometry3d* rigid,
                      std::string* problem);

}  // namespace mlndt
