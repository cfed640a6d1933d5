#pragma once

// The description (common/option_table.h) of PairResidualOptions
// (add_pair_residuals.h): name, unit, range and help of each field, from
// which its IsValid range checks and docs/options.md are made. Its objective
// is ObjectiveOptionsTable's.

#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& PairResidualOptionsTable();

}  // namespace mlndt
