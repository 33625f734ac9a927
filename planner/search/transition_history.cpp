#include "planner/search/transition_history.h"

#include <algorithm>

namespace dashbed::planner {

TransitionHistory TransitionHistory::source(const MotionHypergraph& graph) {
  TransitionHistory history;
  for (const core::RobotSpec& robot : graph.world().world->robots) history.robots.push_back({robot.home, 0, -1, -1});
  history.objects.resize(graph.world().world->objects.size());
  history.site_busy.assign(static_cast<std::size_t>(graph.sites().numSites()), 0);
  return history;
}

SiteSet TransitionHistory::occupied(int sites) const {
  SiteSet set(sites);
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const int object = static_cast<int>(o);
    if (objects[o].place == ObjectPlace::kStart) set.set(ObjectSites::startSite(object));
    if (objects[o].place == ObjectPlace::kGoal) set.set(ObjectSites::goalSite(object));
    if (objects[o].place == ObjectPlace::kAside) set.set(ObjectSites::asideSite(object));
  }
  return set;
}

SiteSet TransitionHistory::filledGoals(int sites) const {
  SiteSet set(sites);
  for (std::size_t o = 0; o < objects.size(); ++o) {
    if (objects[o].place == ObjectPlace::kGoal) set.set(ObjectSites::goalSite(static_cast<int>(o)));
  }
  return set;
}

bool TransitionHistory::complete(const ObjectSites& sites) const {
  for (std::size_t o = 0; o < objects.size(); ++o) {
    if (sites.goal[o] && objects[o].place != ObjectPlace::kGoal) return false;
  }
  return true;
}

int TransitionHistory::objectsAtGoal() const {
  return static_cast<int>(
      std::count_if(objects.begin(), objects.end(), [](const ObjectState& o) { return o.place == ObjectPlace::kGoal; }));
}

Millis TransitionHistory::makespan() const {
  Millis end = 0;
  for (std::size_t r = 0; r < robots.size(); ++r) {
    Millis robot_end = robots[r].free;
    if (r < final_moves.size() && final_moves[r] != nullptr) robot_end = final_starts[r] + final_moves[r]->duration;
    end = std::max(end, robot_end);
  }
  Millis unfolding = 0;
  for (const Move* move : unfold_moves) {
    if (move != nullptr) unfolding = std::max(unfolding, move->duration);
  }
  return end + unfolding;
}

}  // namespace dashbed::planner
