// `dashbed gen`: write a seeded scenario world (sorting or shelving) as YAML.

#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/world_io.h"
#include "tools/cli/commands.h"
#include "tools/cli/number_checks.h"
#include "tools/scenarios/scenarios.h"

namespace dashbed::tools {
namespace {

// Writes the world to `output` ("" = stdout); fails with kExitUsage when the file cannot be
// written.
void emitWorld(const core::World& world, const std::string& output) {
  const std::string yaml = core::writeWorldYaml(world);
  if (output.empty()) {
    std::cout << yaml << std::flush;
    return;
  }
  std::ofstream file(output, std::ios::binary);
  file << yaml;
  file.close();
  if (!file) {
    std::cerr << "dashbed gen: cannot write '" << output << "'\n";
    throw CLI::RuntimeError(kExitUsage);
  }
}

// Runs a generator, turning bad parameters into a usage error.
template <typename Generate>
core::World generateOrFail(Generate&& generate) {
  try {
    return generate();
  } catch (const std::invalid_argument& e) {
    std::cerr << "dashbed gen: " << e.what() << "\n";
    throw CLI::RuntimeError(kExitUsage);
  }
}

}  // namespace

void addGenCommand(CLI::App& app) {
  CLI::App* gen = app.add_subcommand(
      "gen", "Generate a seeded scenario world (YAML) like the DaSH paper's experiments: "
             "`gen sort` or `gen shelf`. Same parameters and seed give the same bytes.");
  gen->require_subcommand(1);

  // sort
  struct SortOptions {
    SortingParams params;
    std::string start = "cross";
    std::string layout = "paper";
    std::string output;
  };
  auto sort_options = std::make_shared<SortOptions>();
  CLI::App* sort = gen->add_subcommand(
      "sort",
      "Sorting: cubes of colour classes (red, green, blue, yellow) on a shared table must go "
      "into one bin per class. 2 robots face each other across the table (r0 owns the red and "
      "blue bins, r1 green and yellow); 4 robots stand in a square facing the centre (robot k "
      "owns class k). With --layout rows, 2..8 robots stand in two facing rows along a long "
      "table with the bins at its two ends; with --layout ring, 3..6 robots stand on a circle "
      "0.75 m from one shared centre (robot k owns class k, its bin on its left) and the cubes "
      "start within 0.35 m of the centre. 'cross' starts every cube in front of a robot "
      "that cannot reach its bin (in a ring: across it), so every cube must be handed over; "
      "'random' starts cubes anywhere in the shared workspace. Cubes stay at least 0.1 m apart; "
      "too many cubes for the zones is an error that says how many fit.");
  sort->add_option("--robots", sort_options->params.robots,
                   "Number of robots: 2 or 4; in rows even, 2..8; in a ring 3..6")
      ->check(CLI::Range(2, 8))
      ->capture_default_str();
  sort->add_option("--layout", sort_options->layout,
                   "Robot layout: paper (2 facing, 4 in a square), rows (two facing rows) or ring (facing one centre)")
      ->check(CLI::IsMember({"paper", "rows", "ring"}))
      ->capture_default_str();
  sort->add_option("--cubes", sort_options->params.cubes, "Number of cubes (>= 1)")
      ->check(integerIn(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  CLI::Option* classes =
      sort->add_option("--classes", sort_options->params.classes,
                       "Number of colour classes, 1..4 (exactly 4 with 4 robots in the paper layout; in a ring at "
                       "most one per robot, and by default one per robot up to 4)")
          ->check(CLI::Range(1, 4))
          ->capture_default_str();
  sort->add_option("--start", sort_options->start, "Start layout: cross or random")
      ->check(CLI::IsMember({"cross", "random"}))
      ->capture_default_str();
  sort->add_option("--seed", sort_options->params.seed, "Random seed (unsigned 64-bit)")
      ->check(unsigned64())
      ->capture_default_str();
  sort->add_option("-o,--output", sort_options->output, "Output file (default: stdout)");
  sort->callback([sort_options, classes] {
    sort_options->params.start = parseStartLayout(sort_options->start);
    sort_options->params.layout = parseRobotLayout(sort_options->layout);
    if (sort_options->params.layout == RobotLayout::kRing && classes->count() == 0) {
      sort_options->params.classes = std::min(sort_options->params.classes, sort_options->params.robots);
    }
    const core::World world =
        generateOrFail([&] { return generateSorting(sort_options->params); });
    emitWorld(world, sort_options->output);
  });

  // shelf
  struct ShelfOptions {
    ShelvingParams params;
    std::string output;
  };
  auto shelf_options = std::make_shared<ShelfOptions>();
  CLI::App* shelf = gen->add_subcommand(
      "shelf",
      "Shelving: two robots side by side stock a shelf with one board. Objects come in pairs "
      "placed in slot columns chosen by the seed: a green object goes to the back slot and its "
      "blue partner to the front slot directly in front of it, which blocks the back one, so "
      "the green object must be placed first. Objects start at random spots on the table "
      "between the robots and the shelf, turned by at most 30 degrees.");
  shelf->add_option("--objects", shelf_options->params.objects,
                    "Number of objects: even, 2..12 (pairs of green back + blue front)")
      ->capture_default_str();
  shelf->add_option("--seed", shelf_options->params.seed, "Random seed (unsigned 64-bit)")
      ->check(unsigned64())
      ->capture_default_str();
  shelf->add_option("-o,--output", shelf_options->output, "Output file (default: stdout)");
  shelf->callback([shelf_options] {
    const core::World world =
        generateOrFail([&] { return generateShelving(shelf_options->params); });
    emitWorld(world, shelf_options->output);
  });
}

}  // namespace dashbed::tools
