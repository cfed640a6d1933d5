#pragma once

// Scan time stamps from a text file: one number of seconds per line (KITTI
// odometry's times.txt, the shared data sets' times.txt), blank lines and
// '#' comments skipped. The stamps must be finite and strictly increasing,
// so they can time-stamp a TUM trajectory (trajectory.h).

#include <string>
#include <vector>

namespace mlndt {

// False with *error "<path>: line <n>: <problem>".
bool ReadScanTimes(const std::string& path,
                   std::vector<double>* stamps_s,
                   std::string* error);

}  // namespace mlndt
