#include "tools/stress/stress_summary.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/number_text.h"

namespace dashbed::tools {
namespace {

using Json = nlohmann::ordered_json;

Json rateJson(const RateInterval& r) {
  return Json{{"total", r.trials}, {"passed", r.successes}, {"rate", r.rate}, {"interval", {r.lower, r.upper}}};
}

Json classCounts(const std::array<int, kFailureClassCount>& counts) {
  Json out = Json::object();
  for (int c = 0; c < kFailureClassCount; ++c) out[std::string(toString(static_cast<FailureClass>(c)))] = counts[c];
  return out;
}

std::string percent(double fraction) { return core::fixedText(100.0 * fraction, 1) + " %"; }

std::string rateText(const RateInterval& r) {
  return std::to_string(r.successes) + "/" + std::to_string(r.trials) + " = " + percent(r.rate) + " (95 % Wilson " +
         core::fixedText(100.0 * r.lower, 1) + "-" + percent(r.upper) + ")";
}

std::string millimetres(double metres) { return core::shortestText(metres * 1e3) + " mm"; }

std::string classesText(const std::vector<FailureClass>& classes) {
  std::string text;
  for (const FailureClass c : classes) {
    if (!text.empty()) text += '+';
    text += toString(c);
  }
  return text;
}

// the five XML special characters; control characters become '?'
std::string xmlText(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += (static_cast<unsigned char>(c) < 0x20 && c != '\n') ? '?' : c;
    }
  }
  return out;
}

// the lines describing one point's results (stdout and JUnit)
std::string pointText(const PointSummary& p) {
  std::string text = "sigma_xy " + millimetres(p.sigma_xy) + ": trials passed " + rateText(p.trials) + "\n";
  for (const auto& [type, rate] : p.per_type) {
    text += "  " + std::string(core::toString(type)) + " actions passed " + rateText(rate) + "\n";
  }
  std::string failures;
  for (int c = 0; c < kFailureClassCount; ++c) {
    if (p.any[c] == 0) continue;
    failures += ' ';
    failures += toString(static_cast<FailureClass>(c));
    failures += ' ' + std::to_string(p.primary[c]) + '/' + std::to_string(p.any[c]);
  }
  text += "  failures (primary/any):";
  text += failures.empty() ? std::string(" none") : failures;
  text += '\n';
  return text;
}

}  // namespace

bool meetsAll(const CampaignInfo& info, const std::vector<PointSummary>& points) {
  return std::all_of(points.begin(), points.end(), [&](const PointSummary& p) { return p.meets(info.min_success); });
}

RateInterval wilsonInterval(int successes, int trials, double z) {
  RateInterval r;
  r.successes = successes;
  r.trials = trials;
  if (trials <= 0) return r;
  const double n = trials;
  const double p = successes / n;
  const double z2 = z * z;
  const double denominator = 1.0 + z2 / n;
  const double centre = (p + z2 / (2.0 * n)) / denominator;
  const double half = z / denominator * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  r.rate = p;
  r.lower = successes == 0 ? 0.0 : std::max(0.0, centre - half);
  r.upper = successes == trials ? 1.0 : std::min(1.0, centre + half);
  return r;
}

std::vector<PointSummary> summarize(const CampaignSettings& settings, const std::vector<TrialOutcome>& outcomes) {
  struct Counts {
    int passed = 0;
    int total = 0;
  };
  std::vector<PointSummary> points(static_cast<std::size_t>(settings.points()));
  std::vector<Counts> trial_counts(points.size());
  std::vector<std::map<core::ActionType, Counts>> type_counts(points.size());
  std::vector<std::map<std::string, Counts>> action_counts(points.size());
  for (const TrialOutcome& o : outcomes) {
    const auto k = static_cast<std::size_t>(o.point);
    ++trial_counts[k].total;
    trial_counts[k].passed += o.passed ? 1 : 0;
    for (const ActionOutcome& a : o.actions) {
      for (Counts* counts : {&type_counts[k][a.type], &action_counts[k][a.id]}) {
        ++counts->total;
        counts->passed += a.passed ? 1 : 0;
      }
    }
    if (o.primary) ++points[k].primary[static_cast<std::size_t>(*o.primary)];
    for (const FailureClass c : o.classes) ++points[k].any[static_cast<std::size_t>(c)];
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    points[k].sigma_xy = settings.sigmasAt(static_cast<int>(k)).xy;
    points[k].trials = wilsonInterval(trial_counts[k].passed, trial_counts[k].total);
    for (const auto& [type, c] : type_counts[k]) points[k].per_type[type] = wilsonInterval(c.passed, c.total);
    for (const auto& [id, c] : action_counts[k]) points[k].per_action[id] = wilsonInterval(c.passed, c.total);
  }
  return points;
}

std::vector<std::size_t> worstTrials(const std::vector<TrialOutcome>& outcomes, int count) {
  std::vector<std::size_t> failed;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    if (!outcomes[i].passed) failed.push_back(i);
  }
  std::sort(failed.begin(), failed.end(), [&](std::size_t a, std::size_t b) {
    const int fa = outcomes[a].failedActions(), fb = outcomes[b].failedActions();
    return fa != fb ? fa > fb : outcomes[a].index < outcomes[b].index;
  });
  if (failed.size() > static_cast<std::size_t>(std::max(count, 0))) failed.resize(static_cast<std::size_t>(count));
  return failed;
}

std::string writeSummaryJson(const CampaignInfo& info, const std::vector<PointSummary>& points,
                             const std::vector<TrialOutcome>& worst) {
  const CampaignSettings& s = info.settings;
  Json out;
  out["dashbed_stress"] = 1;
  out["world"] = info.world;
  out["world_file"] = info.world_file;
  out["plan"] = info.plan;
  out["mode"] = toString(s.mode);
  out["seed"] = s.seed;
  out["trials_per_point"] = s.trials;
  out["perturbation"] = {{"sigma_xy", s.sigmas.xy},
                         {"sigma_yaw", s.sigmas.yaw},
                         {"sigma_log_mass", s.sigmas.mass},
                         {"sigma_log_friction", s.sigmas.friction},
                         {"sweep_xy", s.sweep_xy},
                         {"invalid_starts", "redrawn"}};
  if (s.mode == StressMode::kReplan) {
    out["planner"] = {
        {"method", s.planner.method}, {"time_budget", s.planner.time_budget}, {"max_rounds", s.planner.max_rounds},
        {"fallback_rounds", s.planner.fallback_rounds}};
  }
  out["interval"] = "Wilson score, 95 %";
  out["min_success"] = info.min_success ? Json(*info.min_success) : Json();
  out["verdict"] = meetsAll(info, points) ? "passed" : "failed";
  out["points"] = Json::array();
  for (const PointSummary& p : points) {
    Json point;
    point["sigma_xy"] = p.sigma_xy;
    point["trials"] = p.trials.trials;
    point["passed"] = p.trials.successes;
    point["success_rate"] = p.trials.rate;
    point["interval"] = {p.trials.lower, p.trials.upper};
    point["meets_min_success"] = p.meets(info.min_success);
    point["action_types"] = Json::object();
    for (const auto& [type, rate] : p.per_type) point["action_types"][std::string(core::toString(type))] = rateJson(rate);
    point["actions"] = Json::array();
    for (const auto& [id, rate] : p.per_action) {
      Json action = {{"id", id}};
      action.update(rateJson(rate));
      point["actions"].push_back(action);
    }
    point["failures"] = {{"primary", classCounts(p.primary)}, {"any", classCounts(p.any)}};
    out["points"].push_back(point);
  }
  out["worst_trials"] = Json::array();
  for (const TrialOutcome& o : worst) {
    Json classes = Json::array();
    for (const FailureClass c : o.classes) classes.push_back(toString(c));
    out["worst_trials"].push_back({{"trial", o.index},
                                   {"directory", trialDirectoryName(o.index)},
                                   {"sigma_xy", s.sigmasAt(o.point).xy},
                                   {"seed", o.seed},
                                   {"primary", o.primary ? Json(toString(*o.primary)) : Json()},
                                   {"classes", classes},
                                   {"failed_actions", o.failedActions()},
                                   {"failure", o.failure}});
  }
  return core::formatJson(out);
}

std::string writeStressJUnit(const CampaignInfo& info, const std::vector<PointSummary>& points) {
  int failures = 0;
  for (const PointSummary& p : points) failures += p.meets(info.min_success) ? 0 : 1;
  const std::string count = std::to_string(points.size());
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites name=\"dashbed stress\" tests=\"" + count + "\" failures=\"" + std::to_string(failures) + "\">\n";
  out += "  <testsuite name=\"" + xmlText("dashbed stress: " + info.world + " / " + info.plan) + "\" tests=\"" + count +
         "\" failures=\"" + std::to_string(failures) + "\" errors=\"0\" skipped=\"0\">\n";
  for (const PointSummary& p : points) {
    const std::string name = "success rate at sigma_xy = " + millimetres(p.sigma_xy);
    out += "    <testcase classname=\"dashbed.stress\" name=\"" + xmlText(name) + "\">\n";
    if (!p.meets(info.min_success)) {
      const std::string message = "success rate " + percent(p.trials.rate) + " < " + percent(*info.min_success) +
                                  " required";
      out += "      <failure message=\"" + xmlText(message) + "\" type=\"success_rate\"/>\n";
    }
    out += "      <system-out>" + xmlText(pointText(p)) + "</system-out>\n";
    out += "    </testcase>\n";
  }
  out += "  </testsuite>\n</testsuites>\n";
  return out;
}

std::string writeTrialsCsv(const core::World& world, const CampaignSettings& settings,
                           const std::vector<TrialOutcome>& outcomes) {
  std::string out = "index,point,sigma_xy,seed,passed,primary,classes,failed_actions,actions";
  for (const core::ObjectSpec& object : world.objects) {
    for (const char* field : {"dx", "dy", "dyaw", "mass_scale", "friction_scale"}) out += "," + object.name + "." + field;
  }
  out += "\n";
  std::vector<const TrialOutcome*> sorted;
  for (const TrialOutcome& o : outcomes) sorted.push_back(&o);
  std::sort(sorted.begin(), sorted.end(), [](const auto* a, const auto* b) { return a->index < b->index; });
  for (const TrialOutcome* o : sorted) {
    const std::vector<std::string> fields{std::to_string(o->index),
                                          std::to_string(o->point),
                                          core::shortestText(settings.sigmasAt(o->point).xy),
                                          std::to_string(o->seed),
                                          o->passed ? "1" : "0",
                                          o->primary ? std::string(toString(*o->primary)) : "",
                                          classesText(o->classes),
                                          std::to_string(o->failedActions()),
                                          std::to_string(o->actions.size())};
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i > 0) out += ',';
      out += fields[i];
    }
    for (const ObjectPerturbation& p : o->objects) {
      for (const double value : {p.dx, p.dy, p.dyaw, p.mass_scale, p.friction_scale}) {
        out += ',';
        out += core::shortestText(value);
      }
    }
    out += '\n';
  }
  return out;
}

std::string summaryText(const CampaignInfo& info, const std::vector<PointSummary>& points) {
  const CampaignSettings& s = info.settings;
  std::string text = "stress: " + info.world + ", " + std::string(toString(s.mode)) + ": " + info.plan + ", " +
                     std::to_string(s.trials) + " trials per point, seed " + std::to_string(s.seed) + "\n";
  text += "perturbation: sigma_yaw " + core::shortestText(s.sigmas.yaw) + " rad, log mass " +
          core::shortestText(s.sigmas.mass) + ", log friction " + core::shortestText(s.sigmas.friction) + "\n";
  for (const PointSummary& p : points) text += pointText(p);
  if (info.min_success) {
    text += std::string(meetsAll(info, points) ? "PASSED" : "FAILED") + ": minimum success rate " +
            percent(*info.min_success) + "\n";
  }
  return text;
}

}  // namespace dashbed::tools
