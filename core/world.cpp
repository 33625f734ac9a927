#include "core/world.h"

#include <algorithm>
#include <string>

namespace dashbed::core {
namespace {

template <typename T>
const T* findByName(const std::vector<T>& items, std::string_view name) {
  const auto it = std::find_if(items.begin(), items.end(),
                               [&](const T& item) { return item.name == name; });
  return it == items.end() ? nullptr : &*it;
}

// a box of `size` centred at p_FC in the fixture frame
Box fixtureBox(const FixtureSpec& fixture, const Eigen::Vector3d& p_FC,
               const Eigen::Vector3d& size) {
  Box box;
  box.X_WB = fixture.X_WF * Eigen::Translation3d(p_FC);
  box.size = size;
  return box;
}

StableSurface fixtureSurface(const FixtureSpec& fixture, std::string name,
                             const Eigen::Vector3d& p_FS, const Eigen::Vector2d& size) {
  StableSurface surface;
  surface.name = std::move(name);
  surface.X_WS = fixture.X_WF * Eigen::Translation3d(p_FS);
  surface.size = size;
  surface.fixture = fixture.name;
  surface.where = fixture.where;
  return surface;
}

}  // namespace

double distanceOutside(const Region& region, const Eigen::Vector3d& p_W, double tolerance) {
  const Eigen::Vector3d p = region.X_WR.inverse() * p_W;
  const Eigen::Vector3d half = region.size / 2 + Eigen::Vector3d::Constant(tolerance);
  const Eigen::Vector3d lo(-half.x(), -half.y(), -tolerance);
  const Eigen::Vector3d hi(half.x(), half.y(), region.size.z() + tolerance);
  return (p.cwiseMax(lo).cwiseMin(hi) - p).norm();
}

const RobotSpec* World::findRobot(std::string_view wanted) const {
  return findByName(robots, wanted);
}
const ObjectSpec* World::findObject(std::string_view wanted) const {
  return findByName(objects, wanted);
}
const Region* World::findRegion(std::string_view wanted) const {
  return findByName(regions, wanted);
}
const FixtureSpec* World::findFixture(std::string_view wanted) const {
  return findByName(fixtures, wanted);
}

const Goal* World::goalOf(const ObjectSpec& object) const {
  for (const Goal& goal : goals) {
    if (!goal.object.empty() && goal.object == object.name) return &goal;
  }
  if (object.object_class.empty()) return nullptr;
  for (const Goal& goal : goals) {
    if (goal.object.empty() && goal.object_class == object.object_class) return &goal;
  }
  return nullptr;
}

const Region* World::goalRegionOf(const ObjectSpec& object) const {
  const Goal* goal = goalOf(object);
  return goal != nullptr ? findRegion(goal->region) : nullptr;
}

void deriveFixtureGeometry(World& world) {
  std::erase_if(world.surfaces, [](const StableSurface& s) { return !s.fixture.empty(); });
  std::erase_if(world.regions, [](const Region& r) { return !r.fixture.empty(); });

  for (FixtureSpec& fixture : world.fixtures) {
    const double sx = fixture.size.x();
    const double sy = fixture.size.y();
    const double sz = fixture.size.z();
    const double w = fixture.wall_thickness;
    fixture.boxes.clear();
    switch (fixture.type) {
      case FixtureType::kBox: {
        fixture.boxes.push_back(fixtureBox(fixture, {0.0, 0.0, sz / 2}, fixture.size));
        world.surfaces.push_back(
            fixtureSurface(fixture, fixture.name + "/top", {0.0, 0.0, sz}, {sx, sy}));
        break;
      }
      case FixtureType::kBin: {
        // the floor, then on it the walls at -x, +x (full depth) and -y, +y (between them);
        // the walls' tops are at the bin's full height
        fixture.boxes.push_back(fixtureBox(fixture, {0.0, 0.0, w / 2}, {sx, sy, w}));
        const double wall_height = sz - w;
        const double wall_center = w + wall_height / 2;
        for (const double side : {-1.0, 1.0}) {
          fixture.boxes.push_back(fixtureBox(fixture, {side * (sx - w) / 2, 0.0, wall_center},
                                             {w, sy, wall_height}));
        }
        for (const double side : {-1.0, 1.0}) {
          fixture.boxes.push_back(fixtureBox(fixture, {0.0, side * (sy - w) / 2, wall_center},
                                             {sx - 2 * w, w, wall_height}));
        }
        world.surfaces.push_back(
            fixtureSurface(fixture, fixture.name + "/floor", {0.0, 0.0, w}, {sx - 2 * w, sy - 2 * w}));
        Region inside;
        inside.name = fixture.name;
        inside.X_WR = fixture.X_WF * Eigen::Translation3d(0.0, 0.0, w);
        inside.size = {sx - 2 * w, sy - 2 * w, sz - w};
        inside.fixture = fixture.name;
        inside.where = fixture.where;
        world.regions.push_back(inside);
        break;
      }
      case FixtureType::kShelf: {
        // side panels at -y, +y (full size), back panel at +x between them; boards span from
        // the open front (-x) to the back panel
        for (const double side : {-1.0, 1.0}) {
          fixture.boxes.push_back(
              fixtureBox(fixture, {0.0, side * (sy - w) / 2, sz / 2}, {sx, w, sz}));
        }
        fixture.boxes.push_back(
            fixtureBox(fixture, {(sx - w) / 2, 0.0, sz / 2}, {w, sy - 2 * w, sz}));
        const Eigen::Vector3d board_size{sx - w, sy - 2 * w, w};
        for (std::size_t k = 0; k < fixture.levels.size(); ++k) {
          const double top = fixture.levels[k];
          fixture.boxes.push_back(fixtureBox(fixture, {-w / 2, 0.0, top - w / 2}, board_size));
          world.surfaces.push_back(fixtureSurface(fixture, fixture.name + "/board" + std::to_string(k),
                                                  {-w / 2, 0.0, top}, board_size.head<2>()));
        }
        fixture.boxes.push_back(fixtureBox(fixture, {-w / 2, 0.0, sz - w / 2}, board_size));
        break;
      }
    }
  }
}

}  // namespace dashbed::core
