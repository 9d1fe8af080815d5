// god_finger_scene: a scene file checked as the physics loads it, with no ROS master; what
// check_urdf is for plain URDFs, for the objects a user brings.
//
//   god_finger_scene FILE [--touch BODY] [--model god_object|god_finger|soft_finger]
//
// FILE is any scene the physics takes (scene/scene_file.h: a URDF scene, an object file whose
// root link is the body, a scene list). Prints a summary: each body (fixed or free, mass,
// collision pieces, the surface the pad walks on and its triangles), the load time (file and
// world, convex decompositions included). With --touch BODY, lets the scene settle for 0.5 s,
// then brings a finger straight down over the body's centre of mass from above its highest point,
// to 5 mm below that height, and holds it there (1 s in all), and
// reports the contact area (radius, sub-god-objects), the force on the hand and how the body
// moved. Exit codes: 0 success, 2 bad options or a scene that cannot be used (one line on
// stderr naming the file and the problem, as the physics node would print it).
#include "god_finger/physics/contact_model.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/support/input_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

namespace
{
const char* const kUsage =
    "usage: god_finger_scene FILE [--touch BODY] [--model god_object|god_finger|soft_finger]\n"
    "Loads FILE (a URDF scene, an object URDF whose root link is the body, or a scene list .yaml)\n"
    "as the physics does and prints its bodies and load time; --touch BODY presses a finger on the\n"
    "body (down over its centre, 5 mm below its top) and reports the contact area, the force on the\n"
    "hand, where the finger stopped and how the body moved.\n";

const char* geometryName(god_finger::GeometryKind kind)
{
  switch (kind)
  {
    case god_finger::GeometryKind::kBox:
      return "box";
    case god_finger::GeometryKind::kSphere:
      return "sphere";
    case god_finger::GeometryKind::kCylinder:
      return "cylinder";
    case god_finger::GeometryKind::kMesh:
      return "mesh";
  }
  return "?";
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Over `body`'s centre of mass, at the height of its walk surface's highest point (m, world):
// where a finger coming straight down first meets it (a stool's seat, a cup's hollow).
Eigen::Vector3d topOf(const god_finger::GodFingerWorld& world, int body)
{
  const god_finger::BodyDescription& description = world.scene().bodies[body];
  const god_finger::BodyState state = world.bodyState(body);
  const Eigen::Isometry3d to_world = state.pose * description.collision_origin;
  double top = -1e300;
  for (const Eigen::Vector3d& vertex : world.walkMesh(body).vertices())
  {
    top = std::max(top, (to_world * vertex).z());
  }
  const Eigen::Vector3d centre = description.is_static ? state.pose.translation() : state.center_of_mass;
  return Eigen::Vector3d(centre.x(), centre.y(), top);
}

int touch(god_finger::GodFingerWorld* world, int body)
{
  const double dt = world->params().time_step;
  for (int i = 0; i < static_cast<int>(std::lround(0.5 / dt)); ++i)
  {
    world->step();
  }
  const Eigen::Vector3d top = topOf(*world, body);
  const god_finger::BodyState before = world->bodyState(body);
  const int finger = world->addInterface(top + Eigen::Vector3d(0.0, 0.0, 0.03));
  // Down in 0.3 s (as a hand comes down), then held 5 mm into the body for 0.7 s.
  const int steps = static_cast<int>(std::lround(1.0 / dt));
  for (int i = 1; i <= steps; ++i)
  {
    const double t = i * dt;
    const double depth = t < 0.3 ? -0.03 + 0.035 * t / 0.3 : 0.005;
    world->setInterfaceTarget(finger, top - Eigen::Vector3d(0.0, 0.0, depth));
    world->step();
  }
  const god_finger::InterfaceState& state = world->interfaceState(finger);
  const god_finger::BodyState after = world->bodyState(body);
  std::printf(
      "touch '%s': a finger down over its centre, to 5 mm below its top (%.4f, %.4f, %.4f) m, held 0.7 s (%s):\n",
      world->scene().bodies[body].name.c_str(), top.x(), top.y(), top.z(),
      god_finger::contactModelName(world->contactModel()));
  int touching = -1;
  for (int c = 0; c < state.contact_count; ++c)
  {
    touching = state.contacts[c].body == body ? c : touching;
  }
  if (touching < 0)
  {
    std::printf("  no contact with it (the finger touches %d other bodies)\n", state.contact_count);
    return 1;
  }
  const god_finger::WorldContactArea& area = state.contacts[touching];
  std::printf("  contact area: radius %.2f mm, %d sub-god-objects\n", 1e3 * area.radius, area.sub_god_object_count);
  std::printf("  force on the hand: %.3f N\n", state.user_force.norm());
  std::printf("  the finger (its god-object) stopped at z %.4f m\n", state.proxy_position.z());
  const Eigen::AngleAxisd turned(before.pose.linear().transpose() * after.pose.linear());
  std::printf("  the body moved %.2f mm and turned %.4f rad\n",
              1e3 * (after.pose.translation() - before.pose.translation()).norm(), turned.angle());
  return 0;
}
}  // namespace

int main(int argc, char** argv)
{
  std::string file;
  std::string touch_body;
  god_finger::WorldParams params;
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    if (argument == "--help" || argument == "-h")
    {
      std::cout << kUsage;
      return 0;
    }
    if ((argument == "--touch" || argument == "--model") && i + 1 < argc)
    {
      const std::string value = argv[++i];
      if (argument == "--touch")
      {
        touch_body = value;
      }
      else if (!god_finger::parseContactModel(value, &params.model))
      {
        std::cerr << "god_finger_scene: --model '" << value << "' is not god_object, god_finger or soft_finger\n";
        return 2;
      }
      continue;
    }
    if (argument.rfind("--", 0) == 0 || !file.empty())
    {
      std::cerr << "god_finger_scene: unexpected argument '" << argument << "'\n" << kUsage;
      return 2;
    }
    file = argument;
  }
  if (file.empty())
  {
    std::cerr << kUsage;
    return 2;
  }
  try
  {
    const auto start = std::chrono::steady_clock::now();
    const god_finger::SceneDescription scene = god_finger::loadScene(file);
    const double read_seconds = secondsSince(start);
    god_finger::GodFingerWorld world(scene, params);
    const double load_seconds = secondsSince(start);
    std::printf("scene '%s': %zu bodies, read in %.3f s, world built in %.3f s\n", file.c_str(), scene.bodies.size(),
                read_seconds, load_seconds);
    for (int i = 0; i < world.bodyCount(); ++i)
    {
      const god_finger::BodyDescription& body = scene.bodies[i];
      const Eigen::Vector3d at = body.pose.translation();
      std::printf("  %-16s %s", body.name.c_str(), body.is_static ? "fixed" : "free ");
      if (!body.is_static)
      {
        std::printf(" %.3f kg", body.mass);
      }
      std::printf(" at (%.3f, %.3f, %.3f) m; collides as %s", at.x(), at.y(), at.z(), geometryName(body.geometry.kind));
      for (const god_finger::BodyPart& part : body.more_parts)
      {
        std::printf(" + %s", geometryName(part.geometry.kind));
      }
      std::printf("; the pad walks on %s, %zu triangles\n",
                  body.visual_mesh ? "its visual mesh" : (body.more_parts.empty() ? "it" : "all its pieces"),
                  world.walkMesh(i).triangles().size());
    }
    for (const std::string& warning : scene.warnings)
    {
      std::printf("warning: %s\n", warning.c_str());
    }
    if (touch_body.empty())
    {
      return 0;
    }
    const int body = scene.find(touch_body);
    if (body < 0)
    {
      std::cerr << "god_finger_scene: --touch '" << touch_body << "': no such body in '" << file << "'\n";
      return 2;
    }
    return touch(&world, body);
  }
  catch (const std::exception& error)
  {
    std::cerr << "god_finger_scene: " << error.what() << "\n";
    return 2;
  }
}
