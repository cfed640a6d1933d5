// The enum tables (mlndt/common/enum_table.h) behind every XToString /
// StringToX pair: names round-trip in any case, aliases parse, values
// outside the table are UNKNOWN, and messages list the choices.

#include "mlndt/common/enum_table.h"

#include <gtest/gtest.h>

#include <cctype>

#include "mlndt/cloud/cloud_format.h"
#include "mlndt/common/types.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/ndt/gaussian_score.h"
#include "mlndt/pipeline/localizer.h"
#include "mlndt/sampling/point_sampler.h"
#include "mlndt/solvers/backend.h"
#include "mlndt/solvers/levenberg_marquardt_backend.h"

namespace mlndt {
namespace {

TEST(EnumTable, EveryLibraryEnumRoundTripsInAnyCase) {
  for (const EnumTable* table : {&BackendTypeTable(),
                                 &LossTypeTable(),
                                 &UnmatchedPolicyTable(),
                                 &SamplingMethodTable(),
                                 &CoarseWeightingTable(),
                                 &NdtNeighborsTable(),
                                 &LmResidualTable(),
                                 &TerminationTypeTable(),
                                 &CloudFormatTable(),
                                 &MotionModelTable()}) {
    ASSERT_GE(table->names().size(), 2u);
    for (const EnumTable::Name& name : table->names()) {
      int value = -1;
      std::string lower = name.name;
      for (char& c : lower) c = static_cast<char>(std::tolower(c));
      ASSERT_TRUE(table->FromString(lower, &value)) << lower;
      EXPECT_EQ(value, name.value);
      EXPECT_STREQ(table->ToString(value), name.name);
    }
    EXPECT_STREQ(table->ToString(1000), "UNKNOWN");
    int untouched = 7;
    EXPECT_FALSE(table->FromString("no_such_name", &untouched));
    EXPECT_EQ(untouched, 7);
  }
}

TEST(EnumTable, TypedFunctionsReadTheTable) {
  BackendType type = BackendType::CERES;
  EXPECT_TRUE(StringToBackendType("lm", &type));
  EXPECT_EQ(type, BackendType::LEVENBERG_MARQUARDT);
  EXPECT_STREQ(BackendTypeToString(type), "LEVENBERG_MARQUARDT");
  EXPECT_STREQ(BackendTypeToString(static_cast<BackendType>(42)), "UNKNOWN");
  LossType loss = LossType::NONE;
  EXPECT_TRUE(StringToLossType("Cauchy", &loss));
  EXPECT_EQ(loss, LossType::CAUCHY);
  EXPECT_FALSE(StringToLossType("tukey", &loss));
  EXPECT_EQ(loss, LossType::CAUCHY);
}

TEST(EnumTable, ChoicesListTheNamesWithAliases) {
  EXPECT_EQ(LossTypeTable().Choices(), "none, huber or cauchy");
  EXPECT_EQ(BackendTypeTable().Choices(),
            "ceres, newton or levenberg_marquardt (lm)");
  EXPECT_EQ(UnmatchedPolicyTable().ChoicesForHelp(),
            "zero_residual | nearest_cell");
}

}  // namespace
}  // namespace mlndt
