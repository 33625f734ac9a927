#include "planner/sampling/object_sites.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <stdexcept>
#include <string>

#include "core/geometry.h"

namespace dashbed::planner {

void SiteSet::set(int site, bool on) {
  if (site < 0 || site >= static_cast<int>(bits_.size()) * 64) {
    throw std::out_of_range("site set: site " + std::to_string(site) + " out of range");
  }
  const std::uint64_t bit = std::uint64_t{1} << (site % 64);
  if (on) {
    bits_[site / 64] |= bit;
  } else {
    bits_[site / 64] &= ~bit;
  }
}

bool SiteSet::test(int site) const {
  if (site < 0 || site >= static_cast<int>(bits_.size()) * 64) return false;
  return (bits_[site / 64] >> (site % 64)) & 1U;
}

bool SiteSet::intersects(const SiteSet& other) const {
  const std::size_t n = std::min(bits_.size(), other.bits_.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (bits_[i] & other.bits_[i]) return true;
  }
  return false;
}

bool SiteSet::subsetOf(const SiteSet& other) const {
  if (bits_.size() != other.bits_.size()) throw std::invalid_argument("site set: subsetOf a set of other sites");
  for (std::size_t i = 0; i < bits_.size(); ++i) {
    if (bits_[i] & ~other.bits_[i]) return false;
  }
  return true;
}

bool SiteSet::none() const {
  return std::all_of(bits_.begin(), bits_.end(), [](std::uint64_t word) { return word == 0; });
}

std::optional<RestingObject> ObjectSites::site(int index) const {
  if (index < 0 || index >= numSites()) throw std::invalid_argument("site " + std::to_string(index) + " out of range");
  const int object = objectOf(index);
  if (index == startSite(object)) return RestingObject{object, start[object]};
  if (index == goalSite(object)) return goal[object] ? std::optional(RestingObject{object, *goal[object]}) : std::nullopt;
  const bool set_aside = static_cast<std::size_t>(object) < aside.size() && aside[object];
  return set_aside ? std::optional(RestingObject{object, *aside[object]}) : std::nullopt;
}

std::vector<Eigen::Vector3d> regionSlots(const core::Region& region, const Eigen::Vector3d& size) {
  const double pitch_x = size.x() + 2 * kFingerRoom, pitch_y = size.y() + 2 * kFingerRoom;
  // centres keep the open gripper's reach from the region's edges (a bin's walls)
  const double edge_x = std::max(size.x() / 2, kOpenFingerReach), edge_y = std::max(size.y() / 2, kOpenFingerReach);
  const int nx = std::max(1, static_cast<int>(std::floor((region.size.x() - 2 * edge_x) / pitch_x + 1e-9)) + 1);
  const int ny = std::max(1, static_cast<int>(std::floor((region.size.y() - 2 * edge_y) / pitch_y + 1e-9)) + 1);
  std::vector<Eigen::Vector3d> slots;
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      const Eigen::Vector3d p_R((ix - (nx - 1) / 2.0) * pitch_x, (iy - (ny - 1) / 2.0) * pitch_y, size.z() / 2);
      slots.push_back(region.X_WR * p_R);
    }
  }
  return slots;
}

namespace {

/// The rotation of R_WO's axis nearest the world vertical onto the vertical, keeping which
/// face is down, then turned about the vertical to `yaw`: the resting orientation at a goal.
Eigen::Matrix3d restingOrientation(const Eigen::Matrix3d& R_WO, double yaw) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(R_WO(2, i)) > std::abs(R_WO(2, k))) k = i;
  }
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  const bool up = R_WO(2, k) > 0.0;
  // R_WO' columns: object axis a -> world x, b -> y, k -> z (or b, a, -k when upside down)
  Eigen::Matrix3d R_UO = Eigen::Matrix3d::Zero();
  R_UO(0, up ? a : b) = 1.0;
  R_UO(1, up ? b : a) = 1.0;
  R_UO(2, k) = up ? 1.0 : -1.0;
  return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * R_UO;
}

/// The object's extent along the region's axes when its orientation is R_WO.
Eigen::Vector3d footprintIn(const core::Region& region, const Eigen::Matrix3d& R_WO, const Eigen::Vector3d& size) {
  return core::rotatedBoxExtent(region.X_WR.linear().transpose() * R_WO, size);
}

}  // namespace

bool restsIn(const core::Region& region, const core::Pose& X_WO) {
  return core::distanceOutside(region, X_WO.translation()) <= 0.0;
}

namespace {

/// An object resting in a region, or the goal given to one there: what other slots keep clear of.
struct Occupant {
  core::Pose X_WO;
  Eigen::Vector3d size;
};

/// Whether a slot at p_W for an object of `footprint` (along the region's axes) keeps the
/// fingers' room from every occupant.
bool clearOf(const std::vector<Occupant>& occupants, const core::Region& region, const Eigen::Vector3d& p_W,
             const Eigen::Vector3d& footprint) {
  return std::none_of(occupants.begin(), occupants.end(), [&](const Occupant& other) {
    const Eigen::Vector3d d = region.X_WR.linear().transpose() * (other.X_WO.translation() - p_W);
    const Eigen::Vector3d reach =
        (footprint + footprintIn(region, other.X_WO.linear(), other.size)) / 2 + Eigen::Vector3d::Constant(kFingerRoom);
    return std::abs(d.x()) < reach.x() && std::abs(d.y()) < reach.y();
  });
}

/// The sites of every object, those marked in `stays` left at their starts (no goal site) and
/// the others' slots clear of them and of each other (objects of other sizes have other slot
/// grids). std::nullopt, with why in `full`, when a region has no room for the objects sent
/// there.
std::optional<ObjectSites> assignSites(const core::LoadedWorld& loaded, const std::vector<bool>& stays,
                                       std::string& full) {
  const core::World& world = *loaded.world;
  ObjectSites sites;
  // per region (by index): the objects staying in it, the goals given out in it
  std::vector<std::vector<Occupant>> staying(world.regions.size()), given(world.regions.size());
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    const core::ObjectSpec& object = world.objects[o];
    if (const core::Region* region = world.goalRegionOf(object); stays[o] && region != nullptr) {
      staying[static_cast<std::size_t>(region - world.regions.data())].push_back({object.X_WO, object.size});
    }
  }
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    const core::ObjectSpec& object = world.objects[o];
    sites.start.push_back(object.X_WO);
    const core::Region* region = stays[o] ? nullptr : world.goalRegionOf(object);
    if (region == nullptr) {
      sites.goal.emplace_back();
      sites.goal_region.push_back(-1);
      continue;
    }
    const auto r = static_cast<std::size_t>(region - world.regions.data());
    sites.goal_region.push_back(static_cast<int>(r));
    const Eigen::Matrix3d R_WO =
        restingOrientation(object.X_WO.linear(), std::atan2(region->X_WR.linear()(1, 0), region->X_WR.linear()(0, 0)));
    const Eigen::Vector3d footprint = footprintIn(*region, R_WO, object.size);
    std::vector<core::Pose> slots;
    for (const Eigen::Vector3d& p : regionSlots(*region, footprint)) {
      if (!clearOf(staying[r], *region, p, footprint)) continue;
      core::Pose X_WO = core::Pose::Identity();
      X_WO.linear() = R_WO;
      X_WO.translation() = p;
      slots.push_back(X_WO);
    }
    const auto reached = [&](const core::Pose& X_WO) {
      const auto& robots = loaded.robots->robots();
      return std::any_of(robots.begin(), robots.end(),
                         [&](const core::PlacedRobot& robot) { return core::reachesBox(robot, X_WO, object.size); });
    };
    const auto in_reach = std::stable_partition(slots.begin(), slots.end(), reached);
    const auto slot = std::find_if(slots.begin(), in_reach, [&](const core::Pose& X_WO) {
      return clearOf(given[r], *region, X_WO.translation(), footprint);
    });
    if (slot == in_reach) {
      const auto room = static_cast<std::size_t>(in_reach - slots.begin());
      full = "region " + region->name + " has room for " + std::to_string(room) + (room == 1 ? " object" : " objects") +
             " side by side within reach of a robot (" + std::to_string(slots.size()) + " in all); more are sent there";
      return std::nullopt;
    }
    sites.goal.push_back(*slot);
    given[r].push_back({*slot, object.size});
  }
  sites.aside.resize(sites.start.size());
  return sites;
}

}  // namespace

ObjectSites objectSites(const core::LoadedWorld& loaded) {
  const core::World& world = *loaded.world;
  std::vector<bool> stays(world.objects.size(), false);
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    const core::Region* region = world.goalRegionOf(world.objects[o]);
    stays[o] = region != nullptr && restsIn(*region, world.objects[o].X_WO);
  }
  std::string full;
  if (std::optional<ObjectSites> sites = assignSites(loaded, stays, full)) return *sites;
  // the objects already in their regions leave the others no room: every object gets a slot
  if (std::optional<ObjectSites> sites = assignSites(loaded, std::vector<bool>(world.objects.size(), false), full)) {
    return *sites;
  }
  throw std::runtime_error(full);
}

core::ReachMap placementReach(const core::LoadedWorld& world, const ObjectSites& sites) {
  core::ReachMap reach = world.reach;
  for (int o = 0; o < sites.numObjects(); ++o) {
    std::vector<int>& placers = reach.goal[static_cast<std::size_t>(o)];
    placers.clear();
    if (!sites.goal[o]) continue;
    for (std::size_t r = 0; r < world.robots->size(); ++r) {
      if (core::reachesBox((*world.robots)[r], *sites.goal[o], world.world->objects[o].size)) {
        placers.push_back(static_cast<int>(r));
      }
    }
  }
  return reach;
}

namespace {

/// Height above an object that a gripper picking it from above takes up: 157 mm from the UR
/// tool flange to the Hand-E's fingertips (I/O coupling 11 mm + 99 mm + 46.5 mm fingertip,
/// github.com/AGH-CEAI/robotiq_hande_description) plus the 100 mm straight approach, rounded [m].
constexpr double kGripperAbove = 0.25;

/// UR5e base radius (149 mm base diameter, Universal Robots UR5e data sheet) plus 15 mm [m].
constexpr double kRobotBaseRadius = 0.09;

/// The horizontal distance from p_W to an upright box (X_WB its centre, yawed only) when the
/// box's height span meets [z_low, z_high], else infinity.
double horizontalGap(const core::Pose& X_WB, const Eigen::Vector3d& size, const Eigen::Vector3d& p_W, double z_low,
                     double z_high) {
  const double z = X_WB.translation().z();
  if (z + size.z() / 2 <= z_low + 1e-6 || z - size.z() / 2 >= z_high) return std::numeric_limits<double>::infinity();
  const Eigen::Vector3d p_B = X_WB.inverse(Eigen::Isometry) * p_W;
  const Eigen::Vector2d outside = (p_B.head<2>().cwiseAbs() - size.head<2>() / 2).cwiseMax(0.0);
  return outside.norm();
}

/// Radius of the circle around an object's footprint, for an orientation R_WO.
double footprintRadius(const Eigen::Matrix3d& R_WO, const Eigen::Vector3d& size) {
  return core::rotatedBoxExtent(R_WO, size).head<2>().norm() / 2;
}

/// The stable surface an object rests on (bottom within 5 mm of it, centre over it), or null.
const core::StableSurface* surfaceUnder(const core::World& world, const core::Pose& X_WO, const Eigen::Vector3d& size) {
  const double half_height = core::rotatedBoxExtent(X_WO.linear(), size).z() / 2;
  for (const core::StableSurface& surface : world.surfaces) {
    const Eigen::Vector3d p_S = surface.X_WS.inverse(Eigen::Isometry) * X_WO.translation();
    if (std::abs(p_S.x()) <= surface.size.x() / 2 && std::abs(p_S.y()) <= surface.size.y() / 2 &&
        std::abs(p_S.z() - half_height) <= 0.005) {
      return &surface;
    }
  }
  return nullptr;
}

}  // namespace

std::vector<int> setAsideSites(const core::LoadedWorld& loaded, ObjectSites& sites, const std::vector<int>& objects,
                               const std::function<bool(int, const core::Pose&)>& keeps_clear) {
  const core::World& world = *loaded.world;
  constexpr double kPitch = 0.03;  // candidate spacing on the surface [m]
  std::vector<int> given;
  for (const int o : objects) {
    const core::ObjectSpec& object = world.objects[static_cast<std::size_t>(o)];
    const core::Pose& X_start = sites.start[static_cast<std::size_t>(o)];
    const core::StableSurface* surface = surfaceUnder(world, X_start, object.size);
    if (surface == nullptr) continue;
    const double radius = footprintRadius(X_start.linear(), object.size);
    const double bottom = X_start.translation().z() - core::rotatedBoxExtent(X_start.linear(), object.size).z() / 2;
    // fixtures and regions count from the object's bottom up to where a gripper coming from above
    // would be
    const double top = 2 * X_start.translation().z() - bottom + kGripperAbove;
    // the room around p_W: to the other sites, the regions and fixtures at its height, the robots' bases
    const auto room = [&](const Eigen::Vector3d& p_W) {
      double least = std::numeric_limits<double>::infinity();
      for (int s = 0; s < sites.numSites(); ++s) {
        const std::optional<RestingObject> other = sites.site(s);
        if (!other) continue;
        const Eigen::Vector3d d = other->X_WO.translation() - p_W;
        const Eigen::Vector3d& other_size = world.objects[static_cast<std::size_t>(other->object)].size;
        least = std::min(least, d.head<2>().norm() - footprintRadius(other->X_WO.linear(), other_size) - radius);
      }
      for (const core::Region& region : world.regions) {
        core::Pose X_WB = region.X_WR;
        X_WB.translation() += region.X_WR.linear().col(2) * (region.size.z() / 2);
        least = std::min(least, horizontalGap(X_WB, region.size, p_W, bottom, top) - radius);
      }
      for (const core::FixtureSpec& fixture : world.fixtures) {
        for (const core::Box& box : fixture.boxes) least = std::min(least, horizontalGap(box.X_WB, box.size, p_W, bottom, top) - radius);
      }
      for (const core::RobotSpec& robot : world.robots) {
        least = std::min(least, (robot.X_WBase.translation() - p_W).head<2>().norm() - kRobotBaseRadius - radius);
      }
      return least;
    };
    const auto reached = [&](const core::Pose& X_WO) {
      return std::any_of(loaded.reach.start[static_cast<std::size_t>(o)].begin(),
                         loaded.reach.start[static_cast<std::size_t>(o)].end(),
                         [&](int r) { return core::reachesBox((*loaded.robots)[static_cast<std::size_t>(r)], X_WO, object.size); });
    };
    // candidates on a grid over the surface, best first: room enough all round and nearest to
    // the start, else the roomiest
    struct Spot {
      bool roomy;
      double key;  // distance to the start when roomy, else minus the room
      core::Pose X_WO;
    };
    std::vector<Spot> spots;
    const int nx = static_cast<int>(std::floor((surface->size.x() - 2 * radius) / kPitch)) + 1;
    const int ny = static_cast<int>(std::floor((surface->size.y() - 2 * radius) / kPitch)) + 1;
    for (int iy = 0; iy < ny; ++iy) {
      for (int ix = 0; ix < nx; ++ix) {
        const Eigen::Vector3d p_S((ix - (nx - 1) / 2.0) * kPitch, (iy - (ny - 1) / 2.0) * kPitch, 0.0);
        Eigen::Vector3d p_W = surface->X_WS * p_S;
        p_W.z() = X_start.translation().z();
        const double r = room(p_W);
        if (r < kOpenFingerReach) continue;
        core::Pose X_WO = X_start;
        X_WO.translation() = p_W;
        const bool roomy = r >= kAsideRoom;
        spots.push_back({roomy, roomy ? (p_W - X_start.translation()).norm() : -r, X_WO});
      }
    }
    std::stable_sort(spots.begin(), spots.end(),
                     [](const Spot& a, const Spot& b) { return std::tie(b.roomy, a.key) < std::tie(a.roomy, b.key); });
    auto spot = std::find_if(spots.begin(), spots.end(),
                             [&](const Spot& s) { return reached(s.X_WO) && (!keeps_clear || keeps_clear(o, s.X_WO)); });
    if (spot == spots.end() && keeps_clear) {
      spot = std::find_if(spots.begin(), spots.end(), [&](const Spot& s) { return reached(s.X_WO); });
    }
    if (spot == spots.end()) continue;
    sites.aside[static_cast<std::size_t>(o)] = spot->X_WO;
    given.push_back(o);
  }
  return given;
}

}  // namespace dashbed::planner
