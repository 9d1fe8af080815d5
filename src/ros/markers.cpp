#include "markers.h"

#include "god_finger/ros/conversions.h"

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

visualization_msgs::Marker deleteAll(const std::string& ns, const ros::Time& stamp)
{
  visualization_msgs::Marker m = marker(ns, 0, visualization_msgs::Marker::CUBE, stamp);
  m.action = visualization_msgs::Marker::DELETEALL;
  return m;
}
}  // namespace

void appendBodyMarkers(const SceneDescription& scene, const WorldSnapshot& world, const ros::Time& stamp,
                       visualization_msgs::MarkerArray* markers)
{
  // rviz's DELETEALL clears every namespace: it goes first, and everything is sent again.
  markers->markers.push_back(deleteAll("", stamp));
  for (std::size_t i = 0; i < world.bodies.size() && i < scene.bodies.size(); ++i)
  {
    const BodyDescription& body = scene.bodies[i];
    const Eigen::Isometry3d geometry_pose = world.bodies[i].pose * body.collision_origin;
    visualization_msgs::Marker m = marker("bodies", i, visualization_msgs::Marker::CUBE, stamp);
    setPose(&m, geometry_pose);
    switch (body.geometry.kind)
    {
      case GeometryKind::kBox:
        m.scale.x = body.geometry.size.x();
        m.scale.y = body.geometry.size.y();
        m.scale.z = body.geometry.size.z();
        break;
      case GeometryKind::kSphere:
        m.type = visualization_msgs::Marker::SPHERE;
        m.scale.x = m.scale.y = m.scale.z = 2.0 * body.geometry.radius;
        break;
      case GeometryKind::kCylinder:
        m.type = visualization_msgs::Marker::CYLINDER;
        m.scale.x = m.scale.y = 2.0 * body.geometry.radius;
        m.scale.z = body.geometry.length;
        break;
      case GeometryKind::kMesh:
        m.type = visualization_msgs::Marker::MESH_RESOURCE;
        m.mesh_resource = "file://" + body.geometry.mesh_path;
        m.scale.x = body.geometry.scale.x();
        m.scale.y = body.geometry.scale.y();
        m.scale.z = body.geometry.scale.z();
        break;
    }
    if (body.is_static)
    {
      setColor(&m, 0.55f, 0.45f, 0.35f);
    }
    else
    {
      setColor(&m, 0.6f, 0.7f, 0.85f, 0.9f);
    }
    markers->markers.push_back(m);
  }
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
