#pragma once

// Plotting through the gnuplot program: the tools write whitespace-separated
// data files and a .gp script, then run `gnuplot script.gp`. Nothing links
// against gnuplot; when it is missing the tools say so and skip (or stop).

#include <cstdio>
#include <cstdlib>
#include <string>

#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace tools {

// Single-quotes `text` for /bin/sh.
inline std::string ShellQuote(const std::string& text) {
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

// Quotes `text` as a gnuplot string literal (single quotes, '' for ').
inline std::string GnuplotQuote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    out += c;
    if (c == '\'') out += '\'';
  }
  return out + "'";
}

// True when `gnuplot --version` runs (the program `gnuplot` is a path or a
// name looked up on PATH).
inline bool GnuplotAvailable(const std::string& gnuplot) {
  const std::string command =
      ShellQuote(gnuplot) + " --version >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

// The first lines of every script: a PNG terminal (pngcairo when this
// gnuplot has it, else libgd's png) of the given size in pixels.
inline std::string GnuplotPngHeader(int width, int height) {
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

// Writes `script` to `script_path` and runs gnuplot on it; its stderr goes
// to script_path + ".log". False with *error naming the log on failure.
inline bool RunGnuplot(const std::string& gnuplot,
                       const std::string& script_path,
                       const std::string& script,
                       std::string* error) {
  if (!WriteFileAtomically(script_path, script, error)) return false;
  const std::string log_path = script_path + ".log";
  const std::string command = ShellQuote(gnuplot) + " " +
                              ShellQuote(script_path) + " >" +
                              ShellQuote(log_path) + " 2>&1";
  if (std::system(command.c_str()) != 0) {
    *error = "gnuplot failed on " + script_path + " (see " + log_path + ")";
    return false;
  }
  std::remove(log_path.c_str());
  return true;
}

}  // namespace tools
}  // namespace mlndt
