// Trajectories made elsewhere (ROS 2 JointTrajectory YAML, CSV, gripper timeline YAML): each
// input is written to a file and read as each kind for robot r0 of the default world, or
// refused with a ForeignPlanError.
#include <fstream>
#include <string>
#include <unistd.h>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "fuzz_input.h"
#include "tools/export/foreign_plan.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dashbed;
  static const core::LoadedWorld world = core::loadWorld(core::defaultWorldPath());
  static const std::array<std::string, 6> joints{"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                                 "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};
  static const std::string stem = "/tmp/dashbed_fuzz_foreign_" + std::to_string(getpid());
  static const std::string yaml = stem + ".yaml", csv = stem + ".csv", timeline = stem + "_gripper.yaml";
  for (const std::string& file : {yaml, csv}) {
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  std::ofstream(timeline, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  for (const exporting::ForeignTrajectory& given :
       {exporting::ForeignTrajectory{"r0", yaml, ""}, exporting::ForeignTrajectory{"r0", csv, ""},
        exporting::ForeignTrajectory{"r0", csv, timeline}}) {
    fuzz::expectReadOrRefuse<exporting::ForeignPlanError>(
        [&] { exporting::readForeignPlan(*world.world, joints, {given}); });
  }
  return 0;
}
