#include "tools/cli/results_doc.h"

#include <algorithm>
#include <sstream>

namespace mlndt {
namespace tools {
namespace {

const DescribedResult* Described(const ResultTable* table,
                                 const std::vector<DescribedResult>& list) {
  for (const DescribedResult& d : list) {
    if (d.table == table) return &d;
  }
  return nullptr;
}

void Collect(const ResultTable& table,
             const std::vector<DescribedResult>& described,
             std::vector<const ResultTable*>* tables) {
  if (std::find(tables->begin(), tables->end(), &table) != tables->end() ||
      Described(&table, described) != nullptr) {
    return;
  }
  tables->push_back(&table);
  for (const ResultField& field : table.fields()) {
    if (field.nested != nullptr) Collect(*field.nested, described, tables);
  }
}

// A table cell: '|' would end it.
std::string Cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string MarkdownType(const ResultField& field) {
  std::string type = ResultTypeToString(field.type);
  if (field.nested != nullptr) {
    type += " `" + field.nested->struct_name() + "`";
  }
  if (field.enum_table != nullptr) {
    std::string names;
    for (const EnumTable::Name& name : field.enum_table->names()) {
      names += (names.empty() ? "" : ", ") + std::string("`") + name.name + "`";
    }
    type += ": " + names;
  }
  return type;
}

std::string PythonType(const ResultField& field,
                       const std::vector<DescribedResult>& described) {
  const DescribedResult* d = Described(field.nested, described);
  if (d != nullptr && field.type == ResultType::STRUCT) {
    return d->python_class;
  }
  switch (field.type) {
    case ResultType::NUMBER:
      return "float";
    case ResultType::INTEGER:
      return "int";
    case ResultType::BOOL:
      return "bool";
    case ResultType::STRING:
    case ResultType::ENUM:
      return "str";
    case ResultType::INTEGER_LIST:
      return "list[int]";
    case ResultType::VECTOR:
    case ResultType::MATRIX:
      return "npt.NDArray[np.float64]";
    case ResultType::STRUCT:
      return field.nested->struct_name();
    case ResultType::STRUCT_LIST:
      return "list[" + field.nested->struct_name() + "]";
  }
  return "Any";
}

std::string StubDoc(const ResultField& field) {
  std::string doc = field.help;
  if (!field.unit.empty()) doc += " [" + field.unit + "]";
  return doc;
}

void TypedDict(const ResultTable& table,
               const std::vector<DescribedResult>& described,
               std::ostringstream* out) {
  *out << "class " << table.struct_name() << "(TypedDict):\n";
  for (const ResultField& field : table.fields()) {
    *out << "    " << field.name << ": " << PythonType(field, described)
         << "\n";
  }
  *out << "\n";
}

// `root` and the tables nested in it, each once, root first, then in the
// order they are first met; tables of `described` are not entered.
std::vector<const ResultTable*> ResultTablesUnder(
    const ResultTable& root, const std::vector<DescribedResult>& described) {
  std::vector<const ResultTable*> tables;
  tables.push_back(&root);
  for (const ResultField& field : root.fields()) {
    if (field.nested != nullptr) Collect(*field.nested, described, &tables);
  }
  return tables;
}

}  // namespace

std::string ResultsMarkdown(const ResultTable& root,
                            const std::vector<DescribedResult>& described) {
  std::ostringstream out;
  const std::vector<const ResultTable*> tables =
      ResultTablesUnder(root, described);
  for (const ResultTable* table : tables) {
    out << "### " << table->struct_name() << "\n\n"
        << "| key | type | unit | meaning |\n|---|---|---|---|\n";
    for (const ResultField& field : table->fields()) {
      out << "| `" << field.name << "` | " << MarkdownType(field) << " | "
          << Cell(field.unit) << " | " << Cell(field.help) << " |\n";
    }
    if (table != tables.back()) out << "\n";
  }
  return out.str();
}

std::string ResultsStub(const ResultTable& root,
                        const std::string& python_class,
                        const std::string& class_doc,
                        const std::vector<DescribedResult>& described) {
  std::ostringstream out;
  const std::vector<const ResultTable*> tables =
      ResultTablesUnder(root, described);
  for (const ResultTable* table : tables) {
    if (table != &root) TypedDict(*table, described, &out);
  }
  out << "class " << python_class << ":\n    \"\"\"" << class_doc
      << "\"\"\"\n\n";
  for (const ResultField& field : root.fields()) {
    out << "    @property\n    def " << field.name << "(self) -> "
        << PythonType(field, described) << ":\n        \"\"\"" << StubDoc(field)
        << "\"\"\"\n";
  }
  out << "    def todict(self) -> dict[str, Any]:\n"
      << "        \"\"\"Every field above, nested results as dicts.\"\"\"\n";
  return out.str();
}

}  // namespace tools
}  // namespace mlndt
