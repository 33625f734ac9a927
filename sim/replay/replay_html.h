#pragma once
// The HTML replay of a run: one self-contained file (three.js, the page's code, the scene's
// meshes, the sampled motion and the report inlined) that opens from disk with no server and no
// network, to scrub through the run, look from any side and read each check beside the picture.
// The page's code and template are assets/web/ (replay.html, replay.js); three.js comes pinned
// from npm (assets/web/package.json, installed by tools/setup.sh). Format: docs/replay.md.

#include <filesystem>
#include <string>

#include "core/robot_set.h"
#include "core/world.h"
#include "sim/motion_samples.h"
#include "sim/report.h"

namespace dashbed::replay {

/// The rate at which a replay samples the simulation [Hz of plan time]: the renderer's video
/// frame rate; the page interpolates between samples.
inline constexpr double kReplayRate = 30.0;

/// `text` for HTML element content and attribute values: printable (core::printableText), with
/// & < > " written as entities.
std::string htmlText(const std::string& text);

/// The replay page of a run of `world` sampled as `samples` (every link of every robot) and judged
/// as `report`. Throws std::runtime_error naming a file of assets/web/ or a mesh that cannot be read.
std::string replayHtml(const core::World& world, const core::RobotSet& robots, const sim::MotionSamples& samples,
                       const sim::Report& report);

/// replayHtml written to `file`; throws std::runtime_error naming the file when it cannot be written.
void writeReplayHtml(const std::filesystem::path& file, const core::World& world, const core::RobotSet& robots,
                     const sim::MotionSamples& samples, const sim::Report& report);

}  // namespace dashbed::replay
