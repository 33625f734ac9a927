// The arm's collision detection on synthetic steps: the motion the model predicts has no
// external load; a push at the TCP is estimated to its magnitude and stops the arm past the
// limit; a torque on one joint trips that joint.

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include "controllers/collision_detection.h"
#include "core/dynamics.h"
#include "core/kinematics.h"

#include "tests/core/ur5e_hande_model.h"

using namespace dashbed;
using controllers::CollisionDetector;
using controllers::ProtectiveStopTrip;

namespace {

constexpr double kStep = 0.001;
const Eigen::Vector3d kGravity(0.0, 0.0, -9.81);

struct Scene {
  const core::RobotModel& model = test::ur5eHande();
  int tcp = model.requireLink("tcp");
  Eigen::VectorXd q = Eigen::VectorXd::Zero(8);
  Eigen::VectorXd qd = Eigen::VectorXd::Zero(8);
  Eigen::VectorXd qdd = Eigen::VectorXd::Zero(8);
  Scene() {
    q << 0.3, -1.2, 1.4, -1.8, -1.57, 0.4, 0.01, 0.01;
    qd << 0.2, -0.1, 0.3, 0.1, -0.2, 0.5, 0.0, 0.0;
    qdd << 1.0, -0.5, 0.8, 0.2, 0.3, -1.0, 0.0, 0.0;
  }

  /// Feeds `steps` steps in which the arm makes the motion qdd while `external` (joint
  /// efforts of an outside load) acts on it: the drives apply what the model needs minus it.
  void run(CollisionDetector& detector, const Eigen::Matrix<double, 6, 1>& external, int steps,
           const core::Payload* payload = nullptr) const {
    const Eigen::VectorXd needed = core::inverseDynamics(model, q, qd, qdd, kGravity, payload);
    core::Vector6 tau{};
    for (int i = 0; i < 6; ++i) tau[i] = needed[i] - external[i];
    for (int k = 0; k < steps && !detector.trip(); ++k) detector.update(q, qd, tau, qd + kStep * qdd, payload);
  }

  /// The joint efforts of a force F [N] at the TCP (root frame).
  Eigen::Matrix<double, 6, 1> tcpForce(const Eigen::Vector3d& force) const {
    const Eigen::Matrix<double, 6, 6> J = core::jacobian(model, q, tcp).leftCols<6>();
    return J.topRows<3>().transpose() * force;
  }
};

core::SafetySettings safety(double tcp_force, double external_torque) {
  core::SafetySettings settings;
  settings.tcp_force = tcp_force;
  settings.external_torque = external_torque;
  return settings;
}

}  // namespace

TEST_CASE("the motion the model predicts has no external load", "[collision_detection]") {
  const Scene scene;
  CollisionDetector detector(scene.model, core::SafetySettings{}, kGravity, scene.tcp, kStep);
  scene.run(detector, Eigen::Matrix<double, 6, 1>::Zero(), 200);
  CHECK_FALSE(detector.trip());
  CHECK(detector.maxTcpForce() < 1e-6);
  CHECK(detector.maxTorqueRatio() < 1e-8);
}

TEST_CASE("a payload the controller was not told of is an external load", "[collision_detection]") {
  const Scene scene;
  core::Payload payload;
  payload.link = scene.tcp;
  payload.mass = 2.0;
  payload.inertia = Eigen::Matrix3d::Identity() * 1e-3;
  // the arm carries 2 kg: told of it, no load; not told, about its weight (19.6 N) at the TCP
  CollisionDetector told(scene.model, core::SafetySettings{}, kGravity, scene.tcp, kStep);
  const Eigen::VectorXd with = core::inverseDynamics(scene.model, scene.q, scene.qd, scene.qdd, kGravity, &payload);
  const Eigen::VectorXd without = core::inverseDynamics(scene.model, scene.q, scene.qd, scene.qdd, kGravity);
  core::Vector6 tau{};
  for (int i = 0; i < 6; ++i) tau[i] = with[i];
  CollisionDetector untold(scene.model, core::SafetySettings{}, kGravity, scene.tcp, kStep);
  for (int k = 0; k < 500; ++k) {
    told.update(scene.q, scene.qd, tau, scene.qd + kStep * scene.qdd, &payload);
    untold.update(scene.q, scene.qd, tau, scene.qd + kStep * scene.qdd, nullptr);
  }
  CHECK(told.load().tcp_force < 1e-6);
  const double weight = payload.mass * 9.81;
  // the payload also needs force to accelerate; the estimate is its weight and inertia force
  CHECK(untold.load().tcp_force > 0.8 * weight);
  CHECK(untold.load().tcp_force < 1.5 * weight);
  CHECK((with - without).head<6>().norm() > 0.0);
}

TEST_CASE("a push at the TCP is estimated to its magnitude and stops the arm past the limit", "[collision_detection]") {
  const Scene scene;
  // joint limits far away: only the TCP force decides
  CollisionDetector below(scene.model, safety(150.0, 100.0), kGravity, scene.tcp, kStep);
  scene.run(below, scene.tcpForce({30.0, -40.0, -120.0}), 300);  // 134.2 N
  CHECK_FALSE(below.trip());
  CHECK(below.load().tcp_force == Approx(std::sqrt(30.0 * 30.0 + 40.0 * 40.0 + 120.0 * 120.0)).epsilon(1e-3));

  CollisionDetector above(scene.model, safety(150.0, 100.0), kGravity, scene.tcp, kStep);
  scene.run(above, scene.tcpForce({0.0, 0.0, -200.0}), 300);
  REQUIRE(above.trip());
  CHECK(above.trip()->cause == ProtectiveStopTrip::Cause::kTcpForce);
  CHECK(above.trip()->value > 150.0);
  CHECK(above.trip()->value < 160.0);
  CHECK(above.trip()->limit == 150.0);
  CHECK(controllers::describeTrip(*above.trip(), "") .find("external TCP force 15") == 0);
}

TEST_CASE("a torque on one joint trips that joint", "[collision_detection]") {
  const Scene scene;
  // wrist 2 (index 4): rated 28 Nm, limit half of it
  Eigen::Matrix<double, 6, 1> external = Eigen::Matrix<double, 6, 1>::Zero();
  external[4] = 13.0;
  CollisionDetector below(scene.model, safety(1e6, 0.5), kGravity, scene.tcp, kStep);
  scene.run(below, external, 300);
  CHECK_FALSE(below.trip());
  CHECK(below.maxTorqueRatio() == Approx(13.0 / 14.0).epsilon(1e-3));

  external[4] = -15.0;
  CollisionDetector above(scene.model, safety(1e6, 0.5), kGravity, scene.tcp, kStep);
  scene.run(above, external, 300);
  REQUIRE(above.trip());
  CHECK(above.trip()->cause == ProtectiveStopTrip::Cause::kExternalTorque);
  CHECK(above.trip()->joint == 4);
  CHECK(above.trip()->limit == Approx(14.0));
  CHECK(controllers::describeTrip(*above.trip(), "wrist_2_joint").find("wrist_2_joint external torque 14") == 0);
}
