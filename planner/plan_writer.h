#pragma once
// A conflict-free schedule written as the simulator's timed plan (core::Plan).
//
//  - every gripper opens at t = 0 (robots alone keep their grippers open);
//  - moves are sampled from their rest-to-rest profiles with velocities (timePolyline), so the
//    simulator's Hermite interpolation stays on the straight pieces that were checked;
//  - transition keys are written as they are (the simulator's shape-preserving
//    interpolation passes through them), with their gripper commands;
//  - a robot standing still gets a point where it starts again;
//  - each transition becomes a plan action over its sample's action window.

#include "core/plan.h"
#include "planner/scheduling/scheduled_cbs.h"
#include "planner/search/transition_history.h"

namespace dashbed::planner {

core::Plan writePlan(const MotionHypergraph& graph, const TransitionHistory& history, const Schedule& schedule);

}  // namespace dashbed::planner
