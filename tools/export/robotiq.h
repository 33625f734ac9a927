#pragma once
// The Robotiq Hand-E's command registers (0-255), as its Modbus registers and the Robotiq URCap's
// rq_move, rq_set_speed and rq_set_force take them (Hand-E instruction manual, 4.x "Control":
// position request 0 = fully open, 255 = fully closed; speed and force 0 = the minimum, 255 =
// the maximum). dashbed maps them linearly onto the Hand-E's figures (core/hande.h): opening
// 50 mm .. 0, speed 20 .. 150 mm/s, force 20 .. 185 N. Robotiq does not publish the mapping
// itself; a unit calibrated on the cell may differ.

namespace dashbed::exporting {

/// Register value of an opening between the fingers [m], 0 (50 mm) .. 255 (closed), rounded.
int robotiqPosition(double opening);
/// Register value of a finger speed [m/s], 0 (20 mm/s) .. 255 (150 mm/s), rounded.
int robotiqSpeed(double speed);
/// Register value of a grip force [N], 0 (20 N) .. 255 (185 N), rounded.
int robotiqForce(double force);

/// The inverses: what a register value stands for.
double openingOfRobotiq(int position);
double speedOfRobotiq(int speed);
double forceOfRobotiq(int force);

}  // namespace dashbed::exporting
