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

#include <gflags/gflags.h>

#include <iostream>
#include <string>
#include <vector>

#include "mlndt/common/result_table.h"
#include "mlndt/odometry/odometry.h"
#include "mlndt/pipeline/localizer.h"
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
              "odometry_markdown | odometry_pyi (of OdometryResult)");

namespace {

// The reference of a result table in --format; false for another format.
bool PrintResults(const std::string& format) {
  using mlndt::tools::DescribedResult;
  const std::vector<DescribedResult> registration = {
      {&mlndt::RegistrationSummaryTable(), "RegistrationResult"}};
  if (format == "results_markdown") {
    std::cout << mlndt::tools::ResultsMarkdown(
        mlndt::RegistrationSummaryTable());
  } else if (format == "results_pyi") {
    std::cout << mlndt::tools::ResultsStub(
        mlndt::RegistrationSummaryTable(),
        "RegistrationResult",
        "What a registration reports (mlndt::RegistrationSummary).");
  } else if (format == "localization_markdown") {
    std::cout << mlndt::tools::ResultsMarkdown(mlndt::LocalizationResultTable(),
                                               registration);
  } else if (format == "localization_pyi") {
    std::cout << mlndt::tools::ResultsStub(
        mlndt::LocalizationResultTable(),
        "LocalizationResult",
        "One scan's localisation (mlndt::LocalizationResult).",
        registration);
  } else if (format == "odometry_markdown") {
    std::cout << mlndt::tools::ResultsMarkdown(mlndt::OdometryResultTable(),
                                               registration);
  } else if (format == "odometry_pyi") {
    std::cout << mlndt::tools::ResultsStub(
        mlndt::OdometryResultTable(),
        "OdometryResult",
        "One scan of the odometry (mlndt::OdometryResult).",
        registration);
  } else {
    return false;
  }
  return true;
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
  } else if (!PrintResults(FLAGS_format)) {
    std::cerr << "mlndt_options: --format=" << FLAGS_format
              << ": expected markdown, json, results_markdown, results_pyi, "
                 "localization_markdown, localization_pyi, odometry_markdown "
                 "or odometry_pyi\n";
    return mlndt::tools::kExitUsage;
  }
  return mlndt::tools::kExitOk;
}
