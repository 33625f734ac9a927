#include "tools/planning/run_planner.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "core/number_text.h"

namespace dashbed::tools {

planner::PlannerSettings plannerSettings(const PlannerChoice& choice) {
  planner::PlannerSettings settings;
  if (choice.method == "greedy") {
    settings.method = planner::Method::kGreedy;
  } else if (choice.method == "optimal") {
    settings.method = planner::Method::kOptimal;
  } else {
    throw std::invalid_argument("unknown planning method '" + choice.method + "' (greedy or optimal)");
  }
  if (!(choice.time_budget > 0.0) || !(choice.time_budget <= kMaxTimeBudget)) {
    throw std::invalid_argument("the time budget must be positive and at most " + core::shortestText(kMaxTimeBudget) +
                                " s, got " + core::shortestText(choice.time_budget));
  }
  if (choice.max_rounds < 1) throw std::invalid_argument("the number of rounds must be at least 1");
  settings.seed = choice.seed;
  settings.max_rounds = choice.max_rounds;
  settings.sequential_fallback_rounds = choice.fallback_rounds;
  settings.conflict_focal_weight = choice.conflict_focal;
  settings.set_aside = choice.set_aside;
  return settings;
}

planner::PlanResult planWorld(const core::LoadedWorld& world, const PlannerChoice& choice,
                              std::shared_ptr<const planner::CollisionScene> checked_scene) {
  const planner::PlannerSettings settings = plannerSettings(choice);
  planner::PlannerBudget budget;
  const auto started = std::chrono::steady_clock::now();
  budget.deadline = started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(choice.time_budget));
  if (choice.verbose) {
    budget.progress = [started](const std::string& line) {
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      std::cerr << "[" << std::fixed << std::setprecision(2) << std::setw(7) << t << " s] " << line << "\n";
    };
  }
  return planner::solve(world, settings, budget, std::move(checked_scene));
}

std::string describePlanResult(const planner::PlanResult& result) {
  const planner::PlannerStats& s = result.stats;
  std::ostringstream out;
  out << std::fixed << std::setprecision(3);
  out << "status: " << planner::toString(result.status);
  if (!result.reason.empty()) out << " (" << result.reason << ")";
  out << "\n";
  out << "time: construction " << s.construction_seconds << " s, search " << s.search_seconds << " s, conflict resolution "
      << s.conflict_seconds << " s, " << s.rounds << (s.rounds == 1 ? " round\n" : " rounds\n");
  out << "task-space hypergraph: " << s.task_vertices << " vertices, " << s.task_hyperarcs << " hyperarcs";
  if (s.set_aside_sites > 0) out << " (" << s.set_aside_sites << (s.set_aside_sites == 1 ? " object" : " objects") << " with a set-aside site)";
  out << "\n";
  out << "motion hypergraph: " << s.motion_vertices << " vertices, " << s.motion_transitions << " transitions, "
      << s.motion_moves << " moves, " << s.roadmaps << " roadmaps (" << s.roadmap_nodes << " nodes)\n";
  out << "search: " << s.expansions << " expansions, " << s.task_plans << " task plans, " << s.conflict_nodes
      << " conflict-resolution nodes, " << s.scheduling_constraints << " scheduling constraints fed back, "
      << s.conflict_constraints << " constraints in the plan's conflict resolution\n";
  if (result.plan) {
    out << std::setprecision(2) << "plan: " << result.plan->actions.size() << " actions, "
        << (s.sequential ? "sequential (one object at a time), " : "") << "makespan " << s.makespan
        << " s (" << s.unresolved_makespan << " s before robot-robot conflicts are resolved)\n";
  }
  return out.str();
}

nlohmann::json planResultJson(const planner::PlanResult& result) {
  nlohmann::json out = result.plan ? result.plan->statistics : nlohmann::json::object();
  out["status"] = planner::toString(result.status);
  if (!result.reason.empty()) out["reason"] = result.reason;
  const planner::PlannerStats& s = result.stats;
  out["seconds"] = {{"construction", s.construction_seconds},
                    {"search", s.search_seconds},
                    {"conflict_resolution", s.conflict_seconds}};
  return out;
}

core::Plan planForRun(const core::LoadedWorld& world, const PlannerChoice& choice) {
  planner::PlanResult result = planWorld(world, choice);
  switch (result.status) {
    case planner::PlannerStatus::kSolved:
      return std::move(*result.plan);
    case planner::PlannerStatus::kInfeasible:
      throw PlanningFailed(PlanningStatus::kInfeasible, result.reason);
    case planner::PlannerStatus::kTimeout:
      break;
  }
  throw PlanningFailed(PlanningStatus::kTimeout, result.reason);
}

}  // namespace dashbed::tools
