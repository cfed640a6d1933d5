// The tools' own option tables against their flags (tools/common/
// table_flags.h): every field of every table in ToolTableFlags() has a flag
// named as the field (or as listed), registered as the tool's, whose --help
// is the field's FullHelp and whose default is the struct's, or a shared
// flag of the same option (type, unit, range and default); no flag of the
// tool's table is undescribed; a flag given lands in its field; a value out
// of range is refused naming the flag.

#include <gflags/gflags.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "mlndt/pipeline/localizer.h"
#include "mlndt/pipeline/map_builder.h"
#include "mlndt/pipeline/pipeline_option_tables.h"
#include "tools/common/localizer_flags.h"
#include "tools/common/map_build_flags.h"
#include "tools/common/option_flags.h"
#include "tools/common/tool_table_flags.h"

namespace mlndt {
namespace {

using tools::TableFlags;
using tools::ToolTableFlags;

// gflags writes a double default its own way; compare values.
void ExpectSameDefault(const std::string& flag_default,
                       const OptionField& field,
                       const OptionTable& table,
                       const std::string& what) {
  const std::string field_default = field.Format(table.defaults());
  if (field.type == OptionType::DOUBLE) {
    EXPECT_EQ(std::stod(flag_default), std::stod(field_default)) << what;
  } else {
    EXPECT_EQ(flag_default, field_default) << what;
  }
}

bool Listed(const TableFlags::Names& names, const std::string& field) {
  for (const auto& [name, flag] : names) {
    if (name == field) return true;
  }
  return false;
}

// A field read from a shared flag is the same option as the flag's.
void ExpectSameOption(const OptionField& field, const std::string& flag) {
  const OptionField& shared = *tools::FlagOfName(flag)->field;
  EXPECT_EQ(shared.type, field.type) << flag;
  EXPECT_EQ(shared.unit, field.unit) << flag;
  EXPECT_EQ(shared.RangeText(), field.RangeText())
      << "--" << flag << " is another option's flag: give " << field.name
      << " another flag name";
}

TEST(ToolOptionFlags, EveryToolTableIsListed) {
  std::set<std::string> tables;
  for (const TableFlags* flags : ToolTableFlags()) {
    tables.insert(flags->table().struct_name());
  }
  EXPECT_EQ(tables,
            (std::set<std::string>{"MapBuildOptions", "LocalizerOptions"}));
}

TEST(ToolOptionFlags, EveryFieldHasItsFlagHelpAndDefault) {
  for (const TableFlags* flags : ToolTableFlags()) {
    const OptionTable& table = flags->table();
    for (const OptionField& field : table.fields()) {
      const std::string what = table.struct_name() + "." + field.name;
      const std::string flag = flags->FlagOf(field.name);
      if (flag.empty()) {
        EXPECT_TRUE(Listed(flags->set_by_tool_flag(), field.name)) << what;
        continue;
      }
      if (!Listed(flags->renamed(), field.name)) {
        EXPECT_EQ(flag, field.name) << what;
      }
      gflags::CommandLineFlagInfo info;
      ASSERT_TRUE(gflags::GetCommandLineFlagInfo(flag.c_str(), &info))
          << what << ": --" << flag << " is not registered";
      ExpectSameDefault(info.default_value, field, table, what);
      if (tools::FlagOfName(flag) != nullptr) {  // Shared: its help.
        ExpectSameOption(field, flag);
        continue;
      }
      EXPECT_EQ(info.description, field.FullHelp()) << what;
      EXPECT_EQ(info.filename, "tools/" + flags->tool() + ".cc") << what;
    }
  }
}

TEST(ToolOptionFlags, NoFlagOfATableIsUndescribed) {
  for (const TableFlags* flags : ToolTableFlags()) {
    std::set<std::string> expected;
    for (const std::string& flag : flags->RegisteredFlags()) {
      expected.insert(flag);
    }
    std::set<std::string> registered;
    std::vector<gflags::CommandLineFlagInfo> all;
    gflags::GetAllFlags(&all);
    for (const gflags::CommandLineFlagInfo& info : all) {
      if (info.filename == "tools/" + flags->tool() + ".cc") {
        registered.insert(info.name);
      }
    }
    EXPECT_EQ(registered, expected) << flags->tool();
  }
}

// A valid value of the field other than its default.
std::string OtherValue(const OptionField& field, const OptionTable& table) {
  const std::string current = field.Format(table.defaults());
  if (field.type == OptionType::BOOL) {
    return current == "true" ? "false" : "true";
  }
  if (field.type == OptionType::ENUM) {
    for (const EnumTable::Name& name : field.enum_table->names()) {
      std::string lower = name.name;
      for (char& c : lower) c = static_cast<char>(std::tolower(c));
      if (lower != current) return lower;
    }
  }
  const double value = std::stod(current);
  for (const double v : {field.range.hi, field.range.lo, value + 1}) {
    if (std::isfinite(v) && v != value &&
        (!field.has_range || field.range.Contains(v))) {
      std::ostringstream out;
      out.precision(17);
      out << v;
      return out.str();
    }
  }
  return "";
}

TEST(ToolOptionFlags, AGivenFlagSetsItsField) {
  for (const TableFlags* flags : ToolTableFlags()) {
    const OptionTable& table = flags->table();
    for (const OptionField& field : table.fields()) {
      const std::string flag = flags->FlagOf(field.name);
      if (flag.empty()) continue;
      const std::string value = OtherValue(field, table);
      gflags::FlagSaver saver;
      ASSERT_FALSE(
          gflags::SetCommandLineOption(flag.c_str(), value.c_str()).empty())
          << flag << "=" << value;
      MapBuildOptions map;
      LocalizerOptions localizer;
      void* s = table.struct_name() == "MapBuildOptions"
                    ? static_cast<void*>(&map)
                    : static_cast<void*>(&localizer);
      std::string error;
      ASSERT_TRUE(flags->Apply(s, &error)) << error;
      EXPECT_NE(field.Format(s), field.Format(table.defaults()))
          << "--" << flag << "=" << value << " did not reach " << field.name;
    }
  }
}

TEST(ToolOptionFlags, ValuesOutOfRangeNameTheFlag) {
  MapBuildOptions options;
  std::string error;
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("voxel_size", "0.3");
    ASSERT_TRUE(tools::MapBuildFlags().Apply(&options, &error)) << error;
    EXPECT_EQ(options.voxel_size_m, 0.3);
    gflags::SetCommandLineOption("voxel_size", "-1");
    EXPECT_FALSE(tools::MapBuildFlags().Apply(&options, &error));
    EXPECT_EQ(error, "--voxel_size must be in [0.001, 1000] or 0 (m), not -1");
  }
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("num_threads", "0");
    EXPECT_FALSE(tools::MapBuildFlags().Apply(&options, &error));
    EXPECT_EQ(error, "--num_threads must be in [1, 256], not 0");
  }
  {
    gflags::FlagSaver saver;
    gflags::SetCommandLineOption("motion_model", "kalman");
    LocalizerOptions localizer;
    EXPECT_FALSE(tools::LocalizerFlags().Apply(&localizer, &error));
    EXPECT_EQ(error,
              "--motion_model=kalman: expected constant_velocity or "
              "constant_pose");
  }
}

}  // namespace
}  // namespace mlndt
