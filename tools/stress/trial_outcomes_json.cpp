// Trial outcomes as JSON (trials.json, the MPI gather) and the names of failure classes.
#include "tools/stress/stress.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "core/json_reader.h"

namespace dashbed::tools {
namespace {

constexpr std::array<std::string_view, kFailureClassCount> kFailureNames{
    "missed_grasp", "slip", "handoff_drop", "misplaced", "collision", "protective_stop", "not_ready", "planner_failure",
    "planner_timeout"};

core::ActionType parseActionType(std::string_view name) {
  for (const core::ActionType type : {core::ActionType::kPick, core::ActionType::kPlace, core::ActionType::kHandoff}) {
    if (core::toString(type) == name) return type;
  }
  throw std::invalid_argument("unknown action type '" + std::string(name) + "'");
}

}  // namespace

std::string_view toString(FailureClass failure) { return kFailureNames[static_cast<std::size_t>(failure)]; }

FailureClass parseFailureClass(std::string_view name) {
  const auto it = std::find(kFailureNames.begin(), kFailureNames.end(), name);
  if (it == kFailureNames.end()) throw std::invalid_argument("unknown failure class '" + std::string(name) + "'");
  return static_cast<FailureClass>(it - kFailureNames.begin());
}

std::string writeOutcomesJson(const std::vector<TrialOutcome>& outcomes) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const TrialOutcome& o : outcomes) {
    nlohmann::ordered_json trial;
    trial["index"] = o.index;
    trial["point"] = o.point;
    trial["seed"] = o.seed;
    trial["passed"] = o.passed;
    trial["primary"] = o.primary ? nlohmann::ordered_json(toString(*o.primary)) : nlohmann::ordered_json();
    trial["classes"] = nlohmann::ordered_json::array();
    for (const FailureClass c : o.classes) trial["classes"].push_back(toString(c));
    trial["failure"] = o.failure;
    trial["actions"] = nlohmann::ordered_json::array();
    for (const ActionOutcome& a : o.actions) {
      nlohmann::ordered_json measurements = nlohmann::ordered_json::object();
      for (const MeasuredValue& m : a.measurements) measurements[m.name] = m.value;
      trial["actions"].push_back(
          {{"type", core::toString(a.type)}, {"id", a.id}, {"passed", a.passed}, {"measurements", measurements}});
    }
    trial["objects"] = nlohmann::ordered_json::array();
    for (const ObjectPerturbation& p : o.objects) {
      trial["objects"].push_back({{"dx", p.dx},
                                  {"dy", p.dy},
                                  {"dyaw", p.dyaw},
                                  {"mass_scale", p.mass_scale},
                                  {"friction_scale", p.friction_scale}});
    }
    out.push_back(std::move(trial));
  }
  return core::formatJson(out);
}

std::vector<TrialOutcome> readOutcomesJson(std::string_view json_text) {
  // ordered: measurements keep their order
  using Json = nlohmann::ordered_json;
  const core::JsonReader<core::InputError, Json> reader("trial outcomes");
  const Json in = reader.parse(json_text);
  const auto at = [](const std::string& pointer, auto key) { return core::jsonPointerAt(pointer, key); };
  // a name the reading function knows, or the message of the invalid_argument it throws
  const auto known = [&](const std::string& pointer, const auto& parse, const std::string& text) {
    try {
      return parse(text);
    } catch (const std::invalid_argument& e) {
      reader.fail(pointer, e.what());
    }
  };
  std::vector<TrialOutcome> outcomes;
  for (std::size_t i = 0; i < reader.array(in, "").size(); ++i) {
    const Json& trial = in[i];
    const std::string p = at("", i);
    TrialOutcome o;
    o.index = reader.unsignedInteger(trial, p, "index");
    o.point = static_cast<int>(reader.unsignedInteger(trial, p, "point"));
    o.seed = reader.unsignedInteger(trial, p, "seed");
    o.passed = reader.boolean(trial, p, "passed");
    if (const Json& primary = reader.required(trial, p, "primary"); !primary.is_null()) {
      o.primary = known(at(p, "primary"), parseFailureClass, reader.string(primary, at(p, "primary")));
    }
    const Json& classes = reader.array(trial, p, "classes");
    for (std::size_t c = 0; c < classes.size(); ++c) {
      const std::string q = at(at(p, "classes"), c);
      o.classes.push_back(known(q, parseFailureClass, reader.string(classes[c], q)));
    }
    o.failure = reader.string(trial, p, "failure");
    const Json& actions = reader.array(trial, p, "actions");
    for (std::size_t k = 0; k < actions.size(); ++k) {
      const Json& a = actions[k];
      const std::string q = at(at(p, "actions"), k);
      ActionOutcome& action = o.actions.emplace_back(ActionOutcome{
          known(at(q, "type"), parseActionType, reader.string(a, q, "type")), reader.string(a, q, "id"),
          reader.boolean(a, q, "passed"), {}});
      const Json& measurements = reader.required(a, q, "measurements");
      reader.expectType(measurements, at(q, "measurements"), measurements.is_object(), "an object");
      for (const auto& [name, value] : measurements.items()) {
        action.measurements.push_back({name, reader.number(value, at(at(q, "measurements"), name))});
      }
    }
    const Json& objects = reader.array(trial, p, "objects");
    for (std::size_t k = 0; k < objects.size(); ++k) {
      const Json& d = objects[k];
      const std::string q = at(at(p, "objects"), k);
      o.objects.push_back({reader.number(d, q, "dx"), reader.number(d, q, "dy"), reader.number(d, q, "dyaw"),
                           reader.number(d, q, "mass_scale"), reader.number(d, q, "friction_scale")});
    }
    outcomes.push_back(std::move(o));
  }
  return outcomes;
}

}  // namespace dashbed::tools
