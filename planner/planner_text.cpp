#include "planner/planner_text.h"

#include <iomanip>
#include <sstream>

namespace dashbed::planner {

std::string secondsText(Millis t) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << toSeconds(t) << " s";
  return out.str();
}

std::string nodesText(int nodes) { return " (" + std::to_string(nodes) + " nodes)"; }

std::string describeTransition(const MotionHypergraph& graph, int id) {
  return describeHyperarc(*graph.world().world, graph.taskSpace(), graph.transition(id).sample.hyperarc) +
         " (transition " + std::to_string(id) + ")";
}

std::string objectList(const core::World& world, const std::vector<int>& objects) {
  std::string text;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    text += (k == 0 ? "" : k + 1 == objects.size() ? " and " : ", ") + world.objects[static_cast<std::size_t>(objects[k])].name;
  }
  return text;
}

std::string firstFew(const std::vector<std::string>& items, std::size_t limit, const std::string& separator,
                     const std::string& what) {
  std::string text;
  for (std::size_t k = 0; k < items.size() && k < limit; ++k) text += (k == 0 ? "" : separator) + items[k];
  if (items.size() > limit) text += " and " + std::to_string(items.size() - limit) + " more" + what;
  return text;
}

std::string furthestText(const MotionHypergraph& graph, const TransitionHistory& furthest) {
  const core::World& world = *graph.world().world;
  std::vector<std::string> left;
  int goals = 0;
  for (std::size_t o = 0; o < furthest.objects.size(); ++o) {
    if (!graph.sites().goal[o]) continue;
    ++goals;
    const TransitionHistory::ObjectState& object = furthest.objects[o];
    if (object.place == ObjectPlace::kGoal) continue;
    std::string where = "at its start";
    if (object.place == ObjectPlace::kHeld) where = "held by " + world.robots[static_cast<std::size_t>(object.holder)].name;
    if (object.place == ObjectPlace::kAside) where = "set aside";
    left.push_back(world.objects[o].name + " (" + where + ")");
  }
  if (left.empty()) {  // complete, but finish() found a robot no way to where it rests
    return "; the furthest task plan tried placed all " + std::to_string(goals) +
           " objects, but a robot found no way back to where it rests";
  }
  return "; the furthest task plan tried placed " + std::to_string(furthest.objectsAtGoal()) + " of " +
         std::to_string(goals) + " objects, not " + firstFew(left, 4, ", ");
}

}  // namespace dashbed::planner
