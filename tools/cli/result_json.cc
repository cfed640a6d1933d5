#include "tools/cli/result_json.h"

#include <algorithm>

namespace mlndt {
namespace tools {
namespace {

Json VectorJson(const Eigen::VectorXd& v) {
  Json array = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) array.push_back(Number(v(i)));
  return array;
}

Json MatrixRowsJson(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    rows.push_back(VectorJson(m.row(r).transpose()));
  }
  return rows;
}

struct ToJson {
  Json operator()(double v) const { return Number(v); }
  Json operator()(int64_t v) const { return v; }
  Json operator()(bool v) const { return v; }
  Json operator()(const std::string& v) const { return v; }
  Json operator()(const EnumName& v) const { return v.name; }
  Json operator()(const std::vector<int64_t>& v) const { return v; }
  Json operator()(const Eigen::VectorXd& v) const { return VectorJson(v); }
  Json operator()(const Eigen::MatrixXd& v) const { return MatrixRowsJson(v); }
  Json operator()(const NestedResult& v) const {
    return ResultJson(*v.table, v.object);
  }
  Json operator()(const NestedResults& v) const {
    Json array = Json::array();
    for (const void* object : v.objects) {
      array.push_back(ResultJson(*v.table, object));
    }
    return array;
  }
};

// One value (ResultValue) as JSON.
Json ResultValueJson(const ResultValue& value) {
  return std::visit(ToJson{}, value);
}

}  // namespace

Json ResultJson(const ResultTable& table,
                const void* object,
                const std::vector<std::string>& skip) {
  Json json = Json::object();
  for (const ResultField& field : table.fields()) {
    if (std::find(skip.begin(), skip.end(), field.name) != skip.end()) {
      continue;
    }
    json[field.name] = ResultValueJson(field.get(object));
  }
  return json;
}

}  // namespace tools
}  // namespace mlndt
