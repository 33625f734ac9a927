// dashbed graph [WORLD] [-o FILE.dot]: the task-space hypergraph of a world, its sizes and its
// Graphviz DOT. dashbed graph --counts ROBOTS OBJECTS: the Representation Analysis sizes of
// the composite graph and the hypergraph (paper Fig. 2(b)).

#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "planner/motion/hypergraph_dot.h"
#include "planner/motion/motion_hypergraph.h"
#include "planner/sampling/object_sites.h"
#include "planner/task_space/representation_analysis.h"
#include "planner/task_space/task_space_hypergraph.h"
#include "tools/cli/cli_support.h"

namespace dashbed::tools {
namespace {

using planner::RepresentationSize;
using planner::TaskElementKind;
using planner::TransitionKind;

struct GraphOptions {
  std::string world_file;
  std::string output;
  std::vector<int> counts;  // {robots, objects} when --counts is given
  bool json = false;
  bool list = false;
  std::string motion_output;  // the motion hypergraph's DOT, when given
};

/// The motion hypergraph's first round (Alg. 3): every pick, then the places and handoffs of
/// every grasp the picks and handoffs give, twice over; written as DOT.
void writeMotionDotFile(const core::LoadedWorld& loaded, const planner::TaskSpaceHypergraph& graph,
                        const std::string& output, std::ostream& report) {
  planner::MotionHypergraph motion(loaded, graph, 1);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t h = 0; h < graph.numHyperarcs(); ++h) {
      const planner::TransitionHyperarc& arc = graph.hyperarcs()[h];
      if (arc.kind == TransitionKind::kPick) {
        motion.transitionsOf(static_cast<int>(h), -1);
        continue;
      }
      const std::size_t grasps = motion.graspsOf(arc.object).size();  // sampling may add grasps
      for (std::size_t g = 0; g < grasps; ++g) motion.transitionsOf(static_cast<int>(h), static_cast<int>(g));
    }
  }
  std::ofstream out(output);
  planner::writeMotionDot(out, motion);
  if (!out) throw std::runtime_error("cannot write " + output);
  report << "motion hypergraph (first round, seed 1): " << motion.numVertices() << " motion vertices, "
         << motion.numTransitions() << " transition hyperarcs; wrote Graphviz DOT to " << output << "\n";
}

// the composite graph's size, or nothing when it exceeds 64 bits
std::optional<RepresentationSize> compositeSizeOrOverflow(int robots, int objects) {
  try {
    return planner::compositeGraphSize(robots, objects);
  } catch (const std::overflow_error&) {
    return std::nullopt;
  }
}

nlohmann::json sizeJson(const std::optional<RepresentationSize>& size) {
  if (!size) return {{"vertices", nullptr}, {"transitions", nullptr}, {"overflow", true}};
  return {{"vertices", size->vertices}, {"transitions", size->transitions}};
}

std::string countText(const std::optional<RepresentationSize>& size, bool vertices) {
  if (!size) return "> 2^64";
  return std::to_string(vertices ? size->vertices : size->transitions);
}

void runCounts(const GraphOptions& options) {
  const int robots = options.counts[0], objects = options.counts[1];
  const std::optional<RepresentationSize> hypergraph = [&]() -> std::optional<RepresentationSize> {
    try {
      return planner::hypergraphSize(robots, objects);
    } catch (const std::overflow_error&) {
      return std::nullopt;
    }
  }();
  const std::optional<RepresentationSize> graph = compositeSizeOrOverflow(robots, objects);
  if (options.json) {
    const nlohmann::json out = {{"robots", robots},
                                {"objects", objects},
                                {"hypergraph", sizeJson(hypergraph)},
                                {"graph", sizeJson(graph)}};
    std::cout << jsonText(out) << "\n";
    return;
  }
  std::cout << "representation sizes for " << robots << " robots, " << objects
            << " objects (paper: Representation Analysis, Fig. 2(b))\n";
  std::cout << "  " << std::left << std::setw(16) << "representation" << std::right << std::setw(22) << "vertices"
            << std::setw(22) << "directed transitions" << "\n";
  const auto row = [](const char* name, const std::optional<RepresentationSize>& size) {
    std::cout << "  " << std::left << std::setw(16) << name << std::right << std::setw(22) << countText(size, true)
              << std::setw(22) << countText(size, false) << "\n";
  };
  row("hypergraph", hypergraph);
  row("graph", graph);
}

void writeDotFile(const planner::TaskSpaceHypergraph& graph, const std::string& output) {
  if (output == "-") {
    planner::writeDot(std::cout, graph);
    return;
  }
  std::ofstream out(output, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + output);
  planner::writeDot(out, graph);
  if (!out) throw std::runtime_error("error writing " + output);
}

void runWorld(const GraphOptions& options) {
  const std::filesystem::path file = worldFileOrDefault(options.world_file);
  const core::LoadedWorld loaded = core::loadWorld(file);
  const core::World& world = *loaded.world;
  // the planner's: place hyperarcs for the robots reaching each object's goal slot
  const auto graph = planner::TaskSpaceHypergraph::fromWorld(
      world, *loaded.robots, planner::placementReach(loaded, planner::objectSites(loaded)));
  const RepresentationSize bound = planner::hypergraphSize(graph.numRobots(), graph.numObjects());
  const std::optional<RepresentationSize> composite = compositeSizeOrOverflow(graph.numRobots(), graph.numObjects());

  // with the DOT on standard output the report goes to standard error
  std::ostream& report = options.output == "-" ? std::cerr : std::cout;
  if (options.json) {
    nlohmann::json out;
    out["world"] = {{"name", world.name}, {"file", file.string()}};
    out["robots"] = graph.numRobots();
    out["objects"] = graph.numObjects();
    out["vertices"] = {{"total", graph.numVertices()},
                       {"robot_alone", graph.countVertices(TaskElementKind::kRobotAlone)},
                       {"object_resting", graph.countVertices(TaskElementKind::kObjectResting)},
                       {"robot_holding", graph.countVertices(TaskElementKind::kRobotHolding)}};
    out["hyperarcs"] = {{"total", graph.numHyperarcs()},
                        {"pick", graph.countHyperarcs(TransitionKind::kPick)},
                        {"place", graph.countHyperarcs(TransitionKind::kPlace)},
                        {"handoff", graph.countHyperarcs(TransitionKind::kHandoff)}};
    out["expansion_rounds"] = graph.expansionRounds();
    out["all_reachable"] = {{"hypergraph", sizeJson(bound)}, {"graph", sizeJson(composite)}};
    if (options.list) {
      for (std::size_t v = 0; v < graph.numVertices(); ++v) {
        out["vertex_names"].push_back(graph.vertexName(static_cast<int>(v)));
      }
      for (std::size_t e = 0; e < graph.numHyperarcs(); ++e) {
        out["hyperarc_names"].push_back(graph.hyperarcName(static_cast<int>(e)));
      }
    }
    if (!options.output.empty()) out["dot"] = options.output;
    report << jsonText(out) << "\n";
  } else {
    report << "task-space hypergraph of world " << world.name << " (" << file.string() << "): " << graph.numRobots()
           << " robots, " << graph.numObjects() << " objects\n";
    report << "  vertices  " << std::setw(6) << graph.numVertices() << ": "
           << graph.countVertices(TaskElementKind::kRobotAlone) << " robot alone, "
           << graph.countVertices(TaskElementKind::kObjectResting) << " object resting, "
           << graph.countVertices(TaskElementKind::kRobotHolding) << " robot holding object\n";
    report << "  hyperarcs " << std::setw(6) << graph.numHyperarcs() << ": "
           << graph.countHyperarcs(TransitionKind::kPick) << " pick (at start), "
           << graph.countHyperarcs(TransitionKind::kPlace) << " place (at goal), "
           << graph.countHyperarcs(TransitionKind::kHandoff) << " handoff\n";
    report << "  everything reachable: hypergraph " << bound.vertices << " vertices / " << bound.transitions
           << " hyperarcs; composite graph " << countText(composite, true) << " vertices / "
           << countText(composite, false) << " transitions\n";
    if (options.list) {
      report << "vertices:\n";
      for (std::size_t v = 0; v < graph.numVertices(); ++v) {
        report << "  v" << v << "  " << graph.vertexName(static_cast<int>(v)) << "\n";
      }
      report << "hyperarcs:\n";
      for (std::size_t e = 0; e < graph.numHyperarcs(); ++e) {
        report << "  e" << e << "  " << graph.hyperarcName(static_cast<int>(e)) << "\n";
      }
    }
  }
  if (options.output.empty() && !options.json) report << "(write the Graphviz DOT with -o FILE.dot)\n";
  if (!options.output.empty()) {
    writeDotFile(graph, options.output);
    if (!options.json && options.output != "-") report << "wrote Graphviz DOT to " << options.output << "\n";
  }
  if (!options.motion_output.empty()) writeMotionDotFile(loaded, graph, options.motion_output, report);
}

}  // namespace

void addGraphCommand(CLI::App& app) {
  auto options = std::make_shared<GraphOptions>();
  CLI::App* graph = app.add_subcommand(
      "graph", "The task-space hypergraph of a world (sizes, Graphviz DOT), or with --counts the "
               "representation sizes of the paper's Representation Analysis (default world: worlds/default.yaml)");
  CLI::Option* world = graph->add_option("world", options->world_file, "world file (YAML)");
  CLI::Option* counts =
      graph->add_option("--counts", options->counts, "ROBOTS OBJECTS: print the composite graph and hypergraph sizes instead")
          ->expected(2)
          ->check(CLI::Range(0, 1000000))
          ->excludes(world);
  graph->add_option("-o,--output", options->output, "write the Graphviz DOT here ('-': standard output)")
      ->excludes(counts);
  graph->add_option("--motion", options->motion_output,
                    "also sample the motion hypergraph's first round and write its Graphviz DOT here")
      ->excludes(counts);
  graph->add_flag("--json", options->json, "print JSON");
  graph->add_flag("--list", options->list, "also list every vertex and hyperarc by name");
  graph->callback([options] {
    runGuarded("graph", [&] {
      if (!options->counts.empty()) {
        runCounts(*options);
      } else {
        runWorld(*options);
      }
    });
  });
}

}  // namespace dashbed::tools
