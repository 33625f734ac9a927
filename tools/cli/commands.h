#pragma once
// The subcommands of the `dashbed` command line. Each add*Command registers one subcommand
// on the app; its callback throws CLI::RuntimeError(exit code) to fail with a documented code.

#include <CLI/CLI.hpp>

namespace dashbed::tools {

/// Exit codes of the dashbed command (documented in the README).
enum ExitCode : int {
  kExitOk = 0,
  kExitCheckFailed = 1,     ///< a physical check or validation of the result failed
  kExitUsage = 2,           ///< bad command line
  kExitBadInput = 3,        ///< malformed or invalid input file (world, plan)
  kExitInfeasible = 4,      ///< the planner proved the problem infeasible
  kExitTimeout = 5,         ///< a budget ran out before a result
  kExitInternal = 70,       ///< a bug: an unexpected exception
};

void addRunCommand(CLI::App& app);
void addGenCommand(CLI::App& app);
void addKinCommand(CLI::App& app);
void addScriptCommand(CLI::App& app);
void addSimCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addGraphCommand(CLI::App& app);
void addStressCommand(CLI::App& app);
void addPlanCommand(CLI::App& app);
void addCheckCommand(CLI::App& app);
void addExportCommand(CLI::App& app);
void addViewCommand(CLI::App& app);

}  // namespace dashbed::tools
