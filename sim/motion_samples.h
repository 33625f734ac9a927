#pragma once
// The simulated motion of a run sampled at a fixed rate of plan time: joint positions, link
// poses and object poses, for the user's own plots and replays (the Python API's
// simulate(samples=...)).

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/robot_set.h"
#include "core/world.h"
#include "sim/run_plan.h"

namespace dashbed::sim {

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
  /// [N][robots]: the largest distance of an arm joint from its reference [rad]
  std::vector<double> tracking_error;
  /// [N][robots]: the largest |torque| / effort limit over the arm joints
  std::vector<double> effort_ratio;
  /// [N][robots]: the fingers' squeeze on objects, the mean of the two fingers' contact normal forces [N]
  std::vector<double> grip_force;
  std::size_t count() const { return times.size(); }
};

/// Collects MotionSamples from a running plan: call onStep after every step (a RunOptions::on_step
/// observer). Every robot of the world has the same model.
class MotionSampler {
 public:
  /// Throws std::invalid_argument unless 0 < rate <= 1 / the world's time step.
  MotionSampler(const core::World& world, const core::RobotSet& robots, double rate);
  void onStep(const StepState& step);
  const MotionSamples& samples() const { return samples_; }
  MotionSamples take() { return std::move(samples_); }

 private:
  MotionSamples samples_;
  std::array<double, 6> effort_limits_{};
  std::array<int, 2> finger_links_{-1, -1};  ///< the links the two finger joints move
};

}  // namespace dashbed::sim
