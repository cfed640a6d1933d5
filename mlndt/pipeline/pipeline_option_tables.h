#pragma once

// The descriptions (common/option_table.h) of the map builder's and the
// localiser's own options: name, unit, range and help of each field, from
// which their IsValid range checks, the flags of mlndt_map and
// mlndt_localize, the Python keyword of Localizer and docs/options.md are
// made. The structs they hold are described by their own tables and given
// apart: MapBuildOptions::grid (LayeredGridOptionsTable) and range_filter
// (RangeFilterOptionsTable), LocalizerOptions::registration
// (RegistrationOptionsTable).

#include "mlndt/common/option_table.h"

namespace mlndt {

// MapBuildOptions without grid and range_filter.
const OptionTable& MapBuildOwnOptionsTable();
// PriorCheckOptions (localization_prior.h).
const OptionTable& PriorCheckOptionsTable();
// LocalizerOptions without registration (prior_check nested).
const OptionTable& LocalizerOwnOptionsTable();

}  // namespace mlndt
