#include "python/src/result_binding.h"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

namespace mlndt {
namespace python {
namespace {

struct ToPython {
  py::object operator()(double v) const { return py::float_(v); }
  py::object operator()(int64_t v) const { return py::int_(v); }
  py::object operator()(bool v) const { return py::bool_(v); }
  py::object operator()(const std::string& v) const { return py::str(v); }
  py::object operator()(const EnumName& v) const { return py::str(v.name); }
  py::object operator()(const std::vector<int64_t>& v) const {
    return py::cast(v);
  }
  py::object operator()(const Eigen::VectorXd& v) const { return py::cast(v); }
  py::object operator()(const Eigen::MatrixXd& v) const { return py::cast(v); }
  py::object operator()(const NestedResult& v) const {
    return ResultDict(*v.table, v.object);
  }
  py::object operator()(const NestedResults& v) const {
    py::list list;
    for (const void* object : v.objects) {
      list.append(ResultDict(*v.table, object));
    }
    return list;
  }
};

}  // namespace

py::object ResultValueToPython(const ResultValue& value) {
  return std::visit(ToPython{}, value);
}

py::dict ResultDict(const ResultTable& table, const void* object) {
  py::dict dict;
  for (const ResultField& field : table.fields()) {
    dict[field.name.c_str()] = ResultValueToPython(field.get(object));
  }
  return dict;
}

std::string ResultFieldDoc(const ResultField& field) {
  std::string doc = field.help;
  if (!field.unit.empty()) doc += " [" + field.unit + "]";
  return doc;
}

}  // namespace python
}  // namespace mlndt
