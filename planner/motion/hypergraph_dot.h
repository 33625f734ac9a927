#pragma once
// Graphviz DOT of the task-space hypergraph (and of the motion hypergraph, below). Each hyperarc is drawn as a small node joined by
// plain lines from its tail vertices and by arrows to its head vertices (the usual drawing of
// a directed hypergraph as its bipartite incidence graph; paper Fig. 4).
//
// Vertices: robot alone = blue box, object resting = yellow ellipse, robot holding object =
// orange rounded box. Hyperarc nodes: pick green, place blue, handoff purple. Output is
// deterministic: vertices and hyperarcs in the hypergraph's canonical id order.

#include <ostream>
#include <string>

#include "planner/motion/motion_hypergraph.h"
#include "planner/task_space/task_space_hypergraph.h"

namespace dashbed::planner {

struct DotOptions {
  /// Name of the DOT graph.
  std::string graph_name = "task_space_hypergraph";
  bool label_hyperarcs = true;  ///< write the action name next to each hyperarc node
  bool left_to_right = true;    ///< rankdir=LR, else top to bottom
};

/// Writes the DOT text of `graph` to `out`.
void writeDot(std::ostream& out, const TaskSpaceHypergraph& graph, const DotOptions& options = {});

/// The DOT text of `graph`.
std::string toDot(const TaskSpaceHypergraph& graph, const DotOptions& options = {});

/// Graphviz DOT of the motion hypergraph as sampled so far: its motion vertices in one cluster
/// per task-space vertex (the vertex map), its transition hyperarcs drawn like the task-space
/// hyperarcs, and the virtual source and target joined to the start and goal vertices. Move
/// hyperarcs are planned on demand by the search and are not drawn.
void writeMotionDot(std::ostream& out, const MotionHypergraph& graph);

}  // namespace dashbed::planner
