#pragma once

// An output folder a reader can tell a finished run by (issue 41 item 12):
// the run removes the previous summary.json before it writes anything
// (StartOutputSet), writes every other file, and writes summary.json last
// (FinishOutputSet), naming each file it wrote with its size in bytes
// ("output_files"). A folder without summary.json holds an unfinished run;
// a file whose size is not the one named was written by another run.

#include <string>
#include <vector>

#include "tools/cli/json_output.h"

namespace mlndt {
namespace tools {

// Removes `dir`/summary.json (a symbolic link there is removed, not
// followed). False with *error when it exists and cannot be removed.
bool StartOutputSet(const std::string& dir, std::string* error);

// Writes `summary` with "output_files": [{"name", "bytes"}] of each of
// `files` (names in `dir`) as `dir`/summary.json, atomically. False with
// *error when a file is missing or summary.json cannot be written.
bool FinishOutputSet(const std::string& dir,
                     const std::vector<std::string>& files,
                     Json summary,
                     std::string* error);

}  // namespace tools
}  // namespace mlndt
