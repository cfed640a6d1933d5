#pragma once

// The description (mlndt/common/option_table.h) of the adaptive start
// layer's options (adaptive_start_layer.h): name, unit, range and help of
// each field, from which mlndt_sequence's --adaptive_* flags, their checks
// and the option reference are made.

#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& AdaptiveStartLayerOptionsTable();

}  // namespace mlndt
