#pragma once

// The files a tool reads, so that no output overwrites one of them
// (`mlndt_align R.pcd I.pcd --output_json=R.pcd` is refused before any work
// instead of turning R.pcd into JSON). CheckOutputFile and PrepareOutputDir
// (output_files.h) ask CheckNotAnInput for every output.

#include <string>
#include <vector>

namespace mlndt {
namespace tools {

// The command-line arguments left after the flags (StartTool records them).
void SetToolArguments(const std::vector<std::string>& arguments);

// False, with *error naming --`flag`=`path` and the input, when `path`
// exists and is one of the tool's inputs, compared by device and inode (a
// hard link, a symbolic link or "./x" is caught too). Inputs: the
// recorded arguments, and every part of every string flag other than
// outputs (output*, out, gnuplot) that names a file: the value, its
// comma-separated parts and what follows a "kind:" prefix (--init=poses:F).
// A flag naming a folder makes its point-cloud files (by extension) inputs.
bool CheckNotAnInput(const std::string& flag,
                     const std::string& path,
                     std::string* error);

// False, with *error naming --`flag`=`dir` and the input, when the folder
// `dir` exists and is one the run reads (an argument or a string flag as
// above naming the same folder, by device and inode): a later run would
// read the outputs as inputs (a trajectory_kitti.txt in the scan folder).
bool CheckNotAnInputFolder(const std::string& flag,
                           const std::string& dir,
                           std::string* error);

}  // namespace tools
}  // namespace mlndt
