#pragma once

// mlndt_localize's outputs: trajectory_kitti.txt, trajectory_tum.txt,
// scans.csv and scans.json (LocalizationResultTable, result_csv.h and
// result_json.h), summary.json (docs/json_schema.md, "mlndt_localize"), the
// per-scan table on stdout and the top view trajectory_xy.png.

#include <string>
#include <vector>

#include "lab/eval/verdict_counts.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/pipeline/localizer.h"
#include "tools/cli/json_output.h"
#include "tools/cli/scan_input.h"

namespace mlndt {
namespace tools {

// summary.json; `map_path` as given, the times in seconds.
Json LocalizationSummaryJson(const LocalizerOptions& options,
                             const std::string& map_path,
                             const LayeredGrid& map,
                             const Isometry3d& first_guess,
                             const std::vector<LocalizationResult>& results,
                             double map_load_s,
                             double total_s);

// The trajectories (TUM stamps from `input`), scans.csv and scans.json into
// `dir`; the tool writes summary.json (LocalizationSummaryJson) last
// (output_set.h).
bool WriteLocalizationFiles(const std::string& dir,
                            const ScanInput& input,
                            const std::vector<LocalizationResult>& results,
                            std::string* error);

// "map: PATH, N layers, finest cell X m, SIZE".
void PrintMapLine(const std::string& map_path, const LayeredGrid& map);

// The failure message when some scans have no usable pose.
std::string UnusableScansMessage(const VerdictCounts& verdicts);

// One line a scan and the summary line on stdout; the scans by verdict.
VerdictCounts PrintLocalizationTable(
    const std::vector<std::string>& paths,
    const std::vector<LocalizationResult>& results);

// The files mlndt_localize writes besides the plot (PrepareOutputDir).
const std::vector<std::string>& LocalizationOutputFiles();
// summary.json last (FinishOutputSet, output_set.h), naming the files
// written: WriteLocalizationFiles' and, when `plotted`, trajectory_xy.png.
bool FinishLocalizationOutputs(const std::string& dir,
                               bool plotted,
                               Json summary,
                               std::string* error);
// The map at `path`, with a start layer within its layers (the library
// would clamp a start layer beyond them).
bool LoadLocalizationMap(const std::string& path,
                         const LocalizerOptions& options,
                         LayeredGrid* map,
                         std::string* error);
// WriteLocalizationPlot with "plot: trajectory_xy.png" on stdout; exit code
// 1 (printed as `tool`'s failure) when gnuplot is missing or fails, else 0.
int WriteLocalizationPlotOrFail(const char* tool,
                                bool gnuplot_ok,
                                const std::string& dir,
                                const LayeredGrid& map,
                                const std::vector<LocalizationResult>& results,
                                int plot_max_cells,
                                const std::string& gnuplot);

}  // namespace tools
}  // namespace mlndt
