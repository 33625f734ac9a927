// dashbed.World: a world file loaded and checked (syntax, geometry, the robots' models and
// reach), read-only; and the scenario generators that make one.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "core/asset_paths.h"
#include "core/world_io.h"
#include "tools/python/bindings.h"
#include "tools/scenarios/scenarios.h"

namespace dashbed::python {
namespace {

WorldHandle loadedWorld(core::LoadedWorld loaded) {
  return WorldHandle{std::make_shared<const core::LoadedWorld>(std::move(loaded))};
}

/// A pose as a 4 x 4 homogeneous matrix.
Eigen::Matrix4d matrixOf(const core::Pose& X) { return X.matrix(); }

py::dict colorOf(const core::Color& c) {
  py::dict d;
  d["r"] = c.r;
  d["g"] = c.g;
  d["b"] = c.b;
  return d;
}

/// A parsed world made in memory (a generator's), through its YAML as `dashbed gen` writes it.
WorldHandle generatedWorld(const core::World& world, const std::string& name) {
  return loadedWorld(core::validateWorld(core::parseWorldYaml(core::writeWorldYaml(world), name)));
}

std::string fixtureTypeName(core::FixtureType type) {
  switch (type) {
    case core::FixtureType::kBin:
      return "bin";
    case core::FixtureType::kShelf:
      return "shelf";
    case core::FixtureType::kBox:
      break;
  }
  return "box";
}

}  // namespace

void bindWorld(py::module_& m) {
  py::class_<core::RobotSpec>(m, "Robot", "A robot placed in the world.")
      .def_readonly("name", &core::RobotSpec::name)
      .def_readonly("model", &core::RobotSpec::model, "robot model: assets/<model>.urdf")
      .def_property_readonly("base_pose", [](const core::RobotSpec& r) { return matrixOf(r.X_WBase); },
                             "pose of the base link in the world (4 x 4)")
      .def_readonly("home", &core::RobotSpec::home, "home configuration of the six arm joints [rad]")
      .def("__repr__", [](const core::RobotSpec& r) { return "<dashbed.Robot " + r.name + ">"; });

  py::class_<core::ObjectSpec>(m, "Object", "A movable box-shaped object at its start pose.")
      .def_readonly("name", &core::ObjectSpec::name)
      .def_property_readonly("pose", [](const core::ObjectSpec& o) { return matrixOf(o.X_WO); },
                             "start pose of the object's centre in the world (4 x 4)")
      .def_property_readonly("position", [](const core::ObjectSpec& o) -> Eigen::Vector3d { return o.X_WO.translation(); },
                             "start position of the centre [m]")
      .def_readonly("size", &core::ObjectSpec::size, "edge lengths [m]")
      .def_readonly("mass", &core::ObjectSpec::mass, "[kg]")
      .def_readonly("friction", &core::ObjectSpec::friction, "Coulomb coefficient")
      .def_readonly("object_class", &core::ObjectSpec::object_class, "class name ('' for none)")
      .def_property_readonly("color", [](const core::ObjectSpec& o) { return colorOf(o.color); })
      .def("__repr__", [](const core::ObjectSpec& o) { return "<dashbed.Object " + o.name + ">"; });

  py::class_<core::Goal>(m, "Goal", "One object, or every object of a class, must end inside a region.")
      .def_readonly("object", &core::Goal::object, "the object ('' for a class goal)")
      .def_readonly("object_class", &core::Goal::object_class, "the class ('' for an object goal)")
      .def_readonly("region", &core::Goal::region);

  py::class_<core::Region>(m, "Region", "A goal region: an upright box standing on its floor.")
      .def_readonly("name", &core::Region::name)
      .def_property_readonly("pose", [](const core::Region& r) { return matrixOf(r.X_WR); },
                             "pose of the centre of the region's floor (4 x 4)")
      .def_readonly("size", &core::Region::size, "[m]")
      .def_readonly("fixture", &core::Region::fixture, "the bin that made it, or ''");

  py::class_<core::FixtureSpec>(m, "Fixture", "A static fixture: box, bin or shelf.")
      .def_readonly("name", &core::FixtureSpec::name)
      .def_property_readonly("type", [](const core::FixtureSpec& f) { return fixtureTypeName(f.type); })
      .def_property_readonly("pose", [](const core::FixtureSpec& f) { return matrixOf(f.X_WF); },
                             "pose of the centre of the bottom face (4 x 4)")
      .def_readonly("size", &core::FixtureSpec::size, "outer size [m]");

  py::class_<WorldHandle>(m, "World",
                          "A world: robots, fixtures, objects and goals, loaded and checked (syntax, geometry, "
                          "reach). Read-only.")
      .def_static("load", [](const std::filesystem::path& path) { return loadedWorld(core::loadWorld(path)); },
                  py::arg("path"),
                  "Read and check a world file (YAML). Raises WorldError with file, line and field.")
      .def_static(
          "from_yaml",
          [](const std::string& text, const std::string& name) {
            return loadedWorld(core::validateWorld(core::parseWorldYaml(text, name)));
          },
          py::arg("text"), py::arg("name") = "<memory>",
          "Read and check a world from YAML text; `name` stands for the file in messages.")
      .def_static("default", [] { return loadedWorld(core::loadWorld(core::defaultWorldPath())); },
                  "The built-in default world (worlds/default.yaml).")
      .def_property_readonly("name", [](const WorldHandle& w) { return w.world().name; })
      .def_property_readonly("description", [](const WorldHandle& w) { return w.world().description; })
      .def_property_readonly("file", [](const WorldHandle& w) { return w.world().source_file; },
                             "the file it was read from ('' when made in memory)")
      .def_property_readonly("robots", [](const WorldHandle& w) { return w.world().robots; })
      .def_property_readonly("objects", [](const WorldHandle& w) { return w.world().objects; })
      .def_property_readonly("goals", [](const WorldHandle& w) { return w.world().goals; })
      .def_property_readonly("regions", [](const WorldHandle& w) { return w.world().regions; },
                             "written regions and those of the bins")
      .def_property_readonly("fixtures", [](const WorldHandle& w) { return w.world().fixtures; })
      .def_property_readonly("time_step", [](const WorldHandle& w) { return w.world().physics.time_step; },
                             "the simulation's fixed step [s]")
      .def_property_readonly("grip_force", [](const WorldHandle& w) { return w.world().controller.grip_force; },
                             "the Hand-E's closing force [N]")
      .def("goal_region", [](const WorldHandle& w, const std::string& object) -> py::object {
            const core::ObjectSpec* spec = w.world().findObject(object);
            if (spec == nullptr) throw py::key_error("no object '" + object + "' in world " + w.world().name);
            const core::Region* region = w.world().goalRegionOf(*spec);
            return region == nullptr ? py::object(py::none()) : py::object(py::str(region->name));
          }, py::arg("object"), "The region an object must end in, or None.")
      .def("to_yaml", [](const WorldHandle& w) { return core::writeWorldYaml(w.world()); },
           "The world file's text (what `dashbed gen` writes).")
      .def("__repr__", [](const WorldHandle& w) {
        return "<dashbed.World " + w.world().name + ": " + std::to_string(w.world().robots.size()) + " robots, " +
               std::to_string(w.world().objects.size()) + " objects>";
      });

  m.def(
      "gen_sort",
      [](int robots, int cubes, int classes, const std::string& start, const std::string& layout, std::uint64_t seed) {
        tools::SortingParams params;
        params.robots = robots;
        params.cubes = cubes;
        params.classes = classes;
        params.start = tools::parseStartLayout(start);
        params.layout = tools::parseRobotLayout(layout);
        params.seed = seed;
        return generatedWorld(tools::generateSorting(params), "<gen sort>");
      },
      py::arg("robots") = 2, py::arg("cubes") = 4, py::arg("classes") = 4, py::arg("start") = "cross",
      py::arg("layout") = "paper", py::arg("seed") = 1,
      "The sorting scenario, as `dashbed gen sort` makes it: cubes of colour classes on a table, one bin per "
      "class. start: cross or random; layout: paper, rows or ring.");
  m.def(
      "gen_shelf",
      [](int objects, std::uint64_t seed) {
        tools::ShelvingParams params;
        params.objects = objects;
        params.seed = seed;
        return generatedWorld(tools::generateShelving(params), "<gen shelf>");
      },
      py::arg("objects") = 4, py::arg("seed") = 1,
      "The shelving scenario, as `dashbed gen shelf` makes it: pairs of objects for the back and front slots of a "
      "shelf.");
}

}  // namespace dashbed::python
