#include "tools/cli/sequence_flags.h"

#include "lab/runs/sequence_option_table.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kSequenceFlags(
    SequenceOwnOptionsTable(), "mlndt_sequence", {}, {}, &IsSharedFlag);

}  // namespace

const TableFlags& SequenceFlags() { return kSequenceFlags; }

}  // namespace tools
}  // namespace mlndt
