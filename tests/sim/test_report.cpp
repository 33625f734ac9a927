#include <bit>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sim/report.h"

using namespace dashbed::sim;
using dashbed::core::ActionType;

namespace {

// ---- a tiny XML reader: checks well-formedness and builds a tree ---------------------------
//
// Enough of XML 1.0 for what writeJUnitXml may produce: a declaration, elements, attributes
// in double quotes, text, the five named entities and numeric character references. Anything
// else (raw '<' or '&' in text or attributes, unbalanced or mismatched tags, duplicate
// attributes, trailing content) throws.

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;  // unescaped values
  std::vector<XmlElement> children;
  std::string text;  // unescaped character data directly inside this element

  std::vector<const XmlElement*> all(const std::string& child_name) const {
    std::vector<const XmlElement*> found;
    for (const XmlElement& child : children) {
      if (child.name == child_name) found.push_back(&child);
    }
    return found;
  }
  const XmlElement* first(const std::string& child_name) const {
    const auto found = all(child_name);
    return found.empty() ? nullptr : found.front();
  }
};

class XmlReader {
 public:
  explicit XmlReader(std::string text) : text_(std::move(text)) {}

  XmlElement document() {
    expect("<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
    skipSpace();
    XmlElement root = element();
    skipSpace();
    if (pos_ != text_.size()) error("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void error(const std::string& what) const {
    throw std::runtime_error("XML error at byte " + std::to_string(pos_) + ": " + what);
  }
  bool atEnd() const { return pos_ >= text_.size(); }
  char peek() const { return atEnd() ? '\0' : text_[pos_]; }
  bool startsWith(std::string_view s) const { return text_.compare(pos_, s.size(), s) == 0; }
  void expect(std::string_view s) {
    if (!startsWith(s)) error("expected '" + std::string(s) + "'");
    pos_ += s.size();
  }
  void skipSpace() {
    while (!atEnd() && std::isspace(static_cast<unsigned char>(peek()))) ++pos_;
  }
  std::string name() {
    const std::size_t start = pos_;
    while (!atEnd() && (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_' ||
                        peek() == '-' || peek() == ':' || peek() == '.')) {
      ++pos_;
    }
    if (pos_ == start) error("expected a name");
    return text_.substr(start, pos_ - start);
  }
  // an entity or character reference, after its '&'
  std::string reference() {
    const std::size_t end = text_.find(';', pos_);
    if (end == std::string::npos || end - pos_ > 10) error("unterminated reference");
    const std::string ref = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    static const std::map<std::string, std::string> named{
        {"amp", "&"}, {"lt", "<"}, {"gt", ">"}, {"quot", "\""}, {"apos", "'"}};
    if (const auto it = named.find(ref); it != named.end()) return it->second;
    if (ref.size() > 1 && ref[0] == '#') {
      const long code = std::stol(ref.substr(1));
      if (code == 9 || code == 10 || code == 13 || (code >= 32 && code < 127)) {
        return std::string(1, static_cast<char>(code));
      }
    }
    error("unknown reference '&" + ref + ";'");
  }
  std::string characters(char stop) {
    std::string out;
    while (!atEnd() && peek() != stop) {
      const char c = text_[pos_++];
      if (c == '&') {
        out += reference();
      } else if (c == '<' || (stop == '"' && c == '>')) {
        error("raw '" + std::string(1, c) + "'");
      } else {
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          error("control character");
        }
        out += c;
      }
    }
    return out;
  }
  XmlElement element() {
    expect("<");
    XmlElement element;
    element.name = name();
    while (true) {
      skipSpace();
      if (startsWith("/>")) {
        pos_ += 2;
        return element;
      }
      if (peek() == '>') {
        ++pos_;
        break;
      }
      const std::string attribute = name();
      expect("=\"");
      const std::string value = characters('"');
      expect("\"");
      if (!element.attributes.emplace(attribute, value).second) error("duplicate attribute");
    }
    while (true) {
      element.text += characters('<');
      if (atEnd()) error("unclosed <" + element.name + ">");
      if (startsWith("</")) {
        pos_ += 2;
        if (name() != element.name) error("mismatched end tag of <" + element.name + ">");
        skipSpace();
        expect(">");
        return element;
      }
      element.children.push_back(this->element());
    }
  }

  std::string text_;
  std::size_t pos_ = 0;
};

XmlElement parseXml(const std::string& text) { return XmlReader(text).document(); }

// ---- reports ------------------------------------------------------------------------------

Measurement measurement(std::string name, double value, std::string unit,
                        std::optional<double> threshold, std::string comparison, bool passed) {
  return {std::move(name), value, std::move(unit), threshold, std::move(comparison), passed};
}

// a pick that passed, a handoff that slipped, a place that never finished, one contact
Report sampleReport() {
  Report report;
  report.world = "sort_2r_4c_cross_s1";
  report.plan_file = "plans/a&b <\"quoted\"> 'x'.json";
  report.seed = 7;
  report.time_step = 0.001;
  report.simulated_time = 9.25;

  ActionReport pick;
  pick.id = "pick cube_0 by r0";
  pick.type = ActionType::kPick;
  pick.robots = {"r0"};
  pick.object = "cube_0";
  pick.planned_start = 1.0;
  pick.planned_end = 3.0;
  pick.observed_start = 2.104;
  pick.observed_end = 2.9;
  pick.measurements = {measurement("slip", 0.0021, "m", 0.005, "<=", true),
                       measurement("pad contacts", 2, "", 2.0, ">=", true),
                       measurement("max grip force", 58.25, "N", std::nullopt, "", true)};
  report.actions.push_back(pick);

  ActionReport handoff;
  handoff.id = "handoff cube_0 from r0 to r1";
  handoff.type = ActionType::kHandoff;
  handoff.robots = {"r0", "r1"};
  handoff.object = "cube_0";
  handoff.planned_start = 3.0;
  handoff.planned_end = 6.0;
  handoff.observed_start = 4.5;
  handoff.verdict = Verdict::kFailed;
  handoff.failure = "the receiver lost the object after the giver opened";
  handoff.measurements = {measurement("slip", 0.012, "m", 0.005, "<=", false),
                          measurement("overlap", 0.4, "s", 0.2, ">=", true)};
  report.actions.push_back(handoff);

  ActionReport place;
  place.id = "place cube_0 in bin_red by r1";
  place.type = ActionType::kPlace;
  place.robots = {"r1"};
  place.object = "cube_0";
  place.region = "bin_red";
  place.planned_start = 6.0;
  place.planned_end = 8.5;
  place.verdict = Verdict::kFailed;
  place.failure = "object not in r1's gripper at the start";
  report.actions.push_back(place);

  report.events.push_back({4.2, "robot-robot contact", "r0/wrist_3_link <-> r1/\"finger\" & 'pad'",
                           "handoff cube_0 from r0 to r1", Eigen::Vector3d(0.1, -0.2, 1.05), "stills/event_1.png"});
  report.events.push_back({5.125, "drop", "cube_0 hit table", "", Eigen::Vector3d::Zero(), ""});
  report.robots.push_back({"r0", 0.0123, 0.0, 0.61});
  report.robots.push_back({"r1", 0.0456, 0.002, 1.0});
  report.execution_verdict = Verdict::kFailed;
  report.execution_failure = "1 unplanned robot-robot contact";
  return report;
}

Report passingReport() {
  Report report = sampleReport();
  report.actions.resize(1);
  report.events.clear();
  report.execution_verdict = Verdict::kPassed;
  report.execution_failure.clear();
  return report;
}

bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || same(*a, *b));
}

void requireSameReport(const Report& a, const Report& b) {
  REQUIRE(a.world == b.world);
  REQUIRE(a.plan_file == b.plan_file);
  REQUIRE(a.seed == b.seed);
  REQUIRE(a.actions_inferred == b.actions_inferred);
  REQUIRE(same(a.time_step, b.time_step));
  REQUIRE(same(a.simulated_time, b.simulated_time));
  REQUIRE(a.execution_verdict == b.execution_verdict);
  REQUIRE(a.execution_failure == b.execution_failure);
  REQUIRE(a.actions.size() == b.actions.size());
  for (std::size_t i = 0; i < a.actions.size(); ++i) {
    const ActionReport& x = a.actions[i];
    const ActionReport& y = b.actions[i];
    REQUIRE(x.id == y.id);
    REQUIRE(x.type == y.type);
    REQUIRE(x.robots == y.robots);
    REQUIRE(x.object == y.object);
    REQUIRE(x.region == y.region);
    REQUIRE(same(x.planned_start, y.planned_start));
    REQUIRE(same(x.planned_end, y.planned_end));
    REQUIRE(same(x.observed_start, y.observed_start));
    REQUIRE(same(x.observed_end, y.observed_end));
    REQUIRE(x.verdict == y.verdict);
    REQUIRE(x.failure == y.failure);
    REQUIRE(x.measurements.size() == y.measurements.size());
    for (std::size_t m = 0; m < x.measurements.size(); ++m) {
      REQUIRE(x.measurements[m].name == y.measurements[m].name);
      REQUIRE(same(x.measurements[m].value, y.measurements[m].value));
      REQUIRE(x.measurements[m].unit == y.measurements[m].unit);
      REQUIRE(same(x.measurements[m].threshold, y.measurements[m].threshold));
      REQUIRE(x.measurements[m].comparison == y.measurements[m].comparison);
      REQUIRE(x.measurements[m].passed == y.measurements[m].passed);
    }
  }
  REQUIRE(a.events.size() == b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    REQUIRE(same(a.events[i].t, b.events[i].t));
    REQUIRE(a.events[i].kind == b.events[i].kind);
    REQUIRE(a.events[i].detail == b.events[i].detail);
    REQUIRE(a.events[i].action == b.events[i].action);
    REQUIRE(a.events[i].still == b.events[i].still);
    for (int k = 0; k < 3; ++k) REQUIRE(same(a.events[i].where_W[k], b.events[i].where_W[k]));
  }
  REQUIRE(a.final_still == b.final_still);
  REQUIRE(a.robots.size() == b.robots.size());
  for (std::size_t i = 0; i < a.robots.size(); ++i) {
    REQUIRE(a.robots[i].robot == b.robots[i].robot);
    REQUIRE(same(a.robots[i].max_tracking_error, b.robots[i].max_tracking_error));
    REQUIRE(same(a.robots[i].torque_saturation, b.robots[i].torque_saturation));
    REQUIRE(same(a.robots[i].max_effort_ratio, b.robots[i].max_effort_ratio));
    REQUIRE(same(a.robots[i].max_tcp_force, b.robots[i].max_tcp_force));
    REQUIRE(same(a.robots[i].max_external_torque_ratio, b.robots[i].max_external_torque_ratio));
  }
}

}  // namespace

TEST_CASE("counts and the overall verdict", "[report]") {
  const Report dut = sampleReport();
  CHECK(dut.passedCount() == 1);
  CHECK(dut.failedCount() == 2);
  CHECK_FALSE(dut.passed());
  CHECK(passingReport().passed());
  Report execution_only = passingReport();
  execution_only.execution_verdict = Verdict::kFailed;
  CHECK_FALSE(execution_only.passed());
  CHECK(Report{}.passed());
}

TEST_CASE("measurements as text name the violated relation", "[report]") {
  CHECK(describeMeasurement(measurement("slip", 0.012, "m", 0.005, "<=", false)) ==
        "slip 0.012 m > 0.005 m");
  CHECK(describeMeasurement(measurement("slip", 0.0021, "m", 0.005, "<=", true)) ==
        "slip 0.0021 m <= 0.005 m");
  CHECK(describeMeasurement(measurement("pad contacts", 1, "", 2.0, ">=", false)) ==
        "pad contacts 1 < 2");
  CHECK(describeMeasurement(measurement("in region", 0, "", 1.0, "==", false)) ==
        "in region 0 != 1");
  CHECK(describeMeasurement(measurement("max grip force", 58.25, "N", std::nullopt, "", true)) ==
        "max grip force 58.25 N");
  CHECK(describeMeasurement(measurement("tilt", 1.0 / 3.0, "rad", 0.1, "<=", false)) ==
        "tilt 0.333333 rad > 0.1 rad");
}

TEST_CASE("JSON report: layout, summary and nulls", "[report]") {
  const std::string text = writeReportJson(sampleReport());
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
  std::vector<std::string> keys;
  for (const auto& [key, value] : json.items()) keys.push_back(key);
  CHECK(keys == std::vector<std::string>{"dashbed_report", "world", "plan", "seed", "actions_inferred", "time_step",
                                         "simulated_time", "summary", "actions", "events",
                                         "robots", "final_still", "readiness"});
  CHECK(json["dashbed_report"] == 1);
  CHECK(json["summary"]["actions"] == 3);
  CHECK(json["summary"]["passed"] == 1);
  CHECK(json["summary"]["failed"] == 2);
  CHECK(json["summary"]["execution"] == "failed");
  CHECK(json["summary"]["verdict"] == "failed");

  const auto& pick = json["actions"][0];
  std::vector<std::string> action_keys;
  for (const auto& [key, value] : pick.items()) action_keys.push_back(key);
  CHECK(action_keys == std::vector<std::string>{"id", "type", "robots", "object", "planned",
                                                "observed", "verdict", "failure", "measurements"});
  CHECK(pick["measurements"][2]["threshold"].is_null());
  CHECK(json["actions"][1]["observed"]["end"].is_null());
  CHECK(json["actions"][1]["observed"]["start"] == 4.5);
  CHECK(json["actions"][2]["region"] == "bin_red");
  CHECK(json["actions"][2]["observed"]["start"].is_null());
  CHECK(json["actions"][1]["robots"] == nlohmann::ordered_json{"r0", "r1"});

  const nlohmann::ordered_json passed =
      nlohmann::ordered_json::parse(writeReportJson(passingReport()));
  CHECK(passed["summary"]["verdict"] == "passed");
  CHECK(passed["summary"]["execution"] == "passed");
}

TEST_CASE("JSON report: deterministic and read back exactly", "[report]") {
  Report dut = sampleReport();
  dut.seed = std::numeric_limits<std::uint64_t>::max();
  dut.actions[0].measurements[0].value = 0.1 + 0.2;
  dut.actions[0].observed_start = -0.0;
  dut.robots[0].max_tracking_error = std::numeric_limits<double>::denorm_min();
  dut.robots[0].max_tcp_force = 12.5;
  dut.robots[0].max_external_torque_ratio = 1.0 / 3.0;
  dut.actions_inferred = true;
  const std::string text = writeReportJson(dut);
  CHECK(writeReportJson(dut) == text);
  CHECK(writeReportJson(sampleReport()) == writeReportJson(sampleReport()));
  const Report back = readReportJson(text, "report.json");
  requireSameReport(dut, back);
  CHECK(writeReportJson(back) == text);
}

TEST_CASE("JSON report: non-finite numbers are written as null", "[report]") {
  Report dut = sampleReport();
  dut.actions[1].measurements[0].value = std::numeric_limits<double>::infinity();
  const std::string text = writeReportJson(dut);
  CHECK(nlohmann::json::parse(text)["actions"][1]["measurements"][0]["value"].is_null());
  CHECK(std::isnan(readReportJson(text, "r.json").actions[1].measurements[0].value));
}

TEST_CASE("JSON report: bad input is rejected with its pointer", "[report]") {
  const nlohmann::json good = nlohmann::json::parse(writeReportJson(sampleReport()));
  const auto rejects = [](const nlohmann::json& json, const std::string& message) {
    REQUIRE_THROWS_MATCHES(readReportJson(json.dump(), "r.json"), ReportError,
                           Catch::Matchers::Message("r.json: " + message));
  };
  nlohmann::json bad = good;
  bad["dashbed_report"] = 2;
  rejects(bad, "/dashbed_report: unsupported report format version 2 (this build reads version 1)");
  bad = good;
  bad.erase("dashbed_report");
  rejects(bad, "/dashbed_report: missing: not a dashbed report (expected \"dashbed_report\": 1)");
  bad["dashbed_report"] = "1";
  rejects(bad, "/dashbed_report: expected the integer 1, got a string \"1\"");
  bad = good;
  bad["summary"]["failed"] = 1;
  rejects(bad, "/summary/failed: 1 disagrees with the 2 in /actions");
  bad = good;
  bad["summary"]["verdict"] = "passed";
  rejects(bad, "/summary/verdict: disagrees with the actions, the execution verdict and the readiness checks");
  bad = good;
  bad["actions"][1]["measurements"][0].erase("unit");
  rejects(bad, "/actions/1/measurements/0/unit: missing");
  bad = good;
  bad["actions"][0]["type"] = "push";
  rejects(bad, "/actions/0/type: unknown action type \"push\"");
  bad = good;
  bad["events"][0]["t"] = "soon";
  rejects(bad, "/events/0/t: expected a number, got a string");
  REQUIRE_THROWS_WITH(readReportJson("{", "r.json"),
                      Catch::Matchers::StartsWith("r.json: /: invalid JSON: "));
  REQUIRE_THROWS_AS(loadReportFile("/nonexistent/report.json"), ReportError);
}

TEST_CASE("JUnit XML: well-formed, counts and testcases", "[report]") {
  const std::string text = writeJUnitXml(sampleReport());
  const XmlElement root = parseXml(text);
  REQUIRE(root.name == "testsuites");
  CHECK(root.attributes.at("tests") == "4");
  CHECK(root.attributes.at("failures") == "3");
  const auto suites = root.all("testsuite");
  REQUIRE(suites.size() == 1);
  const XmlElement& suite = *suites.front();
  CHECK(suite.attributes.at("name") ==
        "dashbed: sort_2r_4c_cross_s1 / plans/a&b <\"quoted\"> 'x'.json");
  CHECK(suite.attributes.at("tests") == "4");
  CHECK(suite.attributes.at("failures") == "3");
  CHECK(suite.attributes.at("errors") == "0");
  CHECK(suite.attributes.at("time") == "9.250");

  std::map<std::string, std::string> properties;
  for (const XmlElement* property : suite.first("properties")->all("property")) {
    properties[property->attributes.at("name")] = property->attributes.at("value");
  }
  CHECK(properties.at("seed") == "7");
  CHECK(properties.at("time_step") == "0.001");
  CHECK(properties.at("plan") == "plans/a&b <\"quoted\"> 'x'.json");

  const auto cases = suite.all("testcase");
  REQUIRE(cases.size() == 4);
  CHECK(cases[0]->attributes.at("classname") == "dashbed.pick");
  CHECK(cases[0]->attributes.at("name") == "pick cube_0 by r0");
  CHECK(cases[0]->attributes.at("time") == "2.000");
  CHECK(cases[0]->first("failure") == nullptr);
  REQUIRE(cases[0]->first("system-out") != nullptr);
  CHECK(cases[0]->first("system-out")->text.find("slip 0.0021 m <= 0.005 m  [passed]") !=
        std::string::npos);

  CHECK(cases[1]->attributes.at("classname") == "dashbed.handoff");
  CHECK(cases[1]->attributes.at("time") == "3.000");
  const XmlElement* slip = cases[1]->first("failure");
  REQUIRE(slip != nullptr);
  CHECK(slip->attributes.at("message") == "slip 0.012 m > 0.005 m");
  CHECK(slip->attributes.at("type") == "handoff");
  // the text has every measurement, passed or not, and the monitor's explanation
  CHECK(slip->text.find("failure: the receiver lost the object after the giver opened") !=
        std::string::npos);
  CHECK(slip->text.find("slip 0.012 m > 0.005 m  [FAILED]") != std::string::npos);
  CHECK(slip->text.find("overlap 0.4 s >= 0.2 s  [passed]") != std::string::npos);
  CHECK(slip->text.find("observed: 4.5 s to -") != std::string::npos);

  // no failed measurement: the message is the monitor's failure text
  CHECK(cases[2]->attributes.at("classname") == "dashbed.place");
  const XmlElement* place = cases[2]->first("failure");
  REQUIRE(place != nullptr);
  CHECK(place->attributes.at("message") == "object not in r1's gripper at the start");
  CHECK(place->attributes.at("type") == "placement");

  CHECK(cases[3]->attributes.at("classname") == "dashbed.execution");
  CHECK(cases[3]->attributes.at("name") == "execution");
  CHECK(cases[3]->attributes.at("time") == "9.250");
  const XmlElement* execution = cases[3]->first("failure");
  REQUIRE(execution != nullptr);
  CHECK(execution->attributes.at("message") == "1 unplanned robot-robot contact");
  CHECK(execution->attributes.at("type") == "execution");
  CHECK(execution->text.find("t=4.2 s robot-robot contact: r0/wrist_3_link <-> r1/\"finger\" & "
                             "'pad' (during handoff cube_0 from r0 to r1)") != std::string::npos);
  CHECK(execution->text.find("t=5.125 s drop: cube_0 hit table\n") != std::string::npos);
  CHECK(execution->text.find("r1: max tracking error 0.0456 rad") != std::string::npos);
}

TEST_CASE("JUnit XML: everything is escaped", "[report]") {
  Report dut = sampleReport();
  dut.actions[0].id = "pick <cube> & \"friends\" 'r0'";
  dut.actions[1].measurements[0].name = "slip<&>";
  dut.events[0].detail = "line one\nline two\ttab \x01 bell";
  dut.world = "w\nnewline";
  const std::string text = writeJUnitXml(dut);
  const XmlElement root = parseXml(text);  // throws on raw < or & or control characters
  const XmlElement& suite = *root.first("testsuite");
  CHECK(suite.attributes.at("name") == "dashbed: w\nnewline / " + dut.plan_file);
  const auto cases = suite.all("testcase");
  CHECK(cases[0]->attributes.at("name") == dut.actions[0].id);
  CHECK(cases[1]->first("failure")->attributes.at("message") == "slip<&> 0.012 m > 0.005 m");
  CHECK(cases[3]->first("failure")->text.find("line one\nline two\ttab ? bell") !=
        std::string::npos);
  // the raw text: attribute quotes and apostrophes as entities, newlines in attributes as refs
  CHECK(text.find("name=\"pick &lt;cube&gt; &amp; &quot;friends&quot; &apos;r0&apos;\"") !=
        std::string::npos);
  CHECK(text.find("w&#10;newline") != std::string::npos);
}

TEST_CASE("JUnit XML: deterministic, and a passing report has no failures", "[report]") {
  CHECK(writeJUnitXml(sampleReport()) == writeJUnitXml(sampleReport()));
  const std::string text = writeJUnitXml(passingReport());
  CHECK(text.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites", 0) == 0);
  CHECK(text.find("<failure") == std::string::npos);
  const XmlElement root = parseXml(text);
  CHECK(root.attributes.at("tests") == "2");
  CHECK(root.attributes.at("failures") == "0");
  const auto cases = root.first("testsuite")->all("testcase");
  REQUIRE(cases.size() == 2);
  // the execution case still shows the robots' tracking quality
  REQUIRE(cases[1]->first("system-out") != nullptr);
  CHECK(cases[1]->first("system-out")->text.find("r0: max tracking error 0.0123 rad") !=
        std::string::npos);
}

TEST_CASE("readiness: part of the verdict, written, read back and one JUnit case per check", "[report]") {
  Report dut = passingReport();
  dut.readiness.push_back({"joint speed", "r0 wrist_3_joint", 1.2, 3.14159, "rad/s", 4.5, true, ""});
  dut.readiness.push_back({"payload", "r1 holding box", 6.2, 5.0, "kg", 7.25, false,
                           "r1 holding box carries 6.2 kg with the gripper, above the UR5e's rated 5 kg"});
  CHECK_FALSE(dut.ready());
  CHECK_FALSE(dut.passed());
  CHECK(dut.failedCount() == 0);  // the actions themselves passed

  const std::string text = writeReportJson(dut);
  CHECK(text.find("\"readiness\": \"failed\"") != std::string::npos);
  const Report back = readReportJson(text, "report.json");
  REQUIRE(back.readiness.size() == 2);
  CHECK(back.readiness[1].name == "payload");
  CHECK(back.readiness[1].subject == "r1 holding box");
  CHECK(back.readiness[1].value == 6.2);
  CHECK(back.readiness[1].limit == 5.0);
  CHECK(back.readiness[1].t == 7.25);
  CHECK_FALSE(back.readiness[1].passed);
  CHECK(back.readiness[1].detail == dut.readiness[1].detail);
  CHECK(writeReportJson(back) == text);

  const XmlElement root = parseXml(writeJUnitXml(dut));
  const std::size_t cases = dut.actions.size() + 1 + 2;
  CHECK(root.attributes.at("tests") == std::to_string(cases));
  CHECK(root.attributes.at("failures") == "1");
  const auto testcases = root.first("testsuite")->all("testcase");
  REQUIRE(testcases.size() == cases);
  const XmlElement& payload = *testcases.back();
  CHECK(payload.attributes.at("classname") == "dashbed.readiness");
  CHECK(payload.attributes.at("name") == "payload r1 holding box");
  REQUIRE(payload.first("failure") != nullptr);
  CHECK(payload.first("failure")->attributes.at("type") == "readiness");
  CHECK(payload.first("failure")->attributes.at("message") == dut.readiness[1].detail);
  CHECK(testcases[testcases.size() - 2]->first("failure") == nullptr);

  // a report of a plan the readiness check has not judged: no section, the verdict as before
  dut.readiness.clear();
  CHECK(dut.passed());
}

TEST_CASE("the XML checker itself rejects malformed documents", "[report]") {
  const std::string head = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  CHECK_NOTHROW(parseXml(head + "<a x=\"1\"><b/>t &amp; u</a>"));
  CHECK_THROWS(parseXml(head + "<a><b></a></b>"));
  CHECK_THROWS(parseXml(head + "<a>x & y</a>"));
  CHECK_THROWS(parseXml(head + "<a x=\"<\"/>"));
  CHECK_THROWS(parseXml(head + "<a x=\"1\" x=\"2\"/>"));
  CHECK_THROWS(parseXml(head + "<a>"));
  CHECK_THROWS(parseXml(head + "<a/><b/>"));
  CHECK_THROWS(parseXml("<a/>"));
}
