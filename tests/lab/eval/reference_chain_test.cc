#include "lab/eval/reference_chain.h"

#include <gtest/gtest.h>

#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// The bundled KITTI pairs 0_1 .. 6_7 chain into 8 poses: pose 1 is the
// pair 0_1 itself, and the chained poses agree with the pairs registered
// directly over longer gaps (0_2, 0_3, 0_5) to a few centimetres.
TEST(ChainReferencePairs, AgreesWithTheDirectPairs) {
  std::map<std::string, ReferencePair> pairs;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(
      testing::BundledDataPath("kitti/reference_pairs.json"), &pairs, &error))
      << error;
  const ReferenceChain chain = ChainReferencePairs(pairs);
  ASSERT_EQ(chain.scans.size(), 8u);
  EXPECT_EQ(chain.scans.front(), 0);
  EXPECT_EQ(chain.scans.back(), 7);
  EXPECT_TRUE(chain.consecutive());
  ASSERT_EQ(chain.poses.size(), 8u);
  EXPECT_TRUE(chain.poses[0].isApprox(Isometry3d::Identity()));
  EXPECT_TRUE(chain.poses[1].isApprox(pairs.at("0_1").reference_from_input));
  for (const char* key : {"0_2", "0_3", "0_5"}) {
    const ReferencePair& direct = pairs.at(key);
    const Isometry3d& chained = chain.poses[direct.input_index];
    EXPECT_LT(
        (chained.translation() - direct.reference_from_input.translation())
            .norm(),
        0.05)
        << key;
  }
  // Several metres driven: the chain is not the identity.
  EXPECT_GT(chain.poses.back().translation().norm(), 5.0);
}

// Only the even scans: the chain steps over the gaps ("0_2", "2_4", ...).
TEST(ChainReferencePairs, StepsOverGapsInTheNumbering) {
  std::map<std::string, ReferencePair> all, even;
  std::string error;
  ASSERT_TRUE(ReadReferencePairs(
      testing::BundledDataPath("kitti/reference_pairs.json"), &all, &error))
      << error;
  for (const auto& [key, pair] : all) {
    if (pair.reference_index % 2 == 0 && pair.input_index % 2 == 0) {
      even.emplace(key, pair);
    }
  }
  const ReferenceChain chain = ChainReferencePairs(even);
  EXPECT_EQ(chain.scans, (std::vector<int64_t>{0, 2, 4, 6}));
  EXPECT_FALSE(chain.consecutive());
  const ReferenceChain full = ChainReferencePairs(all);
  ASSERT_EQ(chain.poses.size(), 4u);
  EXPECT_LT((chain.poses[3].translation() - full.poses[6].translation()).norm(),
            0.1);
}

TEST(ChainReferencePairs, NothingToChainWithoutForwardPairs) {
  ReferencePair backwards;
  backwards.reference_index = 3;
  backwards.input_index = 1;
  const ReferenceChain chain = ChainReferencePairs({{"3_1", backwards}});
  EXPECT_LT(chain.scans.size(), 2u);
  EXPECT_TRUE(chain.poses.empty());
}

}  // namespace
}  // namespace mlndt
