#include "sim/render/scene_state.h"

#include <stdexcept>
#include <string>

#include "core/kinematics.h"
#include "sim/simulation.h"

namespace dashbed::render {

SceneState captureScene(const sim::Simulation& simulation) {
  const core::World& world = simulation.world();
  const core::RobotSet& robots = simulation.robots();
  SceneState state;
  state.time = simulation.time();
  state.link_poses.resize(robots.size());
  for (std::size_t r = 0; r < robots.size(); ++r) {
    // one forward-kinematics pass per robot from the simulated joint positions, placed at
    // the base: the same poses Simulation::linkPose returns link by link
    std::vector<core::Pose> X_RL;
    core::linkPoses(*robots[r].model, simulation.jointPositions(static_cast<int>(r)), X_RL);
    state.link_poses[r].reserve(X_RL.size());
    for (const core::Pose& X : X_RL) state.link_poses[r].push_back(robots[r].spec->X_WBase * X);
  }
  state.object_poses.reserve(world.objects.size());
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    state.object_poses.push_back(simulation.objectPose(static_cast<int>(o)));
  }
  return state;
}

SceneState sceneFromConfigurations(const core::World& world, const core::RobotSet& robots,
                                   const std::vector<Eigen::VectorXd>& q, const std::vector<core::Pose>& X_WO,
                                   double time) {
  if (q.size() != robots.size()) {
    throw std::invalid_argument("sceneFromConfigurations: " + std::to_string(q.size()) + " configurations for " +
                                std::to_string(robots.size()) + " robots");
  }
  if (X_WO.size() != world.objects.size()) {
    throw std::invalid_argument("sceneFromConfigurations: " + std::to_string(X_WO.size()) + " object poses for " +
                                std::to_string(world.objects.size()) + " objects");
  }
  SceneState state;
  state.time = time;
  state.link_poses.resize(robots.size());
  for (std::size_t r = 0; r < robots.size(); ++r) {
    const std::vector<core::Pose> X_RL = core::linkPoses(*robots[r].model, q[r]);
    for (const core::Pose& X : X_RL) state.link_poses[r].push_back(robots[r].spec->X_WBase * X);
  }
  state.object_poses = X_WO;
  return state;
}

SceneState sceneAtHome(const core::World& world, const core::RobotSet& robots) {
  std::vector<Eigen::VectorXd> q;
  for (const core::PlacedRobot& robot : robots.robots()) {
    const core::RobotModel& model = *robot.model;
    Eigen::VectorXd q_robot = Eigen::VectorXd::Zero(model.numPositions());
    for (int i = 0; i < 6 && i < model.numPositions(); ++i) q_robot[i] = robot.spec->home[i];
    // finger joints at their upper limit: open, as the simulation starts
    for (int i = 6; i < model.numPositions(); ++i) q_robot[i] = model.joints()[model.movableJoints()[i]].upper;
    q.push_back(std::move(q_robot));
  }
  std::vector<core::Pose> X_WO;
  for (const core::ObjectSpec& object : world.objects) X_WO.push_back(object.X_WO);
  return sceneFromConfigurations(world, robots, q, X_WO);
}

}  // namespace dashbed::render
