#include "tools/cli/output_set.h"

#include <filesystem>
#include <system_error>
#include <utility>

namespace mlndt {
namespace tools {

bool StartOutputSet(const std::string& dir, std::string* error) {
  const std::string path = dir + "/summary.json";
  std::error_code ec;
  std::filesystem::remove(path, ec);
  if (ec) {
    *error =
        path + ": cannot remove the previous run's summary: " + ec.message();
    return false;
  }
  return true;
}

bool FinishOutputSet(const std::string& dir,
                     const std::vector<std::string>& files,
                     Json summary,
                     std::string* error) {
  Json listed = Json::array();
  for (const std::string& name : files) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(dir + "/" + name, ec);
    if (ec) {
      *error = dir + "/" + name + ": " + ec.message() +
               " (written by this run, gone before summary.json)";
      return false;
    }
    listed.push_back({{"name", name}, {"bytes", bytes}});
  }
  summary["output_files"] = std::move(listed);
  return WriteJsonFile(dir + "/summary.json", summary, error);
}

}  // namespace tools
}  // namespace mlndt
