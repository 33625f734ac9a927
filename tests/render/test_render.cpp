#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>
#include <unistd.h>

#include "core/world_loader.h"
#include "sim/render/camera.h"
#include "sim/render/frame_recorder.h"
#include "sim/render/image.h"
#include "sim/render/overlay.h"
#include "sim/render/scene_renderer.h"
#include "sim/render/scene_state.h"
#include "sim/render/video_writer.h"
#include "sim/simulation.h"

using namespace dashbed;

namespace {

const core::LoadedWorld& defaultWorld() {
  static const core::LoadedWorld loaded = core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/default.yaml");
  return loaded;
}

// A fresh temporary folder per test, removed at the end of the test.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("dashbed_test_render_" + std::to_string(::getpid()) + "_" + name)) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

struct Rgb {
  int r, g, b;
};

Rgb pixelAt(const render::Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

// Robot colours are greys and near-blacks (UR links, caps, Hand-E body, aluminium fingers):
// little colour for their brightness. The table under the hands is brown, the bins saturated
// even in shadow.
bool robotLike(Rgb c) {
  const int high = std::max({c.r, c.g, c.b}), low = std::min({c.r, c.g, c.b});
  return high - low < high / 4 + 8;
}

bool reddish(Rgb c) { return c.r > 100 && c.r > 2 * c.g && c.r > 2 * c.b; }

int countInWindow(const render::Image& image, const Eigen::Vector2d& centre, int half, bool (*predicate)(Rgb)) {
  int count = 0;
  const int cx = static_cast<int>(std::floor(centre.x())), cy = static_cast<int>(std::floor(centre.y()));
  for (int y = cy - half; y <= cy + half; ++y) {
    for (int x = cx - half; x <= cx + half; ++x) {
      if (x >= 0 && y >= 0 && x < image.width && y < image.height && predicate(pixelAt(image, x, y))) ++count;
    }
  }
  return count;
}

std::string readFileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs a command and returns its standard output.
std::string capture(const std::string& command) {
  std::string out;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof(buffer), pipe)) out += buffer;
    ::pclose(pipe);
  }
  return out;
}

}  // namespace

TEST_CASE("The default world renders non-blank from every preset", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  render::SceneRenderer dut(*world, *robots);
  const render::SceneState state = render::sceneAtHome(*world, *robots);
  for (const std::string& preset : render::cameraPresetNames(*world)) {
    INFO("preset " << preset);
    const render::Image image = dut.render(state, render::cameraPreset(*world, preset, 320, 240));
    REQUIRE(image.width == 320);
    REQUIRE(image.height == 240);
    REQUIRE(image.rgb.size() == 320u * 240u * 3u);
    std::set<int> colours;
    int background = 0, black = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const Rgb c = pixelAt(image, x, y);
        colours.insert((c.r << 16) | (c.g << 8) | c.b);
        if (c.r == 204 && c.g == 214 && c.b == 227) ++background;  // RenderSettings::background
        if (c.r < 16 && c.g < 16 && c.b < 16) ++black;  // only the Hand-E's black pads and coupling
      }
    }
    CHECK(colours.size() > 200);
    CHECK(background < image.width * image.height / 2);
    CHECK(black < image.width * image.height / 200);
  }
}

TEST_CASE("A world with one object and nothing else renders it", "[render]") {
  core::World world;
  world.name = "one_cube";
  core::ObjectSpec cube;
  cube.name = "cube";
  cube.size = Eigen::Vector3d(0.2, 0.2, 0.2);
  cube.color = {0.1, 0.2, 0.9};
  cube.X_WO = core::makePoseXyzYaw(Eigen::Vector3d(1.0, 2.0, 0.1), 0.3);
  world.objects.push_back(cube);
  const core::RobotSet robots(world);
  render::SceneRenderer dut(world, robots);
  for (const std::string& preset : render::cameraPresetNames(world)) {
    const render::Camera camera = render::cameraPreset(world, preset, 160, 120);
    const render::Image image = dut.render(render::sceneAtHome(world, robots), camera);
    const Rgb centre = pixelAt(image, 80, 60);  // the cube is the whole world: it is in the middle
    INFO("preset " << preset << ": " << centre.r << " " << centre.g << " " << centre.b);
    CHECK((centre.b > 2 * centre.r && centre.b > 100));
  }
}

TEST_CASE("Robot pixels appear where each TCP projects", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  render::SceneRenderer dut(*world, *robots);
  const render::SceneState home = render::sceneAtHome(*world, *robots);
  const render::Camera camera = render::cameraPreset(*world, "oblique", 640, 480);
  const render::Image image = dut.render(home, camera);

  // the same scene with every arm swung about its pan joint: the hands leave those pixels
  std::vector<Eigen::VectorXd> q_moved;
  for (const core::PlacedRobot& robot : robots->robots()) {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(robot.model->numPositions());
    for (int i = 0; i < 6; ++i) q[i] = robot.spec->home[i];
    q[0] += 1.5;
    q_moved.push_back(q);
  }
  std::vector<core::Pose> X_WO;
  for (const core::ObjectSpec& object : world->objects) X_WO.push_back(object.X_WO);
  const render::Image moved = dut.render(render::sceneFromConfigurations(*world, *robots, q_moved, X_WO), camera);

  for (std::size_t r = 0; r < robots->size(); ++r) {
    const int tcp = (*robots)[r].model->requireLink("tcp");
    const Eigen::Vector3d p_WT = home.link_poses[r][tcp].translation();
    // the forward kinematics of the scene state agree with the IK model's TCP
    core::ArmConfig q_home;
    std::copy((*robots)[r].spec->home.begin(), (*robots)[r].spec->home.end(), q_home.begin());
    REQUIRE((p_WT - (*robots)[r].tcpPoseInWorld(q_home).translation()).norm() < 1e-9);
    const Eigen::Vector2d pixel = render::project(camera, p_WT);
    INFO("robot " << r << " TCP at pixel " << pixel.transpose());
    REQUIRE(pixel.x() > 0.0);
    REQUIRE(pixel.x() < camera.width);
    REQUIRE(pixel.y() > 0.0);
    REQUIRE(pixel.y() < camera.height);
    CHECK(countInWindow(image, pixel, 3, robotLike) >= 12);
    // and they are the robot's: they change when the arm swings away
    int changed = 0;
    for (int y = static_cast<int>(pixel.y()) - 3; y <= static_cast<int>(pixel.y()) + 3; ++y) {
      for (int x = static_cast<int>(pixel.x()) - 3; x <= static_cast<int>(pixel.x()) + 3; ++x) {
        changed += std::equal(image.pixel(x, y), image.pixel(x, y) + 3, moved.pixel(x, y)) ? 0 : 1;
      }
    }
    CHECK(changed >= 12);
  }
}

TEST_CASE("An object's colour appears where its centre projects", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  render::SceneRenderer dut(*world, *robots);
  const render::SceneState home = render::sceneAtHome(*world, *robots);
  const core::ObjectSpec* cube = world->findObject("cube_0");
  REQUIRE(cube != nullptr);
  REQUIRE(cube->object_class == "red");
  const Eigen::Vector3d p_WO = cube->X_WO.translation();

  SECTION("in the oblique preset, where the cube is a few pixels wide") {
    const render::Camera camera = render::cameraPreset(*world, "oblique", 640, 480);
    const render::Image image = dut.render(home, camera);
    CHECK(reddish(pixelAt(image, static_cast<int>(render::project(camera, p_WO).x()),
                          static_cast<int>(render::project(camera, p_WO).y()))));
  }
  SECTION("in a close-up camera looking at the cube") {
    render::Camera camera;
    camera.target = p_WO;
    camera.eye = p_WO + Eigen::Vector3d(-0.3, -0.35, 0.35);
    camera.width = 320;
    camera.height = 240;
    const render::Image image = dut.render(home, camera);
    const Eigen::Vector2d pixel = render::project(camera, p_WO);
    CHECK(pixel.isApprox(Eigen::Vector2d(160.0, 120.0), 1e-9));  // the target is the image centre
    CHECK(countInWindow(image, pixel, 4, reddish) == 81);
  }
}

TEST_CASE("The same scene renders byte-identically", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  const render::SceneState home = render::sceneAtHome(*world, *robots);
  const render::Camera oblique = render::cameraPreset(*world, "oblique", 640, 480);
  const render::Camera top = render::cameraPreset(*world, "top", 320, 240);
  const std::vector<render::Overlay> overlays{render::textOverlay("t = 1.00 s"),
                                              render::markerOverlay(world->objects[0].X_WO.translation(), "slip")};

  render::SceneRenderer dut(*world, *robots);
  const render::Image first = dut.render(home, oblique, overlays);
  const render::Image other = dut.render(home, top);  // another size and view in between
  const render::Image second = dut.render(home, oblique, overlays);
  CHECK(first == second);
  CHECK(other.width == 320);

  render::SceneRenderer another(*world, *robots);
  CHECK(another.render(home, oblique, overlays) == first);

  // renderers share nothing: two threads, each with its own renderer, get the same bytes
  render::Image from_thread_a, from_thread_b;
  std::thread a([&] {
    render::SceneRenderer renderer(*world, *robots);
    from_thread_a = renderer.render(home, oblique, overlays);
  });
  std::thread b([&] {
    render::SceneRenderer renderer(*world, *robots);
    from_thread_b = renderer.render(home, oblique, overlays);
  });
  a.join();
  b.join();
  CHECK(from_thread_a == first);
  CHECK(from_thread_b == first);
}

TEST_CASE("A written PNG reads back with the same pixels and bytes", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  render::SceneRenderer renderer(*world, *robots);
  const render::Image image =
      renderer.render(render::sceneAtHome(*world, *robots), render::cameraPreset(*world, "side:r0", 320, 240));
  TempDir dir("png");
  render::writePng(image, dir.path / "a.png");
  render::writePng(image, dir.path / "b.png");
  CHECK(render::readPng(dir.path / "a.png") == image);
  CHECK(readFileBytes(dir.path / "a.png") == readFileBytes(dir.path / "b.png"));

  CHECK_THROWS_WITH(render::readPng(dir.path / "missing.png"), Catch::Contains("missing.png"));
  std::ofstream(dir.path / "text.png") << "not a png";
  CHECK_THROWS_WITH(render::readPng(dir.path / "text.png"), Catch::Contains("not a PNG file"));
  CHECK_THROWS_WITH(render::writePng(image, dir.path / "no_such_dir" / "x.png"), Catch::Contains("cannot open"));
}

TEST_CASE("project() is the pinhole model the renderer draws with", "[render]") {
  render::Camera camera;
  camera.eye = {0.0, -2.0, 0.0};
  camera.target = {0.0, 0.0, 0.0};
  camera.up = {0.0, 0.0, 1.0};
  camera.fov_deg = 90.0;
  camera.width = 200;
  camera.height = 100;
  // tan(45 deg) = 1: at depth 2 the image spans z in [-2, 2] and x in [-4, 4]
  CHECK(render::project(camera, {0.0, 0.0, 0.0}).isApprox(Eigen::Vector2d(100.0, 50.0)));
  CHECK(render::project(camera, {2.0, 0.0, 0.0}).isApprox(Eigen::Vector2d(150.0, 50.0)));
  CHECK(render::project(camera, {0.0, 0.0, 1.0}).isApprox(Eigen::Vector2d(100.0, 25.0)));
  CHECK(render::project(camera, {-1.0, 2.0, -1.0}).isApprox(Eigen::Vector2d(87.5, 62.5)));
  CHECK(render::depthInCamera(camera, {5.0, 1.0, 3.0}) == Approx(3.0));
  CHECK(render::depthInCamera(camera, {0.0, -3.0, 0.0}) < 0.0);

  // the view and projection matrices give the same pixel
  const Eigen::Vector4d clip = render::projectionMatrix(camera, 0.1, 10.0) * render::viewMatrix(camera) *
                               Eigen::Vector4d(-1.0, 2.0, -1.0, 1.0);
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  CHECK(Eigen::Vector2d(0.5 * (ndc.x() + 1.0) * 200, 0.5 * (1.0 - ndc.y()) * 100).isApprox(Eigen::Vector2d(87.5, 62.5)));
}

TEST_CASE("Camera presets frame the whole world", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  const Eigen::AlignedBox3d bounds = render::worldBounds(*world);
  for (const char* preset : {"oblique", "front", "top"}) {
    INFO("preset " << preset);
    const render::Camera camera = render::cameraPreset(*world, preset, 640, 480);
    REQUIRE_NOTHROW(render::validateCamera(camera));
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p = bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
      REQUIRE(render::depthInCamera(camera, p) > 0.0);
      const Eigen::Vector2d pixel = render::project(camera, p);
      CHECK(pixel.x() >= 0.0);
      CHECK(pixel.x() <= 640.0);
      CHECK(pixel.y() >= 0.0);
      CHECK(pixel.y() <= 480.0);
    }
  }
  // the side view looks over the robot's shoulder at the space in front of it (+x of its base)
  const core::RobotSpec& r1 = *world->findRobot("r1");
  const render::Camera side = render::cameraPreset(*world, "side:r1", 640, 480);
  CHECK((side.target - side.eye).dot(r1.X_WBase.linear().col(0)) > 0.0);
  CHECK(render::depthInCamera(side, r1.X_WBase.translation()) > 0.0);

  // in a shelving world the oblique view looks into the shelf's open side (-x of the shelf)
  const core::LoadedWorld shelving = core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/shelf_2r_4o.yaml");
  const core::FixtureSpec& shelf = *shelving.world->findFixture("shelf");
  const render::Camera into_shelf = render::cameraPreset(*shelving.world, "oblique", 640, 480);
  CHECK((into_shelf.eye - shelf.X_WF.translation()).dot(shelf.X_WF.linear().col(0)) < 0.0);
  const render::Camera on_table = render::cameraPreset(*world, "oblique", 640, 480);
  CHECK(on_table.eye.x() > on_table.target.x());  // the default world: from the front right

  CHECK_THROWS_WITH(render::cameraPreset(*world, "side:r7"), Catch::Contains("side:r0") && Catch::Contains("side:r7"));
  CHECK_THROWS_AS(render::cameraPreset(*world, "isometric"), std::invalid_argument);
  CHECK_THROWS_AS(render::cameraPreset(*world, "top", 0, 480), std::invalid_argument);
}

TEST_CASE("Bad cameras, scene states and settings are rejected with a message", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  render::Camera camera = render::cameraPreset(*world, "oblique", 64, 48);
  render::Camera bad = camera;
  bad.fov_deg = 0.0;
  CHECK_THROWS_WITH(render::validateCamera(bad), Catch::Contains("fov_deg"));
  bad = camera;
  bad.target = bad.eye;
  CHECK_THROWS_WITH(render::validateCamera(bad), Catch::Contains("coincide"));
  bad = camera;
  bad.up = bad.target - bad.eye;
  CHECK_THROWS_WITH(render::validateCamera(bad), Catch::Contains("parallel"));

  render::SceneRenderer dut(*world, *robots);
  render::SceneState state = render::sceneAtHome(*world, *robots);
  bad = camera;
  bad.width = -1;
  CHECK_THROWS_AS(dut.render(state, bad), std::invalid_argument);
  state.object_poses.pop_back();
  CHECK_THROWS_WITH(dut.render(state, camera), Catch::Contains("objects"));
  state = render::sceneAtHome(*world, *robots);
  state.link_poses[1].pop_back();
  CHECK_THROWS_WITH(dut.render(state, camera), Catch::Contains("robot 1"));

  render::RenderSettings settings;
  settings.msaa_samples = 3;
  CHECK_THROWS_WITH(render::SceneRenderer(*world, *robots, settings), Catch::Contains("msaa_samples"));
  CHECK_THROWS_AS(render::sceneFromConfigurations(*world, *robots, {}, {}), std::invalid_argument);
}

TEST_CASE("Overlays draw text at the top left and a ring around a marked point", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  render::SceneRenderer dut(*world, *robots);
  const render::SceneState home = render::sceneAtHome(*world, *robots);
  const render::Camera camera = render::cameraPreset(*world, "oblique", 640, 480);
  const Eigen::Vector3d p_W = world->objects[2].X_WO.translation();
  const render::Image plain = dut.render(home, camera);
  const render::Image marked =
      dut.render(home, camera, {render::textOverlay("t = 0.50 s"), render::markerOverlay(p_W, "grasp slip")});

  // the first glyph 't' lights the pixels of its stem (column 1, rows 0-5, scale 2) at (6, 6)
  const Rgb stem = pixelAt(marked, 6 + 2 * 1, 6 + 2 * 2);
  CHECK((stem.r == 255 && stem.g == 255 && stem.b == 255));

  // four points of the ring (radius 14 px) are marker red; the centre is untouched
  const Eigen::Vector2d c = render::project(camera, p_W);
  for (const Eigen::Vector2d& offset : {Eigen::Vector2d(14, 0), Eigen::Vector2d(-14, 0), Eigen::Vector2d(0, 14),
                                        Eigen::Vector2d(0, -14)}) {
    const Eigen::Vector2d q = c + offset;
    const Rgb ring = pixelAt(marked, static_cast<int>(q.x()), static_cast<int>(q.y()));
    CHECK((ring.r == 230 && ring.g == 13 && ring.b == 13));
  }
  const int cx = static_cast<int>(c.x()), cy = static_cast<int>(c.y());
  CHECK(std::equal(plain.pixel(cx, cy), plain.pixel(cx, cy) + 3, marked.pixel(cx, cy)));

  // a marker behind the camera stays in the image (pinned to the bottom edge)
  render::Image image = render::Image::filled(100, 80, 50, 50, 50);
  render::drawOverlays(image, camera, {render::markerOverlay(camera.eye - (camera.target - camera.eye), "")});
  int red = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) red += pixelAt(image, x, y).r == 230 ? 1 : 0;
  }
  CHECK(red > 50);
}

TEST_CASE("Video: 30 frames make an MP4 of 30 frames", "[render][video]") {
  INFO("ffmpeg and ffprobe are part of the set-up (tools/setup.sh installs them)");
  REQUIRE(render::ffmpegAvailable());
  const auto& [world, robots, reach] = defaultWorld();
  render::SceneRenderer renderer(*world, *robots);
  const render::Camera camera = render::cameraPreset(*world, "oblique", 320, 240);
  TempDir dir("video");
  const std::filesystem::path mp4 = dir.path / "out.mp4";
  render::VideoWriter dut(mp4, 320, 240, 30.0);
  std::vector<Eigen::VectorXd> q;
  for (const core::PlacedRobot& robot : robots->robots()) {
    Eigen::VectorXd q_robot = Eigen::VectorXd::Zero(robot.model->numPositions());
    for (int i = 0; i < 6; ++i) q_robot[i] = robot.spec->home[i];
    q.push_back(q_robot);
  }
  std::vector<core::Pose> X_WO;
  for (const core::ObjectSpec& object : world->objects) X_WO.push_back(object.X_WO);
  for (int k = 0; k < 30; ++k) {
    for (Eigen::VectorXd& q_robot : q) q_robot[0] += 0.02;
    dut.add(renderer.render(render::sceneFromConfigurations(*world, *robots, q, X_WO, k / 30.0), camera));
  }
  dut.finish();
  CHECK(dut.frameCount() == 30);
  REQUIRE(std::filesystem::exists(mp4));
  CHECK(std::filesystem::file_size(mp4) > 1000);
  CHECK_THROWS_AS(dut.add(render::Image::filled(320, 240)), std::runtime_error);  // after finish
  CHECK_THROWS_AS(render::VideoWriter(dir.path / "odd.mp4", 321, 240, 30.0), std::invalid_argument);

  REQUIRE(render::ffprobeAvailable());
  const std::string frames =
      capture("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 '" +
              mp4.string() + "'");
  CHECK(std::stoi(frames) == 30);
}

TEST_CASE("Video: a missing ffmpeg or a failing ffmpeg is a clear error", "[render][video]") {
  TempDir dir("noffmpeg");
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path ? old_path : "";
  ::setenv("PATH", dir.path.c_str(), 1);
  CHECK_THROWS_WITH(render::VideoWriter(dir.path / "x.mp4", 64, 48, 30.0), Catch::Contains("ffmpeg is not on PATH"));
  CHECK_FALSE(render::ffmpegAvailable());
  ::setenv("PATH", saved.c_str(), 1);

  // ffmpeg cannot create a file in a folder that does not exist: finish() reports its message
  REQUIRE(render::ffmpegAvailable());
  render::VideoWriter writer(dir.path / "missing" / "x.mp4", 64, 48, 30.0);
  bool threw = false;
  try {
    for (int k = 0; k < 5; ++k) writer.add(render::Image::filled(64, 48, 10, 20, 30));
    writer.finish();
  } catch (const std::runtime_error& e) {
    threw = true;
    CHECK_THAT(e.what(), Catch::Contains("ffmpeg") && Catch::Contains("x.mp4"));
  }
  CHECK(threw);
}

TEST_CASE("FrameRecorder writes one frame per 1/fps of plan time", "[render]") {
  const auto& [world, robots, reach] = defaultWorld();
  TempDir dir("recorder");
  render::RecorderSettings settings;
  settings.fps = 30.0;
  settings.width = 160;
  settings.height = 120;
  settings.out_dir = dir.path / "frames";
  int overlay_calls = 0;
  settings.overlays = [&](const sim::Simulation&, double) {
    ++overlay_calls;
    return std::vector<render::Overlay>{render::textOverlay("pick r0 cube_0")};
  };
  render::FrameRecorder dut(*world, *robots, settings);
  sim::Simulation simulation(*world, *robots);
  dut.onStep(simulation, -0.2);  // settle pre-roll: ignored
  CHECK(dut.framesWritten() == 0);
  // 0.1 s of plan time at 1 kHz: frames at 0, 1/30, 2/30 and 3/30 s
  for (int step = 0; step < 100; ++step) {
    simulation.step();
    dut.onStep(simulation, (step + 1) * simulation.timeStep());
  }
  dut.finish();
  CHECK(dut.framesWritten() == 4);
  CHECK(overlay_calls == 4);
  for (int k = 0; k < 4; ++k) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%06d.png", k);
    CHECK(std::filesystem::exists(*settings.out_dir / name));
  }
  CHECK_FALSE(std::filesystem::exists(*settings.out_dir / "frame_000004.png"));
  CHECK(render::readPng(*settings.out_dir / "frame_000003.png") == dut.lastFrame());

  // a step longer than a frame repeats the frame, keeping simulated time
  render::RecorderSettings coarse = settings;
  coarse.out_dir = dir.path / "coarse";
  coarse.overlays = nullptr;
  render::FrameRecorder repeated(*world, *robots, coarse);
  repeated.onStep(simulation, 0.0);
  repeated.onStep(simulation, 0.2);  // frames 1..6
  CHECK(repeated.framesWritten() == 7);

  // a time window: frames 2 and 3 only (1/15 s and 0.1 s), named by their index
  render::RecorderSettings window = settings;
  window.out_dir = dir.path / "window";
  window.overlays = nullptr;
  window.from = 0.05;
  window.until = 0.1;
  render::FrameRecorder windowed(*world, *robots, window);
  for (int step = 0; step <= 200; ++step) windowed.onStep(simulation, step * 0.001);
  CHECK(windowed.framesWritten() == 2);
  CHECK_FALSE(std::filesystem::exists(*window.out_dir / "frame_000001.png"));
  CHECK(std::filesystem::exists(*window.out_dir / "frame_000002.png"));
  CHECK(std::filesystem::exists(*window.out_dir / "frame_000003.png"));
  CHECK_FALSE(std::filesystem::exists(*window.out_dir / "frame_000004.png"));

  render::RecorderSettings bad = settings;
  bad.fps = 0.0;
  CHECK_THROWS_WITH(render::FrameRecorder(*world, *robots, bad), Catch::Contains("fps"));
  bad = settings;
  bad.from = 2.0;
  bad.until = 1.0;
  CHECK_THROWS_WITH(render::FrameRecorder(*world, *robots, bad), Catch::Contains("time window"));
}
