// Python exceptions for dashbed's errors: a reader's error (world, plan, report, ...) becomes
// dashbed.InputError or a subclass, carrying file, line, column, field and problem.

#include "core/world_io.h"
#include "sim/report.h"
#include "tools/planning/run_planner.h"
#include "tools/python/bindings.h"

namespace dashbed::python {
namespace {

/// Raises `type` with the message and the error's parts as attributes (None when unknown).
void raise(const py::object& type, const core::InputError& error) {
  py::object exception = type(py::str(error.what()));
  const core::SourceLocation& where = error.where();
  exception.attr("file") = where.file.empty() ? py::object(py::none()) : py::object(py::str(where.file));
  exception.attr("line") = where.line > 0 ? py::object(py::int_(where.line)) : py::object(py::none());
  exception.attr("column") = where.column > 0 ? py::object(py::int_(where.column)) : py::object(py::none());
  exception.attr("field") = error.field().empty() ? py::object(py::none()) : py::object(py::str(error.field()));
  exception.attr("problem") = py::str(error.problem().empty() ? std::string(error.what()) : error.problem());
  PyErr_SetObject(type.ptr(), exception.ptr());
}

}  // namespace

void bindErrors(py::module_& m) {
  // created once, kept for the translator (the module lives as long as the interpreter)
  static py::exception<core::InputError> input_error(
      m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input: a world, plan, report or other file dashbed cannot use. Attributes: file, line, column "
      "(None when unknown), field (a world file's path such as objects[2].pose, or a JSON pointer), problem.";
  static py::exception<core::WorldError> world_error(m, "WorldError", input_error.ptr());
  world_error.doc() = "A world that cannot be read or used (syntax, geometry, reach).";
  static py::exception<core::PlanError> plan_error(m, "PlanError", input_error.ptr());
  plan_error.doc() = "A plan that cannot be read or does not fit its world.";
  static py::exception<sim::ReportError> report_error(m, "ReportError", input_error.ptr());
  report_error.doc() = "A report file that cannot be read.";

  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const core::WorldError& e) {
      raise(world_error, e);
    } catch (const core::PlanError& e) {
      raise(plan_error, e);
    } catch (const sim::ReportError& e) {
      raise(report_error, e);
    } catch (const core::InputError& e) {
      raise(input_error, e);
    }
  });
}

}  // namespace dashbed::python
