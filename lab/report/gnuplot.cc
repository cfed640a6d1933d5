#include "lab/report/gnuplot.h"

#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;

// The gnuplot variable that names the private render folder.
constexpr char kRenderDirVariable[] = "mlndt_render_dir";

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// A PNG as written to its end: the signature, and the IEND chunk last.
bool IsCompletePng(const std::string& bytes) {
  static const std::string kSignature("\x89PNG\r\n\x1a\n", 8);
  static const std::string kEnd("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return bytes.size() >= kSignature.size() + kEnd.size() &&
         bytes.compare(0, kSignature.size(), kSignature) == 0 &&
         bytes.compare(bytes.size() - kEnd.size(), kEnd.size(), kEnd) == 0;
}

std::string InFolder(const std::string& working_dir, const std::string& path) {
  if (working_dir.empty() || fs::path(path).is_absolute()) return path;
  return working_dir + "/" + path;
}

// Whether the render folder `name` (".mlndt_plot.<pid>.XXXXXX") was left by
// a process that no longer runs; one of an older version
// (".mlndt_plot.XXXXXX", no pid) when it is over an hour old.
bool IsStaleRenderDir(const fs::path& path) {
  const std::string name = path.filename().string();
  const std::string prefix = ".mlndt_plot.";
  if (name.rfind(prefix, 0) != 0) return false;
  const std::string rest = name.substr(prefix.size());
  const size_t dot = rest.find('.');
  if (dot != std::string::npos && dot > 0 &&
      rest.find_first_not_of("0123456789") == dot) {
    const long pid = std::strtol(rest.substr(0, dot).c_str(), nullptr, 10);
    return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
  }
  std::error_code ec;
  const auto written = fs::last_write_time(path, ec);
  return !ec &&
         fs::file_time_type::clock::now() - written > std::chrono::hours(1);
}

// Removes the render folders in `folder` that a killed run left behind.
void RemoveStaleRenderDirs(const fs::path& folder) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    std::error_code dir_ec;
    if (entry.is_directory(dir_ec) && !entry.is_symlink(dir_ec) &&
        IsStaleRenderDir(entry.path())) {
      fs::remove_all(entry.path(), dir_ec);
    }
  }
}

// A new folder ".mlndt_plot.<pid>.XXXXXX" (mode 0700) next to `near`,
// absolute, after removing the stale ones there (IsStaleRenderDir).
bool MakeRenderDir(const std::string& near,
                   std::string* render_dir,
                   std::string* error) {
  fs::path folder = fs::path(near).parent_path();
  if (folder.empty()) folder = ".";
  RemoveStaleRenderDirs(folder);
  std::string pattern =
      (folder / (".mlndt_plot." + std::to_string(::getpid()) + ".XXXXXX"))
          .string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    *error = "cannot create a folder to draw the figures in " +
             folder.string() + ": " + std::strerror(errno);
    return false;
  }
  std::error_code ec;
  *render_dir = fs::absolute(pattern, ec).string();
  return true;
}

// gnuplot failed: its log goes to `log_path` unless something other than
// a regular file is there; *error says where to read it (or quotes it).
void ReportFailure(const std::string& script_path,
                   const std::string& log_path,
                   const std::string& log,
                   std::string* error) {
  std::string why;
  if (WriteFileAtomically(log_path, log, &why)) {
    *error = "gnuplot failed on " + script_path + " (see " + log_path + ")";
    return;
  }
  const size_t keep = 600;
  *error = "gnuplot failed on " + script_path + "; its log (" + why + "): " +
           (log.size() > keep ? "..." + log.substr(log.size() - keep) : log);
}

// Moves each rendered figure onto its target (WriteFileAtomically).
bool ReplaceFigures(const GnuplotRun& run,
                    const std::string& render_dir,
                    std::string* error) {
  for (const std::string& png : run.pngs) {
    const std::string target = InFolder(run.working_dir, png);
    const std::string bytes =
        ReadFile(render_dir + "/" + fs::path(png).filename().string());
    if (!IsCompletePng(bytes)) {
      *error = target +
               ": gnuplot did not finish the figure (disk full?); the "
               "previous file, if any, is unchanged";
      return false;
    }
    if (!WriteFileAtomically(target, bytes, error)) return false;
  }
  return true;
}

}  // namespace

std::string ShellQuote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

std::string GnuplotQuote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    out += c;
    if (c == '\'') out += '\'';
  }
  return out + "'";
}

bool GnuplotReadyForPlots(const std::string& tool,
                          bool plots,
                          const std::string& gnuplot,
                          const std::string& consequence) {
  if (!plots || GnuplotAvailable(gnuplot)) return true;
  std::cerr << tool << ": gnuplot ('" << gnuplot
            << "') not found: " << consequence << "\n";
  return false;
}

bool MakePlotDataDir(const std::string& dir,
                     std::string* data_dir,
                     std::string* error) {
  *data_dir = dir + "/plot_data";
  std::error_code ec;
  std::filesystem::create_directories(*data_dir, ec);
  if (ec) {
    *error = *data_dir + ": " + ec.message();
    return false;
  }
  return true;
}

std::string PlotSkippedMessage(const std::string& gnuplot,
                               const std::string& what) {
  return what + " skipped: gnuplot ('" + gnuplot +
         "') not found; the other outputs are written. Install "
         "gnuplot-nox or pass --plots=false";
}

bool GnuplotAvailable(const std::string& gnuplot) {
  const std::string command =
      ShellQuote(gnuplot) + " --version >/dev/null 2>&1 </dev/null";
  return std::system(command.c_str()) == 0;
}

std::string GnuplotPngHeader(int width, int height) {
  const std::string size = std::to_string(width) + "," + std::to_string(height);
  return "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
         "  set terminal pngcairo size " +
         size +
         " font 'Sans,10'\n"
         "} else {\n"
         "  set terminal png size " +
         size +
         "\n"
         "}\n"
         "set grid\nset key outside right top\n";
}

std::string GnuplotSetOutput(const std::string& png_path) {
  const std::string variable = kRenderDirVariable;
  return "set output (exists('" + variable + "') ? " + variable + "." +
         GnuplotQuote("/" + fs::path(png_path).filename().string()) + " : " +
         GnuplotQuote(png_path) + ")\n";
}

bool RenderGnuplot(const GnuplotRun& run, std::string* error) {
  std::set<std::string> names;
  for (const std::string& png : run.pngs) {
    if (!names.insert(fs::path(png).filename().string()).second) {
      *error = "two figures named " + png + " in one gnuplot script";
      return false;
    }
  }
  const std::string script = InFolder(run.working_dir, run.script_path);
  std::string render_dir;
  if (!MakeRenderDir(run.pngs.empty()
                         ? script
                         : InFolder(run.working_dir, run.pngs.front()),
                     &render_dir,
                     error)) {
    return false;
  }
  const std::string log = render_dir + "/gnuplot.log";
  const std::string command =
      (run.working_dir.empty() ? ""
                               : "cd " + ShellQuote(run.working_dir) + " && ") +
      ShellQuote(run.gnuplot) + " -e " +
      ShellQuote(std::string(kRenderDirVariable) + "=" +
                 GnuplotQuote(render_dir)) +
      " " + ShellQuote(run.script_path) + " </dev/null >" + ShellQuote(log) +
      " 2>&1";
  const bool ran = std::system(command.c_str()) == 0;
  const std::string log_path = script + ".log";
  bool ok = ran;
  if (!ran) {
    ReportFailure(script, log_path, ReadFile(log), error);
  } else {
    ok = ReplaceFigures(run, render_dir, error);
    // A log of an earlier failure is stale now (only a regular file).
    struct stat status;
    if (ok && ::lstat(log_path.c_str(), &status) == 0 &&
        S_ISREG(status.st_mode)) {
      std::remove(log_path.c_str());
    }
  }
  std::error_code ec;
  fs::remove_all(render_dir, ec);
  return ok;
}

bool RunGnuplot(const std::string& gnuplot,
                const std::string& script_path,
                const std::string& script,
                const std::vector<std::string>& pngs,
                std::string* error) {
  if (!WriteFileAtomically(script_path, script, error)) return false;
  return RenderGnuplot({gnuplot, "", script_path, pngs}, error);
}

}  // namespace mlndt
