#pragma once

// The data of a tool that reads scans into an output folder (mlndt_odometry,
// mlndt_sequence, mlndt_localize: the tools with --scans, --bag and
// --output_dir) given as a user types it: `mlndt_odometry DIR_OR_BAG`.
//  - One argument left after the flags is the data: a folder is --scans, a
//    file --bag (its topic is the bag's one PointCloud2 topic unless
//    --topic names another).
//  - Without --output_dir, the outputs go to a new folder
//    ./<tool>_<UTC date>_<time> in the working folder, named on stderr, so
//    no earlier run is overwritten.

#include <string>

namespace mlndt {
namespace tools {

// Applies both rules for `tool` (argv[0]'s file name) to what is left in
// argv after the flags, removing the data argument. A tool without --scans,
// --bag and --output_dir is left alone. False with *error when the argument
// is neither a folder nor a file, or --scans or --bag is given as well.
bool ApplyDataArgument(const std::string& tool,
                       int* argc,
                       char** argv,
                       std::string* error);

}  // namespace tools
}  // namespace mlndt
