#include "planner/motion/hypergraph_dot.h"

#include <sstream>

namespace dashbed::planner {
namespace {

// a double-quoted DOT string
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

const char* vertexStyle(TaskElementKind kind) {
  switch (kind) {
    case TaskElementKind::kRobotAlone:
      return "shape=box, style=filled, fillcolor=\"#9ecae1\", color=\"#3182bd\"";
    case TaskElementKind::kObjectResting:
      return "shape=ellipse, style=filled, fillcolor=\"#fee391\", color=\"#d9a600\"";
    case TaskElementKind::kRobotHolding:
      return "shape=box, style=\"rounded,filled\", fillcolor=\"#fdae6b\", color=\"#e6550d\"";
  }
  return "";
}

const char* hyperarcColor(TransitionKind kind) {
  switch (kind) {
    case TransitionKind::kPick: return "#31a354";
    case TransitionKind::kPlace: return "#3182bd";
    case TransitionKind::kHandoff: return "#756bb1";
  }
  return "black";
}

}  // namespace

void writeDot(std::ostream& out, const TaskSpaceHypergraph& graph, const DotOptions& options) {
  out << "digraph " << quoted(options.graph_name) << " {\n";
  out << "  rankdir=" << (options.left_to_right ? "LR" : "TB") << ";\n";
  out << "  node [fontname=\"Helvetica\", fontsize=11];\n";
  out << "  edge [fontname=\"Helvetica\", fontsize=9];\n";
  out << "  // " << graph.numRobots() << " robots, " << graph.numObjects() << " objects: " << graph.numVertices()
      << " task-space elements, " << graph.numHyperarcs() << " transition hyperarcs\n";

  out << "  // task-space elements\n";
  for (std::size_t v = 0; v < graph.numVertices(); ++v) {
    const int id = static_cast<int>(v);
    out << "  v" << v << " [label=" << quoted(graph.vertexName(id)) << ", " << vertexStyle(graph.vertices()[v].kind)
        << "];\n";
  }

  out << "  // transition hyperarcs: tail -- node -> head\n";
  for (std::size_t e = 0; e < graph.numHyperarcs(); ++e) {
    const int id = static_cast<int>(e);
    const TransitionHyperarc& arc = graph.hyperarcs()[e];
    const char* color = hyperarcColor(arc.kind);
    out << "  e" << e << " [shape=circle, width=0.12, height=0.12, fixedsize=true, label=\"\", style=filled, "
        << "fillcolor=\"" << color << "\", color=\"" << color << "\", tooltip=" << quoted(graph.hyperarcName(id));
    if (options.label_hyperarcs) out << ", xlabel=" << quoted(graph.hyperarcName(id));
    out << "];\n";
    for (const int v : arc.tail) out << "  v" << v << " -> e" << e << " [arrowhead=none, color=\"" << color << "\"];\n";
    for (const int v : arc.head) out << "  e" << e << " -> v" << v << " [color=\"" << color << "\"];\n";
  }
  out << "}\n";
}

void writeMotionDot(std::ostream& out, const MotionHypergraph& graph) {
  const TaskSpaceHypergraph& ts = graph.taskSpace();
  out << "digraph \"motion_hypergraph\" {\n  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=9];\n";
  out << "  // " << graph.numVertices() << " motion vertices, " << graph.numTransitions() << " transition hyperarcs\n";
  for (std::size_t t = 0; t < ts.numVertices(); ++t) {
    const std::vector<int> members = graph.verticesOf(static_cast<int>(t));
    if (members.empty()) continue;
    out << "  subgraph \"cluster_" << t << "\" {\n    label=" << quoted(ts.vertexName(static_cast<int>(t))) << ";\n";
    for (const int v : members) {
      const MotionVertex& m = graph.vertex(v);
      std::ostringstream label;
      label << 'm' << v;
      if (m.grasp >= 0) label << " g" << m.grasp;
      if (m.site >= 0) {
        const int o = ObjectSites::objectOf(m.site);
        label << (m.site == ObjectSites::startSite(o) ? " start" : m.site == ObjectSites::goalSite(o) ? " goal" : " aside");
      }
      out << "    m" << v << " [label=" << quoted(label.str()) << ", " << vertexStyle(ts.vertices()[t].kind) << "];\n";
    }
    out << "  }\n";
  }
  for (std::size_t e = 0; e < graph.numTransitions(); ++e) {
    const MotionTransition& transition = graph.transition(static_cast<int>(e));
    const char* color = hyperarcColor(transition.sample.kind);
    out << "  t" << e << " [shape=circle, width=0.1, height=0.1, fixedsize=true, label=\"\", style=filled, fillcolor=\""
        << color << "\", color=\"" << color << "\", tooltip=" << quoted(ts.hyperarcName(transition.sample.hyperarc))
        << "];\n";
    for (const int v : transition.tail) out << "  m" << v << " -> t" << e << " [arrowhead=none, color=\"" << color << "\"];\n";
    for (const int v : transition.head) out << "  t" << e << " -> m" << v << " [color=\"" << color << "\"];\n";
  }
  out << "  source [shape=doublecircle, label=\"source\"];\n  target [shape=doublecircle, label=\"target\"];\n";
  for (const int v : graph.sourceVertices()) out << "  source -> m" << v << " [style=dashed];\n";
  for (const int v : graph.targetVertices()) out << "  m" << v << " -> target [style=dashed];\n";
  out << "}\n";
}

std::string toDot(const TaskSpaceHypergraph& graph, const DotOptions& options) {
  std::ostringstream out;
  writeDot(out, graph, options);
  return out.str();
}

}  // namespace dashbed::planner
