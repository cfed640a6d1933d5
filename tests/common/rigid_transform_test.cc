#include "mlndt/common/rigid_transform.h"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <string>

#include "mlndt/common/pose.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

double Orthogonality(const Eigen::Matrix3d& r) {
  return (r.transpose() * r - Eigen::Matrix3d::Identity()).norm();
}

// data/koide3/T_target_source.txt: the pair's reference result, written
// with 6 significant digits.
Eigen::Matrix4d SixDigitMatrix() {
  std::ifstream in(testing::BundledDataPath("koide3/T_target_source.txt"));
  Eigen::Matrix4d m;
  for (int k = 0; k < 16; ++k) in >> m(k / 4, k % 4);
  EXPECT_TRUE(in) << "cannot read the matrix";
  return m;
}

// Issue 27 item 4: a rotation written with 6 digits is accepted and made
// exactly orthonormal (the registration refused |R^T R - I| > 1e-6 before,
// while the pose files accepted 1e-3); the translation is kept.
TEST(ToRigidTransform, AcceptsAndReorthonormalisesSixDigitRotations) {
  const Eigen::Matrix4d m = SixDigitMatrix();
  ASSERT_GT(Orthogonality(m.topLeftCorner<3, 3>()), 1e-6);
  Isometry3d rigid;
  std::string problem;
  ASSERT_TRUE(ToRigidTransform(m, &rigid, &problem)) << problem;
  EXPECT_LT(Orthogonality(rigid.linear()), 1e-14);
  EXPECT_NEAR(rigid.linear().determinant(), 1.0, 1e-14);
  EXPECT_LT((rigid.linear() - m.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff(),
            1e-5);
  EXPECT_EQ(rigid.translation(), Eigen::Vector3d(m.topRightCorner<3, 1>()));
}

TEST(ToRigidTransform, KeepsAnExactRotationBitForBit) {
  const Isometry3d exact =
      PoseVectorToIsometry(PoseVectorFromDegrees(1, -2, 3, 10, -20, 45));
  Isometry3d rigid;
  std::string problem;
  ASSERT_TRUE(ToRigidTransform(exact.matrix(), &rigid, &problem)) << problem;
  EXPECT_EQ(rigid.matrix(), exact.matrix());
}

TEST(ToRigidTransform, RefusesWhatIsNoPlaceAndNoRotation) {
  const Eigen::Matrix4d good = SixDigitMatrix();
  struct Case {
    Eigen::Matrix4d matrix;
    std::string problem;
  };
  std::vector<Case> cases;
  Eigen::Matrix4d m = good;
  m(0, 3) = 1e300;
  cases.push_back({m, "translation (1e+300, "});
  m = good;
  m(2, 3) = -2e8;
  cases.push_back({m, "is beyond 1e+08 m"});
  m = good;
  m(1, 1) = std::numeric_limits<double>::quiet_NaN();
  cases.push_back({m, "non-finite number"});
  m = good;
  m.row(0) *= -1.0;  // A reflection: orthonormal, det -1.
  cases.push_back({m, "det R = -1"});
  m = good;
  m.topLeftCorner<3, 3>() *= 1.001;  // Scaled: |R^T R - I| = 3.5e-3.
  cases.push_back({m, "the 3x3 part is not a rotation (|R^T R - I| = "});
  m = good;
  m(3, 0) = 0.5;
  cases.push_back({m, "the last row is not 0 0 0 1"});
  for (const Case& c : cases) {
    Isometry3d rigid = Isometry3d::Identity();
    std::string problem;
    EXPECT_FALSE(ToRigidTransform(c.matrix, &rigid, &problem)) << c.problem;
    EXPECT_NE(problem.find(c.problem), std::string::npos) << problem;
    EXPECT_TRUE(rigid.isApprox(Isometry3d::Identity()));  // Untouched.
  }
}

}  // namespace
}  // namespace mlndt
