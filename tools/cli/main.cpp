// dashbed: plan and physically check multi-robot pick, place and handoff work.

#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "tools/cli/commands.h"

int main(int argc, char** argv) {
  using namespace dashbed::tools;
  CLI::App app{"dashbed: plan and physically check multi-robot pick, place and handoff work "
               "(UR5e arms with Robotiq Hand-E grippers)."};
  app.set_version_flag("--version", std::string("dashbed ") + DASHBED_VERSION);
  app.require_subcommand(1);
  addRunCommand(app);
  addPlanCommand(app);
  addGenCommand(app);
  addKinCommand(app);
  addScriptCommand(app);
  addCheckCommand(app);
  addExportCommand(app);
  addSimCommand(app);
  addRenderCommand(app);
  addViewCommand(app);
  addBenchCommand(app);
  addGraphCommand(app);
  addStressCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "dashbed: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitOk;
}
