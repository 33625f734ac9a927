#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"
#include "planner/sampling/object_sites.h"
#include "planner/sampling/roadmap.h"
#include "tests/planner/sorting_scene.h"

using namespace dashbed;
using core::ArmConfig;
using core::Pose;
using Eigen::Vector3d;
using Eigen::VectorXd;
using planner::CollisionChecker;
using planner::CollisionScene;
using planner::HeldObject;
using planner::ObjectSites;
using planner::RestingObject;
using planner::Roadmap;
using planner::SiteSet;
using planner::testing::sortingScene;
using planner::testing::sortingWorld;

namespace {

const ObjectSites& sortingSites() {
  static const ObjectSites sites = planner::objectSites(sortingWorld());
  return sites;
}

constexpr int kCube = 3;  // in front of r0
constexpr double kOpen = 0.025;

VectorXd fullQ(const ArmConfig& arm, double finger) {
  VectorXd q(8);
  for (int i = 0; i < 6; ++i) q[i] = arm[i];
  q[6] = finger;
  q[7] = finger;
  return q;
}

/// r0's arm configuration (IK solution nearest home) with the TCP pointing down at p_WT.
ArmConfig r0TcpDownAt(const Vector3d& p_WT) {
  const core::PlacedRobot& robot = (*sortingWorld().robots)[0];
  Pose X_WT = Pose::Identity();
  X_WT.linear() = Vector3d(1.0, -1.0, -1.0).asDiagonal();
  X_WT.translation() = p_WT;
  const auto solutions = robot.solveInWorld(X_WT, robot.spec->home);
  REQUIRE_FALSE(solutions.empty());
  return solutions.front();
}

Vector3d cubeCentre() { return sortingWorld().world->objects[kCube].X_WO.translation(); }

/// r0 holding the cube at the TCP (a top grasp): fingers at half the cube's width.
HeldObject heldCube() { return HeldObject{kCube, Pose::Identity(), true}; }
double heldFinger() { return sortingWorld().world->objects[kCube].size.x() / 2; }

SiteSet noSites() { return SiteSet(sortingSites().numSites()); }

/// Every piece of `path` checked on its own by a fresh checker against `objects`.
bool piecesFree(const std::vector<ArmConfig>& path, std::span<const RestingObject> objects,
                const std::optional<HeldObject>& held, double finger) {
  CollisionChecker checker(sortingScene());
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (!checker.motionFree(0, fullQ(path[i], finger), fullQ(path[i + 1], finger), objects, held)) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("Roadmap paths end at the query nodes and every piece is free at the motion resolution",
          "[planner][roadmap][long]") {
  const core::World& world = *sortingWorld().world;
  for (const std::optional<HeldObject>& held : {std::optional<HeldObject>{}, std::optional{heldCube()}}) {
    const double finger = held ? heldFinger() : kOpen;
    Roadmap roadmap(sortingScene(), sortingSites(), 0, held, finger, 3);
    REQUIRE(roadmap.grow(50) == 50);
    const int home = roadmap.addConfiguration(world.robots[0].home);
    const int above_cube = roadmap.addConfiguration(r0TcpDownAt(cubeCentre() + Vector3d(0.0, 0.0, 0.12)));
    REQUIRE(home >= 0);
    REQUIRE(above_cube >= 0);
    // transition-like nodes, and pairs of samples whose direct motion collides (most are free),
    // each sample in one pair at most (a few samples lie in pockets no path leads to)
    std::vector<std::pair<int, int>> queries{{home, above_cube}};
    std::vector<char> used(50, 0);
    CollisionChecker checker(sortingScene());
    for (int i = 0; i < 50 && queries.size() < 9; ++i) {
      for (int j = i + 1; j < 50 && !used[i] && queries.size() < 9; ++j) {
        if (!used[j] &&
            !checker.motionFree(0, fullQ(roadmap.node(i), finger), fullQ(roadmap.node(j), finger), {}, held)) {
          queries.emplace_back(i, j);
          used[i] = used[j] = 1;
        }
      }
    }
    REQUIRE(queries.size() == 9);
    int through_roadmap = 0;
    for (const auto& [from, to] : queries) {
      const auto path = roadmap.query(from, to, noSites());
      if (!path) continue;
      REQUIRE(path->size() >= 2);
      CHECK(path->front() == roadmap.node(from));
      CHECK(path->back() == roadmap.node(to));
      CHECK(piecesFree(*path, {}, held, finger));
      if (path->size() > 2) ++through_roadmap;
    }
    CHECK(through_roadmap >= 3);
    CHECK(roadmap.numValidatedEdges() > 0);
    CHECK(roadmap.numValidatedEdges() < roadmap.numEdges());  // lazy
  }
}

TEST_CASE("Roadmap queries avoid occupied sites and use the direct motion when it is free",
          "[planner][roadmap]") {
  // the TCP at cube height 10 cm to either side of the resting cube, along the closing axis:
  // the straight motion between them sweeps a finger through the cube
  const ArmConfig a = r0TcpDownAt(cubeCentre() + Vector3d(-0.10, 0.0, 0.01));
  const ArmConfig b = r0TcpDownAt(cubeCentre() + Vector3d(0.10, 0.0, 0.01));
  const RestingObject cube_at_start{kCube, sortingSites().start[kCube]};
  CollisionChecker checker(sortingScene());
  REQUIRE(checker.motionFree(0, fullQ(a, kOpen), fullQ(b, kOpen), {}));
  REQUIRE_FALSE(checker.motionFree(0, fullQ(a, kOpen), fullQ(b, kOpen), std::span(&cube_at_start, 1)));

  SiteSet occupied = noSites();
  occupied.set(ObjectSites::startSite(kCube));
  SiteSet every_other = noSites();
  for (int site = 0; site < sortingSites().numSites(); ++site) every_other.set(site, site != ObjectSites::startSite(kCube));

  Roadmap roadmap(sortingScene(), sortingSites(), 0, std::nullopt, kOpen, 5);
  roadmap.grow(50);
  const int from = roadmap.addConfiguration(a), to = roadmap.addConfiguration(b);
  REQUIRE(from >= 0);
  REQUIRE(to >= 0);
  CHECK_FALSE(roadmap.motionFree(a, b, occupied));
  CHECK(roadmap.motionFree(a, b, every_other));

  SECTION("occupied: around the cube") {
    const auto path = roadmap.query(from, to, occupied);
    REQUIRE(path);
    CHECK(path->size() > 2);
    CHECK(path->front() == a);
    CHECK(path->back() == b);
    CHECK(piecesFree(*path, std::span(&cube_at_start, 1), std::nullopt, kOpen));
  }
  SECTION("unoccupied, other sites occupied or not: the direct motion") {
    CHECK(roadmap.query(from, to, noSites()) == std::vector<ArmConfig>{a, b});
    CHECK(roadmap.query(from, to, every_other) == std::vector<ArmConfig>{a, b});
  }
  SECTION("a held object's own sites never block its roadmap") {
    Roadmap holding(sortingScene(), sortingSites(), 0, heldCube(), heldFinger(), 5);
    const int from_h = holding.addConfiguration(r0TcpDownAt(cubeCentre() + Vector3d(-0.10, 0.0, 0.05)));
    const int to_h = holding.addConfiguration(r0TcpDownAt(cubeCentre() + Vector3d(0.10, 0.0, 0.05)));
    REQUIRE(from_h >= 0);
    REQUIRE(to_h >= 0);
    SiteSet cube_sites = noSites();
    cube_sites.set(ObjectSites::startSite(kCube));
    cube_sites.set(ObjectSites::goalSite(kCube));
    const auto path = holding.query(from_h, to_h, cube_sites);
    REQUIRE(path);
    CHECK(path->size() == 2);
  }
}

TEST_CASE("Roadmaps with the same seed and calls are identical", "[planner][roadmap]") {
  const ArmConfig a = r0TcpDownAt(cubeCentre() + Vector3d(-0.10, 0.0, 0.01));
  const ArmConfig b = r0TcpDownAt(cubeCentre() + Vector3d(0.10, 0.0, 0.01));
  SiteSet occupied = noSites();
  occupied.set(ObjectSites::startSite(kCube));
  struct Result {
    std::vector<ArmConfig> nodes;
    int edges = 0;
    std::vector<std::optional<std::vector<ArmConfig>>> paths;
  };
  const auto run = [&](std::uint64_t seed) {
    Roadmap roadmap(sortingScene(), sortingSites(), 0, std::nullopt, kOpen, seed);
    roadmap.grow(40);
    const int from = roadmap.addConfiguration(a), to = roadmap.addConfiguration(b);
    roadmap.grow(10);
    Result result;
    result.paths.push_back(roadmap.query(from, to, occupied));
    result.paths.push_back(roadmap.query(from, 7, noSites()));
    for (int id = 0; id < roadmap.numNodes(); ++id) result.nodes.push_back(roadmap.node(id));
    result.edges = roadmap.numEdges();
    return result;
  };
  const Result first = run(11), second = run(11), other = run(12);
  REQUIRE(first.nodes.size() == 52);
  CHECK(first.nodes == second.nodes);
  CHECK(first.edges == second.edges);
  REQUIRE(first.paths[0]);
  CHECK(first.paths[0]->size() > 2);
  CHECK(first.paths == second.paths);
  CHECK(first.nodes.front() != other.nodes.front());
  CHECK(first.nodes != other.nodes);
}

TEST_CASE("Roadmap nodes: colliding configurations are refused, repeated ones reuse their id",
          "[planner][roadmap]") {
  const core::World& world = *sortingWorld().world;
  Roadmap roadmap(sortingScene(), sortingSites(), 0, std::nullopt, kOpen, 1);
  ArmConfig into_table = world.robots[0].home;
  into_table[1] = 0.3;  // shoulder lift below horizontal: the arm points into the table
  CHECK(roadmap.addConfiguration(into_table) == -1);
  CHECK(roadmap.numNodes() == 0);
  const int home = roadmap.addConfiguration(world.robots[0].home);
  CHECK(home == 0);
  CHECK(roadmap.addConfiguration(world.robots[0].home) == home);
  CHECK(roadmap.numNodes() == 1);
  CHECK(roadmap.query(home, home, noSites()) == std::vector<ArmConfig>{world.robots[0].home});
  CHECK(roadmap.fullConfiguration(world.robots[0].home) == fullQ(world.robots[0].home, kOpen));
}

TEST_CASE("Roadmap queries between unconnected nodes give no path", "[planner][roadmap]") {
  // the upper arm forward and backward, both a little above horizontal: the straight motion
  // between them swings the arm down through the table
  ArmConfig forward = sortingWorld().world->robots[0].home;
  forward[1] = -0.3;
  forward[2] = 0.0;
  ArmConfig backward = forward;
  backward[1] = std::numbers::pi + 0.3;

  SECTION("joined by an edge that collides") {
    Roadmap roadmap(sortingScene(), sortingSites(), 0, std::nullopt, kOpen, 1);
    const int a = roadmap.addConfiguration(forward), b = roadmap.addConfiguration(backward);
    REQUIRE(a >= 0);
    REQUIRE(b >= 0);
    REQUIRE(roadmap.numEdges() == 1);
    CHECK_FALSE(roadmap.query(a, b, noSites()));
    CHECK(roadmap.numValidatedEdges() == 1);
    CHECK_FALSE(roadmap.query(b, a, noSites()));
  }
  SECTION("not joined at all") {
    planner::RoadmapSettings settings;
    settings.max_edge_time = 0.5;
    Roadmap roadmap(sortingScene(), sortingSites(), 0, std::nullopt, kOpen, 1, settings);
    const int a = roadmap.addConfiguration(forward), b = roadmap.addConfiguration(backward);
    REQUIRE(roadmap.numEdges() == 0);
    CHECK_FALSE(roadmap.query(a, b, noSites()));
  }
}

TEST_CASE("Roadmap growth near a configuration stays within the spread of it", "[planner][roadmap]") {
  const ArmConfig centre = r0TcpDownAt(cubeCentre() + Vector3d(0.0, 0.0, 0.12));
  Roadmap roadmap(sortingScene(), sortingSites(), 0, std::nullopt, kOpen, 3);
  REQUIRE(roadmap.growNear(centre, 20, 0.3) == 20);
  REQUIRE(roadmap.numNodes() == 20);
  bool some_away = false;
  for (int id = 0; id < roadmap.numNodes(); ++id) {
    const ArmConfig& q = roadmap.node(id);
    for (int j = 0; j < 6; ++j) {
      CHECK(std::abs(q[j] - centre[j]) <= 0.3 + 1e-12);
      some_away |= std::abs(q[j] - centre[j]) > 0.05;
    }
  }
  CHECK(some_away);
  // every node is free against the static scene: adding it again returns its id
  for (int id = 0; id < roadmap.numNodes(); ++id) CHECK(roadmap.addConfiguration(roadmap.node(id)) == id);
  // a pose into the table gives no free sample near it within a tiny spread
  ArmConfig into_table = sortingWorld().world->robots[0].home;
  into_table[1] = 0.3;
  CHECK(roadmap.growNear(into_table, 3, 1e-3) == 0);
  CHECK(roadmap.numNodes() == 20);
}

TEST_CASE("Site sets", "[planner][roadmap]") {
  SiteSet a(70), b(70);
  CHECK(a.none());
  a.set(65);
  CHECK(a.test(65));
  CHECK_FALSE(a.test(64));
  CHECK_FALSE(a.intersects(b));
  b.set(65);
  CHECK(a.intersects(b));
  CHECK(a == b);
  CHECK(a.subsetOf(b));
  b.set(3);
  CHECK(a.subsetOf(b));
  CHECK_FALSE(b.subsetOf(a));
  CHECK(SiteSet(70).subsetOf(a));
  CHECK_THROWS_AS(a.subsetOf(SiteSet(200)), std::invalid_argument);
  b.set(65, false);
  b.set(3, false);
  CHECK(b.none());
  CHECK_THROWS_AS(b.set(128), std::out_of_range);
}
