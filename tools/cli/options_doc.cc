#include "tools/cli/options_doc.h"

#include <set>
#include <sstream>

#include "mlndt/ndt/ndt_registration.h"
#include "mlndt/odometry/odometry_option_tables.h"
#include "mlndt/odometry/odometry_options.h"
#include "mlndt/pipeline/localizer.h"
#include "mlndt/registration/registration_options.h"
#include "tools/cli/option_flags.h"
#include "tools/cli/tool_table_flags.h"

namespace mlndt {
namespace tools {
namespace {

const char* TypeName(OptionType type) {
  switch (type) {
    case OptionType::BOOL:
      return "bool";
    case OptionType::INT:
      return "int";
    case OptionType::UINT64:
      return "uint64";
    case OptionType::DOUBLE:
      return "double";
    case OptionType::DOUBLE_LIST:
      return "list of double";
    case OptionType::ENUM:
      return "enum";
    case OptionType::STRUCT:
      break;
  }
  return "struct";
}

// The default of the flag's field: RegistrationOptions()' for an ML-NDT
// option, NdtOptions()' for one of conventional NDT only.
std::string DefaultText(const OptionFlag& flag, bool ndt) {
  const OptionTable& table =
      ndt ? NdtOptionsTable() : RegistrationOptionsTable();
  const void* owner = nullptr;
  const OptionField* field = table.FindPath(
      ndt ? flag.ndt_path : flag.mlndt_path, table.defaults(), &owner);
  return field->Format(owner);
}

// " (mlndt_odometry: 0.8)" for a registration flag whose default differs
// in a tool's registration preset (OdometryRegistrationOptions; the value
// the tool uses when the flag is not given, as its --help shows).
std::string ToolDefaultsNote(const OptionFlag& flag) {
  if (flag.mlndt_path.empty()) return "";
  const struct {
    const char* tool;
    RegistrationOptions options;
  } presets[] = {{"mlndt_odometry", OdometryRegistrationOptions()},
                 {"mlndt_localize", LocalizerRegistrationOptions()}};
  const OptionTable& table = RegistrationOptionsTable();
  std::string note;
  for (const auto& preset : presets) {
    const void* owner = nullptr;
    const OptionField* field =
        table.FindPath(flag.mlndt_path, &preset.options, &owner);
    const std::string value = field->Format(owner);
    if (value == DefaultText(flag, false)) continue;
    note += std::string(" (") + preset.tool + ": " + value + ")";
  }
  return note;
}

std::string RangeText(const OptionField& field) {
  if (field.type == OptionType::ENUM) return field.enum_table->ChoicesForHelp();
  if (!field.has_range) return "";
  return (field.type == OptionType::DOUBLE_LIST ? "each " : "") +
         field.range.ToString();
}

std::string Cell(const std::string& text) {
  std::string out;
  for (const char c : text)
    out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

// "--flag" of a tool table's field, or what sets it.
std::string ToolFlagCell(const TableFlags& flags, const std::string& path) {
  const std::string flag = flags.FlagOf(path);
  if (!flag.empty()) {
    return "`--" + flag + "`";
  }
  for (const auto& [name, tool_flag] : flags.set_by_tool_flag()) {
    if (name == path) return "(`--" + tool_flag + "`)";
  }
  return "";
}

// The tools' own option tables (tool_table_flags.h), one section each.
std::string ToolOptionsMarkdown() {
  std::ostringstream out;
  out << "\n## Options of one tool\n\n"
         "Made from the option tables of the structs a tool fills beside "
         "the registration's;\nthe flag is the field's name (a nested "
         "struct's field: its path with `_` for `.`),\nor another where the "
         "field's name is a registration flag. A flag in\nparentheses is "
         "another flag that sets the field "
         "(in\nanother unit, or a registration flag over the tool's own "
         "default).\n";
  for (const TableFlags* flags : ToolTableFlags()) {
    const OptionTable& table = flags->table();
    out << "\n### " << table.struct_name() << " (" << flags->tool()
        << ")\n\n| flag | field | type | default | unit | valid values | "
           "help |\n|---|---|---|---|---|---|---|\n";
    for (const TableFlags::Field& f : flags->fields()) {
      const OptionField& field = *f.field;
      out << "| " << ToolFlagCell(*flags, f.path) << " | " << f.path << " | "
          << TypeName(field.type) << " | "
          << Cell(field.Format(flags->Owner(f.path, table.defaults()))) << " | "
          << field.unit << " | " << Cell(RangeText(field)) << " | "
          << Cell(field.help) << " |\n";
    }
  }
  return out.str();
}

Json ToolOptionsJson() {
  Json tables = Json::array();
  for (const TableFlags* flags : ToolTableFlags()) {
    const OptionTable& table = flags->table();
    Json rows = Json::array();
    for (const TableFlags::Field& f : flags->fields()) {
      const OptionField& field = *f.field;
      rows.push_back(
          {{"flag", flags->FlagOf(f.path)},
           {"field", f.path},
           {"type", TypeName(field.type)},
           {"default", field.Format(flags->Owner(f.path, table.defaults()))},
           {"unit", field.unit},
           {"range", RangeText(field)},
           {"help", field.help}});
    }
    tables.push_back({{"struct", table.struct_name()},
                      {"tool", flags->tool()},
                      {"options", rows}});
  }
  return tables;
}

// The field's annotation: its Python type, and for an enum its names.
std::string Annotation(const OptionField& field) {
  switch (field.type) {
    case OptionType::BOOL:
      return "bool";
    case OptionType::INT:
    case OptionType::UINT64:
      return "int";
    case OptionType::DOUBLE:
      return "float";
    case OptionType::DOUBLE_LIST:
      return "Sequence[float]";
    case OptionType::ENUM: {
      std::string names;
      for (const EnumTable::Name& name : field.enum_table->names()) {
        names += (names.empty() ? "" : " | ") + std::string(name.name);
      }
      return "str  # " + names;
    }
    case OptionType::STRUCT:
      break;
  }
  return field.nested->struct_name();
}

// The TypedDicts of `table`'s nested structs (not yet written), then its own.
void AppendTypedDicts(const OptionTable& table,
                      std::set<std::string>* written,
                      std::ostringstream* out) {
  if (!written->insert(table.struct_name()).second) return;
  for (const OptionField& field : table.fields()) {
    if (field.type == OptionType::STRUCT) {
      AppendTypedDicts(*field.nested, written, out);
    }
  }
  *out << "class " << table.struct_name() << "(TypedDict, total=False):\n";
  for (const OptionField& field : table.fields()) {
    *out << "    " << field.name << ": " << Annotation(field) << "\n";
  }
  *out << "\n";
}

}  // namespace

std::string OptionsMarkdown() {
  std::ostringstream out;
  out << "# Options\n\n"
         "Generated by `mlndt_options` from the option tables next to each "
         "options struct\n(mlndt/common/option_table.h); do not edit. Every "
         "row is a flag of the registration\ntools; the same field is the "
         "Python keyword at its path (nested structs as dicts:\n"
         "`grid={\"num_layers\": 4}`). The default is the struct's "
         "(RegistrationOptions(), or\nNdtOptions() for a --method=ndt-only "
         "flag); --preset=paper starts from\nPaperRegistrationOptions(). "
         "InitialGuessUncertainty's fields are Python keywords\n"
         "(initial_uncertainty=) with one flag, "
         "`--initial_uncertainty=translation_m,rotation_deg`.\n\n"
         "Adding an option: the field (with its default) in the struct's "
         "header and one entry in\nits table next to `IsValid` (unit, range, "
         "help); the flag, `--help`, the Python\nkeyword and docstring and "
         "this file follow (`build/tools/mlndt_options > docs/options.md`;\n"
         "add the keyword to python/mlndt/__init__.pyi).\n\n"
         "| flag | field (ML-NDT) | field (--method=ndt) | type | default | "
         "unit | valid values | help |\n"
         "|---|---|---|---|---|---|---|---|\n";
  for (const OptionFlag& flag : OptionFlags()) {
    const OptionField& field = *flag.field;
    out << "| `--" << flag.name << "` | " << flag.mlndt_path << " | "
        << flag.ndt_path << " | " << TypeName(field.type) << " | "
        << Cell(DefaultText(flag, flag.mlndt_path.empty()) +
                ToolDefaultsNote(flag))
        << " | " << field.unit << " | " << Cell(RangeText(field)) << " | "
        << Cell(field.help) << " |\n";
  }
  out << ToolOptionsMarkdown();
  return out.str();
}

Json OptionsJson() {
  Json rows = Json::array();
  for (const OptionFlag& flag : OptionFlags()) {
    const OptionField& field = *flag.field;
    rows.push_back({{"flag", flag.name},
                    {"mlndt_path", flag.mlndt_path},
                    {"ndt_path", flag.ndt_path},
                    {"type", TypeName(field.type)},
                    {"default", DefaultText(flag, flag.mlndt_path.empty())},
                    {"unit", field.unit},
                    {"range", RangeText(field)},
                    {"help", field.help}});
  }
  return {{"options", rows}, {"tool_options", ToolOptionsJson()}};
}

std::string OptionsStub(const std::vector<const OptionTable*>& roots) {
  std::ostringstream out;
  std::set<std::string> written;
  for (const OptionTable* table : roots) {
    AppendTypedDicts(*table, &written, &out);
  }
  return out.str();
}

std::vector<const OptionTable*> PythonOptionTables() {
  return {&RegistrationOptionsTable(),
          &LocalMapOptionsTable(),
          &KeyframeOptionsTable(),
          &MotionPredictionOptionsTable(),
          &ConfirmationOptionsTable(),
          &RecoveryOptionsTable()};
}

}  // namespace tools
}  // namespace mlndt
