#pragma once
// A timed multi-robot plan: one arm trajectory per robot, gripper commands and the actions
// (pick, place, handoff) they carry out. Written by the planner and the scripted-plan tool,
// executed by the simulator. File format: JSON, version kPlanFormatVersion (see README).

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_text.h"
#include "core/world.h"

namespace dashbed::core {

inline constexpr int kPlanFormatVersion = 1;

/// One timed point of an arm trajectory (in the spirit of trajectory_msgs/JointTrajectoryPoint).
struct TrajectoryPoint {
  double t = 0.0;                               ///< time from plan start [s]
  std::array<double, 6> q{};                    ///< arm joint positions [rad]
  std::optional<std::array<double, 6>> qd;      ///< joint velocities [rad/s]; interpolated when absent
};

/// The arm trajectory of one robot. Before the first point the robot holds the first point;
/// after the last it holds the last.
struct RobotTrajectory {
  std::string robot;
  std::array<std::string, 6> joint_names;  ///< the model's six arm joints, in q order
  std::vector<TrajectoryPoint> points;     ///< strictly increasing t
};

enum class GripperAction { kOpen, kClose };

struct GripperCommand {
  std::string robot;
  double t = 0.0;          ///< [s]
  GripperAction action = GripperAction::kOpen;
  double force = 0.0;      ///< closing force [N]; 0 = the world's controller.grip_force
};

enum class ActionType { kPick, kPlace, kHandoff };

/// What a stretch of the plan achieves; the simulator's monitor checks each action.
struct PlanAction {
  ActionType type = ActionType::kPick;
  std::string robot;     ///< pick/place: the robot; handoff: the giver
  std::string receiver;  ///< handoff only
  std::string object;
  /// place only: the goal region; empty for a place that sets the object aside on a stable
  /// surface, to be picked up there again (an intermediate placement)
  std::string region;
  double start = 0.0;    ///< [s] the gripper starts approaching
  double end = 0.0;      ///< [s] the action is complete (place: the gripper has released and retreated)
};

struct Plan {
  std::string world;          ///< name of the world the plan is for
  std::uint64_t seed = 0;     ///< seed of the planner run (0 for scripted plans)
  std::vector<RobotTrajectory> trajectories;
  std::vector<GripperCommand> gripper;   ///< sorted by time
  std::vector<PlanAction> actions;       ///< sorted by start time
  nlohmann::json statistics = nlohmann::json::object();  ///< planner statistics (free form)

  /// Time of the last trajectory point, gripper command or action end [s].
  double duration() const;
};

/// Bad plan input. The message names the file, the JSON pointer of the field and the problem,
/// e.g. "plan.json: /robots/0/points/3/t: times must increase (1.2 after 1.5)".
class PlanError : public InputError {
 public:
  using InputError::InputError;
};

/// Parses and checks the structure of a plan (types, required fields, version, increasing
/// times, known action types, finite numbers). Throws PlanError.
Plan parsePlanJson(std::string_view json_text, const std::string& file_name);

/// Reads a file and calls parsePlanJson. Throws PlanError (also when the file is unreadable).
Plan loadPlanFile(const std::filesystem::path& file);

/// Checks a plan against a world: robots, objects and regions exist; each robot has at most
/// one trajectory and its joint names match `arm_joint_names`; positions within
/// [lower, upper] and segment speeds within `max_velocity` (per joint, 1% slack); action
/// times inside the plan. Throws PlanError naming the JSON pointer of the offending field.
void validatePlan(const Plan& plan, const World& world, const std::array<std::string, 6>& arm_joint_names,
                  const std::array<double, 6>& lower, const std::array<double, 6>& upper,
                  const std::array<double, 6>& max_velocity, const std::string& file_name);

/// Checks what a plan must satisfy on its own, without a world: non-empty names, finite
/// numbers, times >= 0 and strictly increasing per robot, at least one point per robot, one
/// trajectory per robot, gripper commands sorted by time (one per robot and instant), forces
/// in [0, 185] N, actions sorted by start with end >= start, a handoff's receiver set and not
/// the giver, a region on place actions only. parsePlanJson and validatePlan call it; the
/// planner may call it before writing. Throws PlanError naming the JSON pointer the field
/// has (or would have) in the plan file.
void checkPlanStructure(const Plan& plan, const std::string& file_name);

/// Serialises a plan (deterministic: fixed key order, shortest round-trip numbers, 2-space
/// indent, arrays of numbers or strings on one line, trailing newline). Precondition: the
/// plan passes checkPlanStructure (a non-finite number would be written as null).
std::string writePlanJson(const Plan& plan);

/// Formats JSON the way plan files and reports are written: 2-space indent, objects and
/// arrays of containers one element per line, arrays of numbers / strings / booleans on one
/// line, shortest round-trip numbers, invalid UTF-8 replaced, trailing newline.
std::string formatJson(const nlohmann::ordered_json& value);

std::string_view toString(ActionType type);
std::string_view toString(GripperAction action);

}  // namespace dashbed::core
