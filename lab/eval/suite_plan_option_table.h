#pragma once

// The description (mlndt/common/option_table.h) of SuitePlanOptions'
// single-value fields (suite_plan.h): the perturbed starts' bound, count and
// seed, and the pairs kept per data set. Not in it (lists and compound
// values no table type holds, parsed from mlndt_suite's text flags): starts
// (--starts), offsets (--offsets), prior_uncertainty (--prior_uncertainty),
// steps (--steps). From it come SuitePlanOptions::IsValid's ranges,
// mlndt_suite's --perturb_count, --perturb_seed, --max_pairs_per_set (the
// bound by --perturb=translation_m,rotation_deg) and the option reference.

#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& SuitePlanOptionsTable();

}  // namespace mlndt
