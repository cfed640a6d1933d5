#include "tools/cli/suite_plan_flags.h"

#include "lab/eval/suite_plan_option_table.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kSuitePlanFlags(SuitePlanOptionsTable(),
                                 "mlndt_suite",
                                 {},
                                 {{"perturb_translation_m", "perturb"},
                                  {"perturb_rotation_deg", "perturb"}},
                                 &IsSharedFlag);

}  // namespace

const TableFlags& SuitePlanFlags() { return kSuitePlanFlags; }

}  // namespace tools
}  // namespace mlndt
