// dashbed check PLAN --world WORLD: could a UR5e with a Hand-E run this plan as written
// (core/readiness.h)? Exit 0 ready, 1 not ready, 3 bad input.

#include <iomanip>
#include <iostream>
#include <optional>

#include "core/asset_paths.h"
#include "core/number_text.h"
#include "core/readiness.h"
#include "core/world_loader.h"
#include "sim/run_plan.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/number_checks.h"

namespace dashbed::tools {
namespace {

struct CheckOptions {
  std::string plan_file;
  std::string world_file;
  std::optional<double> max_joint_acceleration, payload, tcp_speed;  // the world's safety settings unless given
  bool json = false;
};

void runCheck(const CheckOptions& options) {
  const std::filesystem::path world_path = worldFileOrDefault(options.world_file);
  const core::LoadedWorld loaded = core::loadWorld(world_path);
  core::World world = *loaded.world;
  world.safety.max_joint_acceleration = options.max_joint_acceleration.value_or(world.safety.max_joint_acceleration);
  world.safety.payload = options.payload.value_or(world.safety.payload);
  world.safety.tcp_speed = options.tcp_speed.value_or(world.safety.tcp_speed);
  const core::Plan plan = core::loadPlanFile(options.plan_file);
  core::validatePlanForWorld(plan, world, *loaded.robots, options.plan_file);
  const core::ReadinessReport report = core::checkReadiness(plan, world, *loaded.robots);
  if (options.json) {
    nlohmann::json out = {{"ready", report.ready()}, {"checks", nlohmann::json::array()}};
    for (const core::ReadinessCheck& c : report.checks) {
      out["checks"].push_back({{"name", c.name}, {"subject", c.subject}, {"value", c.value}, {"limit", c.limit},
                               {"unit", c.unit}, {"t", c.t}, {"passed", c.passed}, {"detail", c.detail}});
    }
    std::cout << jsonText(out) << "\n";
  } else {
    for (const core::ReadinessCheck& c : report.checks) {
      std::cout << (c.passed ? "  PASS " : "  FAIL ") << std::left << std::setw(19) << c.name << std::setw(34)
                << c.subject << std::right << std::setw(10) << core::significantText(c.value, 4) << " "
                << std::left << std::setw(8) << c.unit << " limit " << core::significantText(c.limit, 4) << " at "
                << core::significantText(c.t, 5) << " s\n";
    }
    std::cout << (report.ready() ? "READY" : "NOT READY: " + report.failures()) << "\n";
  }
  if (!report.ready()) throw CLI::RuntimeError(kExitCheckFailed);
}

}  // namespace

void addCheckCommand(CLI::App& app) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* check = app.add_subcommand(
      "check", "Hardware readiness: whether a UR5e with a Hand-E could run the plan as written, judged on the "
               "interpolated curve (joint positions, speeds, accelerations, efforts, TCP speed), gripper forces, payload and grip "
               "(limits: the robot model's and the world's `safety` section). "
               "Exit 0 ready, 1 not ready, 3 bad input.");
  check->add_option("plan", options->plan_file, "plan file (JSON)")->required();
  check->add_option("--world", options->world_file, "world file (default: worlds/default.yaml)");
  check->add_option("--max-acceleration", options->max_joint_acceleration,
                    "joint acceleration limit [rad/s^2] (default: the world's safety.max_joint_acceleration)")
      ->check(positiveNumber());
  check->add_option("--payload", options->payload, "rated payload, gripper included [kg] (default: the world's safety.payload)")
      ->check(positiveNumber());
  check->add_option("--tcp-speed", options->tcp_speed, "TCP speed limit [m/s] (default: the world's safety.tcp_speed)")
      ->check(positiveNumber());
  check->add_flag("--json", options->json, "the checks as JSON");
  check->callback([options] { runGuarded("check", [&] { runCheck(*options); }); });
}

}  // namespace dashbed::tools
