#pragma once

// The description (mlndt/common/option_table.h) of SequenceOptions' own
// single-value fields (sequence_registration.h): step. Not in it: the
// registration (the shared registration flags), init (InitSpec, parsed from
// mlndt_sequence's --init text), adaptive (AdaptiveStartLayerOptionsTable,
// its own flags) and release_used_scans (set by the tool). From it come
// mlndt_sequence's --step, its check and the option reference.

#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& SequenceOwnOptionsTable();

}  // namespace mlndt
