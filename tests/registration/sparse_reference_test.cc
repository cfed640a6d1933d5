// A sparse reference gets a finest cell it can fill (LayeredGridOptions::
// min_covered_fraction, mlndt/grid/cell_coverage.h): the bundled KITTI
// frames 0-7 thinned to every 40th point (~3100 points a scan, the density
// of a solid-state keyframe over a street). With the 1.2 m rule alone the
// finest cells are ~0.65 m and hold fewer than 5 points for most points:
// 6 of the 7 consecutive pairs from the identity were LOW_QUALITY (one 75
// cm off) and one CONVERGENCE 5.4 cm off. With the coverage rule the finest
// cell grows to ~1.3 m and all 7 converge within 4.2 cm and 0.09 degrees
// (docs/defaults.md, "Resolution from the data").

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/registration/registration.h"
#include "tests/testing/kitti_bundle.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

TEST(SparseReference, ThinnedKittiPairsConvergeRightWithCellsTheyFill) {
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(
      testing::BundledDataPath("kitti/reference_pairs.json"), &pairs, &error))
      << error;
  const RegistrationOptions options;
  ASSERT_GT(options.grid.min_covered_fraction, 0.0);
  for (int i = 0; i + 1 < 8; ++i) {
    SCOPED_TRACE("pair " + std::to_string(i) + "_" + std::to_string(i + 1));
    const PointCloud reference = testing::BundledKittiScan(i, 40);
    ASSERT_LT(reference.size(), 3200u);
    RegistrationSummary s;
    Register(options,
             reference,
             testing::BundledKittiScan(i + 1, 40),
             Isometry3d::Identity(),
             &s);
    const Isometry3d truth =
        pairs.at(ReferencePairKey(i, i + 1)).reference_from_input;
    EXPECT_EQ(s.termination_type, TerminationType::CONVERGENCE) << s.message;
    EXPECT_LT(TranslationErrorM(truth, s.reference_from_input), 0.1);
    EXPECT_LT(RotationErrorRad(truth, s.reference_from_input), 0.5 * kDegToRad);
    // Coarser than the 1.2 m rule's ~0.65 m cells over this street.
    EXPECT_GT(s.finest_cell_size_m, 1.2);
  }
}

}  // namespace
}  // namespace mlndt
