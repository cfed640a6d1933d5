#include "tools/common/tool_main.h"

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <filesystem>
#include <iostream>

namespace mlndt {
namespace tools {

bool StartTool(const char* usage,
               bool reject_arguments,
               int* argc,
               char*** argv) {
  gflags::SetUsageMessage(usage);
  gflags::ParseCommandLineFlags(argc, argv, true);
  google::InitGoogleLogging((*argv)[0]);
  FLAGS_logtostderr = true;
  if (reject_arguments && *argc > 1) {
    std::cerr << std::filesystem::path((*argv)[0]).filename().string()
              << ": unexpected argument '" << (*argv)[1]
              << "' (flags are --name=value)\n";
    return false;
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
