#include "sim/replay/replay_html.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/asset_paths.h"
#include "core/input_text.h"
#include "sim/render/camera.h"
#include "sim/render/link_mesh.h"

namespace dashbed::replay {
namespace {

using Json = nlohmann::ordered_json;

std::string base64(const void* data, std::size_t size) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const std::uint32_t b0 = bytes[i];
    const std::uint32_t b1 = i + 1 < size ? bytes[i + 1] : 0;
    const std::uint32_t b2 = i + 2 < size ? bytes[i + 2] : 0;
    const std::uint32_t word = (b0 << 16) | (b1 << 8) | b2;
    out += kDigits[(word >> 18) & 63];
    out += kDigits[(word >> 12) & 63];
    out += i + 1 < size ? kDigits[(word >> 6) & 63] : '=';
    out += i + 2 < size ? kDigits[word & 63] : '=';
  }
  return out;
}

template <typename T>
std::string base64Of(const std::vector<T>& values) {
  return base64(values.data(), values.size() * sizeof(T));
}

Json vectorJson(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

/// x y z and quaternion x y z w (w >= 0).
Json poseJson(const core::Pose& X) {
  Eigen::Quaterniond q(X.linear());
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d p = X.translation();
  return Json::array({p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()});
}

Json colorJson(const core::Color& c) { return Json::array({c.r, c.g, c.b}); }

std::string readAsset(const std::string& relative) {
  const std::filesystem::path file = core::dataRoot() / relative;
  std::string reason;
  std::optional<std::string> text = core::readFileBytes(file, core::kMaxInputFileBytes, reason);
  if (!text) {
    std::string message = file.string();
    message.append(": cannot read the replay page's ").append(relative).append(": ").append(reason);
    if (relative.find("node_modules") != std::string::npos) message.append(" (run tools/setup.sh)");
    throw std::runtime_error(message);
  }
  return std::move(*text);
}

/// A mesh as base64 arrays: positions and normals (float32 x 3), colours (uint8 RGB), indices (uint32).
Json meshJson(const render::TriangleMesh& mesh) {
  std::vector<float> positions, normals;
  std::vector<std::uint8_t> colors;
  for (const render::MeshVertex& v : mesh.vertices) {
    positions.insert(positions.end(), v.position, v.position + 3);
    normals.insert(normals.end(), v.normal, v.normal + 3);
    for (int k = 0; k < 3; ++k) colors.push_back(static_cast<std::uint8_t>(std::lround(std::clamp(v.color[k], 0.0f, 1.0f) * 255.0f)));
  }
  return {{"positions", base64Of(positions)}, {"normals", base64Of(normals)}, {"colors", base64Of(colors)},
          {"indices", base64Of(mesh.indices)}};
}

/// Poses [n][7] of float64 quantised to int16: positions in units of `unit` [m], quaternion
/// components in units of 1/32767.
std::vector<std::int16_t> quantisedPoses(const std::vector<double>& poses, double unit) {
  std::vector<std::int16_t> out(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const double scaled = i % 7 < 3 ? poses[i] / unit : poses[i] * 32767.0;
    out[i] = static_cast<std::int16_t>(std::clamp(std::lround(scaled), -32767L, 32767L));
  }
  return out;
}

Json measurementJson(const sim::Measurement& m) {
  Json j = {{"name", m.name}, {"value", m.value}, {"unit", m.unit}, {"passed", m.passed},
            {"text", sim::describeMeasurement(m)}};
  if (m.threshold) {
    j["threshold"] = *m.threshold;
    j["comparison"] = m.comparison;
  }
  return j;
}

Json reportJson(const sim::Report& report) {
  Json actions = Json::array();
  for (const sim::ActionReport& a : report.actions) {
    Json measurements = Json::array();
    for (const sim::Measurement& m : a.measurements) measurements.push_back(measurementJson(m));
    actions.push_back({{"id", a.id}, {"type", std::string(core::toString(a.type))}, {"robots", a.robots},
                       {"object", a.object}, {"start", a.planned_start}, {"end", a.planned_end},
                       {"passed", a.verdict == sim::Verdict::kPassed}, {"failure", a.failure},
                       {"measurements", measurements}});
  }
  Json events = Json::array();
  for (const sim::ExecutionEvent& e : report.events) {
    events.push_back({{"t", e.t}, {"kind", e.kind}, {"detail", e.detail}, {"action", e.action},
                      {"where", vectorJson(e.where_W)}});
  }
  Json readiness = Json::array();
  for (const core::ReadinessCheck& c : report.readiness) {
    readiness.push_back({{"name", c.name}, {"subject", c.subject}, {"value", c.value}, {"limit", c.limit},
                         {"unit", c.unit}, {"t", c.t}, {"passed", c.passed}, {"detail", c.detail}});
  }
  Json robots = Json::array();
  for (const sim::RobotExecution& r : report.robots) {
    robots.push_back({{"robot", r.robot}, {"max_tracking_error", r.max_tracking_error},
                      {"max_effort_ratio", r.max_effort_ratio}, {"torque_saturation", r.torque_saturation},
                      {"max_tcp_force", r.max_tcp_force}, {"max_external_torque_ratio", r.max_external_torque_ratio}});
  }
  return {{"passed", report.passed()},
          {"passed_actions", report.passedCount()},
          {"execution_passed", report.execution_verdict == sim::Verdict::kPassed},
          {"execution_failure", report.execution_failure},
          {"ready", report.ready()},
          {"simulated_time", report.simulated_time},
          {"actions", actions},
          {"events", events},
          {"readiness", readiness},
          {"robots", robots}};
}

Json cameraJson(const render::Camera& c) {
  return {{"eye", vectorJson(c.eye)}, {"target", vectorJson(c.target)}, {"up", vectorJson(c.up)}, {"fov", c.fov_deg}};
}

/// JSON safe inside a <script> element: "</" never appears (it is written "<\/", the same string).
std::string scriptSafe(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  std::size_t from = 0;
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", from)) {
    out.append(text, from, at + 1 - from).append("\\");
    from = at + 1;
  }
  return out.append(text, from, std::string::npos);
}

}  // namespace

std::string htmlText(const std::string& text) {
  std::string out;
  for (const char c : core::printableText(text)) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

void replaceMarker(std::string& page, const std::string& marker, const std::string& text) {
  const std::size_t at = page.find(marker);
  if (at == std::string::npos) throw std::runtime_error("assets/web/replay.html: no marker " + marker);
  page.replace(at, marker.size(), text);
}

}  // namespace

std::string replayHtml(const core::World& world, const core::RobotSet& robots, const sim::MotionSamples& samples,
                       const sim::Report& report) {
  Json data;
  data["format"] = 1;
  data["world"] = world.name;
  data["plan"] = report.plan_file;
  data["rate"] = samples.rate;
  data["samples"] = samples.count();
  std::vector<float> times(samples.times.begin(), samples.times.end());
  data["times"] = base64Of(times);

  // robots: the links with visuals, each with its mesh (shared by robots of the same model)
  std::map<std::filesystem::path, render::TriangleMesh> files;
  Json meshes = Json::array();
  std::vector<int> shown_links;  // indices into samples.links
  Json links = Json::array();
  if (robots.size() > 0) {
    const core::RobotModel& model = *robots[0].model;
    for (std::size_t l = 0; l < model.links().size(); ++l) {
      const render::TriangleMesh mesh = render::linkVisualMesh(model.links()[l], files);
      if (mesh.indices.empty()) continue;
      shown_links.push_back(static_cast<int>(l));
      links.push_back({{"name", model.links()[l].name}, {"mesh", meshes.size()}});
      meshes.push_back(meshJson(mesh));
    }
  }
  data["meshes"] = meshes;
  Json robot_list = Json::array();
  for (const core::RobotSpec& r : world.robots) robot_list.push_back({{"name", r.name}});
  data["robots"] = robot_list;
  data["links"] = links;

  // poses: [sample][robot][shown link][7] and [sample][object][7], quantised
  double extent = 1.0;
  for (std::size_t i = 0; i < samples.link_poses.size(); ++i) {
    if (i % 7 < 3) extent = std::max(extent, std::abs(samples.link_poses[i]));
  }
  for (std::size_t i = 0; i < samples.object_poses.size(); i += 7) {
    for (int k = 0; k < 3; ++k) extent = std::max(extent, std::abs(samples.object_poses[i + static_cast<std::size_t>(k)]));
  }
  const double unit = std::max(1e-4, extent / 32767.0);  // 0.1 mm within 3.2 m of the origin
  std::vector<double> link_poses;
  const std::size_t per_robot = samples.links.size();
  for (std::size_t s = 0; s < samples.count(); ++s) {
    for (std::size_t r = 0; r < samples.robots.size(); ++r) {
      for (const int l : shown_links) {
        const auto begin = samples.link_poses.begin() +
                           static_cast<std::ptrdiff_t>(((s * samples.robots.size() + r) * per_robot + static_cast<std::size_t>(l)) * 7);
        link_poses.insert(link_poses.end(), begin, begin + 7);
      }
    }
  }
  data["position_unit"] = unit;
  data["link_poses"] = base64Of(quantisedPoses(link_poses, unit));
  data["object_poses"] = base64Of(quantisedPoses(samples.object_poses, unit));
  const auto floats = [](const std::vector<double>& values) { return std::vector<float>(values.begin(), values.end()); };
  data["signals"] = {{"tracking_error", base64Of(floats(samples.tracking_error))},
                     {"effort_ratio", base64Of(floats(samples.effort_ratio))},
                     {"grip_force", base64Of(floats(samples.grip_force))}};
  data["limits"] = {{"tracking_error", world.checks.tracking_error_limit}, {"effort_ratio", 1.0},
                    {"grip_force", world.controller.grip_force}};

  Json objects = Json::array();
  for (const core::ObjectSpec& o : world.objects) {
    objects.push_back({{"name", o.name}, {"size", vectorJson(o.size)}, {"color", colorJson(o.color)}});
  }
  data["objects"] = objects;
  Json fixtures = Json::array();
  for (const core::FixtureSpec& f : world.fixtures) {
    Json boxes = Json::array();
    for (const core::Box& b : f.boxes) boxes.push_back({{"pose", poseJson(b.X_WB)}, {"size", vectorJson(b.size)}});
    fixtures.push_back({{"name", f.name}, {"color", colorJson(f.color)}, {"boxes", boxes}});
  }
  data["fixtures"] = fixtures;
  Json regions = Json::array();
  for (const core::Region& r : world.regions) {
    regions.push_back({{"name", r.name}, {"pose", poseJson(r.X_WR)}, {"size", vectorJson(r.size)}});
  }
  data["regions"] = regions;
  Json cameras = Json::object();
  for (const std::string& name : render::cameraPresetNames(world)) {
    cameras[name] = cameraJson(render::cameraPreset(world, name, 16, 9));
  }
  data["cameras"] = cameras;
  data["report"] = reportJson(report);

  std::string page = readAsset("assets/web/replay.html");
  replaceMarker(page, "/*@THREE@*/", scriptSafe(readAsset("assets/web/node_modules/three/build/three.min.js")));
  replaceMarker(page, "/*@APP@*/", scriptSafe(readAsset("assets/web/replay.js")));
  replaceMarker(page, "@DATA@", scriptSafe(data.dump(-1, ' ', false, Json::error_handler_t::replace)));
  replaceMarker(page, "@TITLE@", htmlText(world.name).append(report.passed() ? " PASSED" : " FAILED"));
  return page;
}

void writeReplayHtml(const std::filesystem::path& file, const core::World& world, const core::RobotSet& robots,
                     const sim::MotionSamples& samples, const sim::Report& report) {
  core::writeFile(file, replayHtml(world, robots, samples, report));
}

}  // namespace dashbed::replay
