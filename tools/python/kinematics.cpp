// dashbed.kin: forward and inverse kinematics of the UR5e + Hand-E, numpy in and out, as
// `dashbed kin fk / ik` compute them.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "core/asset_paths.h"
#include "core/kinematics.h"
#include "core/robot_model.h"
#include "core/ur_ik.h"
#include "tools/python/bindings.h"

namespace dashbed::python {
namespace {

/// The robot model and the pose of its root in the frame poses are given in: the model's
/// base_link, or the world at the robot's base when a world is given.
struct KinematicFrame {
  std::shared_ptr<const core::RobotModel> model;
  core::Pose X_RefRoot = core::Pose::Identity();
  std::optional<core::ArmConfig> home;
};

KinematicFrame frameOf(const std::optional<WorldHandle>& world, const std::string& robot) {
  if (!world) {
    if (!robot.empty()) throw std::invalid_argument("robot is for poses in a world: give world too");
    return {std::make_shared<const core::RobotModel>(core::RobotModel::fromUrdfFile(core::robotUrdfPath("ur5e_hande"))),
            core::Pose::Identity(), std::nullopt};
  }
  const core::World& w = world->world();
  if (w.robots.empty()) throw std::invalid_argument("world " + w.name + " has no robots");
  const core::RobotSpec* spec = robot.empty() ? &w.robots.front() : w.findRobot(robot);
  if (spec == nullptr) throw py::key_error("no robot '" + robot + "' in world " + w.name);
  const auto r = static_cast<std::size_t>(spec - w.robots.data());
  const core::RobotModel* model = (*world->loaded->robots)[r].model;
  // the model belongs to the world's robot set: keep the world alive with it
  return {std::shared_ptr<const core::RobotModel>(world->loaded, model), spec->X_WBase, spec->home};
}

/// The six arm angles of q: six values, or every joint of the model (arm, then fingers) as
/// simulate(samples=...) gives them. Throws std::invalid_argument for another size or a
/// non-finite angle.
core::ArmConfig armConfig(const Eigen::VectorXd& q, int model_positions, const char* what) {
  if (q.size() != 6 && q.size() != model_positions) {
    throw std::invalid_argument(std::string(what) + ": expected the six arm joint angles (or all " +
                                std::to_string(model_positions) + " joints), got " + std::to_string(q.size()) + " values");
  }
  if (!q.allFinite()) throw std::invalid_argument(std::string(what) + ": the angles must be finite");
  core::ArmConfig config{};
  for (int i = 0; i < 6; ++i) config[static_cast<std::size_t>(i)] = q[i];
  return config;
}

/// A 4 x 4 rigid transform, or std::invalid_argument.
core::Pose rigidPose(const Eigen::Matrix4d& matrix) {
  constexpr double kTolerance = 1e-6;
  const Eigen::Matrix3d R = matrix.topLeftCorner<3, 3>();
  const bool bottom_row = matrix.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1), kTolerance);
  if (!matrix.allFinite() || !bottom_row || !(R * R.transpose()).isIdentity(kTolerance) || R.determinant() < 0.0) {
    throw std::invalid_argument("ik: pose must be a 4 x 4 rigid transform (a rotation and a translation, last row 0 0 0 1)");
  }
  core::Pose X = core::Pose::Identity();
  X.matrix() = matrix;
  return X;
}

}  // namespace

void bindKinematics(py::module_& m) {
  py::module_ kin = m.def_submodule("kin", "Forward and inverse kinematics of a UR5e with a Robotiq Hand-E.");
  kin.def(
      "fk",
      [](const Eigen::VectorXd& q, const std::string& frame, std::optional<WorldHandle> world, const std::string& robot) {
        const KinematicFrame context = frameOf(world, robot);
        const int link = context.model->linkIndex(frame);
        if (link < 0) throw std::invalid_argument("the model has no link '" + frame + "'");
        const core::ArmConfig arm = armConfig(q, context.model->numPositions(), "fk");
        Eigen::VectorXd full = Eigen::VectorXd::Zero(context.model->numPositions());
        for (int i = 0; i < 6; ++i) full[i] = arm[static_cast<std::size_t>(i)];
        const core::Pose X = context.X_RefRoot * core::linkPoses(*context.model, full)[static_cast<std::size_t>(link)];
        return Eigen::Matrix4d(X.matrix());
      },
      py::arg("q"), py::arg("frame") = "tcp", py::arg("world") = py::none(), py::arg("robot") = "",
      "The pose (4 x 4) of a link (tcp, tool0, ...) at arm configuration q (6 angles [rad], or every joint as "
      "samples give them), in the model's "
      "base_link, or in the world at `robot`'s base (default: the first) when a world is given.");
  kin.def(
      "ik",
      [](const Eigen::Matrix4d& pose, const std::string& frame, std::optional<Eigen::VectorXd> seed,
         std::optional<WorldHandle> world, const std::string& robot) {
        if (frame != "tcp" && frame != "tool0") throw std::invalid_argument("IK is available for the frames tcp and tool0");
        const KinematicFrame context = frameOf(world, robot);
        const core::UrArmIk ik(*context.model, core::kUr5eDh, frame);
        const core::Pose X_RefT = rigidPose(pose);
        const core::ArmConfig start = seed ? armConfig(*seed, context.model->numPositions(), "ik seed") : context.home.value_or(core::ArmConfig{});
        const std::vector<core::ArmConfig> solutions = ik.solveNearest(context.X_RefRoot.inverse() * X_RefT, start);
        py::array_t<double> out({static_cast<py::ssize_t>(solutions.size()), py::ssize_t{6}});
        auto view = out.mutable_unchecked<2>();
        for (std::size_t s = 0; s < solutions.size(); ++s) {
          for (std::size_t j = 0; j < 6; ++j) view(static_cast<py::ssize_t>(s), static_cast<py::ssize_t>(j)) = solutions[s][j];
        }
        return out;
      },
      py::arg("pose"), py::arg("frame") = "tcp", py::arg("seed") = py::none(), py::arg("world") = py::none(),
      py::arg("robot") = "",
      "Every arm configuration (up to 8, within the joint limits) putting `frame` (tcp or tool0) at `pose` (4 x 4, "
      "in base_link or, with a world, in the world), as an array (K, 6) [rad], nearest to `seed` (default: the "
      "robot's home, or zeros) first. K = 0 when the pose is out of reach.");
}

}  // namespace dashbed::python
