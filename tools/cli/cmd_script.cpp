// dashbed script: an action script -> a timed plan (IK + straight joint moves), to exercise
// the simulator without the planner.

#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "core/plan.h"
#include "core/world_loader.h"
#include "tools/cli/cli_support.h"
#include "tools/script/scripted_plan.h"

namespace dashbed::tools {
namespace {

struct ScriptOptions {
  std::string world_file;
  std::string script;
  std::string script_file;
  std::string output;
};

std::string readText(const std::string& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw std::runtime_error(file + ": cannot open the script file");
  std::ostringstream text;
  text << stream.rdbuf();
  if (stream.bad()) throw std::runtime_error(file + ": cannot read the script file");
  return text.str();
}

void runScript(const ScriptOptions& options) {
  const core::LoadedWorld world = core::loadWorld(options.world_file);
  const bool from_file = !options.script_file.empty();
  const std::string script = from_file ? readText(options.script_file) : options.script;
  const core::Plan plan = planFromScript(world, script, from_file ? options.script_file : "script");
  const std::string json = core::writePlanJson(plan);
  if (options.output.empty()) {
    std::cout << json;
    return;
  }
  std::ofstream out(options.output, std::ios::binary);
  out << json;
  out.close();
  if (!out) throw std::runtime_error(options.output + ": cannot write the plan file");
}

}  // namespace

void addScriptCommand(CLI::App& app) {
  auto options = std::make_shared<ScriptOptions>();
  CLI::App* sub = app.add_subcommand(
      "script",
      "Turn an action script into a timed plan without the planner (IK waypoints, straight joint moves, "
      "slow straight approaches), e.g. --script \"r0 picks cube_0; r0 places cube_0 in bin_red\". "
      "Verbs: picks [from the side], places in REGION | at X Y Z, hands OBJECT to ROBOT, waits S, "
      "moves home | to Q1..Q6, opens, closes, stays. Exit 3 on a bad world or script.");
  sub->add_option("world", options->world_file, "world file (YAML)")->required();
  CLI::Option* text = sub->add_option("--script", options->script, "the script (statements separated by ';' or newlines)");
  CLI::Option* file = sub->add_option("--file", options->script_file, "read the script from a file")->excludes(text);
  sub->add_option("-o,--output", options->output, "plan file to write (default: standard output)");
  sub->callback([options, text, file] {
    if (text->count() == 0 && file->count() == 0) throw CLI::RequiredError("--script or --file");
    runGuarded("script", [&] { runScript(*options); });
  });
}

}  // namespace dashbed::tools
