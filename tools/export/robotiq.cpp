#include "tools/export/robotiq.h"

#include <algorithm>
#include <cmath>

#include "core/hande.h"

namespace dashbed::exporting {
namespace {

constexpr double kRegisterMax = 255.0;

/// x in [lo, hi] as 0 .. 255 (clamped, rounded).
int reg(double x, double lo, double hi) {
  const double r = std::round((x - lo) / (hi - lo) * kRegisterMax);
  return static_cast<int>(std::clamp(r, 0.0, kRegisterMax));
}

double value(int r, double lo, double hi) { return lo + (hi - lo) * static_cast<double>(r) / kRegisterMax; }

}  // namespace

int robotiqPosition(double opening) { return reg(core::kHandeMaxOpening - opening, 0.0, core::kHandeMaxOpening); }
int robotiqSpeed(double speed) { return reg(speed, core::kHandeMinSpeed, core::kHandeMaxSpeed); }
int robotiqForce(double force) { return reg(force, core::kHandeMinForce, core::kHandeMaxForce); }

double openingOfRobotiq(int position) { return core::kHandeMaxOpening - value(position, 0.0, core::kHandeMaxOpening); }
double speedOfRobotiq(int speed) { return value(speed, core::kHandeMinSpeed, core::kHandeMaxSpeed); }
double forceOfRobotiq(int force) { return value(force, core::kHandeMinForce, core::kHandeMaxForce); }

}  // namespace dashbed::exporting
