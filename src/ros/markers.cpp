#include "markers.h"

#include <algorithm>
#include <cctype>

#include "god_finger/ros/conversions.h"
#include "god_finger/scene/scene_budget.h"

namespace god_finger
{
namespace
{
visualization_msgs::Marker marker(const std::string& ns, int id, int type, const ros::Time& stamp)
{
  visualization_msgs::Marker m;
  m.header.frame_id = "world";
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color.a = 1.0;
  return m;
}

void setColor(visualization_msgs::Marker* m, float r, float g, float b, float a = 1.0f)
{
  m->color.r = r;
  m->color.g = g;
  m->color.b = b;
  m->color.a = a;
}

void setPose(visualization_msgs::Marker* m, const Eigen::Isometry3d& pose)
{
  const Eigen::Quaterniond q(pose.linear());
  m->pose.position = toPoint(pose.translation());
  m->pose.orientation.x = q.x();
  m->pose.orientation.y = q.y();
  m->pose.orientation.z = q.z();
  m->pose.orientation.w = q.w();
}

// The rest of the finger around god-object `index`: a translucent finger body behind the tip
// (finger -x) and the nail on its back (finger -z), so that a look shows which way the pulp
// faces and how the finger is rolled. A 3-DOF finger is drawn pulp down, along world x.
void appendFingertip(const InterfaceState& state, double proxy_radius, int index, const ros::Time& stamp,
                     visualization_msgs::MarkerArray* markers)
{
  const Eigen::Quaterniond finger =
      state.oriented ? state.proxy_orientation.normalized() : Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0);
  const Eigen::Vector3d tip = state.proxy_position;
  const double r = proxy_radius;
  Eigen::Isometry3d body_pose = Eigen::Isometry3d::Identity();
  body_pose.translation() = tip + finger * Eigen::Vector3d(-2.0 * r, 0.0, 0.0);
  // rviz's cylinder runs along its z: turn it onto the finger's x.
  body_pose.linear() = (finger * Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitY())).toRotationMatrix();
  visualization_msgs::Marker body = marker("fingertips", 2 * index, visualization_msgs::Marker::CYLINDER, stamp);
  setPose(&body, body_pose);
  body.scale.x = body.scale.y = 1.8 * r;
  body.scale.z = 4.0 * r;
  setColor(&body, 0.95f, 0.8f, 0.7f, 0.45f);
  markers->markers.push_back(body);
  Eigen::Isometry3d nail_pose = Eigen::Isometry3d::Identity();
  nail_pose.translation() = tip + finger * Eigen::Vector3d(-0.6 * r, 0.0, -0.95 * r);
  nail_pose.linear() = finger.toRotationMatrix();
  visualization_msgs::Marker nail = marker("fingertips", 2 * index + 1, visualization_msgs::Marker::CUBE, stamp);
  setPose(&nail, nail_pose);
  nail.scale.x = 1.4 * r;
  nail.scale.y = 1.2 * r;
  nail.scale.z = 0.3 * r;
  setColor(&nail, 1.0f, 0.95f, 0.95f);
  markers->markers.push_back(nail);
}

visualization_msgs::Marker deleteAll(const std::string& ns, const ros::Time& stamp)
{
  visualization_msgs::Marker m = marker(ns, 0, visualization_msgs::Marker::CUBE, stamp);
  m.action = visualization_msgs::Marker::DELETEALL;
  return m;
}
// One piece of a body drawn at `pose` (its geometry frame in world).
visualization_msgs::Marker geometryMarker(const Geometry& geometry, const Eigen::Isometry3d& pose, int id,
                                          const BodyColour& colour, const ros::Time& stamp)
{
  visualization_msgs::Marker m = marker("bodies", id, visualization_msgs::Marker::CUBE, stamp);
  setPose(&m, pose);
  switch (geometry.kind)
  {
    case GeometryKind::kBox:
      m.scale.x = geometry.size.x();
      m.scale.y = geometry.size.y();
      m.scale.z = geometry.size.z();
      break;
    case GeometryKind::kSphere:
      m.type = visualization_msgs::Marker::SPHERE;
      m.scale.x = m.scale.y = m.scale.z = 2.0 * geometry.radius;
      break;
    case GeometryKind::kCylinder:
      m.type = visualization_msgs::Marker::CYLINDER;
      m.scale.x = m.scale.y = 2.0 * geometry.radius;
      m.scale.z = geometry.length;
      break;
    case GeometryKind::kMesh:
      m.type = visualization_msgs::Marker::MESH_RESOURCE;
      m.mesh_resource = "file://" + geometry.mesh_path;
      m.scale.x = geometry.scale.x();
      m.scale.y = geometry.scale.y();
      m.scale.z = geometry.scale.z();
      break;
  }
  m.color.r = colour.r;
  m.color.g = colour.g;
  m.color.b = colour.b;
  m.color.a = colour.a;
  return m;
}
// A soft body's surface as it is now: one triangle list whose vertices darken toward
// a deep red (0.75, 0.2, 0.25) as they sink, fully at kSoftSinkShown (m) from where they rest
// untouched.
constexpr float kSoftSinkShown = 0.005f;
visualization_msgs::Marker softSurfaceMarker(const SoftSurfaceState& surface, int id, const BodyColour& colour,
                                             const ros::Time& stamp)
{
  visualization_msgs::Marker m = marker("bodies", id, visualization_msgs::Marker::TRIANGLE_LIST, stamp);
  setPose(&m, Eigen::Isometry3d::Identity());
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color.r = colour.r;
  m.color.g = colour.g;
  m.color.b = colour.b;
  m.color.a = colour.a;
  const std::vector<Eigen::Vector3i>& triangles = *surface.triangles;
  m.points.reserve(3 * triangles.size());
  m.colors.reserve(3 * triangles.size());
  for (const Eigen::Vector3i& triangle : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d& p = surface.vertices[triangle[k]];
      geometry_msgs::Point point;
      point.x = p.x();
      point.y = p.y();
      point.z = p.z();
      m.points.push_back(point);
      const float depth = std::min(1.0f, surface.sink[triangle[k]] / kSoftSinkShown);
      std_msgs::ColorRGBA c;
      c.r = colour.r + depth * (0.75f - colour.r);
      c.g = colour.g + depth * (0.2f - colour.g);
      c.b = colour.b + depth * (0.25f - colour.b);
      c.a = colour.a;
      m.colors.push_back(c);
    }
  }
  return m;
}
}  // namespace

void appendBodyMarkers(const SceneDescription& scene, const WorldSnapshot& world, const ros::Time& stamp,
                       visualization_msgs::MarkerArray* markers)
{
  // rviz's DELETEALL clears every namespace: it goes first, and everything is sent again.
  markers->markers.push_back(deleteAll("", stamp));
  int moving_index = 0;  // among the free bodies
  for (std::size_t i = 0; i < world.bodies.size() && i < scene.bodies.size(); ++i)
  {
    const BodyDescription& body = scene.bodies[i];
    const BodyColour colour = bodyColour(body, moving_index);
    moving_index += body.is_static ? 0 : 1;
    if (body.soft)  // its surface as it is now (without the snapshot's surface: nothing to draw)
    {
      for (const SoftSurfaceState& surface : world.soft_surfaces)
      {
        if (surface.body == static_cast<int>(i) && surface.triangles)
        {
          markers->markers.push_back(softSurfaceMarker(surface, static_cast<int>(i), colour, stamp));
        }
      }
      continue;
    }
    if (body.visual_mesh)  // the true surface, over collision pieces that may be coarse hulls
    {
      markers->markers.push_back(geometryMarker(body.visual_mesh->geometry,
                                                world.bodies[i].pose * body.visual_mesh->origin, static_cast<int>(i),
                                                colour, stamp));
      continue;
    }
    // A compound's pieces after the first get ids past every body's (kMaxBodies apart).
    markers->markers.push_back(geometryMarker(body.geometry, world.bodies[i].pose * body.collision_origin,
                                              static_cast<int>(i), colour, stamp));
    for (std::size_t k = 0; k < body.more_parts.size(); ++k)
    {
      const BodyPart& part = body.more_parts[k];
      markers->markers.push_back(geometryMarker(part.geometry, world.bodies[i].pose * part.origin,
                                                static_cast<int>((k + 1) * kMaxBodies + i), colour, stamp));
    }
  }
}

bool isSupport(const BodyDescription& body)
{
  if (!body.is_static)
  {
    return false;
  }
  // A word of the name (split at anything not a letter or digit): "table", "table_top", "my/floor";
  // not "stable" or "vegetable".
  std::string word;
  for (const char c : body.name + " ")
  {
    if (std::isalnum(static_cast<unsigned char>(c)))
    {
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      continue;
    }
    if (word == "table" || word == "ground" || word == "floor" || word == "room" || word == "shelf")
    {
      return true;
    }
    word.clear();
  }
  return false;
}

BodyColour bodyColour(const BodyDescription& body, int moving_index)
{
  if (body.soft)
  {
    return {0.93f, 0.72f, 0.62f, 1.0f};  // flesh: a soft body, its dimple red (softSurfaceMarker)
  }
  if (isSupport(body))
  {
    return {0.55f, 0.45f, 0.35f, 1.0f};  // wood
  }
  if (body.is_static)
  {
    return {0.42f, 0.47f, 0.55f, 1.0f};  // slate: a fixed part (a holder, a rail)
  }
  // Light tints far from the fingers' yellow areas, the blue god-objects and the orange
  // sub-god-objects; the first is the demo's light blue ball.
  static const BodyColour kPalette[] = {
      {0.6f, 0.7f, 0.85f, 0.9f}, {0.95f, 0.55f, 0.5f, 0.9f}, {0.55f, 0.85f, 0.6f, 0.9f}, {0.75f, 0.6f, 0.95f, 0.9f},
      {0.45f, 0.8f, 0.8f, 0.9f}, {0.95f, 0.6f, 0.8f, 0.9f},  {0.8f, 0.85f, 0.5f, 0.9f},  {0.85f, 0.85f, 0.88f, 0.9f},
  };
  const int n = static_cast<int>(sizeof(kPalette) / sizeof(kPalette[0]));
  return kPalette[((moving_index % n) + n) % n];
}

FingerColour fingerColour(int interface)
{
  // Interface 0 keeps the one-finger demo's yellow; then colours far apart on dark grey.
  static const FingerColour kPalette[] = {
      {1.0f, 0.9f, 0.0f},  {0.0f, 0.85f, 1.0f}, {1.0f, 0.3f, 0.85f}, {0.45f, 1.0f, 0.3f}, {1.0f, 0.55f, 0.1f},
      {0.6f, 0.45f, 1.0f}, {1.0f, 1.0f, 1.0f},  {0.0f, 0.6f, 0.5f},  {1.0f, 0.6f, 0.6f},  {0.7f, 0.7f, 0.2f},
  };
  const int n = static_cast<int>(sizeof(kPalette) / sizeof(kPalette[0]));
  return kPalette[((interface % n) + n) % n];
}

void appendInteractionMarkers(const WorldSnapshot& world, double proxy_radius, const ros::Time& stamp,
                              visualization_msgs::MarkerArray* markers)
{
  visualization_msgs::Marker springs = marker("couplings", 0, visualization_msgs::Marker::LINE_LIST, stamp);
  springs.scale.x = 0.001;
  setColor(&springs, 0.2f, 0.9f, 0.2f);
  int area_id = 0;
  for (std::size_t i = 0; i < world.interfaces.size(); ++i)
  {
    const InterfaceState& state = world.interfaces[i];
    visualization_msgs::Marker proxy = marker("god_objects", i, visualization_msgs::Marker::SPHERE, stamp);
    proxy.pose.position = toPoint(state.proxy_position);
    proxy.scale.x = proxy.scale.y = proxy.scale.z = 2.0 * proxy_radius;
    setColor(&proxy, 0.1f, 0.3f, 1.0f);
    markers->markers.push_back(proxy);
    appendFingertip(state, proxy_radius, static_cast<int>(i), stamp, markers);

    visualization_msgs::Marker device = marker("interfaces", i, visualization_msgs::Marker::SPHERE, stamp);
    device.pose.position = toPoint(state.interface_position);
    device.scale.x = device.scale.y = device.scale.z = proxy_radius;
    setColor(&device, 0.2f, 0.9f, 0.2f, 0.8f);
    markers->markers.push_back(device);

    springs.points.push_back(toPoint(state.interface_position));
    springs.points.push_back(toPoint(state.proxy_position));

    visualization_msgs::Marker force = marker("forces", i, visualization_msgs::Marker::ARROW, stamp);
    force.points.push_back(toPoint(state.proxy_position));
    force.points.push_back(toPoint(state.proxy_position + 0.01 * state.user_force));
    force.scale.x = 0.001;
    force.scale.y = 0.002;
    force.scale.z = 0.003;
    setColor(&force, 1.0f, 0.2f, 0.2f);
    markers->markers.push_back(force);

    for (int c = 0; c < state.contact_count; ++c)
    {
      const WorldContactArea& area = state.contacts[c];
      const Eigen::Vector3d lift = kContactAreaLift * area.normal;
      visualization_msgs::Marker polygon =
          marker("contact_areas", area_id, visualization_msgs::Marker::TRIANGLE_LIST, stamp);
      const FingerColour colour = fingerColour(static_cast<int>(i));
      setColor(&polygon, colour.r, colour.g, colour.b);
      const int n = area.sub_god_object_count;
      for (int k = 0; n >= 2 && k < n; ++k)
      {
        polygon.points.push_back(toPoint(area.point + lift));
        polygon.points.push_back(toPoint(area.positions[k] + lift));
        polygon.points.push_back(toPoint(area.positions[(k + 1) % n] + lift));
      }
      if (!polygon.points.empty())
      {
        markers->markers.push_back(polygon);
      }
      visualization_msgs::Marker sgos =
          marker("sub_god_objects", area_id, visualization_msgs::Marker::SPHERE_LIST, stamp);
      sgos.scale.x = sgos.scale.y = sgos.scale.z = 0.0015;
      setColor(&sgos, 1.0f, 0.5f, 0.0f);
      for (int k = 0; k < n; ++k)
      {
        sgos.points.push_back(toPoint(area.positions[k] + lift));
      }
      if (!sgos.points.empty())
      {
        markers->markers.push_back(sgos);
      }
      ++area_id;
    }
  }
  markers->markers.push_back(springs);
}
}  // namespace god_finger
