#pragma once

// mlndt_eval's list flags: the file list of --estimate and the KITTI
// segment lengths of --segments_lengths_m (its flag is made from the table,
// trajectory_evaluation_flags.h; this checks it further).

#include <string>
#include <vector>

namespace mlndt {
namespace tools {

// "a.txt,b.tum" into file names; false with *error naming
// --estimate=`text` on an empty name.
bool SplitEstimateList(const std::string& text,
                       std::vector<std::string>* files,
                       std::string* error);

// "100,200,..." into lengths [m]; false with *error naming
// `flag`=`text` ("--segments_lengths_m=...") when one is not > 0 or is
// given twice.
bool ParseSegmentLengths(const std::string& flag,
                         const std::string& text,
                         std::vector<double>* lengths,
                         std::string* error);

}  // namespace tools
}  // namespace mlndt
