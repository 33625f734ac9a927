// Checks of assets/ur5e_hande.urdf as a file: its visual meshes exist and load, its collision
// geometry is convex primitives only, and its inertials are physical and match the published
// masses (UR's DH-parameters page, universal-robots.com; the Hand-E ROS descriptions).

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <urdf_parser/urdf_parser.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kUrdfFile =
    std::filesystem::path(DASHBED_SOURCE_ROOT) / "assets" / "ur5e_hande.urdf";

urdf::ModelInterfaceSharedPtr parseRobot() {
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDFFile(kUrdfFile.string());
  if (!model) FAIL("cannot parse " << kUrdfFile);
  return model;
}

std::vector<urdf::LinkConstSharedPtr> links(const urdf::ModelInterface& model) {
  std::vector<urdf::LinkConstSharedPtr> out;
  for (const auto& [name, link] : model.links_) out.push_back(link);
  return out;
}

bool hasBody(const urdf::Link& link) {
  return !link.visual_array.empty() || !link.collision_array.empty();
}

Eigen::Matrix3d inertiaMatrix(const urdf::Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz,  //
      in.ixy, in.iyy, in.iyz,   //
      in.ixz, in.iyz, in.izz;
  return I;
}

// the links that carry the arm's moving mass (UR links 1..6)
const std::vector<std::string> kArmLinks = {"shoulder_link", "upper_arm_link", "forearm_link",
                                            "wrist_1_link",  "wrist_2_link",   "wrist_3_link"};

}  // namespace

TEST_CASE("robot URDF: every visual is a mesh that exists and loads", "[assets]") {
  const auto dut = parseRobot();
  int visual_count = 0;
  for (const auto& link : links(*dut)) {
    for (const auto& visual : link->visual_array) {
      INFO("link " << link->name);
      REQUIRE(visual->geometry);
      REQUIRE(visual->geometry->type == urdf::Geometry::MESH);
      const auto& mesh = static_cast<const urdf::Mesh&>(*visual->geometry);
      const std::filesystem::path file = kUrdfFile.parent_path() / mesh.filename;
      INFO("mesh " << file);
      CHECK(mesh.filename.find("://") == std::string::npos);  // plain relative paths only
      REQUIRE(std::filesystem::exists(file));

      Assimp::Importer importer;
      const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate);
      REQUIRE(scene != nullptr);
      unsigned faces = 0;
      for (unsigned m = 0; m < scene->mNumMeshes; ++m) faces += scene->mMeshes[m]->mNumFaces;
      CHECK(faces > 0);

      REQUIRE(visual->material);
      CHECK(visual->material->color.a > 0.0f);
      ++visual_count;
    }
  }
  CHECK(visual_count > 0);
}

TEST_CASE("robot URDF: collision geometry is convex primitives only", "[assets]") {
  const auto dut = parseRobot();
  for (const auto& link : links(*dut)) {
    for (const auto& collision : link->collision_array) {
      INFO("link " << link->name);
      REQUIRE(collision->geometry);
      switch (collision->geometry->type) {
        case urdf::Geometry::BOX: {
          const auto& box = static_cast<const urdf::Box&>(*collision->geometry);
          CHECK(box.dim.x > 0.0);
          CHECK(box.dim.y > 0.0);
          CHECK(box.dim.z > 0.0);
          break;
        }
        case urdf::Geometry::CYLINDER: {
          const auto& cylinder = static_cast<const urdf::Cylinder&>(*collision->geometry);
          CHECK(cylinder.radius > 0.0);
          CHECK(cylinder.length > 0.0);
          break;
        }
        case urdf::Geometry::SPHERE:
          CHECK(static_cast<const urdf::Sphere&>(*collision->geometry).radius > 0.0);
          break;
        default:
          FAIL("collision geometry other than box, cylinder or sphere");
      }
    }
  }
}

TEST_CASE("robot URDF: each finger has exactly one collision named pad", "[assets]") {
  const auto dut = parseRobot();
  for (const char* finger : {"hande_left_finger", "hande_right_finger"}) {
    INFO("link " << finger);
    const auto link = dut->getLink(finger);
    REQUIRE(link);
    int pads = 0;
    for (const auto& collision : link->collision_array) pads += collision->name == "pad" ? 1 : 0;
    CHECK(pads == 1);
  }
}

TEST_CASE("robot URDF: links with a body have physical inertials", "[assets]") {
  const auto dut = parseRobot();
  for (const auto& link : links(*dut)) {
    if (!hasBody(*link)) continue;
    INFO("link " << link->name);
    REQUIRE(link->inertial);
    CHECK(link->inertial->mass > 0.0);

    // positive definite, and the principal moments obey the triangle inequality
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertiaMatrix(*link->inertial));
    REQUIRE(solver.info() == Eigen::Success);
    const Eigen::Vector3d moments = solver.eigenvalues();  // ascending
    INFO("principal moments " << moments.transpose());
    CHECK(moments.minCoeff() > 0.0);
    CHECK(moments(0) + moments(1) >= moments(2) * (1.0 - 1e-12));
  }
}

TEST_CASE("robot URDF: masses match the reference", "[assets]") {
  const auto dut = parseRobot();
  auto mass = [&](const std::string& name) {
    const auto link = dut->getLink(name);
    REQUIRE(link);
    REQUIRE(link->inertial);
    return link->inertial->mass;
  };

  // UR per-link masses (UR's DH-parameters page, universal-robots.com) and their sum
  const std::map<std::string, double> ur_masses = {
      {"shoulder_link", 3.761}, {"upper_arm_link", 8.058}, {"forearm_link", 2.846},
      {"wrist_1_link", 1.37},   {"wrist_2_link", 1.3},     {"wrist_3_link", 0.365}};
  double arm = 0.0;
  for (const auto& name : kArmLinks) {
    INFO("link " << name);
    CHECK(mass(name) == Approx(ur_masses.at(name)).margin(1e-12));
    arm += mass(name);
  }
  CHECK(arm == Approx(17.7).margin(1e-9));

  // Hand-E body + two fingers + I/O coupling (Robotiq Hand-E ROS 2 description,
  // github.com/robotiq/ros; AGH-CEAI robotiq_hande_description; cambel/robotiq)
  const double gripper = mass("hande_base") + mass("hande_left_finger") +
                         mass("hande_right_finger") + mass("hande_coupling");
  CHECK(gripper == Approx(1.05895).margin(1e-9));
  CHECK(mass("hande_left_finger") == mass("hande_right_finger"));
}
