// dashbed export PLAN --world WORLD --to urscript|ros2|csv -o DIR: the plan as programs for the
// real robots (tools/export/plan_export.h). Refuses a plan that fails the hardware readiness
// check unless --force. Exit 0 written, 1 not ready, 3 bad input.

#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/asset_paths.h"
#include "core/readiness.h"
#include "core/world_loader.h"
#include "sim/run_plan.h"
#include "tools/cli/cli_support.h"
#include "tools/export/plan_export.h"

namespace dashbed::tools {
namespace {

struct ExportCommandOptions {
  std::string plan_file;
  std::string world_file;
  std::string format;
  std::string out_dir;
  bool force = false;
  exporting::ExportOptions options;
};

void runExport(ExportCommandOptions o) {
  const std::filesystem::path world_path = worldFileOrDefault(o.world_file);
  const core::LoadedWorld loaded = core::loadWorld(world_path);
  const core::Plan plan = core::loadPlanFile(o.plan_file);
  core::validatePlanForWorld(plan, *loaded.world, *loaded.robots, o.plan_file);
  const core::ReadinessReport readiness = core::checkReadiness(plan, *loaded.world, *loaded.robots);
  if (!readiness.ready() && !o.force) {
    std::cerr << "dashbed export: " << o.plan_file << " is not ready for hardware: " << readiness.failures()
              << "\n(see `dashbed check`; --force exports it anyway)\n";
    throw CLI::RuntimeError(kExitCheckFailed);
  }
  o.options.header = {"world: " + loaded.world->name + " (" + world_path.string() + ")", "plan: " + o.plan_file,
                      readiness.ready()
                          ? "hardware readiness: ready, " + std::to_string(readiness.checks.size()) +
                                " checks passed (dashbed check)"
                          : "hardware readiness: NOT READY, exported with --force: " + readiness.failures(),
                      std::string("written by dashbed ") + DASHBED_VERSION};
  const exporting::ExportTimeline timeline = exporting::exportTimeline(plan, *loaded.world);
  std::vector<exporting::ExportFile> files;
  if (o.format == "urscript") files = exporting::exportUrScript(timeline, o.options);
  if (o.format == "ros2") files = exporting::exportRos2(timeline, o.options);
  if (o.format == "csv") files = exporting::exportCsv(timeline, o.options);
  std::filesystem::create_directories(o.out_dir);
  for (const exporting::ExportFile& file : files) {
    const std::filesystem::path path = std::filesystem::path(o.out_dir) / file.name;
    std::ofstream out(path, std::ios::binary);
    out << file.text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
    std::cout << "wrote " << path.string() << "\n";
  }
}

}  // namespace

void addExportCommand(CLI::App& app) {
  auto o = std::make_shared<ExportCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "export", "The plan as programs for the real robots, each following the plan's interpolated curve: per robot a "
                "URScript program (servoj at 500 Hz, Robotiq Hand-E commands, synchronised handoffs), a ROS 2 "
                "FollowJointTrajectory goal with a gripper timeline, or a CSV table. Refuses a plan that fails the "
                "hardware readiness check unless --force. Exit 0 written, 1 not ready, 3 bad input.");
  cmd->add_option("plan", o->plan_file, "plan file (JSON)")->required();
  cmd->add_option("--world", o->world_file, "world file (default: worlds/default.yaml)");
  cmd->add_option("--to", o->format, "format: urscript, ros2 or csv")
      ->required()
      ->check(CLI::IsMember({"urscript", "ros2", "csv"}));
  cmd->add_option("-o,--out", o->out_dir, "output directory (created)")->required();
  cmd->add_flag("--force", o->force, "export a plan that fails the readiness check (the header says so)");
  cmd->add_option("--sample-step", o->options.sample_step, "ros2, csv: spacing of the samples besides the plan's points [s]")
      ->check(CLI::Range(0.001, 1.0))
      ->capture_default_str();
  cmd->add_option("--lookahead", o->options.lookahead, "urscript: servoj lookahead_time [s]")
      ->check(CLI::Range(0.03, 0.2))
      ->capture_default_str();
  cmd->add_option("--gain", o->options.gain, "urscript: servoj gain")->check(CLI::Range(100.0, 2000.0))->capture_default_str();
  cmd->add_option("--sync-host", o->options.sync_host, "urscript: host of the synchronisation server")
      ->capture_default_str();
  cmd->add_option("--sync-port", o->options.sync_port, "urscript: port of the synchronisation server")
      ->check(CLI::Range(1, 65535))
      ->capture_default_str();
  cmd->callback([o] { runGuarded("export", [&] { runExport(*o); }); });
}

}  // namespace dashbed::tools
