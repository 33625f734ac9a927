// dashbed_gen_meshes: builds the visual meshes of assets/ur5e_hande.urdf procedurally and
// writes them as Wavefront OBJ.
//
//   usage: dashbed_gen_meshes OUTPUT_DIR      (normally assets/meshes)
//
// Writes OUTPUT_DIR/ur5e/*.obj and OUTPUT_DIR/hande/*.obj. Every mesh is in the frame of the
// link that shows it, so the URDF visuals need identity origins. The shapes follow the
// collision primitives of the URDF (same radii and extents, see the constants below) and add
// what makes the robot recognisable: rounded joint housings with dark end caps and light-blue
// bands, the tool flange, the Hand-E's rounded body, fingers and pads. Output is
// deterministic (fixed precision, no dates), so regenerating gives the same bytes.

#include "tools/meshgen/mesh.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <numbers>
#include <string>
#include <string_view>

namespace dashbed::meshgen {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSegments = 32;     // facets around a housing or tube
constexpr int kArcSteps = 3;      // facets per rounded edge

// Housing ends: a dark cap (kCapHeight, with a rounded rim of radius kCapFillet) behind a
// light-blue band (kBandHeight), as on the e-Series joints.
constexpr double kCapHeight = 0.007;
constexpr double kCapFillet = 0.004;
constexpr double kBandHeight = 0.006;
constexpr double kChamfer = 0.0015;  // plain housing ends

/// The three materials of an arm link; the URDF gives each its own <visual>.
struct ArmLinkMeshes {
  Mesh body;  ///< light grey-blue
  Mesh cap;   ///< dark grey
  Mesh ring;  ///< light blue
  Mesh metal; ///< bare aluminium (the tool flange)
};

enum class End {
  kHidden,  ///< flat, inside another housing
  kPlain,   ///< flat with a small chamfer (a seam between two housings)
  kCap,     ///< dark cap with a blue band
};

/// A cylindrical joint housing of radius `radius` along the z axis of X_LH, from z0 to z1.
void addHousing(ArmLinkMeshes& out, const Eigen::Isometry3d& X_LH, double radius, double z0,
                double z1, End bottom, End top) {
  const double R = radius;
  const double f = kCapFillet;
  std::vector<ProfilePatch> body;
  double side0 = z0;
  double side1 = z1;

  switch (bottom) {
    case End::kHidden:
      body.push_back(segment(0.0, z0, R, z0));
      break;
    case End::kPlain:
      body.push_back(segment(0.0, z0, R - kChamfer, z0));
      body.push_back(segment(R - kChamfer, z0, R, z0 + kChamfer));
      side0 = z0 + kChamfer;
      break;
    case End::kCap:
      addLathe(out.cap, X_LH,
               {segment(0.0, z0, R - f, z0), arc(R - f, z0 + f, f, -kPi / 2.0, 0.0, kArcSteps),
                segment(R, z0 + f, R, z0 + kCapHeight)},
               kSegments);
      addLathe(out.ring, X_LH, {segment(R, z0 + kCapHeight, R, z0 + kCapHeight + kBandHeight)},
               kSegments);
      side0 = z0 + kCapHeight + kBandHeight;
      break;
  }
  switch (top) {
    case End::kHidden:
    case End::kPlain:
      side1 = top == End::kPlain ? z1 - kChamfer : z1;
      break;
    case End::kCap:
      addLathe(out.ring, X_LH, {segment(R, z1 - kCapHeight - kBandHeight, R, z1 - kCapHeight)},
               kSegments);
      addLathe(out.cap, X_LH,
               {segment(R, z1 - kCapHeight, R, z1 - f), arc(R - f, z1 - f, f, 0.0, kPi / 2.0, kArcSteps),
                segment(R - f, z1, 0.0, z1)},
               kSegments);
      side1 = z1 - kCapHeight - kBandHeight;
      break;
  }
  body.push_back(segment(R, side0, R, side1));
  if (top == End::kPlain) {
    body.push_back(segment(R, side1, R - kChamfer, z1));
    body.push_back(segment(R - kChamfer, z1, 0.0, z1));
  } else if (top == End::kHidden) {
    body.push_back(segment(R, z1, 0.0, z1));
  }
  addLathe(out.body, X_LH, body, kSegments);
}

/// A plain cylinder (tube) of radius `radius` along the z axis of X_LT, from z0 to z1, flat ends.
void addTube(Mesh& out, const Eigen::Isometry3d& X_LT, double radius, double z0, double z1) {
  addLathe(out, X_LT,
           {segment(0.0, z0, radius, z0), segment(radius, z0, radius, z1),
            segment(radius, z1, 0.0, z1)},
           kSegments);
}

const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();
const Eigen::Vector3d kY = Eigen::Vector3d::UnitY();
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// --- UR5e --------------------------------------------------------------------------------
// Radii from the approximate link radii of UR's ROS 2 description
// (github.com/UniversalRobots/Universal_Robots_ROS2_Description); extents match the URDF
// collision primitives. Lengths from UR's DH-parameters page (universal-robots.com).
constexpr double kShoulderRadius = 0.060;
constexpr double kUpperArmRadius = 0.054;
constexpr double kElbowRadius = 0.060;
constexpr double kForearmRadius = 0.040;
constexpr double kWristRadius = 0.045;
constexpr double kUpperArmOffset = 0.138;   // lateral offset of the upper-arm tube (UR ROS 2)
constexpr double kForearmTubeZ = 0.020;     // forearm tube height above the elbow frame
constexpr double kUpperArmLength = 0.425;   // UR DH a2
constexpr double kForearmLength = 0.3922;   // UR DH a3
constexpr double kWrist1Offset = 0.1333;    // UR DH d4
constexpr double kWrist2Offset = 0.0997;    // UR DH d5
constexpr double kWrist3Offset = 0.0996;    // UR DH d6
constexpr double kWrist3BodyDepth = 0.020;  // wrist_3 body behind the flange face
constexpr double kFlangeRadius = 0.0315;    // 63 mm tool flange
constexpr double kFlangeDepth = 0.006;

ArmLinkMeshes base() {
  ArmLinkMeshes m;
  // mounting plate (r 0.076) with a chamfered rim, then the base joint housing
  addLathe(m.body, Eigen::Isometry3d::Identity(),
           {segment(0.0, 0.0, 0.076, 0.0), segment(0.076, 0.0, 0.076, 0.008),
            segment(0.076, 0.008, 0.072, 0.012), segment(0.072, 0.012, 0.0, 0.012)},
           kSegments);
  addHousing(m, Eigen::Isometry3d::Identity(), 0.066, 0.012, 0.090, End::kHidden, End::kCap);
  return m;
}

ArmLinkMeshes shoulder() {
  ArmLinkMeshes m;
  addHousing(m, Eigen::Isometry3d::Identity(), kShoulderRadius, -0.070, 0.070, End::kPlain,
             End::kCap);
  return m;
}

ArmLinkMeshes upperArm() {
  ArmLinkMeshes m;
  // lift housing: starts on the lift axis so it merges into the shoulder like a pipe tee
  addHousing(m, Eigen::Isometry3d::Identity(), kShoulderRadius, 0.0, 0.200, End::kHidden,
             End::kCap);
  addTube(m.body, axisFrame(Eigen::Vector3d(0.0, 0.0, kUpperArmOffset), -kX), kUpperArmRadius,
          0.010, kUpperArmLength - 0.010);
  addHousing(m, axisFrame(Eigen::Vector3d(-kUpperArmLength, 0.0, 0.0), kZ), kElbowRadius, 0.062,
             0.200, End::kPlain, End::kCap);
  return m;
}

ArmLinkMeshes forearm() {
  ArmLinkMeshes m;
  addHousing(m, Eigen::Isometry3d::Identity(), kElbowRadius, -0.030, 0.060, End::kCap,
             End::kPlain);
  addTube(m.body, axisFrame(Eigen::Vector3d(0.0, 0.0, kForearmTubeZ), -kX), kForearmRadius, 0.020,
          kForearmLength - 0.010);
  // wrist 1 housing: runs up to the wrist_1 axis, inside the wrist_1 housing
  addHousing(m, axisFrame(Eigen::Vector3d(-kForearmLength, 0.0, 0.0), kZ), kWristRadius, -0.025,
             kWrist1Offset, End::kCap, End::kHidden);
  return m;
}

ArmLinkMeshes wrist1() {
  ArmLinkMeshes m;
  // wrist 2 housing along y; its far end reaches the wrist_2 axis inside the next housing
  addHousing(m, axisFrame(Eigen::Vector3d::Zero(), kY), kWristRadius, -kWrist2Offset, 0.045,
             End::kHidden, End::kCap);
  return m;
}

ArmLinkMeshes wrist2() {
  ArmLinkMeshes m;
  // wrist 3 housing along y, from its cap to the rotating wrist_3 body
  addHousing(m, axisFrame(Eigen::Vector3d::Zero(), kY), kWristRadius, -0.045,
             kWrist3Offset - kWrist3BodyDepth, End::kCap, End::kPlain);
  return m;
}

ArmLinkMeshes wrist3() {
  ArmLinkMeshes m;
  const double R = kWristRadius;
  const double zb = -kWrist3BodyDepth;
  const double zf = -kFlangeDepth;
  // rotating body behind the flange: blue band, then the grey body rounded towards the flange
  addLathe(m.ring, Eigen::Isometry3d::Identity(),
           {segment(0.0, zb, R - kChamfer, zb), segment(R - kChamfer, zb, R, zb + kChamfer),
            segment(R, zb + kChamfer, R, zb + 0.005)},
           kSegments);
  addLathe(m.body, Eigen::Isometry3d::Identity(),
           {segment(R, zb + 0.005, R, zf - 0.004),
            arc(R - 0.004, zf - 0.004, 0.004, 0.0, kPi / 2.0, kArcSteps),
            segment(R - 0.004, zf, kFlangeRadius, zf)},
           kSegments);
  // tool flange (ISO 9409-1-50-4-M6 size), metal
  addLathe(m.metal, Eigen::Isometry3d::Identity(),
           {segment(kFlangeRadius, zf, kFlangeRadius, -0.0008),
            segment(kFlangeRadius, -0.0008, kFlangeRadius - 0.0008, 0.0),
            segment(kFlangeRadius - 0.0008, 0.0, 0.0, 0.0)},
           kSegments);
  return m;
}

// --- Robotiq Hand-E ----------------------------------------------------------------------
// Sources: "AGH", AGH-CEAI's Hand-E description (github.com/AGH-CEAI/robotiq_hande_description),
// and "Robotiq", Robotiq's Hand-E Isaac Sim assets (github.com/robotiq/isaacsim_assets).
constexpr double kCouplingRadius = 0.0375;  // AGH
constexpr double kCouplingHeight = 0.011;   // AGH
constexpr double kBodyHalfWidth = 0.0375;   // 75 mm envelope (Robotiq)
constexpr double kHousingFaceZ = 0.0861;    // Robotiq
constexpr double kBodyCornerRadius = 0.008;

Mesh coupling() {
  Mesh m;
  const double R = kCouplingRadius;
  const double h = kCouplingHeight;
  const double c = 0.001;
  addLathe(m, Eigen::Isometry3d::Identity(),
           {segment(0.0, 0.0, R - c, 0.0), segment(R - c, 0.0, R, c), segment(R, c, R, h - c),
            segment(R, h - c, R - c, h), segment(R - c, h, 0.0, h)},
           kSegments);
  return m;
}

/// Hand-E housing: a 75 x 75 mm block with rounded vertical edges and chamfered ends.
Mesh handeBody() {
  Mesh m;
  const double core = kBodyHalfWidth - kBodyCornerRadius;
  const double r = kBodyCornerRadius;
  const double top = kHousingFaceZ;
  addSweep(m, Eigen::Isometry3d::Identity(), roundedRectCore(core, core, 4),
           {segment(0.0, 0.0, r - 0.001, 0.0), segment(r - 0.001, 0.0, r, 0.001),
            segment(r, 0.001, r, top - 0.0025), segment(r, top - 0.0025, r - 0.0025, top),
            segment(r - 0.0025, top, 0.0, top)});
  return m;
}

/// Dark details on the housing: the finger slot in the front face.
Mesh handeSlot() {
  Mesh m;
  addBox(m, Eigen::Vector3d(-0.031, -0.0155, kHousingFaceZ - 0.0005),
         Eigen::Vector3d(0.031, 0.0155, kHousingFaceZ + 0.0002));
  return m;
}

// Finger geometry in the finger frame (pad face = plane x = 0, body at x >= 0); identical to
// the URDF collision boxes except for the chamfered outer tip.
constexpr double kPadThickness = 0.002;
constexpr double kFingerThickness = 0.0174;  // Robotiq standard tip
constexpr double kFingerHalfWidth = 0.0146;  // Robotiq: 29.2 mm wide
constexpr double kFingerBottom = -0.0147;    // reaches into the housing slot
constexpr double kFingerTip = 0.0465;        // AGH: tip end 46.5 mm above the finger joint

Mesh finger() {
  Mesh m;
  // outline in the finger's x-z plane, extruded across y
  Eigen::Isometry3d X_FP = Eigen::Isometry3d::Identity();
  X_FP.linear() << 1, 0, 0,  //
      0, 0, -1,              //
      0, 1, 0;
  addPrism(m, X_FP,
           polygonOutline({{kPadThickness, kFingerBottom},
                           {kFingerThickness, kFingerBottom},
                           {kFingerThickness, kFingerTip - 0.007},
                           {kFingerThickness - 0.005, kFingerTip},
                           {kPadThickness, kFingerTip}}),
           -kFingerHalfWidth, kFingerHalfWidth);
  return m;
}

Mesh pad() {
  Mesh m;
  addBox(m, Eigen::Vector3d(0.0, -0.011, 0.0215), Eigen::Vector3d(kPadThickness, 0.011, 0.0465));
  return m;
}

/// Writes one mesh and reports its size.
std::size_t write(const Mesh& mesh, const std::filesystem::path& dir, const std::string& name) {
  writeObj(mesh, dir / (name + ".obj"), name);
  std::printf("%-24s %6zu triangles\n", (dir.filename().string() + "/" + name).c_str(),
              mesh.triangles.size());
  return mesh.triangles.size();
}

std::size_t writeArmLink(const ArmLinkMeshes& m, const std::filesystem::path& dir,
                         const std::string& name) {
  std::size_t n = write(m.body, dir, name);
  if (!m.cap.triangles.empty()) n += write(m.cap, dir, name + "_cap");
  if (!m.ring.triangles.empty()) n += write(m.ring, dir, name + "_ring");
  if (!m.metal.triangles.empty()) n += write(m.metal, dir, name + "_flange");
  return n;
}

int run(const std::filesystem::path& out_dir) {
  const auto ur_dir = out_dir / "ur5e";
  const auto hande_dir = out_dir / "hande";
  std::filesystem::create_directories(ur_dir);
  std::filesystem::create_directories(hande_dir);

  std::size_t total = 0;
  total += writeArmLink(base(), ur_dir, "base");
  total += writeArmLink(shoulder(), ur_dir, "shoulder");
  total += writeArmLink(upperArm(), ur_dir, "upper_arm");
  total += writeArmLink(forearm(), ur_dir, "forearm");
  total += writeArmLink(wrist1(), ur_dir, "wrist_1");
  total += writeArmLink(wrist2(), ur_dir, "wrist_2");
  total += writeArmLink(wrist3(), ur_dir, "wrist_3");
  total += write(coupling(), hande_dir, "coupling");
  total += write(handeBody(), hande_dir, "body");
  total += write(handeSlot(), hande_dir, "slot");
  // both fingers use the same mesh (the right finger frame is yawed pi)
  total += 2 * write(finger(), hande_dir, "finger");
  total += 2 * write(pad(), hande_dir, "pad");
  std::printf("total (fingers counted twice) %zu triangles\n", total);
  return 0;
}

}  // namespace
}  // namespace dashbed::meshgen

int main(int argc, char** argv) {
  // an option such as --help is not taken for a directory to write into
  if (argc != 2 || argv[1][0] == '-') {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR (writes OUTPUT_DIR/ur5e and OUTPUT_DIR/hande)\n",
                 argc > 0 ? argv[0] : "dashbed_gen_meshes");
    return argc == 2 && std::string_view(argv[1]) == "--help" ? 0 : 2;
  }
  try {
    return dashbed::meshgen::run(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dashbed_gen_meshes: %s\n", e.what());
    return 1;
  }
}
