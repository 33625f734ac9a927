// dashbed kin fk / kin ik: forward and inverse kinematics of a UR5e + Hand-E, for authoring worlds.

#include <cmath>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/asset_paths.h"
#include "core/kinematics.h"
#include "core/robot_model.h"
#include "core/ur_ik.h"
#include "core/world_io.h"
#include "tools/cli/cli_support.h"

namespace dashbed::tools {
namespace {

using core::ArmConfig;
using core::Pose;

struct KinOptions {
  std::string model = "ur5e_hande";
  std::string frame = "tcp";
  std::string world_file;
  std::string robot;
  bool json = false;
  bool degrees = false;
};

/// The model and the pose of its root in the reference frame (identity, or the robot's base
/// pose when a world and robot are given).
struct KinContext {
  core::RobotModel model;
  Pose X_RefRoot = Pose::Identity();
  std::string reference = "base_link";
  std::optional<ArmConfig> home;
};

KinContext makeContext(const KinOptions& options) {
  std::string model_name = options.model;
  KinContext context{core::RobotModel::fromUrdfFile(core::robotUrdfPath(options.model)), Pose::Identity(),
                     "base_link", std::nullopt};
  if (options.world_file.empty()) return context;
  const core::World world = core::loadWorldFile(options.world_file);
  const core::RobotSpec* robot =
      options.robot.empty() ? (world.robots.empty() ? nullptr : &world.robots.front()) : world.findRobot(options.robot);
  if (robot == nullptr) throw CLI::ValidationError("--robot", "no robot '" + options.robot + "' in " + options.world_file);
  if (robot->model != model_name) {
    context.model = core::RobotModel::fromUrdfFile(core::robotUrdfPath(robot->model));
  }
  context.X_RefRoot = robot->X_WBase;
  context.reference = "world (robot " + robot->name + ")";
  context.home = robot->home;
  return context;
}

nlohmann::json poseJson(const Pose& X) {
  const Eigen::Quaterniond quat(X.linear());
  const Eigen::Vector3d rpy = core::rpyFromRotation(X.linear());
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({X.linear()(r, 0), X.linear()(r, 1), X.linear()(r, 2)});
  const double w_sign = quat.w() < 0 ? -1.0 : 1.0;  // w >= 0: one sign for q and -q, the same rotation
  return {{"position", {X.translation().x(), X.translation().y(), X.translation().z()}},
          {"rotation_rows", rows},
          {"quaternion_xyzw", {w_sign * quat.x(), w_sign * quat.y(), w_sign * quat.z(), w_sign * quat.w()}},
          {"rpy", {rpy.x(), rpy.y(), rpy.z()}}};
}

void printPose(std::ostream& out, const nlohmann::json& pose) {
  out << std::fixed << std::setprecision(9);
  const auto list = [&](const nlohmann::json& v) {
    for (const auto& x : v) out << " " << std::setw(13) << x.get<double>();
    out << "\n";
  };
  out << "  position [m]     :";
  list(pose["position"]);
  out << "  rotation (rows)  :";
  list(pose["rotation_rows"][0]);
  out << "                    ";
  list(pose["rotation_rows"][1]);
  out << "                    ";
  list(pose["rotation_rows"][2]);
  out << "  quaternion xyzw  :";
  list(pose["quaternion_xyzw"]);
  out << "  rpy [rad]        :";
  list(pose["rpy"]);
}

double angleIn(double value, bool degrees) { return degrees ? value * std::numbers::pi / 180.0 : value; }

void runFk(const KinOptions& options, const std::vector<double>& q_in) {
  const KinContext context = makeContext(options);
  const int link = context.model.linkIndex(options.frame);
  if (link < 0) throw CLI::ValidationError("--frame", "the model has no link '" + options.frame + "'");
  Eigen::VectorXd q = Eigen::VectorXd::Zero(context.model.numPositions());
  for (std::size_t i = 0; i < q_in.size() && i < 6; ++i) q[static_cast<Eigen::Index>(i)] = angleIn(q_in[i], options.degrees);
  const Pose X = context.X_RefRoot * core::linkPoses(context.model, q)[link];
  const nlohmann::json pose = poseJson(X);
  if (options.json) {
    nlohmann::json out = {{"frame", options.frame}, {"reference", context.reference}, {"q", q_in}, {"pose", pose}};
    std::cout << jsonText(out) << "\n";
    return;
  }
  std::cout << "frame " << options.frame << " in " << context.reference << ":\n";
  printPose(std::cout, pose);
}

void runIk(const KinOptions& options, const std::vector<double>& xyz, const std::vector<double>& rpy,
           const std::vector<double>& quat, const std::vector<double>& seed_in) {
  const KinContext context = makeContext(options);
  if (options.frame != "tcp" && options.frame != "tool0") {
    throw CLI::ValidationError("--frame", "IK is available for the frames tcp and tool0");
  }
  const core::UrArmIk ik(context.model, core::kUr5eDh, options.frame);
  Pose X_RefT = Pose::Identity();
  X_RefT.translation() = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
  if (!quat.empty()) {
    X_RefT.linear() = Eigen::Quaterniond(quat[3], quat[0], quat[1], quat[2]).normalized().toRotationMatrix();
  } else {
    if (rpy.empty()) throw CLI::ValidationError("ik", "give the orientation with --rpy R P Y or --quat X Y Z W");
    X_RefT.linear() = core::rotationFromRpy(Eigen::Vector3d(angleIn(rpy[0], options.degrees),
                                                            angleIn(rpy[1], options.degrees),
                                                            angleIn(rpy[2], options.degrees)));
  }
  ArmConfig seed = context.home.value_or(ArmConfig{});
  if (!seed_in.empty()) {
    for (int i = 0; i < 6; ++i) seed[i] = angleIn(seed_in[static_cast<std::size_t>(i)], options.degrees);
  }
  const std::vector<ArmConfig> solutions = ik.solveNearest(context.X_RefRoot.inverse() * X_RefT, seed);
  const double scale = options.degrees ? 180.0 / std::numbers::pi : 1.0;
  if (options.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const ArmConfig& q : solutions) {
      nlohmann::json row = nlohmann::json::array();
      for (double v : q) row.push_back(v * scale);
      list.push_back(row);
    }
    nlohmann::json out = {{"frame", options.frame},   {"reference", context.reference},
                          {"target", poseJson(X_RefT)}, {"seed", seed},
                          {"units", options.degrees ? "deg" : "rad"}, {"solutions", list}};
    std::cout << jsonText(out) << "\n";
  } else {
    std::cout << solutions.size() << " solution(s) for frame " << options.frame << " in " << context.reference
              << ", nearest to the seed first (" << (options.degrees ? "deg" : "rad") << "):\n";
    std::cout << std::fixed << std::setprecision(6);
    for (const ArmConfig& q : solutions) {
      std::cout << " ";
      for (double v : q) std::cout << " " << std::setw(11) << v * scale;
      std::cout << "\n";
    }
  }
  if (solutions.empty()) {
    if (!options.json) std::cerr << "dashbed kin ik: the pose is out of reach within the joint limits\n";
    throw CLI::RuntimeError(kExitInfeasible);
  }
}

void addCommonOptions(CLI::App& sub, KinOptions& options) {
  sub.add_option("--model", options.model, "robot model (assets/<model>.urdf)")->capture_default_str();
  sub.add_option("--frame", options.frame, "link whose pose is computed (tcp, tool0, ...)")->capture_default_str();
  sub.add_option("--world", options.world_file, "express poses in this world's frame, at a robot's base");
  sub.add_option("--robot", options.robot, "robot of --world (default: the first)");
  sub.add_flag("--json", options.json, "print JSON");
  sub.add_flag("--degrees", options.degrees, "angles in degrees instead of radians");
}

}  // namespace

void addKinCommand(CLI::App& app) {
  CLI::App* kin = app.add_subcommand("kin", "Forward and inverse kinematics of a UR5e + Hand-E");
  kin->require_subcommand(1);

  auto fk_options = std::make_shared<KinOptions>();
  auto q = std::make_shared<std::vector<double>>();
  CLI::App* fk = kin->add_subcommand("fk", "Configuration -> pose of a frame (default: the TCP in base_link)");
  fk->add_option("q", *q, "the six arm joint angles")->required()->expected(6);
  addCommonOptions(*fk, *fk_options);
  fk->callback([fk_options, q] { runGuarded("kin fk", [&] { runFk(*fk_options, *q); }); });

  auto ik_options = std::make_shared<KinOptions>();
  auto xyz = std::make_shared<std::vector<double>>();
  auto rpy = std::make_shared<std::vector<double>>();
  auto quat = std::make_shared<std::vector<double>>();
  auto seed = std::make_shared<std::vector<double>>();
  CLI::App* ik = kin->add_subcommand(
      "ik", "Pose -> every arm configuration reaching it (up to 8), nearest to the seed first. Exit 4 if none.");
  ik->add_option("xyz", *xyz, "position of the frame [m]")->required()->expected(3);
  auto* rpy_opt = ik->add_option("--rpy", *rpy, "orientation as URDF roll pitch yaw")->expected(3);
  ik->add_option("--quat", *quat, "orientation as quaternion x y z w")->expected(4)->excludes(rpy_opt);
  ik->add_option("--seed", *seed, "seed configuration (default: the robot's home, or zeros)")->expected(6);
  addCommonOptions(*ik, *ik_options);
  ik->callback([=] { runGuarded("kin ik", [&] { runIk(*ik_options, *xyz, *rpy, *quat, *seed); }); });
}

}  // namespace dashbed::tools
