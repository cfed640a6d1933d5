// The registration flags against the option description
// (tools/cli/option_flags.h): every described field of RegistrationOptions
// and NdtOptions has a flag named as the field (the renames below are the
// only exceptions) with the field's default; no flag of the shared files is
// undescribed (the tool-specific ones are listed); a flag given lands in its
// field; a deprecated name works and refuses to be given with the new one.

#include "tools/cli/option_flags.h"

#include <gflags/gflags.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "mlndt/ndt/ndt_registration.h"
#include "mlndt/registration/registration_options.h"
#include "tools/cli/registration_flags.h"

namespace mlndt {
namespace {

using tools::OptionFlags;

// The flag of an option path ("objective.loss_scale"; ndt: of NdtOptions),
// nullptr when it has none.
const tools::OptionFlag* FlagOfPath(const std::string& path, bool ndt) {
  for (const tools::OptionFlag& flag : OptionFlags()) {
    if ((ndt ? flag.ndt_path : flag.mlndt_path) == path) return &flag;
  }
  return nullptr;
}

struct Leaf {
  std::string path;
  const OptionField* field;
};

void CollectLeaves(const OptionTable& table,
                   const std::string& prefix,
                   std::vector<Leaf>* leaves) {
  for (const OptionField& field : table.fields()) {
    if (field.type == OptionType::STRUCT) {
      CollectLeaves(*field.nested, prefix + field.name + ".", leaves);
    } else {
      leaves->push_back({prefix + field.name, &field});
    }
  }
}

// The flag name of a field: its name, except these.
std::string ExpectedFlag(const std::string& path, bool ndt) {
  static const std::map<std::string, std::string> kRenamed = {
      {"sampling.method", "sampling"},
      {"backend.type", "backend"},
      {"quality_check.enabled", "quality_check"}};
  if (kRenamed.count(path) > 0) return kRenamed.at(path);
  static const std::set<std::string> kNdtOwn = {"cell_size_m",
                                                "outlier_ratio",
                                                "neighbors",
                                                "max_iterations",
                                                "max_step_norm"};
  if (ndt && kNdtOwn.count(path) > 0) return "ndt_" + path;
  const std::string leaf = path.substr(path.rfind('.') + 1);
  if (path.rfind("backend.newton.", 0) == 0 || path.rfind("newton.", 0) == 0) {
    return "newton_" + leaf;
  }
  if (path.rfind("backend.levenberg_marquardt.", 0) == 0) return "lm_" + leaf;
  return leaf;
}

std::string Default(const OptionTable& table, const std::string& path) {
  const void* owner = nullptr;
  return table.FindPath(path, table.defaults(), &owner)->Format(owner);
}

// gflags writes a double default its own way; compare values.
void ExpectSameDefault(const std::string& flag_default,
                       const std::string& field_default,
                       const OptionField& field,
                       const std::string& what) {
  if (field.type == OptionType::DOUBLE) {
    EXPECT_EQ(std::stod(flag_default), std::stod(field_default)) << what;
  } else {
    EXPECT_EQ(flag_default, field_default) << what;
  }
}

void ExpectFlagsFor(const OptionTable& table, bool ndt) {
  std::vector<Leaf> leaves;
  CollectLeaves(table, "", &leaves);
  for (const Leaf& leaf : leaves) {
    if (leaf.path.rfind("initial_uncertainty.", 0) == 0) continue;  // Below.
    const tools::OptionFlag* flag = FlagOfPath(leaf.path, ndt);
    ASSERT_NE(flag, nullptr) << leaf.path << " has no flag";
    EXPECT_EQ(flag->name, ExpectedFlag(leaf.path, ndt)) << leaf.path;
    gflags::CommandLineFlagInfo info;
    ASSERT_TRUE(gflags::GetCommandLineFlagInfo(flag->name.c_str(), &info))
        << flag->name << " is not registered";
    // A flag both methods read shows the ML-NDT default; NDT's own default
    // differs only for --step_tolerance (NDT takes the flag's value).
    const bool shared = ndt && !flag->mlndt_path.empty();
    if (shared && leaf.path == "step_tolerance") continue;
    ExpectSameDefault(info.default_value,
                      Default(table, leaf.path),
                      *leaf.field,
                      flag->name + " (" + leaf.path + ")");
    EXPECT_NE(info.description.find(leaf.field->help.substr(0, 20)),
              std::string::npos)
        << flag->name << ": --help should carry the field's help";
  }
}

TEST(OptionFlags, EveryRegistrationOptionHasItsFlagAndDefault) {
  ExpectFlagsFor(RegistrationOptionsTable(), false);
}

TEST(OptionFlags, EveryNdtOptionHasItsFlagAndDefault) {
  ExpectFlagsFor(NdtOptionsTable(), true);
}

// initial_uncertainty.* are set by the one --initial_uncertainty=t,r flag.
TEST(OptionFlags, InitialUncertaintyHasTheCompositeFlag) {
  EXPECT_EQ(FlagOfPath("initial_uncertainty.translation_m", false), nullptr);
  gflags::FlagSaver saver;
  gflags::SetCommandLineOption("initial_uncertainty", "0.5,5");
  MatcherOptions options;
  std::string error;
  ASSERT_TRUE(tools::MatcherOptionsFromFlags(&options, &error)) << error;
  EXPECT_TRUE(options.mlndt.initial_uncertainty.given);
  EXPECT_EQ(options.mlndt.initial_uncertainty.translation_m, 0.5);
  EXPECT_EQ(options.mlndt.initial_uncertainty.rotation_deg, 5.0);
}

TEST(OptionFlags, NoSharedFlagIsUndescribed) {
  std::set<std::string> described;
  for (const tools::OptionFlag& flag : OptionFlags()) {
    described.insert(flag.name);
  }
  // Tool-specific, not option fields: the preset, the method and the
  // composite initial uncertainty.
  const std::set<std::string> kToolSpecific = {
      "preset", "method", "initial_uncertainty"};
  std::vector<gflags::CommandLineFlagInfo> all;
  gflags::GetAllFlags(&all);
  int shared = 0;
  for (const gflags::CommandLineFlagInfo& info : all) {
    const std::string& file = info.filename;
    if (file.find("tools/cli/option_flags.cc") != std::string::npos) {
      EXPECT_EQ(described.count(info.name), 1u) << info.name;
      ++shared;
    } else if (file.find("tools/cli/registration_flags.cc") !=
               std::string::npos) {
      EXPECT_EQ(kToolSpecific.count(info.name), 1u) << info.name;
    }
  }
  EXPECT_EQ(shared, static_cast<int>(described.size()));
}

// A valid number of the field's range other than `current`.
std::string OtherNumber(const OptionField& field, double current) {
  std::vector<double> candidates = {current + 1, current * 2 + 1};
  if (field.has_range && std::isfinite(field.range.lo) &&
      std::isfinite(field.range.hi)) {
    const double mid = (field.range.lo + field.range.hi) / 2;
    candidates = {field.range.hi,
                  field.range.lo,
                  field.type == OptionType::INT ? std::floor(mid) : mid};
  }
  for (const double v : candidates) {
    if (v != current && (!field.has_range || field.range.Contains(v))) {
      std::ostringstream out;
      out.precision(17);
      out << v;
      return out.str();
    }
  }
  return "";
}

// Every flag given sets its field: each is given a valid value other than
// its default, and the field reads it back.
TEST(OptionFlags, AGivenFlagSetsItsField) {
  for (const tools::OptionFlag& flag : OptionFlags()) {
    const bool ndt = flag.mlndt_path.empty();
    const OptionTable& table =
        ndt ? NdtOptionsTable() : RegistrationOptionsTable();
    const std::string& path = ndt ? flag.ndt_path : flag.mlndt_path;
    const OptionField& field = *table.FindPath(path);
    std::string value;
    switch (field.type) {
      case OptionType::BOOL:
        value = Default(table, path) == "true" ? "false" : "true";
        break;
      case OptionType::ENUM: {
        const std::string current = Default(table, path);
        for (const EnumTable::Name& name : field.enum_table->names()) {
          std::string lower = name.name;
          for (char& c : lower) c = static_cast<char>(std::tolower(c));
          if (lower != current) value = lower;
        }
        break;
      }
      case OptionType::DOUBLE_LIST:
        value = "10,-10";
        break;
      default:
        value = OtherNumber(field, std::stod(Default(table, path)));
    }
    gflags::FlagSaver saver;
    ASSERT_FALSE(
        gflags::SetCommandLineOption(flag.name.c_str(), value.c_str()).empty())
        << flag.name << "=" << value;
    RegistrationOptions mlndt;
    NdtOptions ndt_options;
    void* s =
        ndt ? static_cast<void*>(&ndt_options) : static_cast<void*>(&mlndt);
    std::string error;
    ASSERT_TRUE(tools::ApplyGivenFlags(table, "", ndt, s, &error)) << error;
    const void* owner = nullptr;
    table.FindPath(path, s, &owner);
    const OptionField& set = *table.FindPath(path);
    EXPECT_NE(set.Format(owner), Default(table, path))
        << "--" << flag.name << "=" << value << " did not reach " << path;
  }
}

TEST(OptionFlags, ARefusalNamesTheFlag) {
  {
    // A refusal names the flag as it was given.
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("method", "ndt");
    gflags::SetCommandLineOption("yaw_seeds_deg", "90");
    MatcherOptions options;
    std::string error;
    EXPECT_FALSE(tools::MatcherOptionsFromFlags(&options, &error));
    EXPECT_EQ(error, "--yaw_seeds_deg does not apply to --method=ndt");
  }
}

TEST(OptionFlags, BadValuesNameTheFlagAndTheChoices) {
  gflags::FlagSaver saver;
  gflags::SetCommandLineOption("loss", "tukey");
  MatcherOptions options;
  std::string error;
  EXPECT_FALSE(tools::MatcherOptionsFromFlags(&options, &error));
  EXPECT_EQ(error, "--loss=tukey: expected none, huber or cauchy");
  gflags::SetCommandLineOption("loss", "huber");
  gflags::SetCommandLineOption("loss_scale", "0");
  EXPECT_FALSE(tools::MatcherOptionsFromFlags(&options, &error));
  EXPECT_NE(error.find("loss_scale = 0; it must be in [0.001, 1000]"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace mlndt
