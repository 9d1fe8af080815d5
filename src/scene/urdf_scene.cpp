#include "god_finger/scene/urdf_scene.h"

#include "god_finger/scene/deformable_object.h"
#include "god_finger/scene/scene_budget.h"
#include "god_finger/scene/xacro.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/memory_budget.h"

#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace god_finger
{
namespace
{
Eigen::Isometry3d toIsometry(const urdf::Pose& pose)
{
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  result.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                        .normalized()
                        .toRotationMatrix();
  return result;
}

std::string directoryOf(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

bool fileExists(const std::string& path)
{
  std::ifstream stream(path);
  return stream.good();
}

// Without a resolver (no ROS): the folders above `start` whose package.xml names `name`.
std::string findPackageAbove(const std::string& name, const std::string& start)
{
  std::error_code error;
  std::string folder = std::filesystem::absolute(start, error).lexically_normal().string();  // "urdf/lists" too
  while (folder.size() > 1 && folder.back() == '/')
  {
    folder.pop_back();
  }
  for (int level = 0; level < 16 && !folder.empty(); ++level)
  {
    std::ifstream manifest(folder + "/package.xml");
    std::stringstream content;
    content << manifest.rdbuf();
    if (content.str().find("<name>" + name + "</name>") != std::string::npos)
    {
      return folder;
    }
    const std::string parent = directoryOf(folder);
    if (parent == folder || parent == ".")
    {
      break;
    }
    folder = parent;
  }
  return std::string();
}

class SceneParser
{
 public:
  SceneParser(const std::string& source, const std::string& base_directory, const PackageResolver& packages)
      : source_(source), base_directory_(base_directory), packages_(packages)
  {
  }

  [[noreturn]] void fail(const std::string& link, const std::string& problem) const
  {
    throw InputError("URDF '" + source_ + "': " + (link.empty() ? "" : "link '" + link + "': ") + problem);
  }

  void warn(const std::string& link, const std::string& problem) const
  {
    warnings_.push_back("URDF '" + source_ + "': link '" + link + "': " + problem);
  }

  std::string resolveMesh(const std::string& link, const std::string& filename) const
  {
    std::string package;
    const std::string path = resolveFileName(filename, base_directory_, packages_, &package);
    if (path.empty())
    {
      fail(link, "mesh '" + filename + "': ROS package '" + package + "' not found");
    }
    if (!fileExists(path))
    {
      fail(link, "mesh '" + filename + "' not found (looked for '" + path + "')");
    }
    return path;
  }

  // Sizes a scene can hold: a body of a hand's world, between a grain and a room.
  void checkSize(const std::string& link, const std::string& what, double metres) const
  {
    if (metres < kMinBodySize || metres > kMaxBodySize)
    {
      std::ostringstream message;
      message << what << " " << metres << " m is outside the sizes a scene can hold, [" << kMinBodySize << ", "
              << kMaxBodySize << "] m (a unit mix-up? URDF lengths are metres)";
      fail(link, message.str());
    }
  }

  Geometry geometry(const std::string& link, const urdf::GeometrySharedPtr& geometry) const
  {
    Geometry result;
    if (!geometry)
    {
      fail(link, "<collision> has no geometry");
    }
    switch (geometry->type)
    {
      case urdf::Geometry::BOX:
      {
        const auto& box = static_cast<const urdf::Box&>(*geometry);
        result.kind = GeometryKind::kBox;
        result.size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
        if (!(result.size.minCoeff() > 0.0) || !result.size.allFinite())
        {
          fail(link, "box size must be positive and finite");
        }
        checkSize(link, "box size", result.size.maxCoeff());
        checkSize(link, "box size", result.size.minCoeff());
        break;
      }
      case urdf::Geometry::SPHERE:
      {
        result.kind = GeometryKind::kSphere;
        result.radius = static_cast<const urdf::Sphere&>(*geometry).radius;
        if (!(result.radius > 0.0 && std::isfinite(result.radius)))
        {
          fail(link, "sphere radius must be positive and finite");
        }
        checkSize(link, "sphere radius", result.radius);
        break;
      }
      case urdf::Geometry::CYLINDER:
      {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*geometry);
        result.kind = GeometryKind::kCylinder;
        result.radius = cylinder.radius;
        result.length = cylinder.length;
        if (!(result.radius > 0.0 && result.length > 0.0 && std::isfinite(result.radius) &&
              std::isfinite(result.length)))
        {
          fail(link, "cylinder radius and length must be positive and finite");
        }
        checkSize(link, "cylinder radius", result.radius);
        checkSize(link, "cylinder length", result.length);
        break;
      }
      case urdf::Geometry::MESH:
      {
        const auto& mesh = static_cast<const urdf::Mesh&>(*geometry);
        result.kind = GeometryKind::kMesh;
        result.mesh_path = resolveMesh(link, mesh.filename);
        result.scale = Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z);
        if (!(result.scale.cwiseAbs().minCoeff() > 0.0) || !result.scale.allFinite())
        {
          fail(link, "mesh scale must be non-zero and finite");
        }
        break;
      }
    }
    return result;
  }

  // A positive finite mass and a positive-definite inertia: what inertial() accepts.
  static bool usableInertial(const urdf::Link& link)
  {
    if (!link.inertial || !(link.inertial->mass > 0.0 && std::isfinite(link.inertial->mass)))
    {
      return false;
    }
    const urdf::Inertial& i = *link.inertial;
    Eigen::Matrix3d inertia;
    inertia << i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz;
    return inertia.allFinite() &&
           Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues().minCoeff() > 0.0;
  }

  void inertial(const urdf::Link& link, BodyDescription* body) const
  {
    if (!link.inertial)
    {
      fail(link.name, "a floating body needs an <inertial> with mass and inertia");
    }
    const urdf::Inertial& inertial = *link.inertial;
    body->mass = inertial.mass;
    if (!(body->mass > 0.0 && std::isfinite(body->mass)))
    {
      std::ostringstream message;
      message << "mass " << inertial.mass << " kg is not positive";
      fail(link.name, message.str());
    }
    body->inertial_origin = toIsometry(inertial.origin);
    Eigen::Matrix3d inertia;
    inertia << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz, inertial.ixz,
        inertial.iyz, inertial.izz;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
    if (!inertia.allFinite() || !(solver.eigenvalues().minCoeff() > 0.0))
    {
      std::ostringstream message;
      message << "inertia is not positive definite (eigenvalues " << solver.eigenvalues().transpose() << " kg m^2)";
      fail(link.name, message.str());
    }
    body->inertia = inertia;
  }

  // urdfdom drops an element whose numbers it cannot read (a NaN scale, an infinite mass) and
  // goes on, so its absence would be blamed ("has no <collision>"): the numbers are checked
  // here first, naming the link, the element and the text.
  void checkNumbers(const std::string& xml) const
  {
    tinyxml2::XMLDocument document;
    if (document.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS)
    {
      return;  // urdfdom reports the syntax error
    }
    const tinyxml2::XMLElement* robot = document.FirstChildElement("robot");
    for (const tinyxml2::XMLElement* link = robot ? robot->FirstChildElement("link") : nullptr; link != nullptr;
         link = link->NextSiblingElement("link"))
    {
      const char* name = link->Attribute("name");
      const std::string link_name = name ? name : "";
      const tinyxml2::XMLElement* inertial = link->FirstChildElement("inertial");
      const tinyxml2::XMLElement* mass = inertial ? inertial->FirstChildElement("mass") : nullptr;
      if (mass != nullptr)
      {
        checkFinite(link_name, "<inertial><mass value>", mass->Attribute("value"), 1);
      }
      const tinyxml2::XMLElement* inertia = inertial ? inertial->FirstChildElement("inertia") : nullptr;
      for (const char* component : {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"})
      {
        if (inertia != nullptr && inertia->Attribute(component) != nullptr)
        {
          checkFinite(link_name, std::string("<inertia ") + component + ">", inertia->Attribute(component), 1);
        }
      }
      for (const char* part : {"collision", "visual"})
      {
        for (const tinyxml2::XMLElement* element = link->FirstChildElement(part); element != nullptr;
             element = element->NextSiblingElement(part))
        {
          const tinyxml2::XMLElement* geometry = element->FirstChildElement("geometry");
          const tinyxml2::XMLElement* mesh = geometry ? geometry->FirstChildElement("mesh") : nullptr;
          if (mesh != nullptr && mesh->Attribute("scale") != nullptr)
          {
            checkFinite(link_name, std::string("<") + part + "> <mesh scale>", mesh->Attribute("scale"), 3);
          }
          const tinyxml2::XMLElement* origin = element->FirstChildElement("origin");
          for (const char* attribute : {"xyz", "rpy"})
          {
            if (origin != nullptr && origin->Attribute(attribute) != nullptr)
            {
              checkFinite(link_name, std::string("<") + part + "><origin " + attribute + ">",
                          origin->Attribute(attribute), 3);
            }
          }
        }
      }
    }
  }

  // `text` must be `count` finite numbers separated by blanks.
  void checkFinite(const std::string& link, const std::string& what, const char* text, int count) const
  {
    std::istringstream stream(text ? text : "");
    int read = 0;
    std::string token;
    while (stream >> token)
    {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0' || !std::isfinite(value))
      {
        read = -1;
        break;
      }
      ++read;
    }
    if (read != count)
    {
      fail(link, what + " '" + (text ? text : "") + "' is not " +
                     (count == 1 ? "a finite number" : std::to_string(count) + " finite numbers"));
    }
  }

  std::map<std::string, ContactMaterial> materials(const std::string& xml) const
  {
    std::map<std::string, ContactMaterial> result;
    tinyxml2::XMLDocument document;
    if (document.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS)
    {
      return result;  // urdfdom reports the syntax error
    }
    const tinyxml2::XMLElement* robot = document.FirstChildElement("robot");
    for (const tinyxml2::XMLElement* link = robot ? robot->FirstChildElement("link") : nullptr; link != nullptr;
         link = link->NextSiblingElement("link"))
    {
      const char* name = link->Attribute("name");
      const tinyxml2::XMLElement* contact = link->FirstChildElement("contact");
      if (name == nullptr || contact == nullptr)
      {
        continue;
      }
      ContactMaterial material;
      const struct
      {
        const char* tag;
        double* value;
        double lower;
      } fields[] = {{"lateral_friction", &material.friction, 0.0},
                    {"rolling_friction", &material.rolling_friction, 0.0},
                    {"spinning_friction", &material.spinning_friction, 0.0},
                    {"restitution", &material.restitution, 0.0}};
      for (const auto& field : fields)
      {
        const tinyxml2::XMLElement* element = contact->FirstChildElement(field.tag);
        if (element == nullptr)
        {
          continue;
        }
        double value = 0.0;
        if (element->QueryDoubleAttribute("value", &value) != tinyxml2::XML_SUCCESS || !std::isfinite(value) ||
            value < field.lower || (field.tag == std::string("restitution") && value > 1.0))
        {
          fail(name, std::string("<contact><") + field.tag + "> needs a value " +
                         (field.tag == std::string("restitution") ? "in [0, 1]" : ">= 0"));
        }
        *field.value = value;
      }
      result[name] = material;
    }
    return result;
  }

  SceneDescription parse(const std::string& xml) const
  {
    checkNumbers(xml);
    // Soft bodies (<deformable>, PyBullet's form): static mesh bodies of the rigid world whose
    // surface deforms (BodyDescription::soft). A file of deformables only (PyBullet's object
    // files) has no link for urdfdom to read.
    std::vector<DeformableDescription> deformables;
    if (hasDeformables(xml))
    {
      deformables = parseDeformables(xml, base_directory_, source_, packages_);
    }
    if (!deformables.empty() && !hasLinks(xml))
    {
      SceneDescription scene;
      scene.name = robotName(xml);
      appendSoftBodies(deformables, &scene);
      scene.warnings = warnings_;
      return scene;
    }
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
    if (!model)
    {
      fail("", "not a valid URDF (urdfdom could not parse it; see the message above)");
    }
    const urdf::LinkConstSharedPtr root = model->getRoot();
    if (!root)
    {
      fail("", "no root link");
    }
    const std::map<std::string, ContactMaterial> link_materials = materials(xml);
    SceneDescription scene;
    scene.name = model->getName();
    std::vector<urdf::LinkSharedPtr> links;
    model->getLinks(links);
    // An object file as PyBullet and Gazebo ship them: the root link is the body.
    const bool object_file = static_cast<bool>(root->collision);
    std::map<std::string, int> body_of_link;
    // A link on a 'fixed' joint to another body's link (to an object file's root, or to any body
    // of a scene but the world) is a piece of that body: the body its fixed chain leads up to,
    // and where the link sits in that body's link frame.
    std::map<std::string, std::pair<std::string, Eigen::Isometry3d>> owner;
    for (const urdf::LinkSharedPtr& link : links)
    {
      Eigen::Isometry3d in_owner = Eigen::Isometry3d::Identity();
      const urdf::Link* at = link.get();
      for (int depth = 0; at->parent_joint && at->parent_joint->type == urdf::Joint::FIXED &&
                          (object_file || at->parent_joint->parent_link_name != root->name);
           ++depth)
      {
        const urdf::Link* parent = model->getLink(at->parent_joint->parent_link_name).get();
        if (depth >= kMaxJointDepth || parent == nullptr)
        {
          fail(link->name, "its chain of fixed joints is more than " + std::to_string(kMaxJointDepth) + " long");
        }
        in_owner = toIsometry(at->parent_joint->parent_to_joint_origin_transform) * in_owner;
        at = parent;
      }
      owner[link->name] = {at->name, in_owner};
    }
    for (const urdf::LinkSharedPtr& link : links)
    {
      if (owner.at(link->name).first != link->name)
      {
        continue;  // a piece of another body: merged below
      }
      if (link->name == root->name)
      {
        if (object_file)
        {
          body_of_link[link->name] = static_cast<int>(scene.bodies.size());
          scene.bodies.push_back(objectBody(*link, link_materials));
        }
        continue;
      }
      const urdf::JointConstSharedPtr joint = link->parent_joint;
      const bool on_root = joint && joint->parent_link_name == root->name;
      if (!joint)
      {
        fail(link->name, "has no joint to a parent link");
      }
      if (jointKind(joint->type) == nullptr)
      {
        if (object_file || !on_root)
        {
          fail(link->name, "joint '" + joint->name + "' is '" + jointTypeName(joint->type) + "' to link '" +
                               joint->parent_link_name +
                               "': a link joined to another body moves on a 'revolute', 'continuous' or "
                               "'prismatic' joint, or is a piece of it on a 'fixed' joint");
        }
        if (joint->type != urdf::Joint::FIXED && joint->type != urdf::Joint::FLOATING)
        {
          fail(link->name, "joint '" + joint->name +
                               "' must be 'fixed' (static body), 'floating' (free body), 'revolute', 'continuous' "
                               "or 'prismatic'");
        }
      }
      BodyDescription body = linkBody(*link, link_materials);
      body.pose = linkPose(*model, *link, root->name);
      body.is_static = joint->type == urdf::Joint::FIXED;
      if (!body.is_static || usableInertial(*link))
      {
        inertial(*link, &body);  // a fixed body keeps a usable one: a scene list may free it
      }
      body_of_link[link->name] = static_cast<int>(scene.bodies.size());
      scene.bodies.push_back(body);
    }
    for (const urdf::LinkSharedPtr& link : links)
    {
      const auto& [body_link, in_body] = owner.at(link->name);
      if (body_link != link->name && body_of_link.count(body_link) > 0)
      {
        mergePiece(*link, body_link, in_body, &scene.bodies[body_of_link.at(body_link)]);
      }
    }
    for (const urdf::LinkSharedPtr& link : links)
    {
      const urdf::JointConstSharedPtr joint = link->parent_joint;
      if (!joint || jointKind(joint->type) == nullptr)
      {
        continue;
      }
      const bool to_world = !object_file && joint->parent_link_name == root->name;
      const auto& [parent_body, parent_in_body] = owner.at(joint->parent_link_name);
      if (!to_world && body_of_link.count(parent_body) == 0)
      {
        fail(link->name, "joint '" + joint->name + "': its parent link '" + joint->parent_link_name +
                             "' is no body (it has no <collision>)");
      }
      JointDescription description =
          jointDescription(*joint, to_world ? -1 : body_of_link.at(parent_body), body_of_link.at(link->name));
      if (!to_world)
      {
        description.joint_in_parent = parent_in_body * description.joint_in_parent;
      }
      scene.joints.push_back(description);
    }
    appendSoftBodies(deformables, &scene);
    if (scene.bodies.empty())
    {
      fail("",
           "no bodies (links with a <collision> joined to the root, or a root link with a <collision>: an "
           "object file)");
    }
    if (scene.bodies.size() > static_cast<std::size_t>(kMaxBodies))
    {
      throw ResourceLimitError("URDF '" + source_ + "': " + std::to_string(scene.bodies.size()) +
                               " bodies, more than the limit of " + std::to_string(kMaxBodies));
    }
    scene.warnings = warnings_;
    return scene;
  }

  static bool hasLinks(const std::string& xml)
  {
    tinyxml2::XMLDocument document;
    const tinyxml2::XMLElement* robot = document.Parse(xml.c_str(), xml.size()) == tinyxml2::XML_SUCCESS
                                            ? document.FirstChildElement("robot")
                                            : nullptr;
    return robot != nullptr && robot->FirstChildElement("link") != nullptr;
  }

  static std::string robotName(const std::string& xml)
  {
    tinyxml2::XMLDocument document;
    const tinyxml2::XMLElement* robot = document.Parse(xml.c_str(), xml.size()) == tinyxml2::XML_SUCCESS
                                            ? document.FirstChildElement("robot")
                                            : nullptr;
    const char* name = robot != nullptr ? robot->Attribute("name") : nullptr;
    return name != nullptr ? name : "";
  }

  // Each deformable as a static body at its <origin>, its volume named by its mesh geometry.
  static void appendSoftBodies(const std::vector<DeformableDescription>& deformables, SceneDescription* scene)
  {
    for (const DeformableDescription& deformable : deformables)
    {
      BodyDescription body;
      body.name = deformable.name;
      body.geometry.kind = GeometryKind::kMesh;
      body.geometry.mesh_path = deformable.volume_file;
      body.pose = deformable.origin;
      body.is_static = true;
      body.material.friction = deformable.friction;
      body.soft = std::make_shared<const DeformableDescription>(deformable);
      scene->bodies.push_back(body);
    }
  }

  // A link on a fixed joint to `body`'s link (`in_body`: its frame in the body's link frame)
  // becomes more pieces of the body: its <collision>s, its mass (the body's centre of mass and
  // inertia combined by the parallel-axis theorem). The body then walks on its pieces' collision
  // surfaces: a visual mesh stands for one link, not for the merged whole.
  void mergePiece(const urdf::Link& link, const std::string& body_link, const Eigen::Isometry3d& in_body,
                  BodyDescription* body) const
  {
    for (const urdf::CollisionSharedPtr& collision : link.collision_array)
    {
      body->more_parts.push_back({geometry(link.name, collision->geometry), in_body * toIsometry(collision->origin)});
    }
    if (body->visual_mesh && !link.collision_array.empty())  // a frame without geometry changes no surface
    {
      warn(body_link, "link '" + link.name +
                          "' is fixed to it: the pad walks on the collision geometry of all its pieces, not on its "
                          "visual mesh");
      body->visual_mesh.reset();
    }
    if (usableInertial(link) && (body->mass > 0.0 || !body->is_static))
    {
      BodyDescription piece;
      inertial(link, &piece);
      const double total = body->mass + piece.mass;
      const Eigen::Isometry3d piece_com = in_body * piece.inertial_origin;
      const Eigen::Vector3d centre =
          (body->mass * body->inertial_origin.translation() + piece.mass * piece_com.translation()) / total;
      const auto about_centre = [&centre](double mass, const Eigen::Isometry3d& com, const Eigen::Matrix3d& inertia)
      {
        const Eigen::Vector3d d = com.translation() - centre;
        return Eigen::Matrix3d(com.linear() * inertia * com.linear().transpose() +
                               mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose()));
      };
      body->inertia = about_centre(body->mass, body->inertial_origin, body->inertia) +
                      about_centre(piece.mass, piece_com, piece.inertia);
      body->mass = total;
      body->inertial_origin = Eigen::Isometry3d::Identity();
      body->inertial_origin.translation() = centre;
    }
  }

  // A link's geometry and material (its pose and mass are the caller's).
  BodyDescription linkBody(const urdf::Link& link, const std::map<std::string, ContactMaterial>& materials) const
  {
    if (!link.collision)
    {
      fail(link.name, "has no <collision>");
    }
    BodyDescription body;
    body.name = link.name;
    body.collision_origin = toIsometry(link.collision_array.front()->origin);
    body.geometry = geometry(link.name, link.collision_array.front()->geometry);
    for (std::size_t i = 1; i < link.collision_array.size(); ++i)  // a compound: one body of all pieces
    {
      body.more_parts.push_back(
          {geometry(link.name, link.collision_array[i]->geometry), toIsometry(link.collision_array[i]->origin)});
    }
    int visual_meshes = 0;
    for (const urdf::VisualSharedPtr& visual : link.visual_array)
    {
      visual_meshes += visual && visual->geometry && visual->geometry->type == urdf::Geometry::MESH ? 1 : 0;
    }
    if (visual_meshes > 1)
    {
      warn(link.name, std::to_string(visual_meshes) +
                          " visual meshes: the pad walks on its collision geometry (one visual mesh is the surface)");
    }
    for (const urdf::VisualSharedPtr& visual : link.visual_array)
    {
      if (visual_meshes == 1 && visual && visual->geometry && visual->geometry->type == urdf::Geometry::MESH)
      {
        BodyPart surface;
        try
        {
          surface = BodyPart{geometry(link.name, visual->geometry), toIsometry(visual->origin)};
        }
        catch (const InputError& error)
        {
          warn(link.name, std::string("its visual mesh cannot be used, the pad walks on its collision geometry (") +
                              error.what() + ")");
          break;
        }
        const bool same_as_collision = body.more_parts.empty() && body.geometry.kind == GeometryKind::kMesh &&
                                       surface.geometry.mesh_path == body.geometry.mesh_path &&
                                       surface.geometry.scale == body.geometry.scale &&
                                       surface.origin.isApprox(body.collision_origin);
        if (!same_as_collision)
        {
          body.visual_mesh = surface;
        }
        break;  // the first visual mesh is the surface
      }
    }
    const auto material = materials.find(link.name);
    if (material != materials.end())
    {
      body.material = material->second;
    }
    return body;
  }

  // An object file's root link, at the origin: free with a positive <inertial> mass, fixed
  // without one or with mass 0 (PyBullet's convention for a fixed base).
  static const JointKind* jointKind(int type)
  {
    static const JointKind revolute = JointKind::kRevolute;
    static const JointKind continuous = JointKind::kContinuous;
    static const JointKind prismatic = JointKind::kPrismatic;
    switch (type)
    {
      case urdf::Joint::REVOLUTE:
        return &revolute;
      case urdf::Joint::CONTINUOUS:
        return &continuous;
      case urdf::Joint::PRISMATIC:
        return &prismatic;
      default:
        return nullptr;
    }
  }

  static std::string jointTypeName(int type)
  {
    switch (type)
    {
      case urdf::Joint::FIXED:
        return "fixed";
      case urdf::Joint::FLOATING:
        return "floating";
      case urdf::Joint::PLANAR:
        return "planar";
      default:
        return "unknown";
    }
  }

  // A link's pose at load (every joint at position 0): its joints' origins composed up to the
  // root (the world, or the object's own frame).
  Eigen::Isometry3d linkPose(const urdf::ModelInterface& model, const urdf::Link& link, const std::string& root) const
  {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    const urdf::Link* at = &link;
    for (int depth = 0; at->name != root; ++depth)
    {
      if (depth >= kMaxJointDepth || !at->parent_joint)
      {
        fail(link.name, "its chain to the root is more than " + std::to_string(kMaxJointDepth) + " joints long");
      }
      pose = toIsometry(at->parent_joint->parent_to_joint_origin_transform) * pose;
      at = model.getLink(at->parent_joint->parent_link_name).get();
    }
    return pose;
  }

  JointDescription jointDescription(const urdf::Joint& joint, int parent, int child) const
  {
    const std::string& link = joint.child_link_name;
    JointDescription result;
    result.name = joint.name;
    result.kind = *jointKind(joint.type);
    result.parent = parent;
    result.child = child;
    result.joint_in_parent = toIsometry(joint.parent_to_joint_origin_transform);
    result.axis = Eigen::Vector3d(joint.axis.x, joint.axis.y, joint.axis.z);
    if (!result.axis.allFinite() || result.axis.norm() < 1e-9)
    {
      fail(link, "joint '" + joint.name + "': <axis> must be a non-zero direction");
    }
    result.axis.normalize();
    if (joint.limits)
    {
      result.lower = joint.limits->lower;
      result.upper = joint.limits->upper;
      result.effort = joint.limits->effort;
      result.velocity = joint.limits->velocity;
    }
    if (joint.dynamics)
    {
      result.damping = joint.dynamics->damping;
      result.friction = joint.dynamics->friction;
    }
    const auto finite_non_negative = [](double value) { return std::isfinite(value) && value >= 0.0; };
    if (!finite_non_negative(result.damping) || !finite_non_negative(result.friction))
    {
      fail(link, "joint '" + joint.name + "': <dynamics> damping and friction must be finite and >= 0");
    }
    if (result.kind != JointKind::kContinuous)
    {
      if (!joint.limits)
      {
        fail(link, "joint '" + joint.name + "' needs a <limit lower upper>");
      }
      if (!std::isfinite(result.lower) || !std::isfinite(result.upper) || result.lower > result.upper)
      {
        fail(link, "joint '" + joint.name + "': <limit> needs finite lower <= upper");
      }
      if (result.kind == JointKind::kRevolute && (result.lower < -M_PI || result.upper > M_PI))
      {
        fail(link, "joint '" + joint.name +
                       "': a revolute joint's <limit> must lie within [-pi, pi] rad (give a "
                       "wider one as 'continuous')");
      }
    }
    return result;
  }

  BodyDescription objectBody(const urdf::Link& link, const std::map<std::string, ContactMaterial>& materials) const
  {
    BodyDescription body = linkBody(link, materials);
    body.is_static = !link.inertial || link.inertial->mass == 0.0;
    if (!body.is_static || usableInertial(link))
    {
      inertial(link, &body);
    }
    return body;
  }

 private:
  std::string source_;
  std::string base_directory_;
  PackageResolver packages_;
  mutable std::vector<std::string> warnings_;
};
}  // namespace

std::string resolveFileName(const std::string& filename, const std::string& base_directory,
                            const PackageResolver& packages, std::string* package)
{
  const std::string package_prefix = "package://";
  const std::string file_prefix = "file://";
  if (filename.rfind(package_prefix, 0) == 0)
  {
    const std::string rest = filename.substr(package_prefix.size());
    const std::size_t slash = rest.find('/');
    *package = rest.substr(0, slash);
    const std::string root = packages ? packages(*package) : findPackageAbove(*package, base_directory);
    return root.empty() ? root : root + (slash == std::string::npos ? "" : rest.substr(slash));
  }
  if (filename.rfind(file_prefix, 0) == 0)
  {
    return filename.substr(file_prefix.size());
  }
  if (!filename.empty() && filename[0] == '/')
  {
    return filename;
  }
  return base_directory + "/" + filename;
}

std::string folderOf(const std::string& path)
{
  return directoryOf(path);
}

SceneDescription parseUrdfScene(const std::string& urdf_xml, const std::string& base_directory,
                                const std::string& source_name, const PackageResolver& packages)
{
  return SceneParser(source_name, base_directory, packages).parse(urdf_xml);
}

std::string readUrdfText(const std::string& urdf_path, const PackageResolver& packages)
{
  std::ifstream stream(urdf_path);
  if (!stream.good())
  {
    throw InputError("URDF '" + urdf_path + "': no such file or not readable");
  }
  std::stringstream content;
  content << stream.rdbuf();
  const std::string xml = content.str();
  return isXacro(urdf_path, xml) ? expandXacro(xml, urdf_path, packages) : xml;
}

SceneDescription loadUrdfScene(const std::string& urdf_path, const PackageResolver& packages)
{
  return parseUrdfScene(readUrdfText(urdf_path, packages), directoryOf(urdf_path), urdf_path, packages);
}
}  // namespace god_finger
