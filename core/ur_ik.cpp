#include "core/ur_ik.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/kinematics.h"

namespace dashbed::core {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr std::array<double, 6> kAlpha{kPi / 2, 0.0, 0.0, kPi / 2, -kPi / 2, 0.0};

Pose dhTransform(double theta, double d, double a, double alpha) {
  const double ct = std::cos(theta), st = std::sin(theta);
  const double ca = std::cos(alpha), sa = std::sin(alpha);
  Pose T = Pose::Identity();
  T.matrix() << ct, -st * ca, st * sa, a * ct,  //
      st, ct * ca, -ct * sa, a * st,            //
      0.0, sa, ca, d,                           //
      0.0, 0.0, 0.0, 1.0;
  return T;
}

/// acos for values that may exceed [-1, 1] by rounding; nullopt when clearly outside.
std::optional<double> safeAcos(double x) {
  constexpr double kSlack = 1e-10;
  if (x > 1.0 + kSlack || x < -1.0 - kSlack) return std::nullopt;
  return std::acos(std::clamp(x, -1.0, 1.0));
}

}  // namespace

Pose urForwardKinematics(const UrDhParameters& dh, const ArmConfig& q) {
  const std::array<double, 6> d{dh.d1, 0.0, 0.0, dh.d4, dh.d5, dh.d6};
  const std::array<double, 6> a{0.0, dh.a2, dh.a3, 0.0, 0.0, 0.0};
  Pose T = Pose::Identity();
  for (int i = 0; i < 6; ++i) T = T * dhTransform(q[i], d[i], a[i], kAlpha[i]);
  return T;
}

std::vector<ArmConfig> urInverseKinematics(const UrDhParameters& dh, const Pose& T_06) {
  std::vector<ArmConfig> solutions;
  solutions.reserve(8);
  const Eigen::Matrix3d& R = T_06.linear();
  const Eigen::Vector3d p = T_06.translation();
  const Eigen::Vector3d n = R.col(0), o = R.col(1), a = R.col(2);

  // shoulder pan: the wrist centre p5 = p - d6 a satisfies s1 p5x - c1 p5y = d4
  const Eigen::Vector3d p5 = p - dh.d6 * a;
  const double r5 = std::hypot(p5.x(), p5.y());
  if (r5 < std::abs(dh.d4) - 1e-12) return solutions;  // wrist centre inside the shoulder cylinder
  const double phi = std::atan2(p5.y(), p5.x());
  const double psi = std::asin(std::clamp(dh.d4 / r5, -1.0, 1.0));
  for (const double q1 : {phi + psi, phi + kPi - psi}) {
    const double s1 = std::sin(q1), c1 = std::cos(q1);
    // wrist 2 from the tool position along the shoulder axis: s1 px - c1 py = d4 + d6 c5
    const auto acos5 = safeAcos((s1 * p.x() - c1 * p.y() - dh.d4) / dh.d6);
    if (!acos5) continue;
    for (const double q5 : {*acos5, -*acos5}) {
      const double s5 = std::sin(q5);
      // wrist 3 from the third row of R_16 = Rz(q234) Ry(-q5) Rz(q6): [s5 c6, -s5 s6, c5]
      double q6 = 0.0;
      if (std::abs(s5) > 1e-10) {
        q6 = std::atan2(-(s1 * o.x() - c1 * o.y()) / s5, (s1 * n.x() - c1 * n.y()) / s5);
      }
      // everything in frame 1 (after the pan joint and the fixed alpha1 twist)
      const Pose T_01 = dhTransform(q1, dh.d1, 0.0, kAlpha[0]);
      const Pose T_16 = T_01.inverse() * T_06;
      const Eigen::Matrix3d R_234 = T_16.linear() * Eigen::AngleAxisd(-q6, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(q5, Eigen::Vector3d::UnitY());
      const double q234 = std::atan2(R_234(1, 0), R_234(0, 0));
      // frame 4 origin: back off d6 along z5 (= z6) and d5 along z4 = (s234, -c234, 0), then d4 along z1
      const Eigen::Vector3d z5 = T_16.linear().col(2);
      const Eigen::Vector3d z4(std::sin(q234), -std::cos(q234), 0.0);
      const Eigen::Vector3d p14 = T_16.translation() - dh.d6 * z5 - dh.d5 * z4;
      const double x = p14.x(), y = p14.y();
      // planar two-link arm a2, a3
      const auto acos3 = safeAcos((x * x + y * y - dh.a2 * dh.a2 - dh.a3 * dh.a3) / (2.0 * dh.a2 * dh.a3));
      if (!acos3) continue;
      for (const double q3 : {*acos3, -*acos3}) {
        const double q2 = std::atan2(y, x) - std::atan2(dh.a3 * std::sin(q3), dh.a2 + dh.a3 * std::cos(q3));
        const double q4 = q234 - q2 - q3;
        ArmConfig q{q1, q2, q3, q4, q5, q6};
        for (double& angle : q) angle = wrapToPi(angle);
        const bool duplicate = std::any_of(solutions.begin(), solutions.end(), [&](const ArmConfig& s) {
          for (int i = 0; i < 6; ++i) {
            if (std::abs(wrapToPi(s[i] - q[i])) > 1e-9) return false;
          }
          return true;
        });
        if (!duplicate) solutions.push_back(q);
      }
    }
  }
  return solutions;
}

UrArmIk::UrArmIk(const RobotModel& model, const UrDhParameters& dh, std::string_view tcp_link) : dh_(dh) {
  const int root = 0;
  const int base = model.requireLink("base");
  const int tool0 = model.requireLink("tool0");
  const int tcp = model.requireLink(tcp_link);
  X_RBase_ = model.fixedTransform(root, base);
  X_Tool0T_ = model.fixedTransform(tool0, tcp);
  if (model.numPositions() < 6) throw std::invalid_argument("UrArmIk: model has fewer than six joints");
  for (int i = 0; i < 6; ++i) {
    const JointModel& joint = model.joints()[model.movableJoints()[i]];
    if (joint.type != JointType::kRevolute) {
      throw std::invalid_argument("UrArmIk: joint '" + joint.name + "' is not revolute");
    }
    lower_[i] = joint.lower;
    upper_[i] = joint.upper;
  }
  // the URDF chain must agree with the DH model, or IK would silently disagree with FK
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.numPositions());
  const std::array<ArmConfig, 3> probes{ArmConfig{0, 0, 0, 0, 0, 0}, ArmConfig{0.3, -1.1, 1.4, -0.7, 0.9, -2.1},
                                        ArmConfig{-2.0, -0.4, -1.9, 2.5, -1.3, 0.6}};
  for (const ArmConfig& probe : probes) {
    for (int i = 0; i < 6; ++i) q[i] = probe[i];
    const Pose X_RTool0 = linkPoses(model, q)[tool0];
    const Pose X_dh = X_RBase_ * urForwardKinematics(dh_, probe);
    if (!X_RTool0.isApprox(X_dh, 1e-9)) {
      throw std::invalid_argument("UrArmIk: the URDF chain of '" + model.name() +
                                  "' does not reproduce the UR DH model");
    }
  }
}

Pose UrArmIk::tcpPose(const ArmConfig& q) const { return X_RBase_ * urForwardKinematics(dh_, q) * X_Tool0T_; }

bool UrArmIk::wrapIntoLimits(int joint, double target, double& angle) const {
  // candidate representatives angle + 2 pi k within the limits; choose the one nearest target
  const double lo = lower_[joint] - 1e-12, hi = upper_[joint] + 1e-12;
  const double k_min = std::ceil((lo - angle) / kTwoPi);
  const double k_max = std::floor((hi - angle) / kTwoPi);
  if (k_min > k_max) return false;
  const double k_best = std::clamp(std::round((target - angle) / kTwoPi), k_min, k_max);
  angle = std::clamp(angle + k_best * kTwoPi, lower_[joint], upper_[joint]);
  return true;
}

std::vector<ArmConfig> UrArmIk::solve(const Pose& X_RT) const {
  const Pose T_06 = X_RBase_.inverse() * X_RT * X_Tool0T_.inverse();
  std::vector<ArmConfig> solutions = urInverseKinematics(dh_, T_06);
  std::size_t kept = 0;  // those within the limits, in order
  for (ArmConfig& q : solutions) {
    bool ok = true;
    for (int i = 0; i < 6 && ok; ++i) ok = wrapIntoLimits(i, 0.0, q[i]);
    if (ok) solutions[kept++] = q;
  }
  solutions.resize(kept);
  return solutions;
}

std::vector<ArmConfig> UrArmIk::solveNearest(const Pose& X_RT, const ArmConfig& seed) const {
  std::vector<ArmConfig> solutions = solve(X_RT);
  for (ArmConfig& q : solutions) {
    for (int i = 0; i < 6; ++i) wrapIntoLimits(i, seed[i], q[i]);
  }
  // insertion by squared distance (at most 8 solutions), each distance computed once; stable:
  // equal distances keep the analytic order, so results are deterministic
  std::array<std::pair<double, ArmConfig>, 8> by_distance;  // 2 pans x 2 wrists x 2 elbows at most
  std::size_t n = 0;
  for (const ArmConfig& q : solutions) {
    double sum = 0.0;
    for (int i = 0; i < 6; ++i) sum += (q[i] - seed[i]) * (q[i] - seed[i]);
    std::size_t at = n++;
    for (; at > 0 && by_distance[at - 1].first > sum; --at) by_distance[at] = by_distance[at - 1];
    by_distance[at] = {sum, q};
  }
  for (std::size_t k = 0; k < n; ++k) solutions[k] = by_distance[k].second;
  return solutions;
}

std::optional<ArmConfig> UrArmIk::nearest(const Pose& X_RT, const ArmConfig& seed) const {
  const std::vector<ArmConfig> solutions = solveNearest(X_RT, seed);
  if (solutions.empty()) return std::nullopt;
  return solutions.front();
}

}  // namespace dashbed::core
