// rviz markers of a physics world, all in `world`: scene bodies (namespace "bodies": the table
// in wood, other fixed parts in slate, each free body in its own tint, bodyColour(); a body
// with a visual mesh as it, else every collision piece), each
// contact area as a filled polygon in its finger's colour ("contact_areas"; the first finger's
// yellow, fingerColour()), its sub-god-objects
// ("sub_god_objects"), god-objects ("god_objects") with the rest of their fingertip, a
// translucent finger body and a nail on the back ("fingertips": which way the pulp faces),
// interface points ("interfaces"),
// coupling springs ("couplings") and the force on the hand ("forces", 1 cm per newton).
#pragma once

#include "god_finger/physics/god_finger_world.h"

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

namespace god_finger
{
// Polygons are lifted this far (m) along their normal, above the surface they lie on.
constexpr double kContactAreaLift = 5e-4;

// The one palette of finger colours (RGB in [0, 1]): interface i's contact areas; interface 0
// yellow; repeats after 10.
struct FingerColour
{
  float r, g, b;
};
FingerColour fingerColour(int interface);

// A body's colour (RGBA in [0, 1]): a support (a fixed body named table, ground, floor, room or
// shelf) in wood, any other fixed body in slate, free body number `moving_index` (counted among
// the free bodies, in scene order) from a palette of 8 light tints, the first light blue.
struct BodyColour
{
  float r, g, b, a;
};
BodyColour bodyColour(const BodyDescription& body, int moving_index);

// A DELETEALL (rviz clears every namespace with it), then the bodies at their current poses.
// Call first, then appendInteractionMarkers: the whole picture is sent at each publish.
void appendBodyMarkers(const SceneDescription& scene, const WorldSnapshot& world, const ros::Time& stamp,
                       visualization_msgs::MarkerArray* markers);
// Contact areas, proxies (spheres of proxy_radius, m), interfaces, couplings and forces of
// every interface.
void appendInteractionMarkers(const WorldSnapshot& world, double proxy_radius, const ros::Time& stamp,
                              visualization_msgs::MarkerArray* markers);
}  // namespace god_finger
