#include "tools/scenarios/scenarios.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "core/colors.h"
#include "core/pose.h"
#include "planner/sampling/object_sites.h"

namespace dashbed::tools {

double ScenarioRng::uniform01() {
  // top 53 bits of the raw output, scaled by 2^-53: exactly representable, in [0, 1)
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double ScenarioRng::uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

std::uint64_t ScenarioRng::index(std::uint64_t n) {
  if (n == 0) throw std::invalid_argument("ScenarioRng::index: n must be positive");
  // reject the top partial block of the 2^64 outputs so every residue is equally likely
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                              std::numeric_limits<std::uint64_t>::max() % n;
  std::uint64_t x = engine_();
  while (x >= limit) x = engine_();
  return x % n;
}

std::string toString(StartLayout layout) {
  return layout == StartLayout::kCross ? "cross" : "random";
}

StartLayout parseStartLayout(const std::string& text) {
  if (text == "cross") return StartLayout::kCross;
  if (text == "random") return StartLayout::kRandom;
  throw std::invalid_argument("start layout must be 'cross' or 'random', got '" + text + "'");
}

std::string toString(RobotLayout layout) {
  switch (layout) {
    case RobotLayout::kPaper:
      return "paper";
    case RobotLayout::kRows:
      return "rows";
    case RobotLayout::kRing:
      return "ring";
  }
  return "paper";
}

RobotLayout parseRobotLayout(const std::string& text) {
  if (text == "paper") return RobotLayout::kPaper;
  if (text == "rows") return RobotLayout::kRows;
  if (text == "ring") return RobotLayout::kRing;
  throw std::invalid_argument("robot layout must be 'paper', 'rows' or 'ring', got '" + text + "'");
}

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTableHeight = 0.75;  // [m], top face of every table
constexpr double kCubeEdge = 0.04;     // [m], Hand-E opens to 50 mm
// Shelf items stand 120 mm tall, so a gripper coming in from the side holds them high enough
// for its 75 mm wide body to clear the shelf board (core/grasps.h).
const Eigen::Vector3d kShelfItemSize(0.04, 0.04, 0.12);
// Shelf items start at least this far from a robot's base axis [m]: an item much nearer
// (0.17 m) has no collision-free grasp for either robot.
constexpr double kShelfBaseClearance = 0.25;
// Shelf items start turned by at most this much from the shelf's axes [rad]. Side grasps come
// in along a face normal; an item midway between the robots turned by 37 degrees or more has
// its faces towards each robot's base, too close for a horizontal grasp, and away from it,
// where the wrist meets the table: no grasp for either.
constexpr double kShelfMaxYaw = kPi / 6.0;
constexpr double kCubeMaxYaw = kPi / 4.0;  // [rad] a cube turned by more is one turned by less
constexpr double kCubeMass = 0.1;      // [kg]
constexpr double kCubeFriction = 0.8;
constexpr double kJitter = 0.01;  // [m], max offset of a cube from its lattice cell per axis
// cells are kMinCubeSpacing + 2 * kJitter apart so that jittered centres keep kMinCubeSpacing
constexpr double kCellPitch = kMinCubeSpacing + 2.0 * kJitter;
constexpr double kRowPitch = 1.0;  // [m] between the columns of the rows layout
constexpr int kMaxRowRobots = 8;
// ring layout: bases this far from the centre (six of them 0.75 m apart; home puts a gripper
// 0.49 m in front of its base, 0.26 m from the centre), cubes within kRingCubeRadius of it
constexpr double kRingRadius = 0.75;
constexpr double kRingCubeRadius = 0.35;
constexpr int kMinRingRobots = 3, kMaxRingRobots = 6;

constexpr std::array<double, 6> kHome{0.0, -1.5708, 1.5708, -1.5708, -1.5708, 0.0};
// shelving: kHome would put the gripper into the shelf (TCP 0.49 m ahead of the base), and a
// robot side by side with the other must wait out of its way: the arm straight up (TCP 1.08 m
// above the table), the wrist offsets (0.38 m sideways) pointing away from the other robot
constexpr std::array<double, 6> kShelfHomeRight{0.0, -1.5708, 0.0, -1.5708, 0.0, 0.0};  // towards +y
constexpr std::array<double, 6> kShelfHomeLeft{3.1416, -1.5708, 0.0, -1.5708, 0.0, 0.0};  // towards -y
constexpr core::Color kWood{0.62, 0.45, 0.28};
constexpr double kBinWall = 0.008;  // [m]
constexpr core::Color kShelfGrey{0.55, 0.56, 0.6};

// object classes in order, coloured by the world format's named colours (core/colors.h)
constexpr std::array<const char*, 4> kClassNames{"red", "green", "blue", "yellow"};

struct ClassInfo {
  const char* name;
  core::Color color;
};

ClassInfo classInfo(std::size_t k) { return {kClassNames[k], *core::colorByName(kClassNames[k])}; }

// A rectangular zone of cube centres in the table plane, given in a robot-like frame: origin
// p_W, unit axis u_W (the frame's x), lateral axis v_W = z × u; the zone is
// [x_lo, x_hi] × [y_lo, y_hi] in that frame.
struct Zone {
  Eigen::Vector2d p_W;
  Eigen::Vector2d u_W;
  double x_lo, x_hi, y_lo, y_hi;
};

// Lattice points of one axis: as many kCellPitch-spaced values as fit in [lo, hi], centred.
std::vector<double> latticeAxis(double lo, double hi) {
  const int count = static_cast<int>(std::floor((hi - lo) / kCellPitch + 1e-9)) + 1;
  const double start = lo + 0.5 * ((hi - lo) - (count - 1) * kCellPitch);
  std::vector<double> values;
  for (int i = 0; i < count; ++i) values.push_back(start + i * kCellPitch);
  return values;
}

std::vector<Eigen::Vector2d> zoneCells(const Zone& zone) {
  const Eigen::Vector2d v_W(-zone.u_W.y(), zone.u_W.x());
  std::vector<Eigen::Vector2d> cells;
  for (double x : latticeAxis(zone.x_lo, zone.x_hi)) {
    for (double y : latticeAxis(zone.y_lo, zone.y_hi)) {
      cells.push_back(zone.p_W + x * zone.u_W + y * v_W);
    }
  }
  return cells;
}

core::RobotSpec makeRobot(std::string name, const Eigen::Vector2d& p_W, double yaw,
                          const std::array<double, 6>& home = kHome) {
  core::RobotSpec robot;
  robot.name = std::move(name);
  robot.model = "ur5e_hande";
  robot.X_WBase = core::makePoseXyzYaw(Eigen::Vector3d(p_W.x(), p_W.y(), kTableHeight), yaw);
  robot.home = home;
  return robot;
}

core::FixtureSpec makeTable(double size_x, double size_y) {
  core::FixtureSpec table;
  table.name = "table";
  table.type = core::FixtureType::kBox;
  table.X_WF = core::Pose::Identity();
  table.size = Eigen::Vector3d(size_x, size_y, kTableHeight);
  table.color = kWood;
  return table;
}

/// Side of a square bin with room for `cubes` cubes side by side (the planner's goal slots, with
/// their pitch and the open gripper's reach from the walls: planner/sampling/object_sites.h), 0.2 m at
/// least [m].
double binSide(int cubes) {
  constexpr double kSlack = 0.004;  // [m]
  const double pitch = 0.04 + 2 * planner::kFingerRoom;  // 40 mm cubes
  const int per_row = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(std::max(cubes, 1))) - 1e-9));
  return std::max(0.2, 2 * planner::kOpenFingerReach + (per_row - 1) * pitch + kSlack + 2 * kBinWall);
}

core::FixtureSpec makeBin(const ClassInfo& cls, const Eigen::Vector2d& p_W, double side) {
  core::FixtureSpec bin;
  bin.name = std::string("bin_") + cls.name;
  bin.type = core::FixtureType::kBin;
  bin.X_WF = core::makePoseXyzYaw(Eigen::Vector3d(p_W.x(), p_W.y(), kTableHeight), 0.0);
  bin.size = Eigen::Vector3d(side, side, 0.08);
  bin.wall_thickness = kBinWall;
  bin.color = cls.color;
  return bin;
}

// A box of `size` standing on the table at a jittered lattice cell with a random yaw.
core::ObjectSpec makeBox(std::string name, const ClassInfo& cls, const Eigen::Vector3d& size,
                         const Eigen::Vector2d& cell_W, double max_yaw, ScenarioRng& rng) {
  const double dx = rng.uniform(-kJitter, kJitter);
  const double dy = rng.uniform(-kJitter, kJitter);
  const double yaw = rng.uniform(-max_yaw, max_yaw);
  core::ObjectSpec cube;
  cube.name = std::move(name);
  cube.size = size;
  cube.mass = kCubeMass;
  cube.friction = kCubeFriction;
  cube.color = cls.color;
  cube.object_class = cls.name;
  cube.X_WO = core::makePoseXyzYaw(
      Eigen::Vector3d(cell_W.x() + dx, cell_W.y() + dy, kTableHeight + 0.5 * size.z()), yaw);
  return cube;
}

// The robots of a sorting layout: base position, unit heading (exact, so that written
// coordinates carry no rounding noise) and the classes whose bins they own.
struct SortingRobot {
  Eigen::Vector2d p_W;
  Eigen::Vector2d heading_W;
  std::vector<int> owned_classes;
};

std::string describeZoneCapacity(const char* zone, std::size_t fit, std::size_t wanted) {
  return std::to_string(wanted) + " cubes must start in " + zone + " but only " +
         std::to_string(fit) + " fit there (centres at least 0.1 m apart)";
}

}  // namespace

namespace {

/// Where a sorting layout puts its table, robots, bins and the cells cubes may start in.
struct SortingLayout {
  core::FixtureSpec table;
  std::vector<SortingRobot> robots;
  std::vector<std::vector<Eigen::Vector2d>> exclusive_cells;  // per robot, in front of it
  std::vector<Eigen::Vector2d> random_cells;                  // where random starts draw from
  std::vector<Eigen::Vector2d> bin_positions = std::vector<Eigen::Vector2d>(kClassNames.size());
  std::vector<Eigen::Vector2d> bin_outward = std::vector<Eigen::Vector2d>(kClassNames.size());  // a bigger bin grows this way
};

void checkSortingParams(const SortingParams& params) {
  const bool rows = params.layout == RobotLayout::kRows;
  const bool ring = params.layout == RobotLayout::kRing;
  if (params.layout == RobotLayout::kPaper && params.robots != 2 && params.robots != 4) {
    throw std::invalid_argument("sorting: robots must be 2 or 4, got " +
                                std::to_string(params.robots));
  }
  if (rows && (params.robots < 2 || params.robots > kMaxRowRobots || params.robots % 2 != 0)) {
    throw std::invalid_argument("sorting: robots in rows must be even, 2.." + std::to_string(kMaxRowRobots) +
                                ", got " + std::to_string(params.robots));
  }
  if (ring && (params.robots < kMinRingRobots || params.robots > kMaxRingRobots)) {
    throw std::invalid_argument("sorting: robots in a ring must be " + std::to_string(kMinRingRobots) + ".." +
                                std::to_string(kMaxRingRobots) + ", got " + std::to_string(params.robots));
  }
  if (params.classes < 1 || params.classes > 4) {
    throw std::invalid_argument("sorting: classes must be in 1..4, got " +
                                std::to_string(params.classes));
  }
  if (params.layout == RobotLayout::kPaper && params.robots == 4 && params.classes != 4) {
    throw std::invalid_argument("sorting: 4 robots need exactly 4 classes (one per robot), got " +
                                std::to_string(params.classes));
  }
  if (ring && params.classes > params.robots) {
    throw std::invalid_argument("sorting: a ring of " + std::to_string(params.robots) +
                                " robots owns at most one class per robot, got " + std::to_string(params.classes) +
                                " classes");
  }
  if (params.cubes < 1) {
    throw std::invalid_argument("sorting: cubes must be at least 1, got " +
                                std::to_string(params.cubes));
  }
}

/// Robots in two facing rows along a long table, the bins at its ends.
SortingLayout rowsLayout(const SortingParams& params) {
  SortingLayout layout;
  const int columns = params.robots / 2;
  const double half = 0.5 * (columns - 1) * kRowPitch;  // x of the last column
  layout.table = makeTable(2 * half + 1.6, 1.4);
  for (int r = 0; r < params.robots; ++r) {
    const double side = r % 2 == 0 ? -1.0 : 1.0;  // r(2k) in the row at y < 0
    const Eigen::Vector2d p(-half + (r / 2) * kRowPitch + 0.0, side * 0.7);
    const Eigen::Vector2d u(0.0, -side);
    layout.robots.push_back({p, u, {}});
    layout.exclusive_cells.push_back(zoneCells({p, u, 0.25, 0.45, -0.3, 0.3}));
  }
  // red and blue beyond the first column, green and yellow beyond the last
  layout.robots[0].owned_classes = {0};
  layout.robots[1].owned_classes = {2};
  layout.robots[params.robots - 1].owned_classes.push_back(1);
  layout.robots[params.robots - 2].owned_classes.push_back(3);
  layout.bin_positions = {{-half - 0.5, -0.35}, {half + 0.5, 0.35}, {-half - 0.5, 0.35}, {half + 0.5, -0.35}};
  layout.bin_outward = {{-1.0, 0.0}, {1.0, 0.0}, {-1.0, 0.0}, {1.0, 0.0}};
  layout.random_cells = zoneCells({{0.0, 0.0}, {1.0, 0.0}, -half - 0.3, half + 0.3, -0.26, 0.26});
  return layout;
}

/// Robots evenly spaced on a circle around one shared centre, robot k owning class k.
SortingLayout ringLayout(const SortingParams& params) {
  SortingLayout layout;
  const int n = params.robots;
  layout.table = makeTable(2 * kRingRadius + 0.9, 2 * kRingRadius + 0.9);
  // (rounded, so that written coordinates carry no rounding noise: e.g. r0 faces +x exactly)
  const auto rounded = [](const Eigen::Vector2d& x, double unit) {
    return Eigen::Vector2d((x / unit).array().round() * unit + 0.0);
  };
  for (int k = 0; k < n; ++k) {
    const double a = kPi + 2 * kPi * k / n;
    const Eigen::Vector2d out = rounded({std::cos(a), std::sin(a)}, 1e-12);  // from the centre to the base
    const Eigen::Vector2d u = -out, v(out.y(), -out.x());  // heading, the robot's left
    const Eigen::Vector2d p = rounded(kRingRadius * out, 1e-6);
    layout.robots.push_back({p, u, {}});
    if (k < params.classes) {
      layout.robots[k].owned_classes = {k};
      layout.bin_positions[k] = rounded(p - 0.2 * u + 0.3 * v, 1e-6);  // as in the square
      layout.bin_outward[k] = v;
    }
  }
  // the lattice of the centre disc, each cell in the zone of the robot nearest by angle
  layout.exclusive_cells.resize(n);
  const Zone square{{0.0, 0.0}, {1.0, 0.0}, -kRingCubeRadius, kRingCubeRadius, -kRingCubeRadius, kRingCubeRadius};
  for (const Eigen::Vector2d& cell : zoneCells(square)) {
    if (cell.norm() > kRingCubeRadius) continue;
    layout.random_cells.push_back(cell);
    int nearest = 0;
    for (int k = 1; k < n; ++k) {
      if (-layout.robots[k].heading_W.dot(cell) > -layout.robots[nearest].heading_W.dot(cell) + 1e-12) nearest = k;
    }
    layout.exclusive_cells[nearest].push_back(cell);
  }
  return layout;
}

/// The paper's two robots facing each other across a table.
SortingLayout pairLayout() {
  SortingLayout layout;
  layout.table = makeTable(2.0, 1.4);
  layout.robots = {{{-0.7, 0.0}, {1.0, 0.0}, {0, 2}},  // r0 owns red, blue
            {{0.7, 0.0}, {-1.0, 0.0}, {1, 3}}};  // r1 owns green, yellow
  layout.bin_positions = {{-0.5, -0.42}, {0.5, 0.42}, {-0.5, 0.42}, {0.5, -0.42}};
  layout.bin_outward = {{0.0, -1.0}, {0.0, 1.0}, {0.0, 1.0}, {0.0, -1.0}};  // away from the cubes
  // zones in the world frame (identity frame): robot-exclusive strips and the shared area
  const Eigen::Vector2d o(0.0, 0.0), x(1.0, 0.0);
  layout.exclusive_cells = {zoneCells({o, x, -0.45, -0.25, -0.26, 0.26}), zoneCells({o, x, 0.25, 0.45, -0.26, 0.26})};
  layout.random_cells = zoneCells({o, x, -0.45, 0.45, -0.26, 0.26});
  return layout;
}

/// The paper's four robots in a square facing the centre.
SortingLayout squareLayout() {
  SortingLayout layout;
  layout.table = makeTable(2.4, 2.4);
  const std::array<Eigen::Vector2d, 4> headings{
      Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, 1.0), Eigen::Vector2d(-1.0, 0.0),
      Eigen::Vector2d(0.0, -1.0)};
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d& u = headings[k];
    const Eigen::Vector2d v(-u.y(), u.x());  // the robot's left
    // (+ 0.0 turns the -0.0 of an exact product into 0.0, which reads better when written)
    const Eigen::Vector2d p = (-0.75 * u).array() + 0.0;
    layout.robots.push_back({p, u, {k}});
    // the bin is beside the robot on its left and slightly behind it
    layout.bin_positions[k] = (p - 0.2 * u + 0.3 * v).array() + 0.0;
    layout.bin_outward[k] = v;
    layout.exclusive_cells.push_back(zoneCells({p, u, 0.25, 0.45, -0.15, 0.15}));
    layout.random_cells.insert(layout.random_cells.end(), layout.exclusive_cells.back().begin(), layout.exclusive_cells.back().end());
  }
  return layout;
}

/// The world's name and description, naming the command that generates it.
void describeSorting(const SortingParams& params, core::World& world) {
  const bool rows = params.layout == RobotLayout::kRows;
  const bool ring = params.layout == RobotLayout::kRing;
  const std::string layout = toString(params.start);
  const bool paper = params.layout == RobotLayout::kPaper;
  const std::string layout_option = paper ? "" : "--layout " + toString(params.layout) + " ";
  world.name = "sort_" + std::to_string(params.robots) + "r_" + std::to_string(params.cubes) + "c_" +
               (paper ? "" : toString(params.layout) + "_") + layout + "_s" + std::to_string(params.seed);
  const char* placement = rows                 ? "in two facing rows along a table (the bins at its ends)"
                          : ring               ? "evenly spaced on a circle around one shared centre"
                          : params.robots == 2 ? "facing each other across a table"
                                               : "in a square facing the centre";
  const char* start = params.start == StartLayout::kRandom
                          ? "random start in the shared workspace"
                      : ring ? "cross start (every cube starts across the ring from its bin's robot)"
                             : "cross start (every cube starts away from its bin's robot and must be handed over)";
  world.description = std::string(paper ? "Sorting (DaSH paper): " : "Sorting: ") + std::to_string(params.robots) +
                      " UR5e + Hand-E robots " + placement + " sort " + std::to_string(params.cubes) + " cubes of " +
                      std::to_string(params.classes) + " colour classes into their bins; " + start +
                      "; generated by `dashbed gen sort " + layout_option + "--robots " + std::to_string(params.robots) +
                      " --cubes " + std::to_string(params.cubes) + " --classes " + std::to_string(params.classes) +
                      " --start " + layout + " --seed " + std::to_string(params.seed) + "`.";
}

}  // namespace

core::World generateSorting(const SortingParams& params) {
  checkSortingParams(params);
  const bool rows = params.layout == RobotLayout::kRows;
  const bool ring = params.layout == RobotLayout::kRing;
  SortingLayout layout = rows ? rowsLayout(params) : ring ? ringLayout(params) : params.robots == 2 ? pairLayout()
                                                                                                  : squareLayout();
  core::World world;
  world.fixtures.push_back(layout.table);
  const std::vector<SortingRobot>& robots = layout.robots;
  const std::vector<Eigen::Vector2d>& bin_positions = layout.bin_positions;
  const std::vector<Eigen::Vector2d>& bin_outward = layout.bin_outward;
  std::vector<std::vector<Eigen::Vector2d>>& exclusive_cells = layout.exclusive_cells;
  std::vector<Eigen::Vector2d>& random_cells = layout.random_cells;

  for (std::size_t r = 0; r < robots.size(); ++r) {
    const double yaw = std::atan2(robots[r].heading_W.y(), robots[r].heading_W.x());
    world.robots.push_back(makeRobot("r" + std::to_string(r), robots[r].p_W, yaw));
  }
  for (int c = 0; c < params.classes; ++c) {
    const int cubes_of_class = params.cubes / params.classes + (c < params.cubes % params.classes ? 1 : 0);
    const double side = binSide(cubes_of_class);
    const Eigen::Vector2d p_W = bin_positions[c] + (side - 0.2) / 2 * bin_outward[c];
    world.fixtures.push_back(makeBin(classInfo(c), p_W, side));
  }

  // class of each cube (round robin) and the robot owning that class's bin
  std::vector<int> cube_class(params.cubes);
  std::vector<int> class_owner(kClassNames.size(), -1);
  for (std::size_t r = 0; r < robots.size(); ++r) {
    for (int c : robots[r].owned_classes) class_owner[c] = static_cast<int>(r);
  }
  for (int i = 0; i < params.cubes; ++i) cube_class[i] = i % params.classes;

  // start zone of each cube: cross puts a cube in front of a robot that cannot reach its bin
  // (the other robot of two; the opposite robot of four, or across a ring), random draws from
  // one pooled zone
  std::vector<int> cube_zone(params.cubes, 0);
  std::vector<std::vector<Eigen::Vector2d>> cells;
  if (params.start == StartLayout::kCross) {
    cells = exclusive_cells;
    const int n = params.robots;
    for (int i = 0; i < params.cubes; ++i) {
      const int owner = class_owner[cube_class[i]];
      // rows: the other end column, the other row (the two orders mirror each other)
      cube_zone[i] = rows ? n - 1 - owner : (owner + n / 2) % n;
    }
  } else {
    cells = {random_cells};
  }

  // cells per zone, shuffled by the seed
  ScenarioRng rng(params.seed);
  for (std::size_t z = 0; z < cells.size(); ++z) {
    const auto wanted = static_cast<std::size_t>(
        std::count(cube_zone.begin(), cube_zone.end(), static_cast<int>(z)));
    if (wanted > cells[z].size()) {
      const std::string zone_name = params.start == StartLayout::kCross
                                        ? "the zone of r" + std::to_string(z)
                                        : std::string("the shared workspace");
      throw std::invalid_argument("sorting: " +
                                  describeZoneCapacity(zone_name.c_str(), cells[z].size(), wanted));
    }
    rng.shuffle(cells[z]);
  }

  std::vector<std::size_t> next_cell(cells.size(), 0);
  for (int i = 0; i < params.cubes; ++i) {
    const int z = cube_zone[i];
    const ClassInfo cls = classInfo(cube_class[i]);
    world.objects.push_back(
        makeBox("cube_" + std::to_string(i), cls, Eigen::Vector3d::Constant(kCubeEdge), cells[z][next_cell[z]++],
                kCubeMaxYaw, rng));
  }
  // a class goal for each class that has cubes (with fewer cubes than classes some bins stay
  // empty; a goal for a class without objects would be an error in the world file)
  for (int c = 0; c < std::min(params.classes, params.cubes); ++c) {
    core::Goal goal;
    goal.object_class = classInfo(c).name;
    goal.region = std::string("bin_") + classInfo(c).name;
    world.goals.push_back(goal);
  }

  describeSorting(params, world);
  return world;
}

core::World generateShelving(const ShelvingParams& params) {
  if (params.objects < 2 || params.objects > 12 || params.objects % 2 != 0) {
    throw std::invalid_argument("shelving: objects must be even and in 2..12, got " +
                                std::to_string(params.objects));
  }
  constexpr int kColumns = 6;
  constexpr double kBoardTop = kTableHeight + 0.2;  // [m], top face of the shelf board
  constexpr double kBackX = 0.67, kFrontX = 0.56;   // [m], slot centres

  core::World world;
  world.fixtures.push_back(makeTable(2.0, 1.6));
  world.robots.push_back(makeRobot("r0", Eigen::Vector2d(0.05, -0.35), 0.0, kShelfHomeLeft));
  world.robots.push_back(makeRobot("r1", Eigen::Vector2d(0.05, 0.35), 0.0, kShelfHomeRight));

  // shelf: opening towards -x (the robots), one board 0.2 above the table and the top board
  core::FixtureSpec shelf;
  shelf.name = "shelf";
  shelf.type = core::FixtureType::kShelf;
  shelf.X_WF = core::makePoseXyzYaw(Eigen::Vector3d(0.6, 0.0, kTableHeight), 0.0);
  shelf.size = Eigen::Vector3d(0.3, 1.0, 0.5);
  shelf.wall_thickness = 0.02;
  shelf.levels = {0.2};
  shelf.color = kShelfGrey;
  world.fixtures.push_back(shelf);

  // a back and a front slot per column, the front one directly in front of the back one
  auto slotName = [](int column, const char* side) {
    return "slot_" + std::to_string(column) + "_" + side;
  };
  for (int j = 0; j < kColumns; ++j) {
    const double y = (-35.0 + 14.0 * j) / 100.0;  // -0.35 + 0.14 j, rounded once
    for (const auto& [side, x] : {std::pair{"back", kBackX}, std::pair{"front", kFrontX}}) {
      core::Region region;
      region.name = slotName(j, side);
      region.X_WR = core::makePoseXyzYaw(Eigen::Vector3d(x, y, kBoardTop), 0.0);
      region.size = Eigen::Vector3d(0.08, 0.08, 0.1);
      world.regions.push_back(region);
    }
  }

  ScenarioRng rng(params.seed);
  std::vector<int> columns(kColumns);
  for (int j = 0; j < kColumns; ++j) columns[j] = j;
  rng.shuffle(columns);
  const int pairs = params.objects / 2;
  columns.resize(pairs);
  std::sort(columns.begin(), columns.end());

  // start cells on the table between the robots and the shelf
  std::vector<Eigen::Vector2d> cells =
      zoneCells({{0.0, 0.0}, {1.0, 0.0}, 0.2, 0.38, -0.6, 0.6});
  rng.shuffle(cells);
  // ... not so close to a base that its arm cannot fold down to the object (after the shuffle,
  // so that the other cells keep their order)
  std::erase_if(cells, [&](const Eigen::Vector2d& cell) {
    return std::any_of(world.robots.begin(), world.robots.end(), [&](const core::RobotSpec& robot) {
      return (cell - robot.X_WBase.translation().head<2>()).norm() < kShelfBaseClearance;
    });
  });

  const ClassInfo green = classInfo(1);
  const ClassInfo blue = classInfo(2);
  std::size_t next_cell = 0;
  for (int k = 0; k < pairs; ++k) {
    for (const auto& [cls, side] : {std::pair{&green, "back"}, std::pair{&blue, "front"}}) {
      const std::string name = std::string(cls->name) + "_" + std::to_string(k);
      world.objects.push_back(makeBox(name, *cls, kShelfItemSize, cells[next_cell++], kShelfMaxYaw, rng));
      core::Goal goal;
      goal.object = name;
      goal.region = slotName(columns[k], side);
      world.goals.push_back(goal);
    }
  }

  world.name = "shelf_2r_" + std::to_string(params.objects) + "o_s" + std::to_string(params.seed);
  world.description =
      "Shelving (DaSH paper): 2 UR5e + Hand-E robots stock a shelf with " +
      std::to_string(pairs) + " pairs of objects; each green object goes to a back slot and its "
      "blue partner to the front slot directly in front of it, so green must be placed first; "
      "generated by `dashbed gen shelf --objects " + std::to_string(params.objects) +
      " --seed " + std::to_string(params.seed) + "`.";
  return world;
}

}  // namespace dashbed::tools
