// The flags mlndt_sequence, mlndt_suite and mlndt_bench define by hand (in
// their mains, not from an option table: tool_option_flags_test.cc checks
// those), each listed with the reason it is not a table flag: a list or
// compound text no table type holds, an input or output, or a name taken.
// A new hand-written flag of these tools fails here until it is made from
// the table or listed with its reason.

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "tests/testing/run_tool.h"
#include "tools/cli/tool_main.h"

namespace mlndt {
namespace {

using Reasons = std::map<std::string, std::string>;

const std::map<std::string, Reasons>& HandWrittenFlags() {
  static const std::map<std::string, Reasons> flags = {
      {"mlndt_sequence",
       {{"scans", "input: the scans' folder"},
        {"gt_poses", "input: the ground-truth pose file"},
        {"max_scans", "input: how many scans are read"},
        {"init",
         "SequenceOptions::init is an InitSpec parsed from mode:argument "
         "text (zero | gt_fraction:c | constant_velocity | poses:FILE)"},
        {"output_dir", "output folder"},
        {"plots", "output: the PNG figures"},
        {"gnuplot", "output: the gnuplot program"},
        {"trace_plot_pairs", "output: pairs shown in a figure"}}},
      {"mlndt_suite",
       {{"datasets", "input: data set folders and their tolerances"},
        {"data_dir", "input: the folder of relative --datasets"},
        {"starts", "SuitePlanOptions::starts: a list of start kinds"},
        {"offsets",
         "SuitePlanOptions::offsets: families AXES:values "
         "(ParseStartOffsets' syntax)"},
        {"perturb",
         "sets perturb_translation_m and perturb_rotation_deg together "
         "(translation_m,rotation_deg)"},
        {"prior_uncertainty",
         "SuitePlanOptions::prior_uncertainty: translation_m,rotation_deg "
         "or empty (unknown)"},
        {"steps", "SuitePlanOptions::steps: a list of integers"},
        {"reach_share", "the report's reach rule, not a plan option"},
        {"output_dir", "output folder"},
        {"plot", "output: quality.png"},
        {"gnuplot", "output: the gnuplot program"},
        {"fail_on", "exit-code targets MEASURE:minimum,..."}}},
      {"mlndt_bench",
       {{"pairs", "BenchPairsOptions::sets: a list of bundled sets"},
        {"data_dir", "BenchPairsOptions::data_dir: a path"},
        {"kitti_gaps", "BenchPairsOptions::kitti_gaps: a list"},
        {"starts", "BenchPairsOptions::starts: a list of start kinds"},
        {"offsets",
         "BenchPairsOptions::offsets: families AXES:values "
         "(ParseStartOffsets' syntax)"},
        {"defaults", "grid list: the defaults configurations start from"},
        {"backends", "grid list: backends"},
        {"samplings", "grid list: input samplings"},
        {"gbs_cell_sizes", "grid list: GBS cell edges"},
        {"start_layers", "grid list: start layers"},
        {"linear_solvers", "grid list: Ceres linear solvers"},
        {"trust_regions", "grid list: Ceres trust-region strategies"},
        {"minimizers", "grid list: Ceres minimizers"},
        {"jacobians", "grid list: Ceres Jacobians"},
        {"losses", "grid list: robust losses"},
        {"loss_scales", "grid list: loss scales"},
        {"threads", "grid list: thread counts"},
        {"seed",
         "BenchGrid::seed: named as the shared registration flag --seed, "
         "which a table flag would clash with where both are linked "
         "(mlndt_options)"},
        {"output_csv", "output: the CSV file"},
        {"output_plot", "output: the PNG file"},
        {"gnuplot", "output: the gnuplot program"}}},
  };
  return flags;
}

// The flags --helpfull lists under the groups ("Flags from <file>:",
// gflags' format) whose file `is_file` accepts.
std::set<std::string> FlagsFromFile(
    const std::string& help,
    const std::function<bool(const std::string&)>& is_file) {
  std::set<std::string> flags;
  std::istringstream in(help);
  std::string line;
  bool inside = false;
  const std::string group = "  Flags from ";
  while (std::getline(in, line)) {
    if (line.rfind(group, 0) == 0 && line.back() == ':') {
      inside =
          is_file(line.substr(group.size(), line.size() - group.size() - 1));
    } else if (inside && line.rfind("    -", 0) == 0) {
      const size_t end = line.find(' ', 5);
      flags.insert(line.substr(5, end - 5));
    }
  }
  return flags;
}

TEST(ToolHandWrittenFlags, EveryHandWrittenFlagIsListedWithItsReason) {
  for (const auto& [tool, reasons] : HandWrittenFlags()) {
    const testing::ToolRun run = testing::RunTool(tool, "--helpfull");
    // The mains' DEFINE_ flags (gflags names their file as compiled:
    // ../../tools/<tool>.cc through scripts/build.sh's ccache, an absolute
    // path without it; lab/programs/<tool>.cc for a lab program), and the
    // table flags (TableFlags names the file MainFile(tool)).
    const std::string table_file = tools::MainFile(tool);
    const std::string main_suffix = "/" + table_file;
    const std::set<std::string> hand_written =
        FlagsFromFile(run.out, [&](const std::string& file) {
          return file.size() > main_suffix.size() &&
                 file.compare(file.size() - main_suffix.size(),
                              main_suffix.size(),
                              main_suffix) == 0;
        });
    const std::set<std::string> from_tables = FlagsFromFile(
        run.out, [&](const std::string& file) { return file == table_file; });
    ASSERT_FALSE(from_tables.empty()) << tool << ": " << run.out;
    std::set<std::string> listed;
    for (const auto& [flag, reason] : reasons) {
      listed.insert(flag);
      EXPECT_FALSE(reason.empty()) << tool << " --" << flag;
      EXPECT_EQ(from_tables.count(flag), 0u)
          << tool << " --" << flag << " is a table flag: unlist it";
    }
    EXPECT_EQ(hand_written, listed) << tool;
  }
}

}  // namespace
}  // namespace mlndt
