#include "core/dynamics.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "core/kinematics.h"

namespace dashbed::core {
namespace {

struct LinkMotion {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();   // angular velocity
  Eigen::Vector3d dw = Eigen::Vector3d::Zero();  // angular acceleration
  Eigen::Vector3d v = Eigen::Vector3d::Zero();   // velocity of the link origin
  Eigen::Vector3d a = Eigen::Vector3d::Zero();   // acceleration of the link origin
};

/// Forward pass: the motion of every link in the root frame. `base_acceleration` is the
/// (fictitious) acceleration of the root, -gravity to include gravity.
std::vector<LinkMotion> linkMotions(const RobotModel& model, const std::vector<Pose>& X_RL,
                                    const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd,
                                    const Eigen::Vector3d& base_acceleration) {
  const auto& links = model.links();
  std::vector<LinkMotion> m(links.size());
  m[0].a = base_acceleration;
  for (std::size_t i = 1; i < links.size(); ++i) {
    const JointModel& joint = model.joints()[links[i].parent_joint];
    const LinkMotion& p = m[joint.parent_link];
    const Eigen::Vector3d r = X_RL[i].translation() - X_RL[joint.parent_link].translation();
    LinkMotion& c = m[i];
    c.w = p.w;
    c.dw = p.dw;
    c.v = p.v + p.w.cross(r);
    c.a = p.a + p.dw.cross(r) + p.w.cross(p.w.cross(r));
    if (joint.q_index < 0) continue;
    const Eigen::Vector3d axis = X_RL[i].linear() * joint.axis;
    const double rate = qd[joint.q_index], accel = qdd[joint.q_index];
    if (joint.type == JointType::kRevolute) {
      c.w += axis * rate;
      c.dw += axis * accel + p.w.cross(axis * rate);
    } else {
      c.v += axis * rate;
      c.a += axis * accel + 2.0 * p.w.cross(axis * rate);
    }
  }
  return m;
}

}  // namespace

Eigen::VectorXd inverseDynamics(const RobotModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                const Eigen::VectorXd& qdd, const Eigen::Vector3d& gravity_R, const Payload* payload) {
  const auto& links = model.links();
  if (payload != nullptr && (payload->link < 0 || payload->link >= static_cast<int>(links.size()))) {
    throw std::invalid_argument("inverseDynamics: payload link " + std::to_string(payload->link) + " out of range");
  }
  const std::vector<Pose> X_RL = linkPoses(model, q);
  const std::vector<LinkMotion> m = linkMotions(model, X_RL, qd, qdd, -gravity_R);
  // per link: net force F and net moment N about the link origin needed for its motion,
  // accumulated from the leaves to the root (links are in topological order)
  std::vector<Eigen::Vector3d> F(links.size(), Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> N(links.size(), Eigen::Vector3d::Zero());
  // a body of link i: the force and moment its motion needs
  const auto add_body = [&](std::size_t i, double mass, const Pose& X_LCom, const Eigen::Matrix3d& inertia) {
    if (mass <= 0.0) return;
    const Pose X_RCom = X_RL[i] * X_LCom;
    const Eigen::Vector3d c = X_RCom.translation() - X_RL[i].translation();
    const Eigen::Matrix3d I = X_RCom.linear() * inertia * X_RCom.linear().transpose();
    const Eigen::Vector3d a_com = m[i].a + m[i].dw.cross(c) + m[i].w.cross(m[i].w.cross(c));
    const Eigen::Vector3d f = mass * a_com;
    F[i] += f;
    N[i] += I * m[i].dw + m[i].w.cross(I * m[i].w) + c.cross(f);
  };
  for (std::size_t i = links.size(); i-- > 0;) {
    const LinkModel& link = links[i];
    add_body(i, link.mass, link.X_LCom, link.inertia);
    if (payload != nullptr && payload->link == static_cast<int>(i)) {
      add_body(i, payload->mass, payload->X_LCom, payload->inertia);
    }
    if (link.parent_joint < 0) continue;
    const int parent = model.joints()[link.parent_joint].parent_link;
    F[parent] += F[i];
    N[parent] += N[i] + (X_RL[i].translation() - X_RL[parent].translation()).cross(F[i]);
  }
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.numPositions());
  for (std::size_t i = 1; i < links.size(); ++i) {
    const JointModel& joint = model.joints()[links[i].parent_joint];
    if (joint.q_index < 0) continue;
    const Eigen::Vector3d axis = X_RL[i].linear() * joint.axis;
    tau[joint.q_index] = joint.type == JointType::kRevolute ? axis.dot(N[i]) : axis.dot(F[i]);
  }
  return tau;
}

Eigen::VectorXd gravityTorques(const RobotModel& model, const Eigen::VectorXd& q, const Eigen::Vector3d& gravity_R) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.numPositions());
  return inverseDynamics(model, q, zero, zero, gravity_R);
}

Eigen::MatrixXd massMatrix(const RobotModel& model, const Eigen::VectorXd& q) {
  const int n = model.numPositions();
  Eigen::MatrixXd M(n, n);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < n; ++k) {
    M.col(k) = inverseDynamics(model, q, zero, Eigen::VectorXd::Unit(n, k), Eigen::Vector3d::Zero());
  }
  return 0.5 * (M + M.transpose());
}

double kineticEnergy(const RobotModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const std::vector<Pose> X_RL = linkPoses(model, q);
  const std::vector<LinkMotion> m =
      linkMotions(model, X_RL, qd, Eigen::VectorXd::Zero(model.numPositions()), Eigen::Vector3d::Zero());
  double energy = 0.0;
  for (std::size_t i = 0; i < model.links().size(); ++i) {
    const LinkModel& link = model.links()[i];
    if (link.mass <= 0.0) continue;
    const Pose X_RCom = X_RL[i] * link.X_LCom;
    const Eigen::Vector3d v_com = m[i].v + m[i].w.cross(X_RCom.translation() - X_RL[i].translation());
    const Eigen::Matrix3d I = X_RCom.linear() * link.inertia * X_RCom.linear().transpose();
    energy += 0.5 * link.mass * v_com.squaredNorm() + 0.5 * m[i].w.dot(I * m[i].w);
  }
  return energy;
}

}  // namespace dashbed::core
