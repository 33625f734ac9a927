// Execution reports as JSON (read back by tools and tests) and JUnit XML (for CI).
// Both writers are deterministic: fixed key / element order, locale-independent numbers,
// nothing from the wall clock.

#include "sim/report.h"

#include "core/json_pointer.h"
#include "core/json_reader.h"
#include "core/number_text.h"
#include "core/input_text.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>
#include <utility>

namespace dashbed::sim {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

// ---- numbers as text (std::to_chars: no locale) ------------------------------------------

std::string sixDigits(double x) { return core::significantText(x, 6); }

// seconds with three decimals: JUnit's time attributes are plain decimals (no exponent)
std::string seconds(double x) { return std::isfinite(x) ? core::fixedText(x, 3) : "0.000"; }

// the relation that holds when the check `comparison` failed
std::string_view violated(std::string_view comparison) {
  if (comparison == "<=") return ">";
  if (comparison == "<") return ">=";
  if (comparison == ">=") return "<";
  if (comparison == ">") return "<=";
  if (comparison == "==") return "!=";
  return "violates";
}

std::string withUnit(double value, const std::string& unit) {
  return unit.empty() ? sixDigits(value) : sixDigits(value) + " " + unit;
}

// ---- JSON writing ---------------------------------------------------------------------------

OrderedJson number(double x) { return std::isfinite(x) ? OrderedJson(x) : OrderedJson(nullptr); }

OrderedJson optionalNumber(const std::optional<double>& x) {
  return x ? number(*x) : OrderedJson(nullptr);
}

OrderedJson toJson(const Measurement& measurement) {
  OrderedJson json;
  json["name"] = measurement.name;
  json["value"] = number(measurement.value);
  json["unit"] = measurement.unit;
  json["threshold"] = optionalNumber(measurement.threshold);
  json["comparison"] = measurement.comparison;
  json["passed"] = measurement.passed;
  return json;
}

OrderedJson toJson(const ActionReport& action) {
  OrderedJson json;
  json["id"] = action.id;
  json["type"] = core::toString(action.type);
  json["robots"] = action.robots;
  json["object"] = action.object;
  if (!action.region.empty()) json["region"] = action.region;
  json["planned"] = {{"start", number(action.planned_start)}, {"end", number(action.planned_end)}};
  json["observed"] = {{"start", optionalNumber(action.observed_start)},
                      {"end", optionalNumber(action.observed_end)}};
  json["verdict"] = toString(action.verdict);
  json["failure"] = action.failure;
  OrderedJson measurements = OrderedJson::array();
  for (const Measurement& measurement : action.measurements) {
    measurements.push_back(toJson(measurement));
  }
  json["measurements"] = std::move(measurements);
  return json;
}

// ---- JSON reading ---------------------------------------------------------------------------

std::string pointerAt(const std::string& pointer, std::string_view key) { return core::jsonPointerAt(pointer, key); }
std::string pointerAt(const std::string& pointer, std::size_t index) { return core::jsonPointerAt(pointer, index); }

using ReportReader = core::JsonReader<ReportError>;

// null (a non-finite number when written) reads as NaN
double numberOrNaN(const ReportReader& reader, const Json& object, const std::string& pointer, std::string_view key) {
  const Json& value = reader.required(object, pointer, key);
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  return reader.number(value, pointerAt(pointer, key));
}

std::optional<double> optionalNumber(const ReportReader& reader, const Json& object, const std::string& pointer,
                                     std::string_view key) {
  const Json& value = reader.required(object, pointer, key);
  if (value.is_null()) return std::nullopt;
  reader.expectType(value, pointerAt(pointer, key), value.is_number(), "a number or null");
  return value.get<double>();
}

Verdict verdict(const ReportReader& reader, const Json& object, const std::string& pointer, std::string_view key) {
  const std::string text = reader.string(object, pointer, key);
  if (text == "passed") return Verdict::kPassed;
  if (text == "failed") return Verdict::kFailed;
  reader.fail(pointerAt(pointer, key), "expected \"passed\" or \"failed\", got \"" + text + "\"");
}

core::ActionType actionType(const ReportReader& reader, const Json& object, const std::string& pointer) {
  const std::string text = reader.string(object, pointer, "type");
  for (const core::ActionType type : {core::ActionType::kPick, core::ActionType::kPlace, core::ActionType::kHandoff}) {
    if (text == core::toString(type)) return type;
  }
  reader.fail(pointerAt(pointer, "type"), "unknown action type \"" + text + "\"");
}

Measurement readMeasurement(const ReportReader& reader, const Json& json, const std::string& pointer) {
  Measurement measurement;
  measurement.name = reader.string(json, pointer, "name");
  measurement.value = numberOrNaN(reader, json, pointer, "value");
  measurement.unit = reader.string(json, pointer, "unit");
  measurement.threshold = optionalNumber(reader, json, pointer, "threshold");
  measurement.comparison = reader.string(json, pointer, "comparison");
  measurement.passed = reader.boolean(json, pointer, "passed");
  return measurement;
}

ActionReport readAction(const ReportReader& reader, const Json& json, const std::string& pointer) {
  ActionReport action;
  action.id = reader.string(json, pointer, "id");
  action.type = actionType(reader, json, pointer);
  const Json& robots = reader.array(json, pointer, "robots");
  for (std::size_t i = 0; i < robots.size(); ++i) {
    if (!robots[i].is_string())
      reader.fail(pointerAt(pointerAt(pointer, "robots"), i), "expected a string");
    action.robots.push_back(robots[i].get<std::string>());
  }
  action.object = reader.string(json, pointer, "object");
  if (json.contains("region")) action.region = reader.string(json, pointer, "region");
  const std::string planned = pointerAt(pointer, "planned");
  action.planned_start = numberOrNaN(reader, reader.required(json, pointer, "planned"), planned, "start");
  action.planned_end = numberOrNaN(reader, reader.required(json, pointer, "planned"), planned, "end");
  const std::string observed = pointerAt(pointer, "observed");
  const Json& observed_json = reader.required(json, pointer, "observed");
  action.observed_start = optionalNumber(reader, observed_json, observed, "start");
  action.observed_end = optionalNumber(reader, observed_json, observed, "end");
  action.verdict = verdict(reader, json, pointer, "verdict");
  action.failure = reader.string(json, pointer, "failure");
  const Json& measurements = reader.array(json, pointer, "measurements");
  for (std::size_t i = 0; i < measurements.size(); ++i) {
    action.measurements.push_back(
        readMeasurement(reader, measurements[i], pointerAt(pointerAt(pointer, "measurements"), i)));
  }
  return action;
}

Report readReport(const ReportReader& reader, const Json& document) {
  if (!document.is_object()) reader.fail("", "expected a JSON object");
  reader.formatVersion(document, "dashbed_report", kReportFormatVersion, "report");

  Report report;
  report.world = reader.string(document, "", "world");
  report.plan_file = reader.string(document, "", "plan");
  report.seed = reader.unsignedInteger(document, "", "seed");
  if (document.contains("actions_inferred")) report.actions_inferred = reader.boolean(document, "", "actions_inferred");
  report.time_step = numberOrNaN(reader, document, "", "time_step");
  report.simulated_time = numberOrNaN(reader, document, "", "simulated_time");

  const Json& actions = reader.array(document, "", "actions");
  for (std::size_t i = 0; i < actions.size(); ++i) {
    report.actions.push_back(readAction(reader, actions[i], pointerAt("/actions", i)));
  }
  const Json& events = reader.array(document, "", "events");
  for (std::size_t i = 0; i < events.size(); ++i) {
    const std::string pointer = pointerAt("/events", i);
    ExecutionEvent event;
    event.t = numberOrNaN(reader, events[i], pointer, "t");
    event.kind = reader.string(events[i], pointer, "kind");
    event.detail = reader.string(events[i], pointer, "detail");
    event.action = reader.string(events[i], pointer, "action");
    if (events[i].contains("still")) event.still = reader.string(events[i], pointer, "still");
    if (events[i].contains("where")) {
      const Json& where = reader.array(events[i], pointer, "where");
      if (where.size() != 3) reader.fail(pointerAt(pointer, "where"), "expected 3 numbers");
      for (int k = 0; k < 3; ++k) {
        if (!where[static_cast<std::size_t>(k)].is_number()) reader.fail(pointerAt(pointer, "where"), "expected 3 numbers");
        event.where_W[k] = where[static_cast<std::size_t>(k)].get<double>();
      }
    }
    report.events.push_back(std::move(event));
  }
  const Json& robots = reader.array(document, "", "robots");
  for (std::size_t i = 0; i < robots.size(); ++i) {
    const std::string pointer = pointerAt("/robots", i);
    RobotExecution robot;
    robot.robot = reader.string(robots[i], pointer, "robot");
    robot.max_tracking_error = numberOrNaN(reader, robots[i], pointer, "max_tracking_error");
    robot.torque_saturation = numberOrNaN(reader, robots[i], pointer, "torque_saturation");
    robot.max_effort_ratio = numberOrNaN(reader, robots[i], pointer, "max_effort_ratio");
    robot.max_tcp_force = numberOrNaN(reader, robots[i], pointer, "max_tcp_force");
    robot.max_external_torque_ratio = numberOrNaN(reader, robots[i], pointer, "max_external_torque_ratio");
    report.robots.push_back(std::move(robot));
  }

  if (document.contains("final_still")) report.final_still = reader.string(document, "", "final_still");
  if (document.contains("readiness")) {
    const Json& readiness = reader.array(document, "", "readiness");
    for (std::size_t i = 0; i < readiness.size(); ++i) {
      const std::string pointer = pointerAt("/readiness", i);
      core::ReadinessCheck check;
      check.name = reader.string(readiness[i], pointer, "name");
      check.subject = reader.string(readiness[i], pointer, "subject");
      check.value = numberOrNaN(reader, readiness[i], pointer, "value");
      check.limit = numberOrNaN(reader, readiness[i], pointer, "limit");
      check.unit = reader.string(readiness[i], pointer, "unit");
      check.t = numberOrNaN(reader, readiness[i], pointer, "t");
      check.passed = reader.boolean(readiness[i], pointer, "passed");
      check.detail = reader.string(readiness[i], pointer, "detail");
      report.readiness.push_back(std::move(check));
    }
  }

  // the summary: the execution verdict lives there; the counts must agree with the actions
  const Json& summary = reader.required(document, "", "summary");
  report.execution_verdict = verdict(reader, summary, "/summary", "execution");
  report.execution_failure = reader.string(summary, "/summary", "execution_failure");
  const std::pair<std::string_view, int> counts[] = {
      {"actions", static_cast<int>(report.actions.size())},
      {"passed", report.passedCount()},
      {"failed", report.failedCount()}};
  for (const auto& [key, expected] : counts) {
    const std::uint64_t written = reader.unsignedInteger(summary, "/summary", key);
    if (written != static_cast<std::uint64_t>(expected)) {
      reader.fail(pointerAt("/summary", key), std::to_string(written) + " disagrees with the " +
                                                  std::to_string(expected) + " in /actions");
    }
  }
  if (verdict(reader, summary, "/summary", "verdict") !=
      (report.passed() ? Verdict::kPassed : Verdict::kFailed)) {
    reader.fail("/summary/verdict", "disagrees with the actions, the execution verdict and the readiness checks");
  }
  return report;
}

// ---- XML ------------------------------------------------------------------------------------

// Escapes the five XML special characters. Control characters XML 1.0 cannot carry become
// '?'; tab, newline and carriage return are kept in text and written as character
// references in attributes (where a parser would otherwise turn them into spaces).
std::string xmlEscape(std::string_view text, bool attribute) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      case '\t':
        out += attribute ? "&#9;" : "\t";
        break;
      case '\n':
        out += attribute ? "&#10;" : "\n";
        break;
      case '\r':
        out += attribute ? "&#13;" : "\r";
        break;
      default:
        out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
    }
  }
  return out;
}

std::string attr(std::string_view name, std::string_view value) {
  std::string out = " ";
  out.append(name).append("=\"").append(xmlEscape(value, true)).append("\"");
  return out;
}

// the JUnit failure type of an action: which physical check it is
std::string_view checkKind(core::ActionType type) {
  switch (type) {
    case core::ActionType::kPick:
      return "grasp";
    case core::ActionType::kPlace:
      return "placement";
    case core::ActionType::kHandoff:
      return "handoff";
  }
  return "action";
}

// the failure message: the failed measurements, else the monitor's failure text
std::string failureMessage(const ActionReport& action) {
  std::string message;
  for (const Measurement& measurement : action.measurements) {
    if (measurement.passed) continue;
    if (!message.empty()) message += "; ";
    message += describeMeasurement(measurement);
  }
  if (message.empty()) message = action.failure;
  return message.empty() ? "failed" : message;
}

std::string optionalSeconds(const std::optional<double>& t) {
  return t ? sixDigits(*t) + " s" : "-";
}

// everything known about an action, one fact per line
std::string actionDetails(const ActionReport& action) {
  std::string text;
  if (!action.failure.empty()) text += "failure: " + action.failure + "\n";
  text += "planned: " + sixDigits(action.planned_start) + " s to " + sixDigits(action.planned_end) +
          " s\n";
  text += "observed: " + optionalSeconds(action.observed_start) + " to " +
          optionalSeconds(action.observed_end) + "\n";
  for (const Measurement& measurement : action.measurements) {
    text +=
        describeMeasurement(measurement) + (measurement.passed ? "  [passed]\n" : "  [FAILED]\n");
  }
  return text;
}

std::string eventLine(const ExecutionEvent& event) {
  std::string line = "t=" + sixDigits(event.t) + " s " + event.kind;
  if (!event.detail.empty()) line += ": " + event.detail;
  if (!event.action.empty()) line += " (during " + event.action + ")";
  return line + "\n";
}

std::string robotLine(const RobotExecution& robot) {
  return robot.robot + ": max tracking error " + sixDigits(robot.max_tracking_error) +
         " rad, torque saturation " + sixDigits(robot.torque_saturation * 100.0) +
         " % of steps, max effort ratio " + sixDigits(robot.max_effort_ratio) + ", max external TCP force " +
         sixDigits(robot.max_tcp_force) + " N, max external torque ratio " + sixDigits(robot.max_external_torque_ratio) +
         "\n";
}

void writeTestcase(std::string& out, std::string_view classname, std::string_view name, double time,
                   bool failed, std::string_view message, std::string_view type,
                   std::string_view details) {
  out += "    <testcase" + attr("classname", classname) + attr("name", name) +
         attr("time", seconds(time));
  if (!failed && details.empty()) {
    out += "/>\n";
    return;
  }
  out += ">\n";
  if (failed) {
    out += "      <failure" + attr("message", message) + attr("type", type) + ">" +
           xmlEscape(details, false) + "</failure>\n";
  } else {
    out += "      <system-out>" + xmlEscape(details, false) + "</system-out>\n";
  }
  out += "    </testcase>\n";
}

}  // namespace

// ---- public -------------------------------------------------------------------------------

std::string_view toString(Verdict verdict) {
  return verdict == Verdict::kPassed ? "passed" : "failed";
}

std::string describeMeasurement(const Measurement& measurement) {
  std::string text = measurement.name + " " + withUnit(measurement.value, measurement.unit);
  if (!measurement.threshold) return text;
  const std::string_view relation = measurement.passed ? std::string_view(measurement.comparison)
                                                       : violated(measurement.comparison);
  return text + " " + std::string(relation) + " " +
         withUnit(*measurement.threshold, measurement.unit);
}

int Report::passedCount() const {
  return static_cast<int>(std::count_if(actions.begin(), actions.end(), [](const ActionReport& a) {
    return a.verdict == Verdict::kPassed;
  }));
}

int Report::failedCount() const { return static_cast<int>(actions.size()) - passedCount(); }

bool Report::ready() const {
  return std::all_of(readiness.begin(), readiness.end(), [](const core::ReadinessCheck& c) { return c.passed; });
}

bool Report::passed() const { return failedCount() == 0 && execution_verdict == Verdict::kPassed && ready(); }

std::string writeReportJson(const Report& report) {
  OrderedJson document;
  document["dashbed_report"] = kReportFormatVersion;
  document["world"] = report.world;
  document["plan"] = report.plan_file;
  document["seed"] = report.seed;
  document["actions_inferred"] = report.actions_inferred;
  document["time_step"] = number(report.time_step);
  document["simulated_time"] = number(report.simulated_time);

  OrderedJson summary;
  summary["actions"] = report.actions.size();
  summary["passed"] = report.passedCount();
  summary["failed"] = report.failedCount();
  summary["execution"] = toString(report.execution_verdict);
  summary["execution_failure"] = report.execution_failure;
  summary["readiness"] = toString(report.ready() ? Verdict::kPassed : Verdict::kFailed);
  summary["verdict"] = toString(report.passed() ? Verdict::kPassed : Verdict::kFailed);
  document["summary"] = std::move(summary);

  OrderedJson actions = OrderedJson::array();
  for (const ActionReport& action : report.actions) actions.push_back(toJson(action));
  document["actions"] = std::move(actions);

  OrderedJson events = OrderedJson::array();
  for (const ExecutionEvent& event : report.events) {
    OrderedJson json;
    json["t"] = number(event.t);
    json["kind"] = event.kind;
    json["detail"] = event.detail;
    json["action"] = event.action;
    json["where"] = {number(event.where_W.x()), number(event.where_W.y()), number(event.where_W.z())};
    json["still"] = event.still;
    events.push_back(std::move(json));
  }
  document["events"] = std::move(events);

  OrderedJson robots = OrderedJson::array();
  for (const RobotExecution& robot : report.robots) {
    OrderedJson json;
    json["robot"] = robot.robot;
    json["max_tracking_error"] = number(robot.max_tracking_error);
    json["torque_saturation"] = number(robot.torque_saturation);
    json["max_effort_ratio"] = number(robot.max_effort_ratio);
    json["max_tcp_force"] = number(robot.max_tcp_force);
    json["max_external_torque_ratio"] = number(robot.max_external_torque_ratio);
    robots.push_back(std::move(json));
  }
  document["robots"] = std::move(robots);
  document["final_still"] = report.final_still;

  OrderedJson readiness = OrderedJson::array();
  for (const core::ReadinessCheck& check : report.readiness) {
    OrderedJson json;
    json["name"] = check.name;
    json["subject"] = check.subject;
    json["value"] = number(check.value);
    json["limit"] = number(check.limit);
    json["unit"] = check.unit;
    json["t"] = number(check.t);
    json["passed"] = check.passed;
    json["detail"] = check.detail;
    readiness.push_back(std::move(json));
  }
  document["readiness"] = std::move(readiness);
  return core::formatJson(document);
}

Report readReportJson(std::string_view json_text, const std::string& file_name) {
  const ReportReader reader(file_name);
  return readReport(reader, reader.parse(json_text));
}

Report loadReportFile(const std::filesystem::path& file) {
  return readReportJson(core::readTextFile<ReportError>(file, "report"), file.string());
}

std::string writeJUnitXml(const Report& report) {
  const int tests = static_cast<int>(report.actions.size() + 1 + report.readiness.size());  // + the execution check
  const int failures = report.failedCount() + (report.execution_verdict == Verdict::kFailed ? 1 : 0) +
                       static_cast<int>(std::count_if(report.readiness.begin(), report.readiness.end(),
                                                      [](const core::ReadinessCheck& c) { return !c.passed; }));
  const std::string suite_name = "dashbed: " + report.world + " / " + report.plan_file;

  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites" + attr("name", "dashbed") + attr("tests", std::to_string(tests)) +
         attr("failures", std::to_string(failures)) + attr("errors", "0") +
         attr("time", seconds(report.simulated_time)) + ">\n";
  out += "  <testsuite" + attr("name", suite_name) + attr("tests", std::to_string(tests)) +
         attr("failures", std::to_string(failures)) + attr("errors", "0") + attr("skipped", "0") +
         attr("time", seconds(report.simulated_time)) + ">\n";
  out += "    <properties>\n";
  const std::pair<std::string_view, std::string> properties[] = {
      {"world", report.world},
      {"plan", report.plan_file},
      {"seed", std::to_string(report.seed)},
      {"time_step", sixDigits(report.time_step)},
      {"simulated_time", sixDigits(report.simulated_time)}};
  for (const auto& [name, value] : properties) {
    out += "      <property" + attr("name", name) + attr("value", value) + "/>\n";
  }
  out += "    </properties>\n";

  for (const ActionReport& action : report.actions) {
    const bool failed = action.verdict == Verdict::kFailed;
    writeTestcase(out, "dashbed." + std::string(core::toString(action.type)), action.id,
                  action.planned_end - action.planned_start, failed,
                  failed ? failureMessage(action) : "", checkKind(action.type),
                  actionDetails(action));
  }

  // the execution check: unplanned contacts and tracking quality
  std::string details;
  if (!report.execution_failure.empty()) details += "failure: " + report.execution_failure + "\n";
  for (const ExecutionEvent& event : report.events) details += eventLine(event);
  for (const RobotExecution& robot : report.robots) details += robotLine(robot);
  const bool failed = report.execution_verdict == Verdict::kFailed;
  std::string message = report.execution_failure;
  if (message.empty()) message = std::to_string(report.events.size()) + " execution events";
  writeTestcase(out, "dashbed.execution", "execution", report.simulated_time, failed, message,
                "execution", details);

  for (const core::ReadinessCheck& check : report.readiness) {
    const std::string measured = sixDigits(check.value) + " " + check.unit + " (limit " + sixDigits(check.limit) + " " +
                                 check.unit + ") at t=" + sixDigits(check.t) + " s\n";
    writeTestcase(out, "dashbed.readiness", check.name + " " + check.subject, 0.0, !check.passed, check.detail,
                  "readiness", measured);
  }

  out += "  </testsuite>\n";
  out += "</testsuites>\n";
  return out;
}

}  // namespace dashbed::sim
