#include "mlndt/common/result_table.h"
#include "mlndt/registration/quality_check.h"

namespace mlndt {

const ResultTable& ConstraintAnalysisTable() {
  using C = ConstraintAnalysis;
  static const ResultTable table =
      ResultTableBuilder<C>("ConstraintAnalysis")
          .Number("constraint_ratio",
                  &C::constraint_ratio,
                  "",
                  "lambda_min / lambda_max of the planar cells' information: "
                  "1 when every direction is constrained alike, 0 for a "
                  "direction with none.")
          .Number("localizability",
                  &C::localizability,
                  "",
                  "The smallest share of the inliers on planar cells whose "
                  "normal constrains a direction of the pose (dimensionless; "
                  "0 along a free direction).")
          .Vector("least_localizable_direction",
                  &C::least_localizable_direction,
                  "",
                  "That direction (unit, scaled as degenerate_directions).")
          .Integer("unlocalizable_directions",
                   &C::unlocalizable_directions,
                   "",
                   "How many of degenerate_directions are below "
                   "min_localizability.")
          .Rows("degenerate_directions",
                &C::degenerate_directions,
                "",
                "(k, 6) unit directions of the pose vector (rotation scaled "
                "by the points' RMS range) whose information is below "
                "min_constraint_ratio times the largest.")
          .Number("flatness",
                  &C::flatness,
                  "",
                  "The largest share of inliers kept when the pose moves one "
                  "cell edge along a weak direction; near 1 along a free "
                  "direction, 0 when nothing was probed.")
          .Number("probe_evidence",
                  &C::probe_evidence,
                  "",
                  "Along the flattest direction: the inliers lost net of "
                  "those gained over the square root of all that changed (a "
                  "z-score; near 0 when free).")
          .Vector("flattest_direction",
                  &C::flattest_direction,
                  "",
                  "The flattest probed direction (unit, scaled as "
                  "degenerate_directions); zero when nothing was probed.")
          .Integer("flat_directions",
                   &C::flat_directions,
                   "",
                   "How many of degenerate_directions the probe found flat.")
          .Matrix("weakest_translations",
                  &C::weakest_translations,
                  "",
                  "3x3: the translations the planar cells constrain least "
                  "with the rotation held, weakest first (columns; zero when "
                  "no cell matched).")
          .Build();
  return table;
}

}  // namespace mlndt
