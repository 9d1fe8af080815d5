// One pad per touched region: a concave body collides as a compound of convex hulls
// (collision_shape.h), and where two hulls meet under a finger each gives a contact at nearly the
// same point. The world must make one contact area of them, walked on the true surface. Scene:
// table_torus (a torus, R = 6 cm, r = 2 cm, 0.1 kg, dynamic, lying on the table).
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
TEST(TouchedRegion, AFingerPressingADecomposedTorusHasOneAreaEverywhere)
{
  const SceneDescription scene = loadUrdfScene(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_torus.urdf");
  const int torus = scene.find("torus");
  const double top = scene.bodies[torus].pose.translation().z() + 0.02;  // the tube's top
  int places_touched = 0;
  int most_areas = 0;
  for (int place = 0; place < 12; ++place)
  {
    SCOPED_TRACE("place " + std::to_string(place));
    // Over the tube's crest at 12 angles (hull seams lie at some of them), 1 cm above it, then
    // pressing 3 mm in over 0.2 s and holding 0.1 s.
    const double angle = 2.0 * M_PI * (place + 0.37) / 12.0;
    const Eigen::Vector3d crest(0.06 * std::cos(angle), 0.06 * std::sin(angle), top);
    GodFingerWorld world(scene, WorldParams());
    const double dt = world.params().time_step;
    const int finger = world.addInterface(crest + Eigen::Vector3d(0, 0, 0.01));
    bool touched = false;
    for (long i = 0; i < std::lround(0.3 / dt); ++i)
    {
      const double t = (i + 1) * dt;
      world.setInterfaceTarget(finger, crest + Eigen::Vector3d(0, 0, 0.01 - 0.013 * std::min(1.0, t / 0.2)));
      world.step();
      const InterfaceState& state = world.interfaceState(finger);
      most_areas = std::max(most_areas, state.contact_count);
      touched = touched || state.contact_count > 0;
    }
    const InterfaceState& state = world.interfaceState(finger);
    ASSERT_EQ(state.contact_count, 1);
    EXPECT_EQ(state.contacts[0].body, torus);
    // A full pad on the crest: most of r_max under ~1 N, every sub-god-object active.
    EXPECT_GT(state.contacts[0].radius, 0.5 * world.params().contact.max_radius);
    EXPECT_EQ(state.contacts[0].sub_god_object_count, world.params().contact.sub_god_objects);
    places_touched += touched ? 1 : 0;
  }
  EXPECT_EQ(places_touched, 12);
  EXPECT_EQ(most_areas, 1) << "two areas of one finger on one body at once";
}
}  // namespace
}  // namespace god_finger
