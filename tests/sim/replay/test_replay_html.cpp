#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "sim/motion_samples.h"
#include "sim/replay/replay_html.h"

namespace {

using namespace dashbed;

std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const std::size_t begin = text.find(open);
  REQUIRE(begin != std::string::npos);
  const std::size_t end = text.find(close, begin + open.size());
  REQUIRE(end != std::string::npos);
  return text.substr(begin + open.size(), end - begin - open.size());
}

std::string unbase64(const std::string& text) {
  static const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::uint32_t word = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    word = (word << 6) | static_cast<std::uint32_t>(digits.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((word >> bits) & 0xFF);
    }
  }
  return out;
}

/// Two samples of every link and object: the second moved by `shift` along x.
sim::MotionSamples samplesOf(const core::World& world, const core::RobotSet& robots, double shift) {
  sim::MotionSamples s;
  s.rate = 30.0;
  s.times = {0.0, 1.0 / 30.0};
  for (const auto& r : world.robots) s.robots.push_back(r.name);
  for (const auto& o : world.objects) s.objects.push_back(o.name);
  for (const auto& link : robots[0].model->links()) s.links.push_back(link.name);
  for (int k = 0; k < 2; ++k) {
    for (std::size_t i = 0; i < s.robots.size() * s.links.size(); ++i) {
      s.link_poses.insert(s.link_poses.end(), {k * shift, 0.5, -0.25, 0.0, 0.0, std::sqrt(0.5), std::sqrt(0.5)});
    }
    for (std::size_t i = 0; i < s.objects.size(); ++i) s.object_poses.insert(s.object_poses.end(), {0.1, 0.2, 0.77, 0, 0, 0, 1});
  }
  return s;
}

}  // namespace

TEST_CASE("replay page: the run's data inlined, decodable, quantised to 0.1 mm", "[replay]") {
  const core::LoadedWorld loaded = core::loadWorld(core::defaultWorldPath());
  const sim::MotionSamples samples = samplesOf(*loaded.world, *loaded.robots, 1.2345);
  sim::Report report;
  report.world = loaded.world->name;
  report.plan_file = "plan.json";
  sim::ActionReport failed;
  failed.id = "pick cube_0 by r0";
  failed.robots = {"r0"};
  failed.verdict = sim::Verdict::kFailed;
  failed.failure = "grasp: </script><b>";  // text that must not end the data's script element
  report.actions.push_back(failed);

  const std::string page = replay::replayHtml(*loaded.world, *loaded.robots, samples, report);
  CHECK(page.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(page.find("/*@") == std::string::npos);  // every marker replaced
  CHECK(page.find("<title>dashbed replay: " + loaded.world->name + " FAILED</title>") != std::string::npos);
  const std::string text = between(page, "<script type=\"application/json\" id=\"replay-data\">", "</script>");
  const nlohmann::json data = nlohmann::json::parse(text);
  CHECK(data["samples"] == 2);
  CHECK(data["report"]["actions"][0]["failure"] == "grasp: </script><b>");
  CHECK(data["report"]["passed"] == false);
  CHECK(data["cameras"].contains("oblique"));
  CHECK(data["cameras"].contains("side:r1"));

  // one pose per sample, robot and link with a mesh; positions in units of 0.1 mm
  const std::size_t links = data["links"].size();
  REQUIRE(links > 0);
  REQUIRE(links < samples.links.size());  // frames without meshes (tcp, base) are left out
  const std::string poses = unbase64(data["link_poses"]);
  REQUIRE(poses.size() == 2 * samples.robots.size() * links * 7 * sizeof(std::int16_t));
  std::vector<std::int16_t> q(poses.size() / 2);
  std::memcpy(q.data(), poses.data(), poses.size());
  CHECK(data["position_unit"] == 1e-4);
  const std::size_t second = samples.robots.size() * links * 7;
  CHECK(q[0] == 0);
  CHECK(q[second] == 12345);  // 1.2345 m
  CHECK(q[second + 1] == 5000);
  CHECK(q[second + 2] == -2500);
  CHECK(q[second + 5] == std::lround(std::sqrt(0.5) * 32767));
  // every mesh has whole triangles of valid vertices
  for (const auto& mesh : data["meshes"]) {
    const std::string positions = unbase64(mesh["positions"]);
    const std::string indices = unbase64(mesh["indices"]);
    const std::size_t vertices = positions.size() / (3 * sizeof(float));
    REQUIRE(indices.size() % (3 * sizeof(std::uint32_t)) == 0);
    std::vector<std::uint32_t> index(indices.size() / 4);
    std::memcpy(index.data(), indices.data(), indices.size());
    for (const std::uint32_t i : index) REQUIRE(i < vertices);
    CHECK(unbase64(mesh["colors"]).size() == 3 * vertices);
  }
}

TEST_CASE("replay page: worlds reaching far from the origin get a coarser unit, not clipped poses", "[replay]") {
  const core::LoadedWorld loaded = core::loadWorld(core::defaultWorldPath());
  const sim::MotionSamples samples = samplesOf(*loaded.world, *loaded.robots, 6.5534);
  const std::string page = replay::replayHtml(*loaded.world, *loaded.robots, samples, sim::Report{});
  const nlohmann::json data = nlohmann::json::parse(between(page, "id=\"replay-data\">", "</script>"));
  const double unit = data["position_unit"];
  CHECK(unit == Approx(6.5534 / 32767));
  const std::string poses = unbase64(data["link_poses"]);
  std::vector<std::int16_t> q(poses.size() / 2);
  std::memcpy(q.data(), poses.data(), poses.size());
  CHECK(q[q.size() / 2] == 32767);
}
