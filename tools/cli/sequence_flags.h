#pragma once

// mlndt_sequence's flags of SequenceOptions' own fields (table_flags.h, made
// from SequenceOwnOptionsTable): --step. --init stays the tool's flag: its
// text (zero | gt_fraction:c | constant_velocity | poses:FILE) is an
// InitSpec, which no table type holds. Linking this file gives a tool these
// flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& SequenceFlags();

}  // namespace tools
}  // namespace mlndt
