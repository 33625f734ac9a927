#pragma once
// Seeded scenario generators: the sorting and shelving experiments of the DaSH paper
// (Sec. "Experiment Configuration": sorting with 2 robots facing each other or 4 robots in a
// square; shelving with front/back object pairs).
//
// A generator returns the written part of a world (robots, fixtures, written regions,
// objects, goals); the derived parts (fixture boxes, bin regions, shelf surfaces) are made by
// the world loader, so `parseWorldYaml(writeWorldYaml(generate(p)))` and
// `validateWorld(generate(p))` give the full world.
// Determinism: the same parameters give the same World and the same YAML bytes on every
// platform (the random numbers come from std::mt19937_64, whose output the standard fixes,
// through our own uniform-double, integer-in-range and shuffle functions).

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/world.h"

namespace dashbed::tools {

/// A platform-independent random stream for scenario generation. Unlike
/// std::uniform_*_distribution (implementation-defined), every value depends only on the seed.
class ScenarioRng {
 public:
  explicit ScenarioRng(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1) with 53 random bits (the top bits of one raw 64-bit output).
  double uniform01();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi);
  /// Uniform integer in [0, n), unbiased (rejection sampling). Precondition: n > 0.
  std::uint64_t index(std::uint64_t n);
  /// Fisher-Yates shuffle in place.
  template <typename T>
  void shuffle(std::vector<T>& items) {
    for (std::size_t i = items.size(); i > 1; --i) {
      const std::size_t j = static_cast<std::size_t>(index(i));
      std::swap(items[i - 1], items[j]);
    }
  }

 private:
  std::mt19937_64 engine_;
};

/// Where sorting cubes start.
enum class StartLayout {
  kCross,   ///< in the zone of a robot that does not own the cube's bin: every cube is handed over
  kRandom,  ///< anywhere in the shared workspace
};

/// "cross" or "random".
std::string toString(StartLayout layout);
/// Parses "cross" or "random"; throws std::invalid_argument otherwise.
StartLayout parseStartLayout(const std::string& text);

/// Where sorting robots stand.
enum class RobotLayout {
  kPaper,  ///< the paper's: 2 robots facing each other, or 4 in a square facing the centre
  kRows,   ///< 2..8 robots (even) in two facing rows along a long table, bins at its two ends
  kRing,   ///< 3..6 robots evenly spaced on a circle, facing one shared centre
};

/// "paper", "rows" or "ring".
std::string toString(RobotLayout layout);
/// Parses "paper", "rows" or "ring"; throws std::invalid_argument otherwise.
RobotLayout parseRobotLayout(const std::string& text);

/// Parameters of the sorting scenario.
struct SortingParams {
  int robots = 2;   ///< paper layout: 2 or 4; rows: even, 2..8; ring: 3..6
  int cubes = 4;    ///< number of 0.04 m cubes, >= 1; the start zones bound it (see generateSorting)
  int classes = 4;  ///< 1..4 colour classes (red, green, blue, yellow); exactly 4 with 4 robots
                    ///< in the paper layout, at most one per robot in a ring
  StartLayout start = StartLayout::kCross;
  std::uint64_t seed = 1;
  RobotLayout layout = RobotLayout::kPaper;
};

/// The sorting scenario: cubes of colour classes on a shared table, one bin per class; cube i
/// has class i mod classes and goal region bin_<class>.
///
/// Paper layout, 2 robots: r0 at (-0.7, 0) facing +x owns the red and blue bins, r1 at (0.7, 0)
/// facing -x owns green and yellow. 4 robots: r0..r3 at (-0.75,0), (0,-0.75), (0.75,0),
/// (0,0.75) facing the centre, robot k owns class k.
/// Rows: column k (1 m apart, centred on x = 0) holds r(2k) at y = -0.7 facing +y and r(2k+1)
/// at y = 0.7 facing -y; the red and blue bins stand beyond the first column (owned by r0 and
/// r1), green and yellow beyond the last (r(n-1) and r(n-2)). A cross start puts a cube in
/// front of the robot of the other end column and the other row, so it travels the table's
/// length from hand to hand; a random start anywhere on the strip between the rows.
/// Ring: r0 at (-0.75, 0) facing +x, the others 360/n degrees apart counter-clockwise, all
/// facing the centre; robot k < classes owns class k, its bin beside it on its left as in the
/// square. Cubes start in the disc of radius 0.35 m around the centre, each robot's zone the
/// part nearest to it (by angle); a cross start puts a cube in the zone of the robot across the
/// ring from its bin's robot. Cubes stand on distinct cells of a lattice in the start
/// zones, jittered so that centres stay at least kMinCubeSpacing apart, with yaw in
/// [-pi/4, pi/4). Throws std::invalid_argument (saying how many cubes fit) for bad parameters.
core::World generateSorting(const SortingParams& params);

/// Parameters of the shelving scenario.
struct ShelvingParams {
  int objects = 4;  ///< even, 2..12: objects/2 pairs of (green back, blue front)
  std::uint64_t seed = 1;
};

/// The shelving scenario: two robots side by side facing a shelf with one board; objects/2
/// slot columns chosen by the seed each get a green object (goal: back slot) and a blue object
/// (goal: the front slot directly in front of it), so each green object must be placed before
/// its blue partner. Objects start at random positions on the table in front of the robots.
/// Throws std::invalid_argument for bad parameters.
core::World generateShelving(const ShelvingParams& params);

/// Smallest distance between the centres of two generated objects [m].
inline constexpr double kMinCubeSpacing = 0.1;

}  // namespace dashbed::tools
