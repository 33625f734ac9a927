#pragma once
// A baseline task sequencer for `dashbed run` until the DaSH planner lands (issues 5 and 6):
// objects are moved strictly one after another along the shortest chain of robots — pick by a
// robot that reaches the start, handoffs between robots whose workspaces overlap, place by a
// robot that reaches the goal — and each object gets its own slot in its goal region. Each
// object's chain is written as an action script, timed by the scripted-plan tool
// (tools/scripted_plan.h) from and back to the home poses, and appended after the previous
// one, so no two objects are ever moved at once. No collision checking: the simulator's
// monitor reports any contact.

#include <string>
#include <vector>

#include "core/plan.h"
#include "core/world_loader.h"

namespace dashbed::tools {

/// One action script per object with a goal, moving it to its goal region. Throws
/// std::runtime_error naming the object when no chain of robots can carry it, or the region
/// when it has no free slot left.
std::vector<std::string> sequentialScripts(const core::LoadedWorld& world);

/// The scripts timed and concatenated into one plan.
core::Plan sequentialPlan(const core::LoadedWorld& world);

}  // namespace dashbed::tools
