// mlndt_options: the option reference made from the library's option tables
// (docs/options.md is its output): every registration flag with the field
// it sets, type, default, unit, valid values and help, and the tools' own
// options (mlndt_map's, mlndt_localize's).
//   mlndt_options                 # Markdown (docs/options.md)
//   mlndt_options --format=json   # the same as JSON
//   mlndt_options --format=results_markdown  # docs/json_schema.md's
//                                            # registration section
//   mlndt_options --format=results_pyi       # the stub's RegistrationResult
//   mlndt_options --format=localization_markdown  # ... mlndt_localize's
//                                                  # scans section
//   mlndt_options --format=localization_pyi       # LocalizationResult
//   mlndt_options --format=odometry_markdown|odometry_pyi  # OdometryResult
//   mlndt_options --format=map_markdown  # MapBuildSummary (mlndt_map's JSON)
//   mlndt_options --format=eval_markdown  # TrajectoryEvaluation (mlndt_eval)
//   mlndt_options --format=options_pyi    # the stub's option TypedDicts

#include <gflags/gflags.h>

#include <iostream>
#include <string>
#include <vector>

#include "lab/eval/trajectory_evaluation.h"
#include "mlndt/common/result_table.h"
#include "mlndt/odometry/odometry.h"
#include "mlndt/pipeline/localizer.h"
#include "mlndt/pipeline/map_builder.h"
#include "mlndt/registration/registration_summary.h"
#include "tools/cli/option_flags.h"
#include "tools/cli/options_doc.h"
#include "tools/cli/results_doc.h"
#include "tools/cli/tool_main.h"
#include "tools/cli/tool_table_flags.h"

DEFINE_string(format,
              "markdown",
              "markdown | json | results_markdown (docs/json_schema.md's "
              "registration section) | results_pyi (the stub's "
              "RegistrationResult) | localization_markdown | "
              "localization_pyi (the same of LocalizationResult) | "
              "odometry_markdown | odometry_pyi (of OdometryResult) | "
              "map_markdown (of MapBuildSummary) | eval_markdown (of "
              "TrajectoryEvaluation) | options_pyi (the stub's option "
              "TypedDicts)");

namespace {

// A result table whose reference is generated: --format=<name>_markdown
// (its docs/json_schema.md block) and, when Python has it, <name>_pyi (its
// class in the stub).
struct DocumentedResult {
  const char* name;
  const mlndt::ResultTable* table;
  const char* python_class;  // Empty: not in Python.
  const char* python_doc;
  std::vector<mlndt::tools::DescribedResult> described;
};

std::vector<DocumentedResult> DocumentedResults() {
  const std::vector<mlndt::tools::DescribedResult> registration = {
      {&mlndt::RegistrationSummaryTable(), "RegistrationResult"}};
  return {
      {"results",
       &mlndt::RegistrationSummaryTable(),
       "RegistrationResult",
       "What a registration reports (mlndt::RegistrationSummary).",
       {}},
      {"localization",
       &mlndt::LocalizationResultTable(),
       "LocalizationResult",
       "One scan's localisation (mlndt::LocalizationResult).",
       registration},
      {"odometry",
       &mlndt::OdometryResultTable(),
       "OdometryResult",
       "One scan of the odometry (mlndt::OdometryResult).",
       registration},
      {"map", &mlndt::MapBuildSummaryTable(), "", "", {}},
      {"eval", &mlndt::TrajectoryEvaluationTable(), "", "", {}},
  };
}

// The reference of a result table in --format; false for another format.
bool PrintResults(const std::string& format) {
  for (const DocumentedResult& r : DocumentedResults()) {
    const std::string name = r.name;
    if (format == name + "_markdown") {
      std::cout << mlndt::tools::ResultsMarkdown(*r.table, r.described);
      return true;
    }
    if (format == name + "_pyi" && *r.python_class != '\0') {
      std::cout << mlndt::tools::ResultsStub(
          *r.table, r.python_class, r.python_doc, r.described);
      return true;
    }
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> option_flags;
  for (const auto& flag : mlndt::tools::OptionFlags()) {
    option_flags.push_back(flag.name);
  }
  for (const auto* table_flags : mlndt::tools::ToolTableFlags()) {
    for (const std::string& flag : table_flags->RegisteredFlags()) {
      option_flags.push_back(flag);
    }
  }
  mlndt::tools::HideFlagsFromHelp(option_flags);
  if (!mlndt::tools::StartTool(
          "Prints the option reference (docs/options.md).\n"
          "  mlndt_options [--format=markdown|json]",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  std::string error;
  if (!mlndt::tools::RefuseGivenFlags(
          option_flags, "does not apply to mlndt_options", &error)) {
    std::cerr << "mlndt_options: " << error << "\n";
    return mlndt::tools::kExitUsage;
  }
  if (FLAGS_format == "markdown") {
    std::cout << mlndt::tools::OptionsMarkdown();
  } else if (FLAGS_format == "json") {
    std::cout << mlndt::tools::OptionsJson().dump(2) << "\n";
  } else if (FLAGS_format == "options_pyi") {
    std::cout << mlndt::tools::OptionsStub(mlndt::tools::PythonOptionTables());
  } else if (!PrintResults(FLAGS_format)) {
    std::cerr << "mlndt_options: --format=" << FLAGS_format
              << ": expected markdown, json, results_markdown, results_pyi, "
                 "localization_markdown, localization_pyi, odometry_markdown, "
                 "odometry_pyi, map_markdown, eval_markdown or options_pyi\n";
    return mlndt::tools::kExitUsage;
  }
  return mlndt::tools::kExitOk;
}
