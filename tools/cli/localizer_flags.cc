#include "tools/cli/localizer_flags.h"

#include "mlndt/pipeline/pipeline_option_tables.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kLocalizerFlags(
    LocalizerOwnOptionsTable(), "mlndt_localize", {}, {}, &IsSharedFlag);

}  // namespace

const TableFlags& LocalizerFlags() { return kLocalizerFlags; }

}  // namespace tools
}  // namespace mlndt
