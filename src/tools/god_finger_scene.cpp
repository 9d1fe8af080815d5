// god_finger_scene: a scene file checked as the physics loads it, with no ROS master; what
// check_urdf is for plain URDFs, for the objects a user brings.
//
//   god_finger_scene FILE [--touch BODY] [--model god_object|god_finger|soft_finger]
//
// FILE is any scene the physics takes (scene/scene_file.h: a URDF scene, an object file whose
// root link is the body, a scene list). Prints a summary: each body (fixed or free, mass,
// collision pieces, the surface the pad walks on and its triangles), the load time (file and
// world, convex decompositions included). With --touch BODY, lets the scene settle for 0.5 s,
// then brings a finger straight down over the body's centre of mass from 3 cm above its highest
// point to 5 mm below the surface under it (a ball's top, a cup's inner floor), and holds it
// there (1 s in all), and
// reports the contact area (radius, sub-god-objects), the force on the hand and how the body
// moved. Exit codes: 0 success, 2 bad options or a scene that cannot be used (one line on
// stderr naming the file and the problem, as the physics node would print it).
#include "god_finger/physics/contact_model.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/deformable_object.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/support/input_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace
{
const char* const kUsage =
    "usage: god_finger_scene FILE [--touch BODY] [--model god_object|god_finger|soft_finger]\n"
    "Loads FILE (a URDF scene, an object URDF whose root link is the body, or a scene list .yaml)\n"
    "as the physics does and prints its bodies and load time; --touch BODY presses a finger on the\n"
    "body (down over its centre, 5 mm below its top) and reports the contact area, the force on the\n"
    "hand, where the finger stopped and how the body moved (a soft body: how deep its surface sank).\n";

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
// Where a finger coming straight down over the body's centre (its centre of mass; a static
// body's link origin) first meets its surface: the highest crossing of that vertical with the
// walk mesh (a cup's inner floor, a ball's top), or the mesh's highest point when the vertical
// misses it (a ring's hole); `highest` is the mesh's highest point (m, world z).
Eigen::Vector3d surfaceUnderFinger(const god_finger::GodFingerWorld& world, int body, double* highest)
{
  const god_finger::BodyDescription& description = world.scene().bodies[body];
  const god_finger::BodyState state = world.bodyState(body);
  const Eigen::Isometry3d to_world = state.pose * description.collision_origin;
  const Eigen::Vector3d centre = description.is_static ? state.pose.translation() : state.center_of_mass;
  const god_finger::TriangleMesh& mesh = world.walkMesh(body);
  double top = -1e300;
  double crossing = -1e300;
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    const Eigen::Vector3d a = to_world * mesh.corner(t, 0);
    const Eigen::Vector3d b = to_world * mesh.corner(t, 1);
    const Eigen::Vector3d c = to_world * mesh.corner(t, 2);
    top = std::max({top, a.z(), b.z(), c.z()});
    // The vertical through the centre in the triangle's (x, y) projection: barycentric weights.
    const Eigen::Vector2d ab = (b - a).head<2>();
    const Eigen::Vector2d ac = (c - a).head<2>();
    const Eigen::Vector2d ap = (centre - a).head<2>();
    const double area = ab.x() * ac.y() - ab.y() * ac.x();
    if (std::abs(area) < 1e-18)
    {
      continue;  // seen edge-on from above
    }
    const double u = (ap.x() * ac.y() - ap.y() * ac.x()) / area;
    const double v = (ab.x() * ap.y() - ab.y() * ap.x()) / area;
    if (u >= 0.0 && v >= 0.0 && u + v <= 1.0)
    {
      crossing = std::max(crossing, a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z()));
    }
  }
  *highest = top;
  return Eigen::Vector3d(centre.x(), centre.y(), crossing > -1e300 ? crossing : top);
}

int touch(god_finger::GodFingerWorld* world, int body)
{
  const double dt = world->params().time_step;
  for (int i = 0; i < static_cast<int>(std::lround(0.5 / dt)); ++i)
  {
    world->step();
  }
  double highest = 0.0;
  const Eigen::Vector3d top = surfaceUnderFinger(*world, body, &highest);
  const god_finger::BodyState before = world->bodyState(body);
  // From 3 cm above the body's highest point (over a cup's rim), down in 0.3 s (as a hand comes
  // down), then held 5 mm into the surface under it for 0.7 s.
  const std::vector<Eigen::Vector3d> untouched = world->walkMesh(body).vertices();  // a soft body's, before
  const double start = highest + 0.03 - top.z();
  const int finger = world->addInterface(top + Eigen::Vector3d(0.0, 0.0, start));
  const int steps = static_cast<int>(std::lround(1.0 / dt));
  for (int i = 1; i <= steps; ++i)
  {
    const double t = i * dt;
    const double depth = t < 0.3 ? -start + (start + 0.005) * t / 0.3 : 0.005;
    world->setInterfaceTarget(finger, top - Eigen::Vector3d(0.0, 0.0, depth));
    world->step();
  }
  const god_finger::InterfaceState& state = world->interfaceState(finger);
  const god_finger::BodyState after = world->bodyState(body);
  std::printf(
      "touch '%s': a finger down over its centre, to 5 mm below its surface there (%.4f, %.4f, %.4f) m, held 0.7 s "
      "(%s):\n",
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
  if (world->scene().bodies[body].soft)
  {
    double dimple = 0.0;
    const std::vector<Eigen::Vector3d>& now = world->walkMesh(body).vertices();
    for (std::size_t v = 0; v < now.size(); ++v)
    {
      dimple = std::max(dimple, (now[v] - untouched[v]).norm());
    }
    std::printf("  its surface sank %.2f mm under the finger (a soft body)\n", 1e3 * dimple);
  }
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
    std::printf("scene '%s': %zu bodies, %zu joints, read in %.3f s, world built in %.3f s\n", file.c_str(),
                scene.bodies.size(), scene.joints.size(), read_seconds, load_seconds);
    for (int i = 0; i < world.bodyCount(); ++i)
    {
      const god_finger::BodyDescription& body = scene.bodies[i];
      const Eigen::Vector3d at = body.pose.translation();
      std::printf("  %-16s %s", body.name.c_str(), body.is_static ? "fixed" : "free ");
      if (!body.is_static)
      {
        std::printf(" %.3f kg", body.mass);
      }
      if (body.soft)
      {
        std::printf(" soft (%zu nodes, %zu tetrahedra, E %.3g kPa, nu %.3g, %.3g kg, glued where it rests)",
                    body.soft->mesh.nodes.size(), body.soft->mesh.tets.size(), 1e-3 * body.soft->material.young_modulus,
                    body.soft->material.poisson_ratio, body.soft->mass);
      }
      std::printf(" at (%.3f, %.3f, %.3f) m; collides as %s", at.x(), at.y(), at.z(), geometryName(body.geometry.kind));
      for (const god_finger::BodyPart& part : body.more_parts)
      {
        std::printf(" + %s", geometryName(part.geometry.kind));
      }
      const god_finger::GodFingerWorld::BodyCollision collision = world.bodyCollision(i);
      if (collision.convex_hulls > 0)
      {
        std::printf(" (%d convex hull%s%s)", collision.convex_hulls, collision.convex_hulls == 1 ? "" : "s",
                    collision.hulls_as_given ? ", its own pieces as given" : "");
      }
      if (collision.fingers_touch_walk_mesh)
      {
        std::printf("; fingers touch its true surface");
      }
      std::printf("; the pad walks on %s, %zu triangles\n",
                  body.visual_mesh ? "its visual mesh" : (body.more_parts.empty() ? "it" : "all its pieces"),
                  world.walkMesh(i).triangles().size());
    }
    for (const god_finger::JointDescription& joint : scene.joints)
    {
      const bool prismatic = joint.kind == god_finger::JointKind::kPrismatic;
      std::printf("  joint %-10s %s, %s -> %s, axis (%.3f, %.3f, %.3f)", joint.name.c_str(),
                  god_finger::jointKindName(joint.kind),
                  joint.parent < 0 ? "world" : scene.bodies[joint.parent].name.c_str(),
                  scene.bodies[joint.child].name.c_str(), joint.axis.x(), joint.axis.y(), joint.axis.z());
      if (joint.kind != god_finger::JointKind::kContinuous)
      {
        std::printf(", limits [%.3f, %.3f] %s", joint.lower, joint.upper, prismatic ? "m" : "rad");
      }
      std::printf(", damping %g, friction %g\n", joint.damping, joint.friction);
    }
    for (const std::string& warning : scene.warnings)
    {
      std::printf("warning: %s\n", warning.c_str());
    }
    for (const std::string& warning : world.startWarnings())
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
