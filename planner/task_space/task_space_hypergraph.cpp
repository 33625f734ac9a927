#include "planner/task_space/task_space_hypergraph.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dashbed::planner {
namespace {

// one allowed action, before vertex ids exist
struct Action {
  TransitionKind kind;
  int robot;
  int object;
  int receiver;
  bool aside = false;  ///< at the object's set-aside site
};

void checkRobotList(const std::vector<int>& robots, int num_robots, const char* field, std::size_t object) {
  std::vector<bool> seen(static_cast<std::size_t>(num_robots), false);
  for (const int r : robots) {
    if (r < 0 || r >= num_robots) {
      throw std::invalid_argument("AllowedTransitions: " + std::string(field) + "[" + std::to_string(object) +
                                  "] names robot " + std::to_string(r) + " of " + std::to_string(num_robots));
    }
    if (seen[r]) {
      throw std::invalid_argument("AllowedTransitions: " + std::string(field) + "[" + std::to_string(object) +
                                  "] names robot " + std::to_string(r) + " twice");
    }
    seen[r] = true;
  }
}

std::vector<std::string> defaultNames(char prefix, int count) {
  std::vector<std::string> names;
  for (int i = 0; i < count; ++i) names.push_back(prefix + std::to_string(i));
  return names;
}

}  // namespace

const char* toString(TaskElementKind kind) {
  switch (kind) {
    case TaskElementKind::kRobotAlone: return "robot";
    case TaskElementKind::kObjectResting: return "object";
    case TaskElementKind::kRobotHolding: return "holding";
  }
  return "?";
}

const char* toString(TransitionKind kind) {
  switch (kind) {
    case TransitionKind::kPick: return "pick";
    case TransitionKind::kPlace: return "place";
    case TransitionKind::kHandoff: return "handoff";
  }
  return "?";
}

AllowedTransitions AllowedTransitions::everything(int robots, int objects) {
  AllowedTransitions allowed;
  allowed.robots = robots;
  allowed.objects = objects;
  std::vector<int> all;
  for (int r = 0; r < robots; ++r) all.push_back(r);
  allowed.reach.start.assign(static_cast<std::size_t>(std::max(objects, 0)), all);
  allowed.reach.goal = allowed.reach.start;
  allowed.handoff.assign(static_cast<std::size_t>(std::max(robots, 0)),
                         std::vector<bool>(static_cast<std::size_t>(std::max(robots, 0)), true));
  return allowed;
}

void AllowedTransitions::validate() const {
  if (robots < 0 || objects < 0) {
    throw std::invalid_argument("AllowedTransitions: robots and objects must be >= 0");
  }
  const auto m = static_cast<std::size_t>(objects), n = static_cast<std::size_t>(robots);
  if (reach.start.size() != m || reach.goal.size() != m) {
    throw std::invalid_argument("AllowedTransitions: reach.start and reach.goal need one entry per object (" +
                                std::to_string(objects) + "), got " + std::to_string(reach.start.size()) + " and " +
                                std::to_string(reach.goal.size()));
  }
  if (!aside.empty() && aside.size() != m) {
    throw std::invalid_argument("AllowedTransitions: aside needs no entry or one per object (" + std::to_string(objects) +
                                "), got " + std::to_string(aside.size()));
  }
  for (std::size_t o = 0; o < m; ++o) {
    checkRobotList(reach.start[o], robots, "reach.start", o);
    checkRobotList(reach.goal[o], robots, "reach.goal", o);
    if (!aside.empty()) checkRobotList(aside[o], robots, "aside", o);
  }
  if (handoff.size() != n) {
    throw std::invalid_argument("AllowedTransitions: the handoff matrix needs " + std::to_string(robots) +
                                " rows, got " + std::to_string(handoff.size()));
  }
  for (std::size_t r = 0; r < n; ++r) {
    if (handoff[r].size() != n) {
      throw std::invalid_argument("AllowedTransitions: handoff row " + std::to_string(r) + " has " +
                                  std::to_string(handoff[r].size()) + " entries, expected " +
                                  std::to_string(robots));
    }
  }
}

TaskSpaceHypergraph::TaskSpaceHypergraph(const AllowedTransitions& allowed)
    : TaskSpaceHypergraph(allowed, defaultNames('r', std::max(allowed.robots, 0)),
                          defaultNames('o', std::max(allowed.objects, 0))) {}

TaskSpaceHypergraph::TaskSpaceHypergraph(int robots, int objects, const core::ReachMap& reach,
                                         const std::vector<std::vector<bool>>& overlap)
    : TaskSpaceHypergraph(AllowedTransitions{robots, objects, reach, overlap, {}}) {}

TaskSpaceHypergraph::TaskSpaceHypergraph(const AllowedTransitions& allowed, std::vector<std::string> robot_names,
                                         std::vector<std::string> object_names)
    : allowed_(allowed), robot_names_(std::move(robot_names)), object_names_(std::move(object_names)) {
  allowed_.validate();
  build();
}

TaskSpaceHypergraph TaskSpaceHypergraph::fromWorld(const core::World& world, const core::RobotSet& robots,
                                                   const core::ReachMap& reach) {
  return fromWorld(world, robots, reach, {});
}

TaskSpaceHypergraph TaskSpaceHypergraph::fromWorld(const core::World& world, const core::RobotSet& robots,
                                                   const core::ReachMap& reach,
                                                   const std::vector<std::vector<int>>& aside) {
  if (robots.size() != world.robots.size()) {
    throw std::invalid_argument("TaskSpaceHypergraph::fromWorld: the robot set has " + std::to_string(robots.size()) +
                                " robots, the world " + std::to_string(world.robots.size()));
  }
  AllowedTransitions allowed;
  allowed.robots = static_cast<int>(robots.size());
  allowed.objects = static_cast<int>(world.objects.size());
  allowed.reach = reach;
  allowed.aside = aside;
  allowed.handoff.assign(robots.size(), std::vector<bool>(robots.size(), false));
  // a handoff zone is a symmetric property: ask once per pair
  for (std::size_t a = 0; a < robots.size(); ++a) {
    for (std::size_t b = a + 1; b < robots.size(); ++b) {
      const bool overlap = core::handoffZone(world, robots[a], robots[b]).has_value();
      allowed.handoff[a][b] = overlap;
      allowed.handoff[b][a] = overlap;
    }
  }
  std::vector<std::string> robot_names, object_names;
  for (const auto& robot : world.robots) robot_names.push_back(robot.name);
  for (const auto& object : world.objects) object_names.push_back(object.name);
  return TaskSpaceHypergraph(allowed, std::move(robot_names), std::move(object_names));
}

void TaskSpaceHypergraph::build() {
  const int n = allowed_.robots, m = allowed_.objects;
  const auto holdingIndex = [m](int r, int o) { return static_cast<std::size_t>(r) * m + o; };

  // candidate actions in canonical order: picks, places by (robot, object); handoffs by
  // (object, giver, receiver)
  std::vector<Action> candidates;
  for (int r = 0; r < n; ++r) {
    for (int o = 0; o < m; ++o) {
      const auto& starts = allowed_.reach.start[o];
      if (std::find(starts.begin(), starts.end(), r) != starts.end()) {
        candidates.push_back({TransitionKind::kPick, r, o, -1});
      }
    }
  }
  for (int r = 0; r < n; ++r) {
    for (int o = 0; o < m; ++o) {
      const auto& goals = allowed_.reach.goal[o];
      if (std::find(goals.begin(), goals.end(), r) != goals.end()) {
        candidates.push_back({TransitionKind::kPlace, r, o, -1});
      }
    }
  }
  for (int o = 0; o < m; ++o) {
    for (int giver = 0; giver < n; ++giver) {
      for (int receiver = 0; receiver < n; ++receiver) {
        if (giver != receiver && allowed_.handoff[giver][receiver]) {
          candidates.push_back({TransitionKind::kHandoff, giver, o, receiver});
        }
      }
    }
  }

  // Alg. 2. Decompose(T_init) and Initialize: every robot alone and every object resting are
  // vertices from the start, so only "robot holding object" elements are discovered.
  std::vector<bool> obtainable(static_cast<std::size_t>(n) * m, false);
  std::vector<bool> added(candidates.size(), false);
  expansion_rounds_ = 0;
  while (true) {
    // ExpandHypergraph, breadth first: every transition whose tail is in the current V_T
    std::vector<std::size_t> fresh;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (added[c]) continue;
      const Action& a = candidates[c];
      const bool tail_present = a.kind == TransitionKind::kPick || obtainable[holdingIndex(a.robot, a.object)];
      if (tail_present) fresh.push_back(c);
    }
    if (fresh.empty()) break;
    ++expansion_rounds_;
    for (const std::size_t c : fresh) {
      added[c] = true;
      const Action& a = candidates[c];
      if (a.kind == TransitionKind::kPick) obtainable[holdingIndex(a.robot, a.object)] = true;
      if (a.kind == TransitionKind::kHandoff) obtainable[holdingIndex(a.receiver, a.object)] = true;
    }
  }

  // set-asides and pick-ups again, by robots that can hold the object anyway (they add no
  // vertex: the object rests, the robot holds it)
  for (const TransitionKind kind : {TransitionKind::kPlace, TransitionKind::kPick}) {
    for (int r = 0; r < n && !allowed_.aside.empty(); ++r) {
      for (int o = 0; o < m; ++o) {
        const auto& robots = allowed_.aside[o];
        if (obtainable[holdingIndex(r, o)] && std::find(robots.begin(), robots.end(), r) != robots.end()) {
          candidates.push_back({kind, r, o, -1, true});
          added.push_back(true);
        }
      }
    }
  }

  // canonical vertex ids
  vertices_.clear();
  for (int r = 0; r < n; ++r) vertices_.push_back({TaskElementKind::kRobotAlone, r, -1});
  for (int o = 0; o < m; ++o) vertices_.push_back({TaskElementKind::kObjectResting, -1, o});
  holding_vertex_.assign(static_cast<std::size_t>(n) * m, -1);
  for (int r = 0; r < n; ++r) {
    for (int o = 0; o < m; ++o) {
      if (!obtainable[holdingIndex(r, o)]) continue;
      holding_vertex_[holdingIndex(r, o)] = static_cast<int>(vertices_.size());
      vertices_.push_back({TaskElementKind::kRobotHolding, r, o});
    }
  }

  // hyperarcs in candidate (canonical) order
  hyperarcs_.clear();
  const auto sorted = [](std::vector<int> ids) {
    std::sort(ids.begin(), ids.end());
    return ids;
  };
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!added[c]) continue;
    const Action& a = candidates[c];
    TransitionHyperarc arc;
    arc.kind = a.kind;
    arc.object = a.object;
    arc.robot = a.robot;
    arc.receiver = a.receiver;
    switch (a.kind) {
      case TransitionKind::kPick:
        arc.tail = sorted({robotAloneVertex(a.robot), objectRestingVertex(a.object)});
        arc.head = {holdingVertex(a.robot, a.object)};
        arc.rest_pose = a.aside ? RestPose::kAside : RestPose::kStart;
        break;
      case TransitionKind::kPlace:
        arc.tail = {holdingVertex(a.robot, a.object)};
        arc.head = sorted({robotAloneVertex(a.robot), objectRestingVertex(a.object)});
        arc.rest_pose = a.aside ? RestPose::kAside : RestPose::kGoal;
        break;
      case TransitionKind::kHandoff:
        arc.tail = sorted({holdingVertex(a.robot, a.object), robotAloneVertex(a.receiver)});
        arc.head = sorted({robotAloneVertex(a.robot), holdingVertex(a.receiver, a.object)});
        break;
    }
    hyperarcs_.push_back(std::move(arc));
  }

  outgoing_.assign(vertices_.size(), {});
  incoming_.assign(vertices_.size(), {});
  for (std::size_t e = 0; e < hyperarcs_.size(); ++e) {
    for (const int v : hyperarcs_[e].tail) outgoing_[v].push_back(static_cast<int>(e));
    for (const int v : hyperarcs_[e].head) incoming_[v].push_back(static_cast<int>(e));
  }
}

std::size_t TaskSpaceHypergraph::countVertices(TaskElementKind kind) const {
  return static_cast<std::size_t>(
      std::count_if(vertices_.begin(), vertices_.end(), [kind](const TaskSpaceVertex& v) { return v.kind == kind; }));
}

std::size_t TaskSpaceHypergraph::countHyperarcs(TransitionKind kind) const {
  return static_cast<std::size_t>(std::count_if(hyperarcs_.begin(), hyperarcs_.end(),
                                                [kind](const TransitionHyperarc& e) { return e.kind == kind; }));
}

int TaskSpaceHypergraph::robotAloneVertex(int robot) const {
  if (robot < 0 || robot >= allowed_.robots) throw std::out_of_range("robotAloneVertex: no robot " + std::to_string(robot));
  return robot;
}

int TaskSpaceHypergraph::objectRestingVertex(int object) const {
  if (object < 0 || object >= allowed_.objects) {
    throw std::out_of_range("objectRestingVertex: no object " + std::to_string(object));
  }
  return allowed_.robots + object;
}

int TaskSpaceHypergraph::holdingVertex(int robot, int object) const {
  if (robot < 0 || robot >= allowed_.robots || object < 0 || object >= allowed_.objects) {
    throw std::out_of_range("holdingVertex: no robot " + std::to_string(robot) + " or object " +
                            std::to_string(object));
  }
  return holding_vertex_[static_cast<std::size_t>(robot) * allowed_.objects + object];
}

std::vector<int> TaskSpaceHypergraph::initialElements() const {
  std::vector<int> ids;
  for (int v = 0; v < allowed_.robots + allowed_.objects; ++v) ids.push_back(v);
  return ids;
}

std::string TaskSpaceHypergraph::vertexName(int vertex) const {
  const TaskSpaceVertex& v = vertices_.at(vertex);
  switch (v.kind) {
    case TaskElementKind::kRobotAlone: return robot_names_[v.robot];
    case TaskElementKind::kObjectResting: return object_names_[v.object];
    case TaskElementKind::kRobotHolding: return robot_names_[v.robot] + ":" + object_names_[v.object];
  }
  return "?";
}

std::string TaskSpaceHypergraph::hyperarcName(int hyperarc) const {
  const TransitionHyperarc& e = hyperarcs_.at(hyperarc);
  std::string name = std::string(toString(e.kind)) + "(" + robot_names_[e.robot] + ",";
  if (e.kind == TransitionKind::kHandoff) name += robot_names_[e.receiver] + ",";
  return name + object_names_[e.object] + (e.rest_pose == RestPose::kAside ? ",aside)" : ")");
}

std::string describeHyperarc(const core::World& world, const TaskSpaceHypergraph& task_space, int hyperarc) {
  const TransitionHyperarc& arc = task_space.hyperarcs().at(static_cast<std::size_t>(hyperarc));
  const bool aside = arc.rest_pose == RestPose::kAside;
  static const char* const kinds[] = {"pick", "place", "handoff"};
  std::string text = std::string(aside && arc.kind == TransitionKind::kPlace ? "set aside" : kinds[static_cast<int>(arc.kind)]) +
                     " " + world.objects[arc.object].name + " by " + world.robots[arc.robot].name;
  if (arc.kind == TransitionKind::kHandoff) text += " to " + world.robots[arc.receiver].name;
  if (aside && arc.kind == TransitionKind::kPick) text += " where it was set aside";
  return text;
}

}  // namespace dashbed::planner
