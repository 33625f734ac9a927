#pragma once
// The Python module dashbed._dashbed: one function per part binds its classes and functions
// (world, plan, simulation, stress, kinematics), and the conversions they share.

#include <memory>
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "core/plan.h"
#include "core/world_loader.h"

namespace dashbed::python {

namespace py = pybind11;

/// A loaded, validated world (robots' models and reach included), shared by the Python objects
/// that refer to it. Immutable.
struct WorldHandle {
  std::shared_ptr<const core::LoadedWorld> loaded;
  const core::World& world() const { return *loaded->world; }
};

/// A plan and the file it was read from or written to ("" for none): reports name it.
struct PlanHandle {
  std::shared_ptr<const core::Plan> plan;
  std::string file;
};

/// A JSON value as the Python value json.loads would give (dict keys in the document's order).
py::object toPython(const nlohmann::json& value);
py::object toPython(const nlohmann::ordered_json& value);

void bindErrors(py::module_& m);
void bindWorld(py::module_& m);
void bindPlan(py::module_& m);
void bindSimulation(py::module_& m);
void bindStress(py::module_& m);
void bindKinematics(py::module_& m);

}  // namespace dashbed::python
