#include "python/json_from_python.h"

#include <limits>

namespace baize::python {
namespace {

namespace py = pybind11;

std::string typeName(py::handle value) {
  return py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>();
}

std::string keyPath(const std::string& where, const std::string& key) {
  return where.empty() ? key : where + "." + key;
}

nlohmann::json integerFrom(py::handle value, const std::string& where) {
  try {
    return value.cast<long long>();
  } catch (const py::cast_error&) {
    throw py::value_error(where + " = " + py::str(value).cast<std::string>() +
                          " is not allowed: an integer must fit in 64 bits");
  }
}

}  // namespace

nlohmann::json jsonFromPython(py::handle value, const std::string& where) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::int_>(value)) return integerFrom(value, where);
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  const py::module_ numpy = py::module_::import("numpy");
  if (py::isinstance(value, numpy.attr("bool_"))) return value.cast<bool>();
  if (py::isinstance(value, numpy.attr("integer"))) return integerFrom(value, where);
  if (py::isinstance(value, numpy.attr("floating"))) return value.cast<double>();
  if (py::isinstance<py::dict>(value)) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& item : py::reinterpret_borrow<py::dict>(value)) {
      if (!py::isinstance<py::str>(item.first)) {
        throw py::type_error(where + ": the key " + py::repr(item.first).cast<std::string>() +
                             " is a " + typeName(item.first) + "; keys must be str");
      }
      const std::string key = item.first.cast<std::string>();
      object[key] = jsonFromPython(item.second, keyPath(where, key));
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value) ||
      py::isinstance(value, numpy.attr("ndarray"))) {
    nlohmann::json array = nlohmann::json::array();
    int index = 0;
    for (const py::handle element : value) {
      array.push_back(jsonFromPython(element, where + "[" + std::to_string(index++) + "]"));
    }
    return array;
  }
  throw py::type_error((where.empty() ? std::string("the value") : where) + " is a " +
                       typeName(value) +
                       "; allowed: dict, list, tuple, str, int, float, bool, None or numpy numbers");
}

}  // namespace baize::python
