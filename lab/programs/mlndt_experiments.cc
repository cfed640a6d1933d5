// mlndt_experiments: reproduces the paper's Section 5 (Tables 2-9, Figs.
// 10-18) on the data sets with references, under the paper preset and under
// the defaults (plus the ablation between them), and writes the report
// (issue 15; lab/experiments/ holds the logic):
//
//   mlndt_experiments --data_dir=/work/shared/data --out=results/experiments
//   mlndt_experiments --quick --out=/tmp/quick      # bundled data/, < 1 min
//
// OUT/README_RESULTS.md: one section per table and figure with the paper's
// number, ours under the paper preset and under the defaults, and one
// sentence of conclusion from this run's numbers. OUT/csv/*.csv holds every
// run (runs.csv) and every table and figure's data; OUT/figures/*.gp redraw
// the PNGs from them. OUT/summary.json: the headline numbers. Progress and
// ETA on stderr. Exit 0 after a complete report, 1 on any error.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <chrono>
#include <iostream>

#include "lab/experiments/datasets.h"
#include "lab/experiments/experiment_plan.h"
#include "lab/experiments/report.h"
#include "lab/experiments/run_batch.h"
#include "lab/experiments/trace_experiment.h"
#include "lab/report/gnuplot.h"
#include "tools/cli/progress_printer.h"
#include "tools/cli/tool_main.h"
#include "tools/cli/tool_utils.h"

// clang-format off
DEFINE_string(data_dir, MLNDT_DATA_DIR,
              "Folder holding the data sets (shared names such as "
              "kitti00_frames_0000_0007, or the bundled kitti, room, koide3)");
DEFINE_string(out, "", "Report folder (README_RESULTS.md, csv/, figures/)");
DEFINE_bool(quick, false, "Few pairs, offsets and fractions (a smoke test)");
DEFINE_bool(plots, true, "Run gnuplot on the figure scripts (exit 1 when it fails)");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_experiments";

int Run() {
  using namespace experiments;
  if (FLAGS_out.empty()) return tools::Fail(kTool, "--out is required");
  if (FLAGS_plots && !GnuplotAvailable(FLAGS_gnuplot))
    return tools::Fail(
        kTool,
        "--gnuplot=" + FLAGS_gnuplot + " does not run (or --plots=false)");
  std::vector<ExperimentDataset> datasets;
  ReportHeader header;
  header.command = tools::CommandLine();
  header.quick = FLAGS_quick;
  header.data_dir = FLAGS_data_dir;
  std::string error;
  if (!FindDatasets(FLAGS_data_dir, &datasets, &header.missing, &error))
    return tools::Fail(kTool, error);
  if (datasets.empty())
    return tools::Fail(kTool, FLAGS_data_dir + ": no data set found");

  ReportContext context;
  context.plan = MakePlan(FLAGS_quick);
  const std::vector<Job> jobs = MakeJobs(context.plan, datasets);
  const auto start = std::chrono::steady_clock::now();
  TraceExperiment trace;
  if (!RunTraceExperiment(datasets, &trace, &error))
    std::cerr << "mlndt_experiments: Figs. 10-13: " << error << "\n";
  std::vector<RunRecord> records;
  tools::ProgressPrinter progress(kTool);
  const bool ran = RunJobs(datasets, jobs, &progress, &records, &error);
  progress.Finish();
  if (!ran) return tools::Fail(kTool, error);
  header.run_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  header.runs = records.size();

  ReportFiles files;
  context.datasets = &datasets;
  context.records = &records;
  context.files = &files;
  files.Add("csv/runs.csv", RunRecordsCsv(records));
  BuildReport(header, context, trace);
  if (!files.WriteAll(FLAGS_out, FLAGS_plots, FLAGS_gnuplot, &error))
    return tools::Fail(kTool, error);
  std::cout << FLAGS_out << "/README_RESULTS.md: " << records.size()
            << " registrations in " << header.run_seconds << " s\n";
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Reproduces the paper's Section 5 under the paper preset and the "
          "defaults and writes OUT/README_RESULTS.md with CSVs and figures.",
          true,
          &argc,
          &argv)) {
    return 1;
  }
  return mlndt::Run();
}
