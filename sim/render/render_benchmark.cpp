#include "sim/render/render_benchmark.h"

#include <chrono>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "sim/render/scene_state.h"

namespace dashbed::render {

double benchmarkFps(const core::World& world, const core::RobotSet& robots, int width, int height, int frames,
                    bool with_png, const RenderSettings& settings) {
  SceneRenderer renderer(world, robots, settings);
  const Camera camera = cameraPreset(world, "oblique", width, height);
  const std::filesystem::path png =
      std::filesystem::temp_directory_path() / ("dashbed_bench_" + std::to_string(::getpid()) + ".png");

  std::vector<Eigen::VectorXd> q;
  for (const core::PlacedRobot& robot : robots.robots()) {
    Eigen::VectorXd q_robot = Eigen::VectorXd::Zero(robot.model->numPositions());
    for (int i = 0; i < 6; ++i) q_robot[i] = robot.spec->home[i];
    q.push_back(q_robot);
  }
  std::vector<core::Pose> X_WO;
  for (const core::ObjectSpec& object : world.objects) X_WO.push_back(object.X_WO);

  const auto frame = [&](int k) {
    std::vector<Eigen::VectorXd> q_k = q;
    for (Eigen::VectorXd& q_robot : q_k) q_robot[0] += 0.01 * k;
    const Image image = renderer.render(sceneFromConfigurations(world, robots, q_k, X_WO), camera);
    if (with_png) writePng(image, png);
  };
  frame(0);
  const auto start = std::chrono::steady_clock::now();
  for (int k = 1; k <= frames; ++k) frame(k);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (with_png) std::filesystem::remove(png);
  return frames / seconds;
}

}  // namespace dashbed::render
