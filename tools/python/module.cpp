// dashbed._dashbed: the compiled part of the Python package (tools/python/dashbed/__init__.py
// re-exports it).

#include "tools/python/bindings.h"

namespace dashbed::python {
namespace {

template <class Json>
py::object jsonToPython(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return py::none();
    case Json::value_t::boolean:
      return py::bool_(value.template get<bool>());
    case Json::value_t::number_integer:
      return py::int_(value.template get<std::int64_t>());
    case Json::value_t::number_unsigned:
      return py::int_(value.template get<std::uint64_t>());
    case Json::value_t::number_float:
      return py::float_(value.template get<double>());
    case Json::value_t::string:
      return py::str(value.template get_ref<const std::string&>());
    case Json::value_t::array: {
      py::list list;
      for (const auto& item : value) list.append(jsonToPython(item));
      return list;
    }
    case Json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = jsonToPython(item);
      return dict;
    }
    default:
      break;
  }
  throw std::invalid_argument("a JSON value Python has no type for");
}

}  // namespace

py::object toPython(const nlohmann::json& value) { return jsonToPython(value); }
py::object toPython(const nlohmann::ordered_json& value) { return jsonToPython(value); }

}  // namespace dashbed::python

PYBIND11_MODULE(_dashbed, m) {
  using namespace dashbed::python;
  m.doc() = "dashbed: DaSH multi-robot task and motion planning, checked in a Bullet simulation";
  bindErrors(m);
  bindWorld(m);
  bindPlan(m);
  bindSimulation(m);
  bindStress(m);
  bindKinematics(m);
}
