#pragma once

// What mlndt_bench prints and writes from a BenchResult (lab/bench/bench.h):
// the markdown table with its preamble and notes, the CSV (one row per set
// of pairs and method), and the points of the time-vs-error plot.

#include <string>
#include <vector>

#include "lab/bench/bench.h"
#include "lab/bench/bench_pareto.h"

namespace mlndt {

// The markdown table's header, and one row (`pcl`: PCL NDT's row for the
// pcl/ours ratio, or null).
std::vector<std::string> BenchTableHeader();
std::vector<std::string> BenchTableRow(const std::string& set,
                                       const BenchMethodLabels& labels,
                                       const BenchRowStats& s,
                                       const BenchRowStats* pcl);

// The CSV's header line (with its newline) and one row (without).
std::string BenchCsvHeader();
std::string BenchCsvRow(const std::string& set,
                        const BenchMethodLabels& labels,
                        const BenchRowStats& s,
                        const BenchRowStats* pcl);

// Rows (the first is the header) as a markdown table with padded columns.
std::string MarkdownTable(const std::vector<std::vector<std::string>>& rows);

// Standard output: the preamble (rounds, methods, runs per set), the table
// (per set, every method; the peers last) and the notes.
std::string BenchReportText(const BenchOptions& options,
                            const BenchResult& result);

// The CSV file: the header and a row per set and method.
std::string BenchCsvText(const BenchResult& result);

// One point per set and method: median time, mean translation error.
std::vector<BenchPlotPoint> BenchPlotPoints(const BenchResult& result);

}  // namespace mlndt
