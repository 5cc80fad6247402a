// JSON objects of the jobs -> Python objects (numbers stay the decimal strings the
// jobs write; docs/python.md), shared by the module's binding files.
#pragma once

#include <viscor/jobs/json_fields.hpp>

#include <pybind11/pybind11.h>

namespace viscor::python {

/// The Python object of a JSON value: dict, list, str, bool, int, float or None.
inline pybind11::object to_python(const jobs::json& j) {
  namespace py = pybind11;
  using json = jobs::json;
  switch (j.type()) {
    case json::value_t::object: {
      py::dict d;
      for (const auto& [key, value] : j.items()) d[py::str(key)] = to_python(value);
      return d;
    }
    case json::value_t::array: {
      py::list l;
      for (const auto& value : j) l.append(to_python(value));
      return l;
    }
    case json::value_t::string: return py::str(j.get<std::string>());
    case json::value_t::boolean: return py::bool_(j.get<bool>());
    case json::value_t::number_integer: return py::int_(j.get<long long>());
    case json::value_t::number_unsigned: return py::int_(j.get<unsigned long long>());
    case json::value_t::number_float: return py::float_(j.get<double>());
    default: return py::none();
  }
}

/// Adds the one-shot jobs (exact, approx, scale, calibrate, dem, physical cor and
/// the physical -> scaled arrays of evaluate) to the module (command_bindings.cpp).
void bind_commands(pybind11::module_& m);

}  // namespace viscor::python
