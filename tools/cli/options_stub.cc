#include "tools/cli/options_stub.h"

#include <set>
#include <sstream>

#include "mlndt/odometry/odometry_option_tables.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {
namespace tools {
namespace {

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
