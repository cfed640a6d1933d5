#pragma once

// Output files of the tools: checked before the run (so that a long
// computation does not end in "cannot write"); they are then written with
// WriteFileAtomically (mlndt/common/atomic_file.h) from text built in
// memory.

#include <string>
#include <vector>

namespace mlndt {
namespace tools {

// Refuses a `dir` that is an input folder of the run (CheckNotAnInputFolder,
// input_files.h), creates the folder `dir` of the flag --`flag` (with its
// parents), then checks that each of `files` (names inside it) can be written
// there (CheckWritableFilePath) and that a file can really be created in it (a
// probe file, removed again), and that none of them is an input of the
// run (CheckNotAnInput). False with *error naming the flag.
bool PrepareOutputDir(const std::string& flag,
                      const std::string& dir,
                      const std::vector<std::string>& files,
                      std::string* error);

// For an output file flag --`flag`=`path` (empty: not given, true): its
// folder exists and `path` can be replaced (CheckWritableFilePath), and it
// is not an input of the run (CheckNotAnInput). False with *error naming
// the flag.
bool CheckOutputFile(const std::string& flag,
                     const std::string& path,
                     std::string* error);

// The folder of --<flag>=`path` exists; else *error "--<flag>=<path>:
// folder <folder> does not exist".
bool CheckOutputFolderExists(const std::string& flag,
                             const std::string& path,
                             std::string* error);

}  // namespace tools
}  // namespace mlndt
