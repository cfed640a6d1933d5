#include "tools/cli/odometry_flags.h"

#include "mlndt/odometry/odometry_option_tables.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kOdometryFlags(
    OdometryOwnOptionsTable(), "mlndt_odometry", {}, {}, &IsSharedFlag);

}  // namespace

const TableFlags& OdometryFlags() { return kOdometryFlags; }

}  // namespace tools
}  // namespace mlndt
