#include "mlndt/cost/point_matches.h"

#include <gtest/gtest.h>

#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/koide3_pair.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// The bundled koide3 samples moved off the map's scan by 0.4 m and 3 deg:
// on the last layer some points fall in occupied cells, some next to them
// and some far from any, so every branch of the match is taken.
TEST(MatchPoints, AgreesWithMatchCellAndTheWhitenedResidualOnRealScans) {
  const testing::Koide3MapAndSamples& pair = testing::Koide3Pair();
  const NdtLayer& layer = pair.map.layer(pair.map.num_layers());
  Vector6d xi;
  xi << 0.4, -0.2, 0.05, 0.0, 0.01, 0.05;
  const Isometry3d pose = PoseVectorToIsometry(xi);
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    const std::vector<PointMatch> matches = MatchPoints(
        layer, pair.samples, pose.linear(), pose.translation(), policy);
    ASSERT_EQ(matches.size(), pair.samples.size());
    size_t own = 0, nearest = 0, unmatched = 0;
    for (size_t k = 0; k < matches.size(); ++k) {
      const PointMatch& m = matches[k];
      const Eigen::Vector3d x = pose * pair.samples[k];
      ASSERT_NEAR((m.x - x).norm(), 0.0, 1e-9);
      ASSERT_EQ(m.cell, MatchCell(layer, m.x, policy)) << "point " << k;
      ASSERT_EQ(m.own_cell, layer.Lookup(m.x) != nullptr) << "point " << k;
      if (m.cell == nullptr) {
        ++unmatched;
        EXPECT_EQ(m.score, 0.0);
        continue;
      }
      (m.own_cell ? own : nearest)++;
      // s = e^T C^-1 e = ||W e||^2 (W^T W = C^-1).
      const double whitened =
          (m.cell->whitening * (m.x - m.cell->mean)).squaredNorm();
      ASSERT_NEAR(m.score, whitened, 1e-9 * (1.0 + whitened)) << "point " << k;
    }
    EXPECT_GT(own, matches.size() / 4);
    EXPECT_GT(unmatched, 0u);
    if (policy == UnmatchedPolicy::NEAREST_CELL) {
      EXPECT_GT(nearest, 0u);
    } else {
      EXPECT_EQ(nearest, 0u);
    }
  }
}

// With the cell rules on (CellRegularization::plane_ratio), a planar cell's
// objective scores its normal only; the match's score, which the verdict
// judges the fit by, is still the Mahalanobis distance of the cell's whole
// covariance, and it is the objective's ||W e||^2 on every other cell.
TEST(MatchPoints, ScoreIsOfTheWholeCovarianceOnCellsScoredAlongTheirNormal) {
  PointCloud reference;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(testing::BundledDataPath("koide3/251370668.pcd"),
                             &reference,
                             nullptr,
                             &error))
      << error;
  LayeredGridOptions options;
  options.regularization.line_ratio = 0.1;
  options.regularization.plane_ratio = 0.1;
  LayeredGrid map;
  ASSERT_TRUE(LayeredGrid::Build(options, reference, &map, &error)) << error;
  const NdtLayer& layer = map.layer(map.num_layers());
  const std::vector<Eigen::Vector3d>& samples = testing::Koide3Pair().samples;
  const Isometry3d pose = PoseVectorToIsometry(Vector6d::Constant(0.02));
  size_t planar = 0, whole = 0;
  for (const PointMatch& m : MatchPoints(layer,
                                         samples,
                                         pose.linear(),
                                         pose.translation(),
                                         UnmatchedPolicy::NEAREST_CELL)) {
    if (m.cell == nullptr) continue;
    const Eigen::Vector3d e = m.x - m.cell->mean;
    const double mahalanobis = e.dot(m.cell->covariance.inverse() * e);
    const double whitened = (m.cell->whitening * e).squaredNorm();
    if (m.cell->normal_only) {
      ++planar;
      ASSERT_NEAR(m.score, mahalanobis, 1e-9 * (1.0 + mahalanobis));
    } else {
      ++whole;
      ASSERT_NEAR(m.score, whitened, 1e-9 * (1.0 + whitened));
    }
  }
  // Both kinds are matched, and on the planar cells the objective's
  // residual is not the fit's (the normal-only whitening ignores the plane).
  EXPECT_GT(planar, 100u);
  EXPECT_GT(whole, 100u);
}

}  // namespace
}  // namespace mlndt
