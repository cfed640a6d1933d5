#include "tools/cli/result_csv.h"

#include <cmath>
#include <cstdio>
#include <utility>
#include <variant>

#include "lab/report/text_format.h"

namespace mlndt {
namespace tools {
namespace {

std::string FullNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", v);
  return text;
}

std::string Joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& part : parts) {
    out += (out.empty() ? "" : " ") + part;
  }
  return out;
}

struct ToCells {
  std::vector<std::string>* cells;

  void operator()(double v) const { cells->push_back(FullNumber(v)); }
  void operator()(int64_t v) const { cells->push_back(std::to_string(v)); }
  void operator()(bool v) const { cells->push_back(v ? "true" : "false"); }
  void operator()(const std::string& v) const { cells->push_back(CsvField(v)); }
  void operator()(const EnumName& v) const { cells->push_back(v.name); }
  void operator()(const std::vector<int64_t>& v) const {
    std::vector<std::string> parts;
    for (const int64_t x : v) parts.push_back(std::to_string(x));
    cells->push_back(Joined(parts));
  }
  void operator()(const Eigen::VectorXd& v) const {
    std::vector<std::string> parts;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      parts.push_back(FullNumber(v(i)));
    }
    cells->push_back(Joined(parts));
  }
  void operator()(const Eigen::MatrixXd& m) const {
    std::vector<std::string> parts;
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      for (Eigen::Index c = 0; c < m.cols(); ++c) {
        parts.push_back(FullNumber(m(r, c)));
      }
    }
    cells->push_back(Joined(parts));
  }
  void operator()(const NestedResult& v) const {
    for (std::string& cell : ResultCsvCells(*v.table, v.object)) {
      cells->push_back(std::move(cell));
    }
  }
  void operator()(const NestedResults&) const {}  // JSON only.
};

void AppendLine(const std::vector<std::string>& cells, std::string* out) {
  for (size_t i = 0; i < cells.size(); ++i) {
    *out += (i == 0 ? "" : ",") + cells[i];
  }
  *out += "\n";
}

}  // namespace

std::vector<std::string> ResultCsvColumns(const ResultTable& table) {
  std::vector<std::string> columns;
  for (const ResultField& field : table.fields()) {
    if (field.type == ResultType::STRUCT_LIST) continue;
    if (field.type != ResultType::STRUCT) {
      columns.push_back(field.name);
      continue;
    }
    for (const std::string& inner : ResultCsvColumns(*field.nested)) {
      columns.push_back(field.name + "." + inner);
    }
  }
  return columns;
}

std::vector<std::string> ResultCsvCells(const ResultTable& table,
                                        const void* object) {
  std::vector<std::string> cells;
  for (const ResultField& field : table.fields()) {
    std::visit(ToCells{&cells}, field.get(object));
  }
  return cells;
}

std::string ResultCsv(const ResultTable& table,
                      const std::vector<const void*>& objects,
                      const std::vector<CsvColumn>& leading) {
  std::vector<std::string> header;
  for (const CsvColumn& column : leading) header.push_back(column.name);
  for (const std::string& name : ResultCsvColumns(table)) {
    header.push_back(name);
  }
  std::string out;
  AppendLine(header, &out);
  for (size_t k = 0; k < objects.size(); ++k) {
    std::vector<std::string> cells;
    for (const CsvColumn& column : leading) {
      cells.push_back(CsvField(column.cells.at(k)));
    }
    for (std::string& cell : ResultCsvCells(table, objects[k])) {
      cells.push_back(std::move(cell));
    }
    AppendLine(cells, &out);
  }
  return out;
}

}  // namespace tools
}  // namespace mlndt
