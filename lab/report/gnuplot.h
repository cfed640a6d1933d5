#pragma once

// Plotting through the gnuplot program: the tools write whitespace-separated
// data files and a .gp script, then run `gnuplot script.gp`. Nothing links
// against gnuplot; when it is missing the tools say so and skip (or stop).
//
// Figures are files like any other output (mlndt/common/atomic_file.h): the
// script draws into a private folder made for the run, each finished PNG is
// then checked (it ends with its IEND chunk) and moved onto its target with
// WriteFileAtomically. A full disk, a symbolic link or a FIFO at a target
// leaves that target as it was; the gnuplot log is kept the same way, only
// when gnuplot fails.

#include <string>
#include <vector>

namespace mlndt {

// Single-quotes `text` for /bin/sh.
std::string ShellQuote(const std::string& text);

// Quotes `text` as a gnuplot string literal (single quotes, '' for ').
std::string GnuplotQuote(const std::string& text);

// True when `gnuplot --version` runs (the program `gnuplot` is a path or a
// name looked up on PATH).
bool GnuplotAvailable(const std::string& gnuplot);

// With `plots`, true when gnuplot runs; else prints "<tool>: gnuplot
// ('<gnuplot>') not found: <consequence>" on stderr and returns false.
// Without `plots`, true.
bool GnuplotReadyForPlots(const std::string& tool,
                          bool plots,
                          const std::string& gnuplot,
                          const std::string& consequence);

// The message of a tool that asked for plots without gnuplot: "<what>
// skipped: gnuplot ('<gnuplot>') not found; the other outputs are written.
// Install gnuplot-nox or pass --plots=false".
std::string PlotSkippedMessage(const std::string& gnuplot,
                               const std::string& what = "plot");

// Creates `dir`/plot_data (the data and scripts of a tool's figures) and
// sets *data_dir to it; false with *error naming it when it cannot be made.
bool MakePlotDataDir(const std::string& dir,
                     std::string* data_dir,
                     std::string* error);

// The first lines of every script: a PNG terminal (pngcairo when this
// gnuplot has it, else libgd's png) of the given size in pixels.
std::string GnuplotPngHeader(int width, int height);

// The `set output` line of the figure `png_path` (as the script names it):
// into the private render folder when RunGnuplot runs the script, at
// `png_path` itself when someone runs the saved script by hand.
std::string GnuplotSetOutput(const std::string& png_path);

// One gnuplot run: the script (already written) and the figures it draws.
struct GnuplotRun {
  std::string gnuplot;      // Program: a path or a name on PATH.
  std::string working_dir;  // Folder to run in; "" = the current one.
  std::string script_path;  // Relative to working_dir when that is set.
  // Figures the script draws with GnuplotSetOutput, as it names them
  // (relative to working_dir when that is set). Their file names differ.
  std::vector<std::string> pngs;
};

// Runs the script, then replaces each figure of `run.pngs` with its new
// rendering. False with *error on a failing gnuplot (its log is written to
// script_path + ".log" when that can be done safely, else quoted), a
// missing or truncated figure, or a figure that cannot be replaced; the
// figures not yet replaced keep their previous contents.
bool RenderGnuplot(const GnuplotRun& run, std::string* error);

// Writes `script` to `script_path` (atomically), then RenderGnuplot.
bool RunGnuplot(const std::string& gnuplot,
                const std::string& script_path,
                const std::string& script,
                const std::vector<std::string>& pngs,
                std::string* error);

}  // namespace mlndt
