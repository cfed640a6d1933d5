#include "tools/cli/tool_main.h"

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "tools/cli/data_argument.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/input_files.h"

// gflags' own help flags (gflags_reporting.cc).
DECLARE_bool(help);
DECLARE_bool(version);

namespace mlndt {
namespace tools {

const char kExitCodesHelp[] =
    "Exit codes: 0 success; 1 the run failed (a registration FAILED or its "
    "result is not to be used, or an output could not be written); 2 usage "
    "or misconfiguration (a flag, argument or input refused before any work, "
    "the message names it).";

ToolArguments ParseSubcommand(const std::string& tool,
                              int argc,
                              char** argv,
                              const std::string& name,
                              int num_args,
                              const std::string& usage,
                              const std::string& synopsis) {
  if (argc <= 1) return ToolArguments::NONE;
  if (argv[1] == name) {
    if (argc == num_args + 2) return ToolArguments::SUBCOMMAND;
    std::cerr << tool << ": usage: " << usage << "\n";
    return ToolArguments::MISUSE;
  }
  std::cerr << tool << ": unexpected argument '" << argv[1]
            << "' (flags are --name=value; the one subcommand is '" << synopsis
            << "')\n";
  return ToolArguments::MISUSE;
}

int Fail(const std::string& tool, const std::string& message) {
  std::cerr << tool << ": " << message << std::endl;
  return kExitFailed;
}

int Refuse(const std::string& tool, const std::string& message) {
  std::cerr << tool << ": " << message << std::endl;
  return kExitUsage;
}

namespace {

OptionPathOfFlag& OptionPathLookup() {
  static OptionPathOfFlag lookup = nullptr;
  return lookup;
}

std::set<std::string>& HiddenFlags() {
  static std::set<std::string> hidden;
  return hidden;
}

// RefuseUnreadFlags: the flags and the reason given for them.
std::vector<std::string>& UnreadFlags() {
  static std::vector<std::string> flags;
  return flags;
}
std::string& UnreadFlagsReason() {
  static std::string reason;
  return reason;
}

std::string FileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

// "tools/cli/registration_flags.cc" (or "lab/programs/mlndt_suite.cc")
// for a flag's full source path.
std::string ShortPath(const std::string& path) {
  size_t at = path.rfind("lab/programs/");
  if (at == std::string::npos) at = path.rfind("tools/");
  return at == std::string::npos ? FileName(path) : path.substr(at);
}

// The shortest text that reads back as the same double: "0.95", not
// gflags' "0.94999999999999996".
std::string ShortestDouble(const std::string& text) {
  const double value = std::strtod(text.c_str(), nullptr);
  char buffer[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

void AppendFlag(const gflags::CommandLineFlagInfo& flag, std::ostream* out) {
  *out << "  --" << flag.name;
  if (flag.type == "string") {
    *out << "=\"" << flag.default_value << "\"";
  } else if (flag.type == "double") {
    *out << "=" << ShortestDouble(flag.default_value);
  } else {
    *out << "=" << flag.default_value;
  }
  *out << "  (" << flag.type << ")\n      " << flag.description << "\n";
}

// gflags exits with 1 on an unknown flag or a value it cannot parse; a
// usage error is kExitUsage in every tool, so the flags are checked first.
void ExitOnBadFlags(const std::string& tool, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (arg.size() < 2 || arg[0] != '-') continue;
    const std::string body = arg.substr(arg[1] == '-' ? 2 : 1);
    const size_t eq = body.find('=');
    const std::string name = body.substr(0, eq);
    gflags::CommandLineFlagInfo info;
    if (gflags::GetCommandLineFlagInfo(name.c_str(), &info)) {
      // "--name value": the next argument is the value, not a flag.
      if (eq == std::string::npos) {
        if (info.type != "bool") ++i;
        continue;
      }
      // Setting it now is harmless: the parse sets it again.
      const std::string value = body.substr(eq + 1);
      if (gflags::SetCommandLineOption(name.c_str(), value.c_str()).empty()) {
        std::cerr << tool << ": --" << name << "=" << value << ": not a valid "
                  << info.type << " (see --help)\n";
        std::exit(kExitUsage);
      }
      continue;
    }
    if (name.rfind("no", 0) == 0 && eq == std::string::npos &&
        gflags::GetCommandLineFlagInfo(name.substr(2).c_str(), &info) &&
        info.type == "bool") {
      continue;
    }
    std::cerr << tool << ": unknown flag --" << name << " (see --help)\n";
    std::exit(kExitUsage);
  }
}

// Whose program `tool` is: true for the lab's programs (lab/programs/,
// built but not installed), false for the product's tools (tools/,
// installed). MLNDT_LAB_DRIVERS: their names, separated by spaces
// (lab/programs/CMakeLists.txt's list, the only one).
bool IsLabProgram(const std::string& tool) {
  const std::string names = std::string(" ") + MLNDT_LAB_DRIVERS + " ";
  return names.find(" " + tool + " ") != std::string::npos;
}

// "mlndt <PROJECT_VERSION>".
std::string VersionLine() { return std::string("mlndt ") + MLNDT_VERSION; }

// What a shared flag is for, the heading --help lists it under: the
// options it sets (the first part of its option path, option_flags.h) or
// the file that defines it.
std::string Purpose(const gflags::CommandLineFlagInfo& flag,
                    const std::string& path) {
  static const std::map<std::string, std::string> kHeadings = {
      {"range_filter", "2 Range filter"},
      {"grid", "3 Map"},
      {"sampling", "4 Sampling of the input"},
      {"schedule", "5 Layer schedule"},
      {"objective", "6 Objective"},
      {"backend", "7 Solver backend"},
      {"retry", "8 Retries"},
      {"quality_check", "9 Verdict"},
      {"tools/cli/scan_input.cc", "0 Scans"},
      {"tools/cli/pose_flags.cc", "1 Poses"},
      {"tools/cli/verdict_flags.cc", "9 Verdict"},
  };
  std::string key = path;
  const std::string option_path =
      OptionPathLookup() != nullptr ? OptionPathLookup()(flag.name) : "";
  if (option_path.rfind("ndt:", 0) == 0) {
    return "7 Conventional NDT (--method=ndt)";
  }
  if (!option_path.empty()) key = option_path.substr(0, option_path.find('.'));
  const auto found = kHeadings.find(key);
  return found != kHeadings.end() ? found->second : "7 Registration";
}

// The --help text of the tool `tool` (its file is MainFile(tool)): its own
// flags, then the shared ones by purpose.
std::string ToolHelp(const std::string& tool) {
  std::vector<gflags::CommandLineFlagInfo> flags;
  gflags::GetAllFlags(&flags);
  std::vector<gflags::CommandLineFlagInfo> own;
  std::map<std::string, std::vector<gflags::CommandLineFlagInfo>> shared;
  for (const gflags::CommandLineFlagInfo& flag : flags) {
    const std::string path = ShortPath(flag.filename);
    if (path == MainFile(tool)) {
      own.push_back(flag);
    } else if (path.rfind("tools/cli/", 0) == 0 &&
               HiddenFlags().count(flag.name) == 0) {
      shared[Purpose(flag, path)].push_back(flag);
    }
  }
  std::ostringstream out;
  const std::string usage = gflags::ProgramUsage();
  out << tool << ": " << usage << "\n";
  if (usage.find("Exit codes") == std::string::npos) {
    out << "\n" << kExitCodesHelp << "\n";
  }
  if (!own.empty()) {
    out << "\nFlags of " << tool << ":\n";
    for (const auto& flag : own) AppendFlag(flag, &out);
  }
  for (const auto& [purpose, group] : shared) {
    out << "\n" << purpose.substr(2) << ":\n";
    for (const auto& flag : group) AppendFlag(flag, &out);
  }
  out << "\n  --help, -h  this text;  --version  print \"" << VersionLine()
      << "\";  --helpfull  every flag, glog's and gflags' included\n";
  return out.str();
}

}  // namespace

std::string MainFile(const std::string& tool) {
  return (IsLabProgram(tool) ? "lab/programs/" : "tools/") + tool + ".cc";
}

void SetOptionPathOfFlag(OptionPathOfFlag lookup) {
  OptionPathLookup() = lookup;
}

void HideFlagsFromHelp(const std::vector<std::string>& flags) {
  HiddenFlags().insert(flags.begin(), flags.end());
}

void RefuseUnreadFlags(const std::vector<std::string>& flags,
                       const std::string& reason) {
  HideFlagsFromHelp(flags);
  UnreadFlags().insert(UnreadFlags().end(), flags.begin(), flags.end());
  UnreadFlagsReason() = reason;
}

bool StartTool(const char* usage,
               bool reject_arguments,
               int* argc,
               char*** argv) {
  // -h is the ecosystem's --help; gflags does not know it.
  static char help_flag[] = "--help";
  for (int i = 1; i < *argc; ++i) {
    if (std::strcmp((*argv)[i], "-h") == 0) (*argv)[i] = help_flag;
    if (std::strcmp((*argv)[i], "--") == 0) break;
  }
  const std::string tool = FileName((*argv)[0]);
  gflags::SetUsageMessage(usage);
  gflags::SetVersionString(MLNDT_VERSION);
  ExitOnBadFlags(tool, *argc, *argv);
  gflags::ParseCommandLineNonHelpFlags(argc, argv, true);
  if (FLAGS_help) {
    std::cout << ToolHelp(tool);
    std::exit(0);
  }
  if (FLAGS_version) {
    std::cout << VersionLine() << "\n";
    std::exit(0);
  }
  gflags::HandleCommandLineHelpFlags();  // --helpfull, --helpmatch, ...
  SetToolArguments(std::vector<std::string>(*argv + 1, *argv + *argc));
  google::InitGoogleLogging((*argv)[0]);
  FLAGS_logtostderr = true;
  std::string error;
  if (!RefuseGivenFlags(UnreadFlags(), UnreadFlagsReason(), &error)) {
    std::cerr << tool << ": " << error << "\n";
    return false;
  }
  if (!ApplyDataArgument(tool, argc, *argv, &error)) {
    std::cerr << tool << ": " << error << "\n";
    return false;
  }
  if (reject_arguments && *argc > 1) {
    std::cerr << tool << ": unexpected argument '" << (*argv)[1]
              << "' (flags are --name=value)\n";
    return false;
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
