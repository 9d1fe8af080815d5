#include "god_finger/scene/scene_file.h"

#include "god_finger/support/input_error.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace god_finger
{
namespace
{
bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

class SceneListParser
{
 public:
  SceneListParser(const std::string& path, const PackageResolver& packages) : path_(path), packages_(packages) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const
  {
    throw InputError("scene list '" + path_ + "': " + (where.empty() ? "" : where + ": ") + problem);
  }

  SceneDescription parse() const
  {
    try
    {
      return parseYaml();
    }
    catch (const YAML::Exception& error)  // a node of an unexpected kind (a list as a key, ...)
    {
      fail("line " + std::to_string(error.mark.line + 1), "not a scene list: " + error.msg);
    }
  }

 private:
  SceneDescription parseYaml() const
  {
    YAML::Node root;
    try
    {
      root = YAML::LoadFile(path_);
    }
    catch (const YAML::BadFile&)
    {
      fail("", "no such file or not readable");
    }
    catch (const YAML::Exception& error)
    {
      fail("line " + std::to_string(error.mark.line + 1), "not YAML: " + error.msg);
    }
    if (!root.IsMap())
    {
      fail("", "must be a map with 'objects' (and optionally 'support')");
    }
    checkKeys(root, {"support", "objects"}, "");
    SceneDescription scene;
    scene.name = path_;
    const std::string support = root["support"] ? text(root["support"], "support") : "table";
    if (support == "table")
    {
      scene.bodies.push_back(supportTable());
    }
    else if (support != "none")
    {
      fail("support", "'" + support + "' is not one of table, none");
    }
    const YAML::Node objects = root["objects"];
    if (!objects || !objects.IsSequence() || objects.size() == 0)
    {
      fail("objects", "must be a non-empty list of objects (file, and optionally name, xyz, rpy, fixed)");
    }
    std::set<std::string> names;
    for (const BodyDescription& body : scene.bodies)
    {
      names.insert(body.name);
    }
    for (std::size_t i = 0; i < objects.size(); ++i)
    {
      appendObject(objects[i], "objects[" + std::to_string(i) + "]", &scene, &names);
    }
    return scene;
  }

  void checkKeys(const YAML::Node& map, const std::set<std::string>& known, const std::string& where) const
  {
    for (const auto& entry : map)
    {
      const std::string key = entry.first.IsScalar() ? entry.first.as<std::string>() : std::string("(not a text)");
      if (known.count(key) == 0)
      {
        std::string list;
        for (const std::string& name : known)
        {
          list += (list.empty() ? "" : ", ") + name;
        }
        fail(where, "unknown key '" + key + "' (known: " + list + ")");
      }
    }
  }

  std::string text(const YAML::Node& node, const std::string& where) const
  {
    if (!node.IsScalar())
    {
      fail(where, "must be a text");
    }
    return node.as<std::string>();
  }

  Eigen::Vector3d vector3(const YAML::Node& node, const std::string& where) const
  {
    Eigen::Vector3d result;
    bool good = node.IsSequence() && node.size() == 3;
    for (std::size_t i = 0; good && i < 3; ++i)
    {
      try
      {
        result[i] = node[i].as<double>();
      }
      catch (const YAML::Exception&)
      {
        good = false;
      }
    }
    if (!good || !result.allFinite())
    {
      fail(where, "must be three finite numbers, [a, b, c]");
    }
    return result;
  }

  void appendObject(const YAML::Node& object, const std::string& where, SceneDescription* scene,
                    std::set<std::string>* names) const
  {
    if (!object.IsMap())
    {
      fail(where, "must be a map (file, and optionally name, xyz, rpy, fixed)");
    }
    checkKeys(object, {"file", "name", "xyz", "rpy", "fixed"}, where);
    if (!object["file"])
    {
      fail(where, "has no 'file'");
    }
    const std::string file = text(object["file"], where + ".file");
    std::string package;
    const std::string path = resolveFileName(file, folderOf(path_), packages_, &package);
    if (path.empty())
    {
      fail(where, "file '" + file + "': ROS package '" + package + "' not found");
    }
    if (endsWith(path, ".yaml") || endsWith(path, ".yml"))
    {
      fail(where, "file '" + file + "': a scene list cannot list another (give URDF files)");
    }
    SceneDescription parts;
    try
    {
      parts = loadUrdfScene(path, packages_);
    }
    catch (const InputError& error)
    {
      fail(where, error.what());
    }
    Eigen::Isometry3d placement = Eigen::Isometry3d::Identity();
    if (object["xyz"])
    {
      placement.translation() = vector3(object["xyz"], where + ".xyz");
    }
    if (object["rpy"])
    {
      const Eigen::Vector3d rpy = vector3(object["rpy"], where + ".rpy");
      placement.linear() = rpyRotation(rpy);
    }
    ObjectPlacement placed;
    placed.pose = placement;
    placed.name = object["name"] ? text(object["name"], where + ".name") : std::string();
    if (object["fixed"])
    {
      try
      {
        placed.fixed = object["fixed"].as<bool>();
      }
      catch (const YAML::Exception&)
      {
        fail(where + ".fixed", "must be true or false");
      }
    }
    const std::size_t first_body = scene->bodies.size();
    try
    {
      placeObject(parts, placed, scene);
    }
    catch (const InputError& error)
    {
      fail(where, error.what());
    }
    for (std::size_t i = first_body; i < scene->bodies.size(); ++i)
    {
      if (!names->insert(scene->bodies[i].name).second)
      {
        fail(where, "the name '" + scene->bodies[i].name + "' is given twice (give each object its own 'name')");
      }
    }
  }

  std::string path_;
  PackageResolver packages_;
};
}  // namespace

Eigen::Matrix3d rpyRotation(const Eigen::Vector3d& rpy)
{
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

BodyDescription supportTable()
{
  BodyDescription table;
  table.name = "table";
  table.geometry.kind = GeometryKind::kBox;
  table.geometry.size = Eigen::Vector3d(1.0, 1.0, 0.04);
  table.pose.translation() = Eigen::Vector3d(0.0, 0.0, -0.02);
  table.is_static = true;
  table.material.friction = 0.6;
  return table;
}

void placeObject(const SceneDescription& object, const ObjectPlacement& placement, SceneDescription* scene)
{
  const int first_body = static_cast<int>(scene->bodies.size());
  const std::string& name = placement.name;
  std::vector<bool> jointed(object.bodies.size(), false);  // an articulated object's moving links
  for (JointDescription joint : object.joints)
  {
    jointed[joint.child] = true;
    joint.child += first_body;
    joint.parent = joint.parent < 0 ? -1 : joint.parent + first_body;
    joint.joint_in_parent = joint.parent < 0 ? placement.pose * joint.joint_in_parent : joint.joint_in_parent;
    joint.name = name.empty() ? joint.name : name + "/" + joint.name;
    scene->joints.push_back(joint);
  }
  for (std::size_t part = 0; part < object.bodies.size(); ++part)
  {
    BodyDescription body = object.bodies[part];
    body.pose = placement.pose * body.pose;
    if (!name.empty())
    {
      body.name = object.bodies.size() == 1 ? name : name + "/" + body.name;
    }
    if (placement.fixed && !jointed[part])  // fixed: the object's base; its jointed links still move
    {
      if (!*placement.fixed && body.soft)
      {
        throw InputError("body '" + body.name +
                         "' is a soft body: it is glued by its lowest nodes to what it rests on, and cannot be made "
                         "free (fixed: false)");
      }
      if (!*placement.fixed && body.is_static && !(body.mass > 0.0))
      {
        throw InputError("body '" + body.name +
                         "' is fixed in its file and has no usable <inertial> (a positive mass, a positive-definite "
                         "inertia): it cannot be made free");
      }
      body.is_static = *placement.fixed;
    }
    scene->bodies.push_back(body);
  }
  scene->warnings.insert(scene->warnings.end(), object.warnings.begin(), object.warnings.end());
}

SceneDescription loadPlacedObject(const std::string& path, const ObjectPlacement& placement,
                                  const PackageResolver& packages)
{
  if (endsWith(path, ".yaml") || endsWith(path, ".yml"))
  {
    throw InputError("'" + path + "': a scene list is not one object (give a URDF file)");
  }
  if (!placement.pose.matrix().allFinite())
  {
    throw InputError("'" + path + "': the pose must be finite");
  }
  const SceneDescription object = loadUrdfScene(path, packages);
  SceneDescription placed;
  placed.name = placement.name.empty() ? object.name : placement.name;
  try
  {
    placeObject(object, placement, &placed);
  }
  catch (const InputError& error)
  {
    throw InputError("'" + path + "': " + error.what());
  }
  return placed;
}

SceneDescription loadScene(const std::string& path, const PackageResolver& packages)
{
  if (endsWith(path, ".yaml") || endsWith(path, ".yml"))
  {
    return SceneListParser(path, packages).parse();
  }
  return loadUrdfScene(path, packages);
}
}  // namespace god_finger
