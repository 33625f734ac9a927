#pragma once
// The simulated motion of a run sampled at a fixed rate of plan time: joint positions, link
// poses and object poses, for the user's own plots and replays (the Python API's
// simulate(samples=...)).

#include <cstddef>
#include <string>
#include <vector>

#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::sim {

class Simulation;

/// Samples at plan times k / rate (k = 0, 1, ...), each taken at the first simulation step at
/// or after it. Arrays are flat, row-major, in the shapes given.
struct MotionSamples {
  double rate = 0.0;                    ///< [Hz]
  std::vector<double> times;            ///< [N] plan time of each sample [s]
  std::vector<std::string> robots;      ///< robot names, in world order
  std::vector<std::string> joints;      ///< the model's joint names in q order (arm, then fingers)
  std::vector<std::string> links;       ///< the model's link names
  std::vector<std::string> objects;     ///< object names, in world order
  std::vector<double> joint_positions;  ///< [N][robots][joints] [rad, m for fingers]
  /// [N][robots][links][7]: position x y z [m], then quaternion x y z w (w >= 0), world frame
  std::vector<double> link_poses;
  std::vector<double> object_poses;     ///< [N][objects][7]: as link_poses
  std::size_t count() const { return times.size(); }
};

/// Collects MotionSamples from a running simulation: call onStep after every step (a
/// RunOptions::on_step observer). Every robot of the world has the same model.
class MotionSampler {
 public:
  /// Throws std::invalid_argument unless 0 < rate <= 1 / the world's time step.
  MotionSampler(const core::World& world, const core::RobotSet& robots, double rate);
  void onStep(const Simulation& simulation, double plan_time);
  const MotionSamples& samples() const { return samples_; }
  MotionSamples take() { return std::move(samples_); }

 private:
  MotionSamples samples_;
};

}  // namespace dashbed::sim
