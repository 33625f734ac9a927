#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>

#include "core/grasps.h"
#include "core/kinematics.h"
#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"
#include "tests/planner/sorting_scene.h"

using namespace dashbed;
using core::Pose;
using Eigen::Vector3d;
using Eigen::VectorXd;
using planner::CollisionChecker;
using planner::CollisionScene;
using planner::CollisionSettings;
using planner::HeldObject;
using planner::RestingObject;
using planner::testing::sortingScene;
using planner::testing::sortingWorld;

namespace {

VectorXd fullQ(const core::ArmConfig& arm, double finger) {
  VectorXd q(8);
  for (int i = 0; i < 6; ++i) q[i] = arm[i];
  q[6] = finger;
  q[7] = finger;
  return q;
}

VectorXd homeQ(const core::World& world, int robot, double finger = 0.025) {
  return fullQ(world.robots[robot].home, finger);
}

Pose tcpDown(const Vector3d& p_WT) {
  Pose X = Pose::Identity();
  X.linear() = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  X.translation() = p_WT;
  return X;
}

core::ArmConfig solveNearHome(const core::PlacedRobot& robot, const Pose& X_WT) {
  const auto solutions = robot.solveInWorld(X_WT, robot.spec->home);
  REQUIRE_FALSE(solutions.empty());
  return solutions.front();
}

/// The reference: every shape pair with plain fcl::collide, no prefilter, no broad phase.
/// It builds its own geometry from the robot models (links' primitives grown by the margin as
/// documented in collision_checker.h) and its own poses from core::linkPoses; it takes from
/// the scene only the rules that are configuration: which self pairs are checked, which links
/// are fixed and which hold objects.
class BruteForce {
 public:
  BruteForce(const CollisionScene& scene, const core::World& world, const core::RobotSet& robots)
      : scene_(scene), robots_(robots) {
    const double margin = scene.settings().margin;
    for (std::size_t r = 0; r < robots.size(); ++r) {
      std::vector<LinkShape> shapes;
      const auto& links = robots[r].model->links();
      for (std::size_t l = 0; l < links.size(); ++l) {
        for (const core::CollisionShape& shape : links[l].collisions) {
          std::shared_ptr<fcl::CollisionGeometryd> geometry;
          switch (shape.type) {
            case core::ShapeType::kBox:
              geometry = std::make_shared<fcl::Boxd>(shape.size + Vector3d::Constant(2 * margin));
              break;
            case core::ShapeType::kCylinder:
              geometry = std::make_shared<fcl::Cylinderd>(shape.size.x() + margin, shape.size.z() + 2 * margin);
              break;
            case core::ShapeType::kSphere:
              geometry = std::make_shared<fcl::Sphered>(shape.size.x() + margin);
              break;
          }
          shapes.push_back({static_cast<int>(l), geometry, shape.X_LS});
        }
      }
      shapes_.push_back(std::move(shapes));
    }
    for (const core::FixtureSpec& fixture : world.fixtures) {
      for (const core::Box& box : fixture.boxes) statics_.push_back({std::make_shared<fcl::Boxd>(box.size), box.X_WB});
    }
    Pose X_WFloor = Pose::Identity();
    X_WFloor.translation() = Vector3d(0, 0, -0.05);
    statics_.push_back({std::make_shared<fcl::Boxd>(100.0, 100.0, 0.1), X_WFloor});
    for (const core::ObjectSpec& object : world.objects) {
      objects_.push_back(std::make_shared<fcl::Boxd>(object.size));
      held_objects_.push_back(std::make_shared<fcl::Boxd>(object.size + Vector3d::Constant(2 * margin)));
    }
  }

  bool robotFree(int r, const VectorXd& q, const std::vector<RestingObject>& objects,
                 const std::optional<HeldObject>& held) const {
    const std::vector<Placed> placed = place(r, q);
    std::optional<Placed> held_placed;
    if (held) held_placed = placeHeld(r, q, *held);
    // static scene
    for (const Placed& s : placed) {
      if (!scene_.linkMoves(r, s.link)) continue;
      for (const Static& box : statics_) {
        if (collide(s.geometry.get(), s.X_W, box.geometry.get(), box.X_W)) return false;
      }
    }
    if (held_placed && held->check_static) {
      for (const Static& box : statics_) {
        if (collide(held_placed->geometry.get(), held_placed->X_W, box.geometry.get(), box.X_W)) return false;
      }
    }
    // self
    for (std::size_t i = 0; i < placed.size(); ++i) {
      for (std::size_t j = i + 1; j < placed.size(); ++j) {
        if (placed[i].link == placed[j].link || !scene_.selfPairChecked(r, placed[i].link, placed[j].link)) continue;
        if (collide(placed[i].geometry.get(), placed[i].X_W, placed[j].geometry.get(), placed[j].X_W)) return false;
      }
    }
    if (held_placed) {
      for (const Placed& s : placed) {
        if (scene_.linkHoldsObjects(r, s.link)) continue;
        if (collide(s.geometry.get(), s.X_W, held_placed->geometry.get(), held_placed->X_W)) return false;
      }
    }
    // resting objects
    for (const RestingObject& o : objects) {
      if (held && o.object == held->object) continue;
      for (const Placed& s : placed) {
        if (collide(s.geometry.get(), s.X_W, objects_[o.object].get(), o.X_WO)) return false;
      }
      if (held_placed && collide(held_placed->geometry.get(), held_placed->X_W, objects_[o.object].get(), o.X_WO)) {
        return false;
      }
    }
    return true;
  }

  /// The held object (grown by the margin) alone at X_WO against the fixtures and the floor.
  bool heldObjectFree(int object, const Pose& X_WO) const {
    return std::none_of(statics_.begin(), statics_.end(), [&](const Static& box) {
      return collide(held_objects_[object].get(), X_WO, box.geometry.get(), box.X_W);
    });
  }

  Pose heldPose(int r, const VectorXd& q, const HeldObject& held) const { return placeHeld(r, q, held).X_W; }

  bool robotsFree(int ra, const VectorXd& qa, const std::optional<HeldObject>& held_a, int rb, const VectorXd& qb,
                  const std::optional<HeldObject>& held_b) const {
    const std::vector<Placed> a = place(ra, qa);
    const std::vector<Placed> b = place(rb, qb);
    const bool shared = held_a && held_b && held_a->object == held_b->object;
    for (const Placed& sa : a) {
      for (const Placed& sb : b) {
        if (!scene_.linkMoves(ra, sa.link) && !scene_.linkMoves(rb, sb.link)) continue;
        if (collide(sa.geometry.get(), sa.X_W, sb.geometry.get(), sb.X_W)) return false;
      }
    }
    if (held_a) {
      const Placed h = placeHeld(ra, qa, *held_a);
      for (const Placed& sb : b) {
        if (shared && scene_.linkHoldsObjects(rb, sb.link)) continue;
        if (collide(h.geometry.get(), h.X_W, sb.geometry.get(), sb.X_W)) return false;
      }
      if (held_b && !shared) {
        const Placed hb = placeHeld(rb, qb, *held_b);
        if (collide(h.geometry.get(), h.X_W, hb.geometry.get(), hb.X_W)) return false;
      }
    }
    if (held_b) {
      const Placed h = placeHeld(rb, qb, *held_b);
      for (const Placed& sa : a) {
        if (shared && scene_.linkHoldsObjects(ra, sa.link)) continue;
        if (collide(h.geometry.get(), h.X_W, sa.geometry.get(), sa.X_W)) return false;
      }
    }
    return true;
  }

 private:
  struct LinkShape {
    int link;
    std::shared_ptr<fcl::CollisionGeometryd> geometry;
    Pose X_LS;
  };
  struct Placed {
    int link;
    std::shared_ptr<fcl::CollisionGeometryd> geometry;
    Pose X_W;
  };
  struct Static {
    std::shared_ptr<fcl::CollisionGeometryd> geometry;
    Pose X_W;
  };

  static bool collide(const fcl::CollisionGeometryd* a, const Pose& X_a, const fcl::CollisionGeometryd* b,
                      const Pose& X_b) {
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    fcl::collide(a, X_a, b, X_b, request, result);
    return result.isCollision();
  }

  std::vector<Placed> place(int r, const VectorXd& q) const {
    const std::vector<Pose> X_RL = core::linkPoses(*robots_[r].model, q);
    const Pose& X_WR = robots_[r].spec->X_WBase;
    std::vector<Placed> placed;
    for (const LinkShape& s : shapes_[r]) placed.push_back({s.link, s.geometry, X_WR * X_RL[s.link] * s.X_LS});
    return placed;
  }

  Placed placeHeld(int r, const VectorXd& q, const HeldObject& held) const {
    const std::vector<Pose> X_RL = core::linkPoses(*robots_[r].model, q);
    const Pose X_WT = robots_[r].spec->X_WBase * X_RL[scene_.tcpLink(r)];
    return {-1, held_objects_[held.object], X_WT * held.X_TO};
  }

  const CollisionScene& scene_;
  const core::RobotSet& robots_;
  std::vector<std::vector<LinkShape>> shapes_;
  std::vector<Static> statics_;
  std::vector<std::shared_ptr<fcl::CollisionGeometryd>> objects_;
  std::vector<std::shared_ptr<fcl::CollisionGeometryd>> held_objects_;
};

/// Seeded random queries over the sorting world.
class RandomQueries {
 public:
  explicit RandomQueries(std::uint64_t seed) : rng_(seed) {}

  /// Mostly above the table (shoulder lift in [-pi, 0]), sometimes anywhere within the limits.
  VectorXd configuration(const core::RobotModel& model) {
    VectorXd q(model.numPositions());
    const bool anywhere = uniform(0, 1) < 0.3;
    for (int j : model.movableJoints()) {
      const core::JointModel& joint = model.joints()[j];
      double lo = joint.lower;
      double hi = joint.upper;
      if (!anywhere && joint.type == core::JointType::kRevolute) {
        lo = std::max(lo, -std::numbers::pi);
        hi = std::min(hi, std::numbers::pi);
        if (joint.q_index == 1) hi = 0.0;
      }
      q[joint.q_index] = uniform(lo, hi);
    }
    return q;
  }

  /// Often a configuration reaching over the table centre (IK of a random TCP pose there,
  /// a random solution), else configuration(model).
  VectorXd towardsCentre(const core::PlacedRobot& robot) {
    if (uniform(0, 1) < 0.9) {
      Pose X_WT = Pose::Identity();
      X_WT.linear() = Eigen::Quaterniond(Eigen::Vector4d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)))
                          .normalized()
                          .toRotationMatrix();
      X_WT.translation() = Vector3d(uniform(-0.12, 0.12), uniform(-0.15, 0.15), uniform(0.8, 1.05));
      const auto solutions = robot.solveInWorld(X_WT, robot.spec->home);
      if (!solutions.empty()) {
        const auto& arm = solutions[static_cast<std::size_t>(uniform(0, static_cast<double>(solutions.size()) - 1e-9))];
        VectorXd q(robot.model->numPositions());
        for (int i = 0; i < 6; ++i) q[i] = arm[i];
        for (int i = 6; i < q.size(); ++i) q[i] = uniform(0.0, 0.025);
        return q;
      }
    }
    return configuration(*robot.model);
  }

  std::optional<HeldObject> held(const core::World& world, double probability) {
    if (uniform(0, 1) >= probability) return std::nullopt;
    const int object = static_cast<int>(uniform(0, static_cast<double>(world.objects.size()) - 1e-9));
    const auto grasps = core::boxGrasps(world.objects[object].size);
    const auto& grasp = grasps[static_cast<std::size_t>(uniform(0, static_cast<double>(grasps.size()) - 1e-9))];
    return HeldObject{object, grasp.X_OT.inverse(), uniform(0, 1) < 0.8};
  }

  /// The start placement, or the objects scattered around points of the robot.
  std::vector<RestingObject> objects(const core::World& world, const std::vector<Vector3d>& near_points) {
    std::vector<RestingObject> placement = planner::startPlacement(world);
    if (uniform(0, 1) < 0.3) return placement;
    for (RestingObject& o : placement) {
      if (uniform(0, 1) < 0.3) continue;
      const Vector3d& centre =
          near_points[static_cast<std::size_t>(uniform(0, static_cast<double>(near_points.size()) - 1e-9))];
      Pose X = Pose::Identity();
      X.linear() = Eigen::Quaterniond(Eigen::Vector4d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)))
                       .normalized()
                       .toRotationMatrix();
      X.translation() = centre + Vector3d(uniform(-0.12, 0.12), uniform(-0.12, 0.12), uniform(-0.12, 0.12));
      o.X_WO = X;
    }
    return placement;
  }

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

 private:
  std::mt19937_64 rng_;
};

std::vector<Vector3d> linkOrigins(const core::PlacedRobot& robot, const VectorXd& q) {
  std::vector<Vector3d> points;
  for (const Pose& X_RL : core::linkPoses(*robot.model, q)) points.push_back(robot.spec->X_WBase * X_RL.translation());
  return points;
}

}  // namespace

TEST_CASE("Collision settings and queries reject bad input with a message", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  CollisionSettings settings;
  settings.margin = -0.001;
  CHECK_THROWS_WITH(settings.validate(), Catch::Contains("margin"));
  settings = {};
  settings.motion_step = 0.0;
  CHECK_THROWS_WITH(CollisionScene(*loaded.world, *loaded.robots, settings), Catch::Contains("motion_step"));

  CollisionChecker dut(sortingScene());
  const auto objects = planner::startPlacement(*loaded.world);
  const VectorXd home = homeQ(*loaded.world, 0);
  CHECK_THROWS_WITH(dut.robotFree(2, home, objects), Catch::Contains("robot index 2"));
  CHECK_THROWS_WITH(dut.robotFree(0, VectorXd::Zero(6), objects), Catch::Contains("expects 8"));
  CHECK_THROWS_WITH(dut.robotFree(0, home, objects, HeldObject{7, Pose::Identity()}),
                    Catch::Contains("held object index 7"));
  const std::vector<RestingObject> bad_objects{{-1, Pose::Identity()}};
  CHECK_THROWS_WITH(dut.robotFree(0, home, bad_objects), Catch::Contains("resting object index -1"));
  VectorXd nan_q = home;
  nan_q[2] = std::nan("");
  CHECK_THROWS_WITH(dut.robotFree(0, nan_q, objects), Catch::Contains("not finite"));
  CHECK_THROWS_WITH(dut.robotsFree(0, home, std::nullopt, 0, home, std::nullopt),
                    Catch::Contains("two different robots"));
  planner::TimedPath bad{{0.0, 0.0}, {home, home}};
  CHECK_THROWS_WITH(dut.timedPathsFree(0, bad, std::nullopt, 1, bad, std::nullopt), Catch::Contains("increase"));
}

TEST_CASE("Self-collision pairs ignore adjacent bodies and the two fingers and check the rest",
          "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const CollisionScene& dut = sortingScene();
  const core::RobotModel& model = *(*loaded.robots)[0].model;
  const auto link = [&](const char* name) { return model.requireLink(name); };
  // same rigid body or joined by one joint
  CHECK_FALSE(dut.selfPairChecked(0, link("wrist_3_link"), link("hande_coupling")));
  CHECK_FALSE(dut.selfPairChecked(0, link("hande_base"), link("hande_left_finger")));
  CHECK_FALSE(dut.selfPairChecked(0, link("forearm_link"), link("wrist_1_link")));
  CHECK_FALSE(dut.selfPairChecked(0, link("upper_arm_link"), link("forearm_link")));
  // the pads touch when the gripper is closed
  CHECK_FALSE(dut.selfPairChecked(0, link("hande_left_finger"), link("hande_right_finger")));
  // the gripper can hit the upper arm, the shoulder and the base
  CHECK(dut.selfPairChecked(0, link("hande_base"), link("upper_arm_link")));
  CHECK(dut.selfPairChecked(0, link("hande_left_finger"), link("upper_arm_link")));
  CHECK(dut.selfPairChecked(0, link("hande_base"), link("shoulder_link")));
  CHECK(dut.selfPairChecked(0, link("hande_base"), link("base_link_inertia")));
  CHECK(dut.selfPairChecked(0, link("wrist_2_link"), link("upper_arm_link")));
  bool fingers_listed = false;
  for (const auto& pair : dut.ignoredSelfPairs(0)) {
    if (pair.body_a == "hande_left_finger" && pair.body_b == "hande_right_finger") fingers_listed = pair.reason == "home";
  }
  CHECK(fingers_listed);
  // the base never moves and is not checked against the table it stands on
  CHECK_FALSE(dut.linkMoves(0, link("base_link_inertia")));
  CHECK(dut.linkMoves(0, link("shoulder_link")));
  CHECK(dut.linkHoldsObjects(0, link("hande_right_finger")));
  CHECK_FALSE(dut.linkHoldsObjects(0, link("hande_base")));
}

TEST_CASE("robotFree agrees with a brute-force FCL check on random configurations", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const CollisionScene& scene = sortingScene();
  const BruteForce reference(scene, world, *loaded.robots);
  CollisionChecker dut(scene);
  RandomQueries random(20240501);
  constexpr int kSamples = 4000;
  int free = 0;
  int mismatches = 0;
  for (int i = 0; i < kSamples; ++i) {
    const int r = i % 2;
    const core::PlacedRobot& robot = (*loaded.robots)[r];
    const VectorXd q = random.configuration(*robot.model);
    const auto held = random.held(world, 0.4);
    const auto objects = random.objects(world, linkOrigins(robot, q));
    const bool expected = reference.robotFree(r, q, objects, held);
    const bool actual = dut.robotFree(r, q, objects, held);
    if (expected != actual) {
      ++mismatches;
      UNSCOPED_INFO("sample " << i << " robot " << r << " q " << q.transpose() << " expected " << expected);
    }
    free += expected ? 1 : 0;
  }
  CHECK(mismatches == 0);
  // both outcomes are well represented
  CHECK(free > kSamples / 10);
  CHECK(free < kSamples * 9 / 10);
}

TEST_CASE("robotFree agrees with brute force on the static scene and self-collision alone", "[planner][collision]") {
  // without objects and held objects, the cross-check exercises the broad phase over the
  // fixtures and the self pairs only, over the full joint ranges
  const auto& loaded = sortingWorld();
  const CollisionScene& scene = sortingScene();
  const BruteForce reference(scene, *loaded.world, *loaded.robots);
  CollisionChecker dut(scene);
  RandomQueries random(7);
  int mismatches = 0;
  int free = 0;
  for (int i = 0; i < 3000; ++i) {
    const int r = i % 2;
    const VectorXd q = random.configuration(*(*loaded.robots)[r].model);
    const bool expected = reference.robotFree(r, q, {}, std::nullopt);
    mismatches += expected != dut.robotFree(r, q, {}, std::nullopt) ? 1 : 0;
    free += expected ? 1 : 0;
  }
  CHECK(mismatches == 0);
  CHECK(free > 300);
}

TEST_CASE("heldObjectFree agrees with brute force and with robotFree's check of the held object",
          "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const CollisionScene& scene = sortingScene();
  const BruteForce reference(scene, world, *loaded.robots);
  CollisionChecker dut(scene);
  CollisionChecker check(scene);
  RandomQueries random(11);
  int mismatches = 0;
  int blocked = 0;
  int unsound = 0;  // the object alone hits the scene, the robot holding it there is free
  for (int i = 0; i < 3000; ++i) {
    const int r = i % 2;
    const VectorXd q = random.towardsCentre((*loaded.robots)[r]);
    std::optional<HeldObject> held = random.held(world, 1.0);
    held->check_static = true;
    const Pose X_WO = reference.heldPose(r, q, *held);
    const bool free = dut.heldObjectFree(r, held->object, X_WO);
    mismatches += free != reference.heldObjectFree(held->object, X_WO) ? 1 : 0;
    if (free) continue;
    ++blocked;
    unsound += check.robotFree(r, q, {}, held) ? 1 : 0;
  }
  CHECK(mismatches == 0);
  CHECK(unsound == 0);
  CHECK(blocked > 100);  // 177 of the 3000: both outcomes are represented
  CHECK(blocked < 2900);
}

TEST_CASE("robotsFree agrees with a brute-force FCL check on random configuration pairs", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const CollisionScene& scene = sortingScene();
  const BruteForce reference(scene, world, *loaded.robots);
  CollisionChecker dut(scene);
  RandomQueries random(99);
  constexpr int kSamples = 4000;
  int free = 0;
  int mismatches = 0;
  for (int i = 0; i < kSamples; ++i) {
    const VectorXd q0 = random.towardsCentre((*loaded.robots)[0]);
    const VectorXd q1 = random.towardsCentre((*loaded.robots)[1]);
    auto held0 = random.held(world, 0.4);
    auto held1 = random.held(world, 0.4);
    // now and then both hold the same object, as in a handoff
    if (held0 && held1 && random.uniform(0, 1) < 0.3) held1->object = held0->object;
    const bool expected = reference.robotsFree(0, q0, held0, 1, q1, held1);
    if (expected != dut.robotsFree(0, q0, held0, 1, q1, held1)) {
      ++mismatches;
      UNSCOPED_INFO("sample " << i << " q0 " << q0.transpose() << " q1 " << q1.transpose());
    }
    // the order of the robots does not matter
    if (expected != dut.robotsFree(1, q1, held1, 0, q0, held0)) ++mismatches;
    free += expected ? 1 : 0;
  }
  CHECK(mismatches == 0);
  CHECK(free > kSamples / 10);
  CHECK(free < kSamples * 9 / 10);
}

TEST_CASE("robotContact and robotsContact name a collision exactly when robotFree and robotsFree find one",
          "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  CollisionChecker dut(sortingScene());
  RandomQueries random(2026);
  const auto names_a_part = [](const std::string& contact) {
    return contact.rfind("its ", 0) == 0 &&
           (contact.find(" and fixture '") != std::string::npos || contact.find(" and the floor") != std::string::npos ||
            contact.find(" and the base of robot '") != std::string::npos || contact.find(" and its ") != std::string::npos);
  };
  int mismatches = 0;
  int unnamed = 0;
  int colliding = 0;
  for (int i = 0; i < 1000; ++i) {
    const int r = i % 2;
    const VectorXd q = random.configuration(*(*loaded.robots)[r].model);
    const std::string contact = dut.robotContact(r, q);
    mismatches += contact.empty() != dut.robotFree(r, q, {}) ? 1 : 0;
    if (contact.empty()) continue;
    ++colliding;
    if (!names_a_part(contact)) {
      ++unnamed;
      UNSCOPED_INFO("robot " << r << ": " << contact);
    }
  }
  CHECK(mismatches == 0);
  CHECK(unnamed == 0);
  CHECK(colliding > 100);
  int pair_colliding = 0;
  for (int i = 0; i < 1000; ++i) {
    const VectorXd q0 = random.towardsCentre((*loaded.robots)[0]);
    const VectorXd q1 = random.towardsCentre((*loaded.robots)[1]);
    const std::string contact = dut.robotsContact(0, q0, 1, q1);
    mismatches += contact.empty() != dut.robotsFree(0, q0, std::nullopt, 1, q1, std::nullopt) ? 1 : 0;
    if (contact.empty()) continue;
    ++pair_colliding;
    unnamed += contact.rfind("its ", 0) == 0 && contact.find(" and robot '" + world.robots[1].name + "''s ") != std::string::npos ? 0 : 1;
  }
  CHECK(mismatches == 0);
  CHECK(unnamed == 0);
  CHECK(pair_colliding > 100);

  // the arm driven into the table names the table
  VectorXd q = homeQ(world, 0);
  q[1] = 0.3;
  CHECK_THAT(dut.robotContact(0, q), Catch::Matchers::EndsWith(" and fixture 'table'"));
  CHECK(dut.robotContact(0, homeQ(world, 0)).empty());
}

TEST_CASE("robotsClearance: the robots stay free while they travel less than it", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const CollisionScene& scene = sortingScene();
  CollisionChecker dut(scene);
  CollisionChecker check(scene);
  RandomQueries random(7);
  int positive = 0;
  int mismatches = 0;
  int violations = 0;
  int colliding = 0, overlapping = 0;
  for (int i = 0; i < 3000; ++i) {
    const VectorXd q0 = random.towardsCentre((*loaded.robots)[0]);
    const VectorXd q1 = random.towardsCentre((*loaded.robots)[1]);
    const auto held0 = random.held(world, 0.4);
    const auto held1 = random.held(world, 0.4);
    const double clearance = dut.robotsClearance(0, q0, held0, 1, q1, held1);
    if ((clearance >= 0.0) != check.robotsFree(0, q0, held0, 1, q1, held1)) ++mismatches;
    // colliding, and free with the capsules around their shapes overlapping (checked shape
    // against shape)
    colliding += clearance < 0.0 ? 1 : 0;
    overlapping += clearance == 0.0 ? 1 : 0;
    if (clearance <= 1e-3) continue;
    ++positive;
    // move both arms straight in random directions, together just under the clearance
    for (int trial = 0; trial < 5; ++trial) {
      VectorXd d0 = VectorXd::Zero(q0.size()), d1 = VectorXd::Zero(q1.size());
      for (int j = 0; j < 6; ++j) {
        d0[j] = random.uniform(-1, 1);
        d1[j] = random.uniform(-1, 1);
      }
      const double travel = scene.motionTravel(0, q0, q0 + d0, held0) + scene.motionTravel(1, q1, q1 + d1, held1);
      const double scale = (clearance - 1e-4) / travel;
      if (!check.robotsFree(0, q0 + scale * d0, held0, 1, q1 + scale * d1, held1)) ++violations;
    }
  }
  CHECK(mismatches == 0);
  CHECK(violations == 0);
  CHECK(positive > 100);
  CHECK(colliding > 100);
  CHECK(overlapping > 40);
}

TEST_CASE("motionClearOf, which skips samples within its clearance, agrees with motionsFree on random motions",
          "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  CollisionChecker dut(sortingScene());
  CollisionChecker check(sortingScene());
  RandomQueries random(11);
  int clear = 0, blocked = 0, mismatches = 0;
  for (int i = 0; i < 400; ++i) {
    const VectorXd from = random.towardsCentre((*loaded.robots)[0]);
    const VectorXd to = random.towardsCentre((*loaded.robots)[0]);
    const auto held = random.held(world, 0.4);
    std::vector<planner::StandingRobot> others;
    for (int k = 0; k < 3; ++k) others.push_back({1, random.towardsCentre((*loaded.robots)[1]), random.held(world, 0.3)});
    const bool expected = std::all_of(others.begin(), others.end(), [&](const planner::StandingRobot& o) {
      return check.motionsFree(0, from, to, held, o.robot, o.q, o.q, o.held);
    });
    if (dut.motionClearOf(0, from, to, held, others) != expected) ++mismatches;
    ++(expected ? clear : blocked);
  }
  CHECK(mismatches == 0);
  CHECK(clear > 40);
  CHECK(blocked > 40);
}

TEST_CASE("motionObjectHits names the objects motionFree finds in the way", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const CollisionScene& scene = sortingScene();
  CollisionChecker dut(scene);
  CollisionChecker check(scene);
  RandomQueries random(11);
  const std::vector<RestingObject> objects = planner::startPlacement(world);
  int compared = 0;
  int hit = 0;
  int mismatches = 0;
  for (int i = 0; i < 400 && compared < 60; ++i) {
    const VectorXd a = random.towardsCentre((*loaded.robots)[0]);
    VectorXd b = a;
    for (int j = 0; j < 6; ++j) b[j] += random.uniform(-0.3, 0.3);
    const auto held = random.held(world, 0.3);
    if (!check.motionFree(0, a, b, {}, held)) continue;
    ++compared;
    const std::vector<char> hits = dut.motionObjectHits(0, a, b, objects, held);
    REQUIRE(hits.size() == objects.size());
    for (std::size_t k = 0; k < objects.size(); ++k) {
      const bool free = check.motionFree(0, a, b, std::span(&objects[k], 1), held);
      if (free == static_cast<bool>(hits[k])) ++mismatches;
      hit += hits[k] ? 1 : 0;
    }
  }
  CHECK(mismatches == 0);
  CHECK(compared >= 20);
  CHECK(hit > 0);
}

TEST_CASE("Known configurations of the sorting world", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const core::RobotSet& robots = *loaded.robots;
  CollisionChecker dut(sortingScene());
  const auto objects = planner::startPlacement(world);

  SECTION("home is free, alone and together") {
    for (int r = 0; r < 2; ++r) {
      CHECK(dut.robotFree(r, homeQ(world, r, 0.025), objects));
      CHECK(dut.robotFree(r, homeQ(world, r, 0.0), objects));
    }
    CHECK(dut.robotsFree(0, homeQ(world, 0), std::nullopt, 1, homeQ(world, 1), std::nullopt));
  }

  SECTION("the arm driven into the table collides") {
    VectorXd q = homeQ(world, 0);
    q[1] = 0.3;  // shoulder lift below horizontal: the arm points into the table
    CHECK_FALSE(dut.robotFree(0, q, {}));
  }

  SECTION("open fingers around a resting cube are free, closed fingers collide") {
    const int cube = 3;  // in front of r0
    const Pose X_WO = world.objects[cube].X_WO;
    const auto grasps = core::boxGrasps(world.objects[cube].size);
    REQUIRE(grasps.front().approach == core::GraspApproach::kTop);
    const core::ArmConfig arm = solveNearHome(robots[0], X_WO * grasps.front().X_OT);
    CHECK(dut.robotFree(0, fullQ(arm, 0.025), objects));
    CHECK_FALSE(dut.robotFree(0, fullQ(arm, 0.0), objects));
    // during the pick the planner leaves the grasped cube out of the resting objects
    std::vector<RestingObject> others;
    for (const RestingObject& o : objects) {
      if (o.object != cube) others.push_back(o);
    }
    CHECK(dut.robotFree(0, fullQ(arm, 0.0), others));
  }

  SECTION("a held object hitting a fixture collides") {
    const int cube = 3;
    const auto grasps = core::boxGrasps(world.objects[cube].size);
    const Pose X_TO = grasps.front().X_OT.inverse();
    // at the grasp the (grown) cube reaches into the table; the gripper alone is clear of it
    const core::ArmConfig at_grasp = solveNearHome(robots[0], world.objects[cube].X_WO * grasps.front().X_OT);
    const VectorXd q = fullQ(at_grasp, 0.02);
    CHECK(dut.robotFree(0, q, {}));
    CHECK_FALSE(dut.robotFree(0, q, {}, HeldObject{cube, X_TO, true}));
    CHECK(dut.robotFree(0, q, {}, HeldObject{cube, X_TO, false}));  // still on its support
    // lifted 5 cm it is free; pushed sideways into a bin wall it is not
    Pose X_WT = world.objects[cube].X_WO * grasps.front().X_OT;
    X_WT.translation().z() += 0.05;
    CHECK(dut.robotFree(0, fullQ(solveNearHome(robots[0], X_WT), 0.02), {}, HeldObject{cube, X_TO, true}));
    // over a bin wall the gripper clears it by 3 mm, the held cube dips 2 mm into it
    const core::Box& bin_wall = world.findFixture("bin_blue")->boxes.at(1);
    const double wall_top = bin_wall.X_WB.translation().z() + bin_wall.size.z() / 2;
    const Vector3d p_over_wall(bin_wall.X_WB.translation().x(), bin_wall.X_WB.translation().y(), wall_top + 0.018);
    const VectorXd q_wall = fullQ(solveNearHome(robots[0], tcpDown(p_over_wall)), 0.025);
    CHECK(dut.robotFree(0, q_wall, {}));
    CHECK_FALSE(dut.robotFree(0, q_wall, {}, HeldObject{cube, Pose::Identity(), true}));
  }

  SECTION("a held object is part of its robot against the other robot") {
    const Pose X_WT0 = tcpDown({-0.12, 0.0, 0.95});
    const Pose X_WT1 = tcpDown({0.12, 0.0, 0.95});
    const VectorXd q0 = fullQ(solveNearHome(robots[0], X_WT0), 0.025);
    const VectorXd q1 = fullQ(solveNearHome(robots[1], X_WT1), 0.025);
    CHECK(dut.robotsFree(0, q0, std::nullopt, 1, q1, std::nullopt));
    // a cube held 19 cm to the side of r0's TCP reaches into r1's finger
    Pose X_TO = Pose::Identity();
    X_TO.translation() = Vector3d(0.19, 0.0, 0.0);
    const HeldObject held0{0, X_TO, true};
    CHECK(dut.robotFree(0, q0, {}, held0));
    CHECK_FALSE(dut.robotsFree(0, q0, held0, 1, q1, std::nullopt));
    CHECK_FALSE(dut.robotsFree(1, q1, std::nullopt, 0, q0, held0));
    // once r1 holds it too (a handoff) it may touch r1's fingers
    const HeldObject held1{0, X_WT1.inverse() * X_WT0 * X_TO, true};
    CHECK(dut.robotsFree(0, q0, held0, 1, q1, held1));
  }
}

TEST_CASE("Motion steps bound every point's travel by the motion step", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const CollisionScene& dut = sortingScene();
  const core::PlacedRobot& robot = (*loaded.robots)[0];
  const double step = dut.settings().motion_step;
  CHECK(dut.settings().motionChecksConservative());
  RandomQueries random(3);
  for (int trial = 0; trial < 30; ++trial) {
    const VectorXd a = random.configuration(*robot.model);
    VectorXd b = a;
    for (int i = 0; i < 8; ++i) b[i] += random.uniform(-0.5, 0.5) * (i < 6 ? 1.0 : 0.05);
    const auto held = random.held(world, 0.5);
    const int n = dut.motionSteps(0, a, b, held);
    REQUIRE(n >= 1);
    // points: the corners of every link shape's bounding box and of the held object
    double worst = 0.0;
    std::vector<Vector3d> previous;
    for (int i = 0; i <= n; ++i) {
      const VectorXd q = a + (static_cast<double>(i) / n) * (b - a);
      const std::vector<Pose> X_RL = core::linkPoses(*robot.model, q);
      std::vector<Vector3d> points;
      const auto corners = [&](const Pose& X, const Vector3d& half) {
        for (int c = 0; c < 8; ++c) {
          points.push_back(X * Vector3d((c & 1) ? half.x() : -half.x(), (c & 2) ? half.y() : -half.y(),
                                        (c & 4) ? half.z() : -half.z()));
        }
      };
      const auto& links = robot.model->links();
      for (std::size_t l = 0; l < links.size(); ++l) {
        for (const auto& shape : links[l].collisions) {
          const Vector3d half = shape.type == core::ShapeType::kBox ? Vector3d(shape.size / 2)
                                                                    : Vector3d(shape.size.x(), shape.size.x(), shape.size.z() / 2);
          corners(X_RL[l] * shape.X_LS, half);
        }
      }
      if (held) corners(X_RL[dut.tcpLink(0)] * held->X_TO, world.objects[held->object].size / 2);
      if (!previous.empty()) {
        for (std::size_t p = 0; p < points.size(); ++p) worst = std::max(worst, (points[p] - previous[p]).norm());
      }
      previous = points;
    }
    CHECK(worst <= step + 1e-12);
    // and the bound is not wildly loose
    CHECK(worst > step / 20);
  }
  // the travel radius of the base joint covers the stretched-out arm and gripper (~1 m)
  CHECK(dut.jointTravelRadius(0, 0) > 0.95);
  CHECK(dut.jointTravelRadius(0, 0) < 1.3);
  CHECK(dut.jointTravelRadius(0, 6) == 1.0);
}

/// The sorting world with a 1 cm x 1 mm x 1 cm plate that only the tip of robot 0's left
/// finger passes through at `mid`, about halfway through a 1.75 rad turn of the base from
/// `before` to `after`.
struct PlateWorld {
  PlateWorld() : world(withPlate(mid)), robots(world), scene(world, robots), before(mid), after(mid) {
    before[0] -= 1.0;
    after[0] += 0.75;
  }

  core::ArmConfig mid{};
  core::World world;
  core::RobotSet robots;
  CollisionScene scene;
  core::ArmConfig before, after;

 private:
  static core::World withPlate(core::ArmConfig& mid) {
    const auto& loaded = sortingWorld();
    core::World world = *loaded.world;
    mid = solveNearHome((*loaded.robots)[0], tcpDown({-0.30, 0.0, 0.95}));
    core::FixtureSpec plate;
    plate.name = "plate";
    plate.type = core::FixtureType::kBox;
    plate.X_WF = Pose::Identity();
    plate.X_WF.translation() = Vector3d(-0.30 + 0.035, 0.0, 0.935);
    plate.size = Vector3d(0.01, 0.001, 0.01);
    world.fixtures.push_back(plate);
    core::deriveFixtureGeometry(world);
    return world;
  }
};

const PlateWorld& plateWorld() {
  static const PlateWorld plate;
  return plate;
}

/// A staircase from `from` to `to`: first arm joint `first` moves, then every other position,
/// each over half of s. Monotone in every position, speed twice the mean.
planner::CurvePiece staircase(const VectorXd& from, const VectorXd& to, int first) {
  planner::CurvePiece piece{from, to, {}, 2.0};
  piece.at = [from, to, first](double s, VectorXd& q) {
    q = from;
    q[first] += std::min(2 * s, 1.0) * (to[first] - from[first]);
    for (int j = 0; j < q.size(); ++j) {
      if (j != first) q[j] += std::max(2 * s - 1, 0.0) * (to[j] - from[j]);
    }
  };
  return piece;
}

TEST_CASE("motionFree detects a thin obstacle crossed mid-motion", "[planner][collision]") {
  const PlateWorld& plate = plateWorld();
  CollisionChecker dut(plate.scene);
  const core::ArmConfig& from = plate.before;
  const core::ArmConfig& to = plate.after;
  const VectorXd q_from = fullQ(from, 0.025);
  const VectorXd q_to = fullQ(to, 0.025);
  const VectorXd q_mid = fullQ(plate.mid, 0.025);
  REQUIRE(dut.robotFree(0, q_from, {}));
  REQUIRE(dut.robotFree(0, q_to, {}));
  REQUIRE_FALSE(dut.robotFree(0, q_mid, {}));
  CHECK_FALSE(dut.motionFree(0, q_from, q_to, {}));
  CHECK_FALSE(dut.motionFree(0, q_to, q_from, {}));
  // ten evenly spaced samples would have missed it
  bool coarse_hit = false;
  for (int i = 0; i <= 10; ++i) coarse_hit |= !dut.robotFree(0, q_from + (i / 10.0) * (q_to - q_from), {});
  CHECK_FALSE(coarse_hit);
  // a motion that stays on one side of the plate is free
  core::ArmConfig side = from;
  side[0] += 0.6;
  CHECK(dut.motionFree(0, q_from, fullQ(side, 0.025), {}));
  // without the plate the whole motion is free
  CollisionChecker plain(sortingScene());
  CHECK(plain.motionFree(0, q_from, q_to, {}));
}

TEST_CASE("A curved motion is checked along its curve at its peak speed's samples", "[planner][collision]") {
  const PlateWorld& plate = plateWorld();
  CollisionChecker dut(plate.scene);
  // the base turns past the plate while the shoulder lifts the gripper 2-3 cm over it
  const core::ArmConfig& from = plate.before;
  core::ArmConfig to = plate.after;
  to[1] -= 0.05;
  const VectorXd q_from = fullQ(from, 0.025);
  const VectorXd q_to = fullQ(to, 0.025);
  REQUIRE(dut.motionFree(0, q_from, q_to, {}));
  // turning first, at the plate's height, hits it; lifting first clears it
  const planner::CurvePiece turn_first = staircase(q_from, q_to, 0);
  const planner::CurvePiece lift_first = staircase(q_from, q_to, 1);
  CHECK_FALSE(dut.motionFree(0, turn_first, {}));
  dut.resetCounters();
  CHECK(dut.motionFree(0, lift_first, {}));
  // at twice the straight line's samples: every step within the motion step (the samples
  // within a measured gap of one evaluated are known free without being evaluated)
  const double travel = plate.scene.motionTravel(0, q_from, q_to);
  const auto n = static_cast<std::uint64_t>(std::ceil(2 * travel / plate.scene.settings().motion_step - 1e-9));
  CHECK(dut.counters().motion_samples == n + 1);
  CHECK(dut.counters().configurations <= n + 1);
  CHECK(n + 1 > 2 * static_cast<std::uint64_t>(plate.scene.motionSteps(0, q_from, q_to)) - 2);
  // a curve whose peak bound is unset or below 1, or that gives configurations of the wrong
  // size, is refused
  planner::CurvePiece bad = lift_first;
  bad.peak_over_mean = 0.5;
  CHECK_THROWS_AS(dut.motionFree(0, bad, {}), std::invalid_argument);
  bad.peak_over_mean = planner::CurvePiece{}.peak_over_mean;
  CHECK_THROWS_AS(dut.motionFree(0, bad, {}), std::invalid_argument);
  bad.peak_over_mean = 2.0;
  bad.at = [](double, VectorXd& q) { q = VectorXd::Zero(6); };
  CHECK_THROWS_AS(dut.motionFree(0, bad, {}), std::invalid_argument);
  bad.at = nullptr;
  CHECK_THROWS_AS(dut.motionFree(0, bad, {}), std::invalid_argument);
}

TEST_CASE("Motion queries skip the samples within measured gaps and agree with robotFree at every sample",
          "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const CollisionScene& scene = sortingScene();
  CollisionChecker dut(scene);
  CollisionChecker check(scene);
  RandomQueries random(23);
  int free = 0, blocked = 0, touching = 0;
  std::uint64_t samples_of_free = 0, evaluated_of_free = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const VectorXd a = random.towardsCentre((*loaded.robots)[0]);
    VectorXd b = a;
    for (int j = 0; j < 6; ++j) b[j] += random.uniform(-0.3, 0.3);
    const auto held = random.held(world, 0.4);
    const std::vector<RestingObject> objects = random.objects(world, linkOrigins((*loaded.robots)[0], b));
    const int n = scene.motionSteps(0, a, b, held);
    std::vector<VectorXd> samples;
    for (int k = 0; k <= n; ++k) samples.emplace_back(a + (static_cast<double>(k) / n) * (b - a));
    const auto all = [&](std::span<const RestingObject> among) {
      return std::all_of(samples.begin(), samples.end(),
                         [&](const VectorXd& q) { return check.robotFree(0, q, among, held); });
    };
    dut.resetCounters();
    const bool expected_free = all(objects);
    REQUIRE(dut.motionFree(0, a, b, objects, held) == expected_free);
    if (expected_free) {
      ++free;
      CHECK(dut.counters().motion_samples == static_cast<std::uint64_t>(n) + 1);
      samples_of_free += dut.counters().motion_samples;
      evaluated_of_free += dut.counters().configurations;
    }
    const std::optional<std::vector<char>> hits = dut.motionCheck(0, a, b, objects, held);
    REQUIRE(hits.has_value() == all({}));
    if (!hits) {
      ++blocked;
      continue;
    }
    for (std::size_t k = 0; k < objects.size(); ++k) {
      const bool expected = !all(std::span(&objects[k], 1));
      CHECK(static_cast<bool>((*hits)[k]) == expected);
      touching += expected;
    }
  }
  // both answers of each query are covered
  CHECK(free > 10);
  CHECK(blocked > 10);
  CHECK(touching > 0);
  // most samples of the free motions are known free without being evaluated
  CHECK(evaluated_of_free * 2 < samples_of_free);
}

TEST_CASE("Curve queries agree with the single-configuration checks at the curve's samples", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const core::RobotSet& robots = *loaded.robots;
  const CollisionScene& scene = sortingScene();
  CollisionChecker dut(scene);
  const std::vector<RestingObject> objects = planner::startPlacement(world);
  const std::vector<planner::StandingRobot> standing{
      {1, homeQ(world, 1), std::nullopt}, {1, fullQ(solveNearHome(robots[1], tcpDown({0.035, 0.0, 0.95})), 0.025), std::nullopt}};
  RandomQueries random(11);
  int hits = 0, clashes = 0, free = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const VectorXd a = random.towardsCentre(robots[0]);
    VectorXd b = a;
    for (int j = 0; j < 6; ++j) b[j] += random.uniform(-0.4, 0.4);
    // every other motion ends with the open gripper down at a cube
    const RestingObject& cube = objects[static_cast<std::size_t>(trial / 2) % objects.size()];
    const auto down = robots[0].solveInWorld(tcpDown(cube.X_WO.translation() + Vector3d(0, 0, 0.01)), robots[0].spec->home);
    if (trial % 2 == 1 && !down.empty()) b = fullQ(down.front(), 0.025);
    const planner::CurvePiece piece = staircase(a, b, trial % 6);
    const int n = static_cast<int>(std::ceil(2 * scene.motionTravel(0, a, b) / scene.settings().motion_step - 1e-9));
    std::vector<VectorXd> samples;
    for (int k = 0; k <= n; ++k) {
      samples.emplace_back();
      piece.at(static_cast<double>(k) / n, samples.back());
    }
    const auto all = [&](const auto& free_at) { return std::all_of(samples.begin(), samples.end(), free_at); };
    const bool expected_free = all([&](const VectorXd& q) { return dut.robotFree(0, q, objects); });
    CHECK(dut.motionFree(0, piece, objects) == expected_free);
    if (all([&](const VectorXd& q) { return dut.robotFree(0, q, {}); })) {
      const std::vector<char> object_hits = dut.motionObjectHits(0, piece, objects);
      for (std::size_t k = 0; k < objects.size(); ++k) {
        const bool expected = !all([&](const VectorXd& q) { return dut.robotFree(0, q, std::span(&objects[k], 1)); });
        CHECK(static_cast<bool>(object_hits[k]) == expected);
        hits += expected;
      }
    }
    const bool expected_clear = all([&](const VectorXd& q) {
      return std::all_of(standing.begin(), standing.end(), [&](const planner::StandingRobot& o) {
        return dut.robotsFree(0, q, std::nullopt, o.robot, o.q, o.held);
      });
    });
    CHECK(dut.motionClearOf(0, piece, std::nullopt, standing) == expected_clear);
    clashes += !expected_clear;
    free += expected_free;
  }
  // the trials cover both answers of each query
  CHECK(hits > 0);
  CHECK(clashes > 0);
  CHECK(clashes < 40);
  CHECK(free > 0);
  CHECK(free < 40);
}

TEST_CASE("timedPathsFree checks two robots at common times", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const core::RobotSet& robots = *loaded.robots;
  CollisionChecker dut(sortingScene());
  // r0 sweeps its gripper across the table centre; r1 reaches to the centre
  const core::ArmConfig centre0 = solveNearHome(robots[0], tcpDown({-0.035, 0.0, 0.95}));
  core::ArmConfig left = centre0;
  core::ArmConfig right = centre0;
  left[0] -= 0.8;
  right[0] += 0.8;
  const VectorXd sweep_from = fullQ(left, 0.025);
  const VectorXd sweep_to = fullQ(right, 0.025);
  const VectorXd reach1 = fullQ(solveNearHome(robots[1], tcpDown({0.035, 0.0, 0.95})), 0.025);
  const VectorXd home1 = homeQ(world, 1);
  REQUIRE_FALSE(dut.robotsFree(0, fullQ(centre0, 0.025), std::nullopt, 1, reach1, std::nullopt));
  REQUIRE(dut.robotsFree(0, sweep_from, std::nullopt, 1, reach1, std::nullopt));
  REQUIRE(dut.robotsFree(0, sweep_to, std::nullopt, 1, reach1, std::nullopt));

  // r1 waits at the centre while r0 sweeps through it
  CHECK_FALSE(dut.motionsFree(0, sweep_from, sweep_to, std::nullopt, 1, reach1, reach1, std::nullopt));
  const planner::TimedPath sweep{{0.0, 1.0}, {sweep_from, sweep_to}};
  CHECK_FALSE(dut.timedPathsFree(0, sweep, std::nullopt, 1, {{0.0}, {reach1}}, std::nullopt));
  // r1 goes to the centre only after r0 has passed
  const planner::TimedPath after{{0.0, 1.0, 2.0}, {home1, home1, reach1}};
  CHECK(dut.timedPathsFree(0, sweep, std::nullopt, 1, after, std::nullopt));
  // ... but not if it leaves too early
  const planner::TimedPath early{{0.0, 0.5}, {home1, reach1}};
  CHECK_FALSE(dut.timedPathsFree(0, sweep, std::nullopt, 1, early, std::nullopt));
}

TEST_CASE("motionClearOf answers as motionsFree against each standing robot", "[planner][collision]") {
  const auto& loaded = sortingWorld();
  const core::World& world = *loaded.world;
  const core::RobotSet& robots = *loaded.robots;
  CollisionChecker dut(sortingScene());
  const core::ArmConfig centre0 = solveNearHome(robots[0], tcpDown({-0.035, 0.0, 0.95}));
  const core::ArmConfig centre1 = solveNearHome(robots[1], tcpDown({0.035, 0.0, 0.95}));
  // r0's motions: sweeps across the centre, to it, and staying home
  std::vector<std::pair<VectorXd, VectorXd>> motions;
  for (const double swing : {0.3, 0.8}) {
    core::ArmConfig left = centre0, right = centre0;
    left[0] -= swing;
    right[0] += swing;
    motions.emplace_back(fullQ(left, 0.025), fullQ(right, 0.025));
  }
  motions.emplace_back(homeQ(world, 0), fullQ(centre0, 0.0));
  motions.emplace_back(homeQ(world, 0), homeQ(world, 0));
  // r1 standing: at home, at the centre, on the way, and beside it
  std::vector<planner::StandingRobot> standing;
  for (const double s : {0.0, 0.5, 1.0}) {
    standing.push_back({1, homeQ(world, 1) + s * (fullQ(centre1, 0.025) - homeQ(world, 1)), std::nullopt});
  }
  core::ArmConfig beside = centre1;
  beside[0] += 0.6;
  standing.push_back({1, fullQ(beside, 0.025), std::nullopt});
  int clear = 0, blocked = 0;
  for (const auto& [from, to] : motions) {
    for (std::size_t first = 0; first < standing.size(); ++first) {
      for (std::size_t count = 1; first + count <= standing.size(); ++count) {
        const std::span<const planner::StandingRobot> others(standing.data() + first, count);
        const bool expected = std::all_of(others.begin(), others.end(), [&](const planner::StandingRobot& o) {
          return dut.motionsFree(0, from, to, std::nullopt, o.robot, o.q, o.q, o.held);
        });
        CHECK(dut.motionClearOf(0, from, to, std::nullopt, others) == expected);
        ++(expected ? clear : blocked);
      }
    }
  }
  // both answers occur
  CHECK(clear > 0);
  CHECK(blocked > 0);
  CHECK(dut.motionClearOf(0, motions[0].first, motions[0].second, std::nullopt, {}));
  const planner::StandingRobot itself{0, homeQ(world, 0), std::nullopt};
  CHECK_THROWS_AS(dut.motionClearOf(0, motions[0].first, motions[0].second, std::nullopt, {&itself, 1}),
                  std::invalid_argument);
}
