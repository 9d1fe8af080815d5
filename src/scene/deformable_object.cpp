#include "god_finger/scene/deformable_object.h"

#include "god_finger/soft/vtk_tet_reader.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"

#include <tinyxml2.h>

#include <cctype>
#include <cmath>
#include <cstring>

namespace god_finger
{
namespace
{
const char* const kKnownElements[] = {"inertial",       "collision_margin", "friction",  "neohookean",
                                      "corotated",      "visual",           "collision", "repulsion_stiffness",
                                      "gravity_factor", "cache_barycenter", "spring",    "origin",
                                      "support"};

class DeformableParser
{
 public:
  DeformableParser(const std::string& source, const std::string& base_directory, const PackageResolver& packages)
      : source_(source), base_directory_(base_directory), packages_(packages)
  {
  }

  std::vector<DeformableDescription> parse(const std::string& xml)
  {
    tinyxml2::XMLDocument document;
    if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
    {
      throw InputError("URDF '" + source_ +
                       "': not XML: " + std::string(document.ErrorStr() != nullptr ? document.ErrorStr() : "?"));
    }
    std::vector<DeformableDescription> result;
    const tinyxml2::XMLElement* robot = document.FirstChildElement("robot");
    for (const tinyxml2::XMLElement* element = robot ? robot->FirstChildElement("deformable") : nullptr;
         element != nullptr; element = element->NextSiblingElement("deformable"))
    {
      result.push_back(deformable(*element));
    }
    return result;
  }

 private:
  [[noreturn]] void fail(const std::string& name, const tinyxml2::XMLElement& element, const std::string& problem) const
  {
    throw InputError("URDF '" + source_ + "': deformable '" + name + "' (line " + std::to_string(element.GetLineNum()) +
                     "): " + problem);
  }

  double number(const std::string& name, const tinyxml2::XMLElement& element, const char* attribute) const
  {
    const char* text = element.Attribute(attribute);
    double value = 0.0;
    if (text == nullptr || !parseDouble(text, &value) || !std::isfinite(value))
    {
      fail(name, element,
           std::string("<") + element.Name() + " " + attribute + "> '" + (text ? text : "") +
               "' is not a finite number");
    }
    return value;
  }

  // Three finite numbers separated by spaces (URDF's xyz and rpy), default `fallback` when absent.
  Eigen::Vector3d triple(const std::string& name, const tinyxml2::XMLElement& element, const char* attribute) const
  {
    const char* text = element.Attribute(attribute);
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    if (text == nullptr)
    {
      return value;
    }
    std::string rest = text;
    for (int i = 0; i < 3; ++i)
    {
      const std::size_t begin = rest.find_first_not_of(" \t\n\r");
      const std::size_t end = begin == std::string::npos ? begin : rest.find_first_of(" \t\n\r", begin);
      if (begin == std::string::npos || !parseDouble(rest.substr(begin, end - begin), &value[i]) ||
          !std::isfinite(value[i]))
      {
        fail(name, element, std::string("<origin ") + attribute + "> '" + text + "' is not three finite numbers");
      }
      rest = end == std::string::npos ? "" : rest.substr(end);
    }
    if (rest.find_first_not_of(" \t\n\r") != std::string::npos)
    {
      fail(name, element, std::string("<origin ") + attribute + "> '" + text + "' is not three finite numbers");
    }
    return value;
  }

  // <origin xyz rpy>: where the body's frame (its volume file's) goes in the file's frame.
  Eigen::Isometry3d origin(const std::string& name, const tinyxml2::XMLElement& element) const
  {
    const Eigen::Vector3d xyz = triple(name, element, "xyz");
    const Eigen::Vector3d rpy = triple(name, element, "rpy");
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = xyz;
    pose.linear() =
        (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    return pose;
  }

  DeformableDescription deformable(const tinyxml2::XMLElement& element) const
  {
    DeformableDescription body;
    const char* name = element.Attribute("name");
    if (name == nullptr || name[0] == '\0')
    {
      fail("", element, "<deformable> needs a name");
    }
    body.name = name;
    const tinyxml2::XMLElement* material = nullptr;
    const tinyxml2::XMLElement* collision = nullptr;
    const tinyxml2::XMLElement* visual = nullptr;
    bool has_spring = false;
    for (const tinyxml2::XMLElement* child = element.FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement())
    {
      const std::string tag = child->Name();
      bool known = false;
      for (const char* known_tag : kKnownElements)
      {
        known = known || tag == known_tag;
      }
      if (!known)
      {
        fail(body.name, *child,
             "unknown element <" + tag +
                 "> (a deformable has inertial, neohookean or corotated, collision, visual, friction, "
                 "collision_margin, origin, support)");
      }
      if (tag == "inertial")
      {
        const tinyxml2::XMLElement* mass = child->FirstChildElement("mass");
        if (mass == nullptr)
        {
          fail(body.name, *child, "<inertial> needs a <mass value>");
        }
        body.mass = number(body.name, *mass, "value");
      }
      else if (tag == "neohookean" || tag == "corotated")
      {
        if (material != nullptr)
        {
          fail(body.name, *child, "a second material (<" + tag + "> after <" + material->Name() + ">)");
        }
        material = child;
      }
      else if (tag == "collision")
      {
        collision = child;
      }
      else if (tag == "visual")
      {
        visual = child;
      }
      else if (tag == "friction")
      {
        body.friction = number(body.name, *child, "value");
      }
      else if (tag == "collision_margin")
      {
        body.collision_margin = number(body.name, *child, "value");
      }
      else if (tag == "spring")
      {
        has_spring = true;
      }
      else if (tag == "origin")
      {
        body.origin = origin(body.name, *child);
      }
      else if (tag == "support")
      {
        const char* value = child->Attribute("value");
        const std::string support = value != nullptr ? value : "";
        if (support != "glued" && support != "resting")
        {
          fail(body.name, *child, "<support value> is '" + support + "': give glued or resting");
        }
        body.resting = support == "resting";
      }
    }
    if (material == nullptr)
    {
      fail(body.name, element,
           has_spring ? "mass-spring deformables (<spring> alone) are not modelled: give <neohookean mu lambda> or "
                        "<corotated mu lambda>"
                      : "no material: give <neohookean mu lambda [damping]> or <corotated mu lambda [damping]>");
    }
    body.model = material->Name();
    const double mu = number(body.name, *material, "mu");
    const double lambda = number(body.name, *material, "lambda");
    if (!(mu > 0.0) || !(lambda >= 0.0))
    {
      fail(body.name, *material,
           "mu = " + roundedNumber(mu) + " and lambda = " + roundedNumber(lambda) + " must be > 0 and >= 0 (Pa)");
    }
    body.material = materialFromLame(mu, lambda);
    if (material->Attribute("damping") != nullptr)
    {
      body.material.stiffness_damping = number(body.name, *material, "damping");
    }
    if (!(body.mass > 0.0))
    {
      fail(body.name, element, "needs <inertial><mass value> > 0 (kg)");
    }
    if (!(body.friction >= 0.0) || !(body.collision_margin >= 0.0))
    {
      fail(body.name, element, "<friction> and <collision_margin> must be >= 0");
    }
    const tinyxml2::XMLElement* volume = collision != nullptr ? collision : visual;
    const char* filename = volume != nullptr ? volume->Attribute("filename") : nullptr;
    if (filename == nullptr)
    {
      fail(body.name, volume != nullptr ? *volume : element,
           "needs <collision filename> or <visual filename> naming its tetrahedral .vtk volume");
    }
    body.volume_file = resolve(body.name, *volume, filename);
    const std::string lower = lowerCase(body.volume_file);
    if (lower.size() < 4 || lower.compare(lower.size() - 4, 4, ".vtk") != 0)
    {
      fail(body.name, *volume,
           "'" + std::string(filename) +
               "' is not a .vtk volume: a surface mesh would have to be filled with tetrahedra first (TetWild, "
               "gmsh), which the loader does not do");
    }
    if (visual != nullptr && visual->Attribute("filename") != nullptr)
    {
      body.visual_file = resolve(body.name, *visual, visual->Attribute("filename"));
    }
    body.mesh = readVtkTetMesh(body.volume_file);
    double volume_m3 = 0.0;
    for (const auto& tet : body.mesh.tets)
    {
      volume_m3 += signedTetVolume(body.mesh.nodes, tet);
    }
    body.material.density = body.mass / volume_m3;
    checkSoftMaterial(body.material, "URDF '" + source_ + "': deformable '" + body.name + "'");
    return body;
  }

  std::string resolve(const std::string& name, const tinyxml2::XMLElement& element, const char* filename) const
  {
    std::string package;
    const std::string path = resolveFileName(filename, base_directory_, packages_, &package);
    if (path.empty())
    {
      fail(name, element, "package '" + package + "' of '" + filename + "' is not known");
    }
    return path;
  }

  static std::string lowerCase(std::string text)
  {
    for (char& c : text)
    {
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return text;
  }

  std::string source_;
  std::string base_directory_;
  PackageResolver packages_;
};
}  // namespace

bool hasDeformables(const std::string& xml)
{
  return xml.find("<deformable") != std::string::npos;
}

std::vector<DeformableDescription> parseDeformables(const std::string& xml, const std::string& base_directory,
                                                    const std::string& source, const PackageResolver& packages)
{
  return DeformableParser(source, base_directory, packages).parse(xml);
}

std::vector<DeformableDescription> loadDeformables(const std::string& path, const PackageResolver& packages)
{
  return parseDeformables(readUrdfText(path, packages), folderOf(path), path, packages);
}
}  // namespace god_finger
