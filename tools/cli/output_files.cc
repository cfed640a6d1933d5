#include "tools/cli/output_files.h"

#include <unistd.h>

#include <filesystem>

#include "mlndt/common/atomic_file.h"
#include "tools/cli/input_files.h"

namespace mlndt {
namespace tools {

bool PrepareOutputDir(const std::string& flag,
                      const std::string& dir,
                      const std::vector<std::string>& files,
                      std::string* error) {
  const std::string name = "--" + flag + "=" + dir;
  if (dir.empty()) {
    *error = "--" + flag + " is empty";
    return false;
  }
  if (!CheckNotAnInputFolder(flag, dir, error)) return false;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir, ec)) {
    *error = name + ": cannot create the folder" +
             (ec ? ": " + ec.message() : std::string(": not a directory"));
    return false;
  }
  std::string why;
  for (const std::string& file : files) {
    if (!CheckWritableFilePath(dir + "/" + file, &why)) {
      *error = name + ": " + why;
      return false;
    }
    if (!CheckNotAnInput(flag, dir + "/" + file, error)) return false;
  }
  // access() says yes to root on a read-only file system; writing tells.
  const std::string probe =
      dir + "/.mlndt_write_probe." + std::to_string(::getpid());
  if (!WriteFileAtomically(probe, "", &why)) {
    *error = name + ": the folder cannot be written: " + why;
    return false;
  }
  std::filesystem::remove(probe, ec);
  return true;
}

bool CheckOutputFile(const std::string& flag,
                     const std::string& path,
                     std::string* error) {
  if (path.empty()) return true;
  std::string why;
  if (!CheckWritableFilePath(path, &why)) {
    *error = "--" + flag + "=" + path + ": " + why;
    return false;
  }
  return CheckNotAnInput(flag, path, error);
}

bool CheckOutputFolderExists(const std::string& flag,
                             const std::string& path,
                             std::string* error) {
  const std::filesystem::path folder =
      std::filesystem::absolute(path).parent_path();
  std::error_code ec;
  if (std::filesystem::is_directory(folder, ec)) return true;
  *error = "--" + flag + "=" + path + ": folder " + folder.string() +
           " does not exist";
  return false;
}

}  // namespace tools
}  // namespace mlndt
