// A soft block on a table in the physics world (physics/soft_body.h): it starts settled under
// gravity and sleeps; a finger pressing it makes a dimple the proxy rides on (on the deformed
// surface, not sunk into the rest one); the dimple under the pad is the static elastic solution
// of the pad's pressure (checked against an ElasticBody of its own); a point contact (god_object)
// digs deeper than the pad under the same coupling; released, the block springs back and sleeps;
// a reset brings the settled surface back bit for bit; two fingers both load it and their
// overlapping areas are pushed apart as on a rigid body.
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/deformable_object.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/soft/block_mesh.h"
#include "god_finger/soft/elastic_body.h"
#include "god_finger/soft/soft_surface.h"
#include "god_finger/soft/surface_load.h"
#include "god_finger/soft/vtk_tet_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace god_finger
{
namespace
{
constexpr double kSide = 0.06;  // m: the block's side, resting on the table at z = 0

class SoftBodyWorld : public ::testing::Test
{
 protected:
  SoftBodyWorld()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "god_finger_soft_world_XXXXXX").string();
    folder_ = mkdtemp(pattern.data());
    BlockMeshSpec spec;
    spec.size = Eigen::Vector3d::Constant(kSide);
    spec.cells = {6, 6, 6};
    spec.grading = 1.5;
    std::ofstream(folder_ + "/block.vtk") << vtkTetMeshText(blockTetMesh(spec), "soft world test block");
    // E 20 kPa, nu 0.4 (mu, lambda its Lame parameters), 0.2 kg.
    std::ofstream(folder_ + "/scene.urdf")
        << "<robot name=\"soft\"><link name=\"world\"/>\n"
           "<link name=\"table\"><collision><geometry><box size=\"1 1 0.04\"/></geometry></collision></link>\n"
           "<joint name=\"j\" type=\"fixed\"><parent link=\"world\"/><child link=\"table\"/>"
           "<origin xyz=\"0 0 -0.02\"/></joint>\n"
           "<deformable name=\"block\"><inertial><mass value=\"0.2\"/></inertial><friction value=\"0.8\"/>"
           "<neohookean mu=\"7142.857142857143\" lambda=\"28571.428571428572\" damping=\"0.01\"/>"
           "<collision filename=\"block.vtk\"/></deformable>\n</robot>\n";
    scene_ = loadScene(folder_ + "/scene.urdf");
  }
  ~SoftBodyWorld() override
  {
    std::filesystem::remove_all(folder_);
  }

  // The soft body's surface now (world), from a snapshot.
  static SoftSurfaceState surface(const GodFingerWorld& world)
  {
    WorldSnapshot snapshot;
    world.snapshot(&snapshot);
    EXPECT_EQ(snapshot.soft_surfaces.size(), 1u);
    return snapshot.soft_surfaces.front();
  }
  static double deepestSink(const SoftSurfaceState& state)
  {
    double deepest = 0.0;
    for (const float sink : state.sink)
    {
      deepest = std::max(deepest, double(sink));
    }
    return deepest;
  }
  // The surface's height (m) right under (x, y): the highest vertex within 2 mm of that line.
  static double topAt(const SoftSurfaceState& state, double x, double y)
  {
    double top = -1.0;
    for (const Eigen::Vector3d& v : state.vertices)
    {
      if (std::hypot(v.x() - x, v.y() - y) < 2e-3)
      {
        top = std::max(top, v.z());
      }
    }
    return top;
  }

  std::string folder_;
  SceneDescription scene_;
};

TEST_F(SoftBodyWorld, StartsSettledAndSleeps)
{
  GodFingerWorld world(scene_, WorldParams());
  ASSERT_EQ(world.bodyCount(), 2);
  EXPECT_EQ(world.walkMesh(1).vertexCount(), static_cast<int>(surface(world).vertices.size()));
  // Settled under its weight (the top sank a little from the file's 6 cm), so nothing moves.
  const double settled_top = topAt(surface(world), 0.0, 0.0);
  EXPECT_LT(settled_top, kSide);
  EXPECT_GT(settled_top, kSide - 1e-3);
  for (int i = 0; i < 150; ++i)
  {
    world.step();
  }
  EXPECT_TRUE(world.bodyState(1).asleep);
  EXPECT_LT(deepestSink(surface(world)), 1e-9);
}

// Presses the top centre with the coupling's target `depth` below the settled top; returns the
// world after `steps` steps.
std::unique_ptr<GodFingerWorld> press(const SceneDescription& scene, ContactModel model, double depth, int steps)
{
  WorldParams params;
  params.model = model;
  auto world = std::make_unique<GodFingerWorld>(scene, params);
  const int finger = world->addInterface(Eigen::Vector3d(0.0, 0.0, kSide + 0.01));
  world->setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, kSide - depth));
  for (int i = 0; i < steps; ++i)
  {
    world->step();
  }
  return world;
}

TEST_F(SoftBodyWorld, APadPressMakesADimpleTheProxyRidesOnWithTheStaticSolutionsDepth)
{
  const std::unique_ptr<GodFingerWorld> world = press(scene_, ContactModel::kGodFinger, 0.012, 3000);
  const InterfaceState& finger = world->interfaceState(0);
  ASSERT_EQ(finger.contact_count, 1);
  EXPECT_EQ(finger.contacts[0].body, 1);
  const double force = finger.user_force.norm();
  const double radius = finger.contacts[0].radius;
  const SoftSurfaceState dimple = surface(*world);
  const double sink = deepestSink(dimple);
  const double top = topAt(dimple, 0.0, 0.0);
  const double proxy_radius = world->params().coupling.proxy_radius;
  std::printf("pad press: %.3f N on the hand, area radius %.2f mm, dimple %.3f mm, surface's top centre %.3f mm\n",
              force, 1e3 * radius, 1e3 * sink, 1e3 * top);
  // The hand feels the block: the coupling stretched, at rest.
  EXPECT_GT(force, 1.0);
  EXPECT_LT(finger.proxy_velocity.norm(), 1e-3);
  EXPECT_NEAR(force, world->params().coupling.stiffness * (finger.proxy_position - finger.interface_position).norm(),
              1e-6 * force + 1e-3);
  // A dimple of millimetres, and the proxy on it: its sphere touches the deformed surface (within
  // the contact's 0.3 mm), far below where the settled top was.
  EXPECT_GT(sink, 1e-3);
  const SurfaceLocator deformed(world->walkMesh(1));  // the body's frame is the world's here
  const double gap = deformed.closest(finger.proxy_position).distance - proxy_radius;
  std::printf("proxy sphere %.3f mm from the deformed surface\n", 1e3 * gap);
  EXPECT_NEAR(gap, 0.0, 3e-4);
  EXPECT_LT(finger.proxy_position.z() - proxy_radius, kSide - 1e-3);
  // The static solution of the same pad pressure on the same block, glued the same way: the
  // dimple's centre within 10 % (the world loads the deformed surface, the static solve the rest one).
  const DeformableDescription& soft = *scene_.bodies[1].soft;
  ElasticBody alone(soft.mesh, soft.material, nodesGluedToSupport(soft.mesh, Eigen::Isometry3d::Identity()), 1e-3,
                    Eigen::Vector3d::Zero());
  Eigen::VectorXd loads = Eigen::VectorXd::Zero(3 * alone.nodeCount());
  PadDisk pad;
  pad.centre = Eigen::Vector3d(0.0, 0.0, kSide);
  pad.radius = radius;
  ASSERT_GT(addPadPressure(soft.mesh.nodes, alone.surface(), pad, Eigen::Vector3d(0.0, 0.0, -force), &loads), 0.0);
  const Eigen::VectorXd u = alone.staticDisplacement(loads);
  const double expected = -surfaceDisplacementAt(soft.mesh.nodes, alone.surface(), u, pad.centre).z();
  std::printf("static solution of the same pad: %.3f mm\n", 1e3 * expected);
  EXPECT_NEAR(sink, expected, 0.1 * expected);
}

TEST_F(SoftBodyWorld, APointDigsDeeperThanThePadUnderTheSameCoupling)
{
  const std::unique_ptr<GodFingerWorld> pad = press(scene_, ContactModel::kGodFinger, 0.012, 3000);
  const std::unique_ptr<GodFingerWorld> point = press(scene_, ContactModel::kGodObject, 0.012, 3000);
  const double pad_sink = deepestSink(surface(*pad));
  const double point_sink = deepestSink(surface(*point));
  const double proxy_radius = point->params().coupling.proxy_radius;
  const SurfaceLocator deformed(point->walkMesh(1));
  const double gap = deformed.closest(point->interfaceState(0).proxy_position).distance - proxy_radius;
  std::printf("dimple: pad %.3f mm, point %.3f mm; the point's proxy %.3f mm from the surface\n", 1e3 * pad_sink,
              1e3 * point_sink, 1e3 * gap);
  EXPECT_GT(point_sink, 1.2 * pad_sink);
  EXPECT_NEAR(gap, 0.0, 3e-4);  // the point's proxy on the deformed surface too
}

// Two fingers on the block's top, 12 mm apart (their 1 cm areas overlap): each makes its dimple
// and feels the block, both loads reach it (deeper than one finger's), and the overlap push
// (WorldParams::overlap) drives them apart as on a rigid body; without it they stay.
TEST_F(SoftBodyWorld, TwoFingersPressTogetherAndTheirOverlappingAreasPushApart)
{
  const auto run = [this](double overlap_stiffness, double* one_finger_sink)
  {
    WorldParams params;
    params.overlap.stiffness = overlap_stiffness;
    GodFingerWorld world(scene_, params);
    const int left = world.addInterface(Eigen::Vector3d(-0.006, 0.0, kSide + 0.01));
    const int right = world.addInterface(Eigen::Vector3d(0.006, 0.0, kSide + 0.01));
    world.setInterfaceTarget(left, Eigen::Vector3d(-0.006, 0.0, kSide - 0.008));
    world.setInterfaceTarget(right, Eigen::Vector3d(0.006, 0.0, kSide - 0.008));
    double largest_overlap = 0.0;
    for (int i = 0; i < 2000; ++i)
    {
      world.step();
      largest_overlap = std::max(largest_overlap, world.interfaceState(left).overlap_area);
    }
    for (const int finger : {left, right})
    {
      EXPECT_EQ(world.interfaceState(finger).contact_count, 1);
      EXPECT_EQ(world.interfaceState(finger).contacts[0].body, 1);
      EXPECT_GT(world.interfaceState(finger).user_force.z(), 1.0);
    }
    EXPECT_GT(largest_overlap, 0.0);
    if (one_finger_sink != nullptr)
    {
      const std::unique_ptr<GodFingerWorld> one = press(scene_, ContactModel::kGodFinger, 0.008, 2000);
      *one_finger_sink = deepestSink(surface(*one));
    }
    return std::make_pair(
        world.interfaceState(right).proxy_position.x() - world.interfaceState(left).proxy_position.x(),
        deepestSink(surface(world)));
  };
  double one_finger_sink = 0.0;
  const auto [apart_pushed, sink_two] = run(WorldParams().overlap.stiffness, &one_finger_sink);
  const auto [apart_still, sink_still] = run(0.0, nullptr);
  std::printf(
      "two fingers: %.2f mm apart with the push, %.2f mm without; dimple %.2f mm with the push, %.2f mm without (one "
      "finger: %.2f mm)\n",
      1e3 * apart_pushed, 1e3 * apart_still, 1e3 * sink_two, 1e3 * sink_still, 1e3 * one_finger_sink);
  // Both loads reach the block: 12 mm apart, each finger's dimple deepens the other's.
  EXPECT_GT(sink_still, 1.2 * one_finger_sink);
  EXPECT_GT(sink_two, one_finger_sink);
  // No push: near where the hands put them, leaning a little into their shared dimple.
  EXPECT_NEAR(apart_still, 0.012, 2e-3);
  EXPECT_GT(apart_pushed, apart_still + 3e-3);  // pushed apart on the soft surface too
}

// A pad that sticks holds the material under it, not the point of space where it began to stick:
// a finger held still on the block while a second one presses beside it is carried with the
// surface the second one's dimple drags toward itself (its friction anchor, a material point of
// the block, moves with the block: physics/soft_body.h materialMotion). Anchored at the old
// point, it stayed where it was, and the block's surface slid under it by the dimple's pull.
TEST_F(SoftBodyWorld, APadThatSticksRidesTheMaterialTheSurfaceCarries)
{
  WorldParams params;
  GodFingerWorld world(scene_, params);
  const int held = world.addInterface(Eigen::Vector3d(-0.012, 0.0, kSide + 0.01));
  world.setInterfaceTarget(held, Eigen::Vector3d(-0.012, 0.0, kSide - 0.006));
  for (int i = 0; i < 1500; ++i)
  {
    world.step();
  }
  ASSERT_EQ(world.interfaceState(held).contact_count, 1);
  const Eigen::Vector3d before = world.interfaceState(held).proxy_position;
  // The material point under the held pad's centre: its face and barycentric weights now, followed.
  const std::vector<Eigen::Vector3d> surface_before = world.walkMesh(1).vertices();
  const SurfaceLocation on = SurfaceLocator(world.walkMesh(1)).closest(world.interfaceState(held).contacts[0].point);
  ASSERT_GE(on.face, 0);
  const Eigen::Vector3i face = world.walkMesh(1).triangles()[on.face];
  const auto materialX = [&](const std::vector<Eigen::Vector3d>& vertices)
  { return on.barycentric.dot(Eigen::Vector3d(vertices[face[0]].x(), vertices[face[1]].x(), vertices[face[2]].x())); };
  const double material_before = materialX(surface_before);
  const int pressing = world.addInterface(Eigen::Vector3d(0.008, 0.0, kSide + 0.01));
  world.setInterfaceTarget(pressing, Eigen::Vector3d(0.008, 0.0, kSide - 0.014));
  for (int i = 0; i < 2000; ++i)
  {
    world.step();
  }
  const double proxy_moved = world.interfaceState(held).proxy_position.x() - before.x();
  const double material_moved = materialX(world.walkMesh(1).vertices()) - material_before;
  std::printf("the second dimple drags the material under the held pad %.3f mm sideways; the pad moves %.3f mm\n",
              1e3 * material_moved, 1e3 * proxy_moved);
  // Toward the second finger, and the pad with it: measured 0.49 of 0.84 mm (left at its point
  // of space the pad moved -0.09 mm while the material slid 2.2 mm under it). The rest is the
  // friction rows' doing: they hold the relative velocity at the anchor, and pull the pad back
  // onto it only in part (the anchor's positional error), against the coupling's spring.
  EXPECT_GT(material_moved, 1e-4);
  EXPECT_GT(proxy_moved, 0.5 * material_moved);
  EXPECT_LE(proxy_moved, material_moved);  // dragged by the material, never past it
}

TEST_F(SoftBodyWorld, ReleasedItSpringsBackAndSleepsAndAResetRestoresItBitForBit)
{
  WorldParams params;
  GodFingerWorld world(scene_, params);
  const std::vector<Eigen::Vector3d> settled = world.walkMesh(1).vertices();
  const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, kSide + 0.01));
  world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, kSide - 0.01));
  for (int i = 0; i < 1000; ++i)
  {
    world.step();
  }
  ASSERT_GT(deepestSink(surface(world)), 1e-3);
  EXPECT_FALSE(world.bodyState(1).asleep);
  world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, kSide + 0.03));
  int steps = 0;
  while (!world.bodyState(1).asleep && steps < 5000)
  {
    world.step();
    ++steps;
  }
  std::printf("asleep %d steps after the release, deepest sink %.2e m\n", steps, deepestSink(surface(world)));
  EXPECT_TRUE(world.bodyState(1).asleep);
  EXPECT_LT(deepestSink(surface(world)), 2e-5);
  world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, kSide - 0.01));
  for (int i = 0; i < 300; ++i)
  {
    world.step();
  }
  EXPECT_FALSE(world.bodyState(1).asleep);  // touched again: awake
  world.reset();
  EXPECT_EQ(world.walkMesh(1).vertices(), settled);
}
}  // namespace
}  // namespace god_finger
