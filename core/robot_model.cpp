#include "core/robot_model.h"

#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

#include <urdf_parser/urdf_parser.h>

namespace dashbed::core {
namespace {

Pose toPose(const urdf::Pose& p) {
  Pose X = Pose::Identity();
  X.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  X.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  return X;
}

std::runtime_error urdfError(const std::filesystem::path& file, const std::string& what) {
  return std::runtime_error(file.string() + ": " + what);
}

CollisionShape toShape(const std::filesystem::path& file, const std::string& link,
                       const urdf::Collision& c) {
  CollisionShape shape;
  shape.name = c.name;
  shape.X_LS = toPose(c.origin);
  if (!c.geometry) throw urdfError(file, "link '" + link + "': collision without geometry");
  switch (c.geometry->type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(*c.geometry);
      shape.type = ShapeType::kBox;
      shape.size = {b.dim.x, b.dim.y, b.dim.z};
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cy = static_cast<const urdf::Cylinder&>(*c.geometry);
      shape.type = ShapeType::kCylinder;
      shape.size = {cy.radius, cy.radius, cy.length};
      break;
    }
    case urdf::Geometry::SPHERE: {
      const auto& s = static_cast<const urdf::Sphere&>(*c.geometry);
      shape.type = ShapeType::kSphere;
      shape.size = Eigen::Vector3d::Constant(s.radius);
      break;
    }
    default:
      throw urdfError(file, "link '" + link +
                                "': collision geometry must be a box, cylinder or sphere (convex "
                                "primitives shared by FCL and Bullet)");
  }
  return shape;
}

VisualMesh toVisual(const std::filesystem::path& file, const std::string& link,
                    const urdf::Visual& v) {
  if (!v.geometry || v.geometry->type != urdf::Geometry::MESH) {
    throw urdfError(file, "link '" + link + "': visual geometry must be a mesh");
  }
  const auto& m = static_cast<const urdf::Mesh&>(*v.geometry);
  VisualMesh visual;
  visual.file = file.parent_path() / m.filename;
  visual.X_LV = toPose(v.origin);
  visual.scale = {m.scale.x, m.scale.y, m.scale.z};
  if (v.material) {
    const auto& c = v.material->color;
    visual.rgba = {c.r, c.g, c.b, c.a};
  }
  return visual;
}

}  // namespace

RobotModel RobotModel::fromUrdfFile(const std::filesystem::path& urdf_file) {
  std::ifstream in(urdf_file);
  if (!in) throw urdfError(urdf_file, "cannot read the robot description");
  std::stringstream text;
  text << in.rdbuf();
  const urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(text.str());
  if (!urdf) throw urdfError(urdf_file, "not a valid URDF (urdfdom could not parse it)");
  const urdf::LinkConstSharedPtr root = urdf->getRoot();
  if (!root) throw urdfError(urdf_file, "URDF has no root link");

  RobotModel model;
  model.name_ = urdf->getName();
  // depth-first from the root, children in URDF order: a deterministic topological order
  std::function<void(const urdf::Link&, int)> visit = [&](const urdf::Link& link, int parent_joint) {
    const int link_index = static_cast<int>(model.links_.size());
    LinkModel lm;
    lm.name = link.name;
    lm.parent_joint = parent_joint;
    if (link.inertial) {
      lm.mass = link.inertial->mass;
      lm.X_LCom = toPose(link.inertial->origin);
      const auto& i = *link.inertial;
      lm.inertia << i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz;
    }
    for (const auto& c : link.collision_array) lm.collisions.push_back(toShape(urdf_file, link.name, *c));
    for (const auto& v : link.visual_array) lm.visuals.push_back(toVisual(urdf_file, link.name, *v));
    model.links_.push_back(std::move(lm));
    if (parent_joint >= 0) model.joints_[parent_joint].child_link = link_index;

    for (const auto& child_joint : link.child_joints) {
      JointModel jm;
      jm.name = child_joint->name;
      jm.parent_link = link_index;
      jm.X_PJ = toPose(child_joint->parent_to_joint_origin_transform);
      jm.axis = Eigen::Vector3d(child_joint->axis.x, child_joint->axis.y, child_joint->axis.z);
      switch (child_joint->type) {
        case urdf::Joint::FIXED: jm.type = JointType::kFixed; break;
        case urdf::Joint::REVOLUTE: jm.type = JointType::kRevolute; break;
        case urdf::Joint::PRISMATIC: jm.type = JointType::kPrismatic; break;
        default:
          throw urdfError(urdf_file, "joint '" + jm.name +
                                         "': only fixed, revolute and prismatic joints are supported");
      }
      if (jm.type != JointType::kFixed) {
        if (!child_joint->limits) throw urdfError(urdf_file, "joint '" + jm.name + "' has no <limit>");
        if (jm.axis.norm() < 1e-9) throw urdfError(urdf_file, "joint '" + jm.name + "' has a zero axis");
        jm.axis.normalize();
        jm.lower = child_joint->limits->lower;
        jm.upper = child_joint->limits->upper;
        jm.max_velocity = child_joint->limits->velocity;
        jm.max_effort = child_joint->limits->effort;
      }
      const int joint_index = static_cast<int>(model.joints_.size());
      model.joints_.push_back(jm);
      const urdf::LinkConstSharedPtr child = urdf->getLink(child_joint->child_link_name);
      if (!child) throw urdfError(urdf_file, "joint '" + jm.name + "' names a missing child link");
      visit(*child, joint_index);
    }
  };
  visit(*root, -1);

  for (const auto& link : model.links_) {
    if (link.parent_joint < 0) continue;
    const JointModel& j = model.joints_[link.parent_joint];
    if (j.type != JointType::kFixed) {
      model.joints_[link.parent_joint].q_index = static_cast<int>(model.movable_joints_.size());
      model.movable_joints_.push_back(link.parent_joint);
    }
  }
  return model;
}

int RobotModel::linkIndex(std::string_view name) const {
  for (std::size_t i = 0; i < links_.size(); ++i) {
    if (links_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int RobotModel::jointIndex(std::string_view name) const {
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    if (joints_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int RobotModel::requireLink(std::string_view name) const {
  const int index = linkIndex(name);
  if (index < 0) throw std::out_of_range("robot model '" + name_ + "' has no link '" + std::string(name) + "'");
  return index;
}

Pose RobotModel::fixedTransform(int ancestor, int descendant) const {
  Pose X = Pose::Identity();
  int link = descendant;
  while (link != ancestor) {
    const int joint = links_.at(link).parent_joint;
    if (joint < 0) throw std::invalid_argument("fixedTransform: link is not a descendant");
    const JointModel& j = joints_[joint];
    if (j.type != JointType::kFixed) {
      throw std::invalid_argument("fixedTransform: movable joint '" + j.name + "' in between");
    }
    X = j.X_PJ * X;
    link = j.parent_link;
  }
  return X;
}

}  // namespace dashbed::core
