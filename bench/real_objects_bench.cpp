// Real objects in budget (issue 27): real-style meshes of ours on a table, loaded and touched as a
// user's object files are, against the paper's box scene.
//
// Objects (written to a temporary folder as binary PLY, free bodies resting on a 1 m table):
//   box    the paper's scene: a 4 cm box (a primitive), the reference;
//   mug    a mug with its hollow and a ring handle (r 4 cm, 9 cm high, 5 mm wall), ~5k triangles;
//   bowl   a bowl (r 8 cm, 5 cm deep, 4 mm wall);
//   brick  a toy brick with studs (32 x 16 x 9.6 mm, 8 studs r 2.4 mm), one mesh of 9 closed parts;
//   scan   a scanned-size mesh: a 100,000-triangle torus (R 6 cm, r 2 cm).
// Benchmarks:
//   BM_Load/OBJECT/cached:0|1  one whole world construction (table + object) through
//       GodFingerWorld: first load with an empty hull cache (simplify, decompose, write the hulls),
//       cached with the hulls read from the disk cache. Targets: bench/targets.yaml's
//       real_objects.mug_first_load and real_objects.mug_cached_load (the 5k-triangle mug).
//   BM_Step/OBJECT/fingers:1|2/god_object:0|1  one world step (god_finger, or god_object: what
//       the pad adds) (manual time) while each finger, having
//       come down onto the object (the mug's and the bowl's inner floor, the brick's top between
//       its studs, the torus's top) and pressed 3 mm past its contact, drags 1 cm along y per
//       second. Counters: p50_us and p99_us of the timed steps, pad_error_um: the largest distance
//       of a sub-god-object from the object's true surface (the mesh as written, located by its
//       own tree) over the timed steps. Target: brick and scan one-finger p50 <= 2 x box's
//       (interleaved: --benchmark_enable_random_interleaving).
//   BM_ContactArea/OBJECT  one contact area (n_SGO = 8, location included) on the object's
//       walk mesh at the pressing finger's contact, as the world computes it.
#include "god_finger/contact/contact_area.h"
#include "god_finger/contact/radial_frame.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/mesh_io/mesh_writer.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/convex_decomposition.h"
#include "god_finger/scene/scene_file.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
enum Object
{
  kBox,
  kMug,
  kBowl,
  kBrick,
  kScan,
  kObjectCount
};
const char* const kNames[kObjectCount] = {"box", "mug", "bowl", "brick", "scan"};

const std::string& workFolder()
{
  static const std::string folder = []
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "god_finger_real_objects_XXXXXX").string();
    const std::string made = mkdtemp(pattern.data());
    std::atexit([] { std::filesystem::remove_all(workFolder()); });
    return made;
  }();
  return folder;
}

void append(TriangleSoup* to, const TriangleSoup& part, const Eigen::Vector3d& offset)
{
  const int base = static_cast<int>(to->vertices.size());
  for (const Eigen::Vector3d& v : part.vertices)
  {
    to->vertices.push_back(v + offset);
  }
  for (const std::array<int, 3>& t : part.triangles)
  {
    to->triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
}

// The object's mesh, its frame's origin on the table (z = 0 the object's lowest point).
TriangleSoup objectMesh(Object object)
{
  switch (object)
  {
    case kMug:
      return makeMug(0.04, 0.09, 0.005, 0.012, 208);
    case kBowl:
      return makePlate(0.08, 0.05, 0.004, 128);
    case kBrick:
    {
      TriangleSoup brick;
      append(&brick, makeBox(Eigen::Vector3d(0.016, 0.008, 0.0048)), Eigen::Vector3d(0, 0, 0.0048));
      for (int i = 0; i < 4; ++i)
      {
        for (int j = 0; j < 2; ++j)
        {
          // Studs standing on the top (9.6 mm), 1.7 mm high, sunk 0.1 mm into it.
          append(&brick, makeCylinder(0.0024, 0.0018, 24),
                 Eigen::Vector3d(-0.012 + 0.008 * i, -0.004 + 0.008 * j, 0.0096 + 0.0008));
        }
      }
      return brick;
    }
    case kScan:
    {
      TriangleSoup torus = makeTorus(0.06, 0.02, 250, 200);
      for (Eigen::Vector3d& v : torus.vertices)
      {
        v.z() += 0.02;
      }
      return torus;
    }
    default:
      return TriangleSoup();
  }
}

// Where each finger comes down (x, y in the object's frame): the second 12 mm from the first
// (16 mm on the brick).
Eigen::Vector2d pressPoint(Object object, int finger)
{
  const double spread = finger == 0 ? 0.0 : 0.012;
  switch (object)
  {
    case kBrick:
      return Eigen::Vector2d(-0.008 + spread * 4.0 / 3.0, 0.0);  // between the studs (x -8 and 8 mm, y 0)
    case kScan:
      return Eigen::Vector2d(0.06, spread);
    default:
      return Eigen::Vector2d(spread, 0.0);
  }
}

const std::string& meshPath(Object object)
{
  static std::map<int, std::string> paths;
  std::string& path = paths[object];
  if (path.empty())
  {
    path = workFolder() + "/" + kNames[object] + ".ply";
    writeTriangleSoup(objectMesh(object), path);
  }
  return path;
}

SceneDescription objectScene(Object object)
{
  SceneDescription scene;
  scene.name = kNames[object];
  scene.bodies.push_back(supportTable());  // the scene lists' table: 1 m x 1 m, its top z = 0
  if (object == kBox)
  {
    scene.bodies.push_back(boxBody("box", Eigen::Vector3d::Constant(0.04), 0.1, Eigen::Vector3d(0, 0, 0.0205)));
    return scene;
  }
  BodyDescription body;
  body.name = kNames[object];
  body.geometry.kind = GeometryKind::kMesh;
  body.geometry.mesh_path = meshPath(object);
  // The mesh's bounding box as a solid of 0.2 kg (the brick 2.5 g): inertia about its centre.
  const TriangleSoup soup = objectMesh(object);
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : soup.vertices)
  {
    box.extend(v);
  }
  const Eigen::Vector3d size = box.sizes();
  body.mass = object == kBrick ? 0.0025 : 0.2;
  body.inertia = (body.mass / 12.0 *
                  Eigen::Vector3d(size.y() * size.y() + size.z() * size.z(), size.x() * size.x() + size.z() * size.z(),
                                  size.x() * size.x() + size.y() * size.y()))
                     .asDiagonal();
  body.inertial_origin.translation() = box.center();
  body.pose.translation().z() = 0.0005;
  body.material.friction = 0.8;
  scene.bodies.push_back(body);
  return scene;
}

void useCache(const std::string& name)
{
  const std::string cache = workFolder() + "/" + name;
  setenv("GOD_FINGER_CACHE_DIR", cache.c_str(), 1);
}

void BM_Load(benchmark::State& state)
{
  const Object object = static_cast<Object>(state.range(0));
  const bool cached = state.range(1) != 0;
  const SceneDescription scene = objectScene(object);
  const std::string cache = std::string(cached ? "cached_" : "first_") + kNames[object];
  useCache(cache);
  if (cached)
  {
    clearProcessDecompositionCache();
    GodFingerWorld warm(scene, WorldParams());  // fills the disk cache
  }
  for (auto _ : state)
  {
    state.PauseTiming();
    clearProcessDecompositionCache();
    if (!cached)
    {
      std::filesystem::remove_all(workFolder() + "/" + cache);
    }
    state.ResumeTiming();
    GodFingerWorld world(scene, WorldParams());
    benchmark::DoNotOptimize(world.bodyCount());
  }
  state.counters["triangles"] = static_cast<double>(objectMesh(object).triangles.size());
  state.SetLabel(kNames[object]);
}

// The object's true surface (its mesh as written) with its tree, in the object's frame.
struct TrueSurface
{
  TriangleMesh mesh;
  std::unique_ptr<SurfaceLocator> locator;
};

const TrueSurface& trueSurface(Object object)
{
  static std::map<int, std::unique_ptr<TrueSurface>> cache;
  std::unique_ptr<TrueSurface>& entry = cache[object];
  if (!entry)
  {
    entry = std::make_unique<TrueSurface>();
    entry->mesh = TriangleMesh::build(objectMesh(object));
    entry->locator = std::make_unique<SurfaceLocator>(entry->mesh);
  }
  return *entry;
}

// A world with `fingers` fingers pressing the object 3 mm past their contacts, ready to drag.
struct Pressing
{
  std::unique_ptr<GodFingerWorld> world;
  std::vector<Eigen::Vector3d> targets;  // m, world
};

Pressing press(Object object, int fingers, ContactModel model = ContactModel::kGodFinger)
{
  useCache(std::string("cached_") + kNames[object]);
  Pressing result;
  WorldParams params;
  params.model = model;
  result.world = std::make_unique<GodFingerWorld>(objectScene(object), params);
  GodFingerWorld& world = *result.world;
  for (int i = 0; i < 500; ++i)  // the object settles on the table
  {
    world.step();
  }
  const double start = 0.13;
  for (int f = 0; f < fingers; ++f)
  {
    const Eigen::Vector2d xy = pressPoint(object, f);
    result.targets.emplace_back(xy.x(), xy.y(), start);
    world.addInterface(result.targets.back());
  }
  // Down 1 mm per 4 steps until a contact, then 3 mm past it.
  std::vector<bool> pressed(fingers, false);
  for (int i = 0; i < 4000 && std::find(pressed.begin(), pressed.end(), false) != pressed.end(); ++i)
  {
    for (int f = 0; f < fingers; ++f)
    {
      if (!pressed[f])
      {
        if (world.interfaceState(f).contact_count > 0)
        {
          pressed[f] = true;
          result.targets[f].z() = world.interfaceState(f).proxy_position.z() - 0.003;
        }
        else
        {
          result.targets[f].z() -= 0.00025;
        }
      }
      world.setInterfaceTarget(f, result.targets[f]);
    }
    world.step();
  }
  for (int i = 0; i < 300; ++i)
  {
    world.step();
  }
  return result;
}

void BM_Step(benchmark::State& state)
{
  const Object object = static_cast<Object>(state.range(0));
  const int fingers = static_cast<int>(state.range(1));
  const ContactModel model = state.range(2) == 0 ? ContactModel::kGodFinger : ContactModel::kGodObject;
  Pressing pressing = press(object, fingers, model);
  GodFingerWorld& world = *pressing.world;
  const TrueSurface* surface = object == kBox ? nullptr : &trueSurface(object);
  std::vector<double> times;
  double pad_error = 0.0;
  long touching = 0;
  for (auto _ : state)
  {
    for (int f = 0; f < fingers; ++f)
    {
      pressing.targets[f].y() += 1e-5;  // 1 cm/s
      world.setInterfaceTarget(f, pressing.targets[f]);
    }
    // The step's contact areas are made with the object where the step begins.
    const Eigen::Isometry3d to_object = world.bodyState(1).pose.inverse();
    const auto begin = std::chrono::steady_clock::now();
    world.step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    state.SetIterationTime(seconds);
    times.push_back(seconds);
    for (int f = 0; f < fingers; ++f)
    {
      const InterfaceState& finger = world.interfaceState(f);
      for (int c = 0; c < finger.contact_count; ++c)
      {
        const WorldContactArea& area = finger.contacts[c];
        if (area.body != 1)
        {
          continue;
        }
        ++touching;
        for (int s = 0; surface && s < area.sub_god_object_count; ++s)
        {
          const Eigen::Vector3d local = to_object * area.positions[s];
          pad_error = std::max(pad_error, (surface->locator->closest(local).point - local).norm());
        }
      }
    }
  }
  std::sort(times.begin(), times.end());
  state.counters["p50_us"] = 1e6 * times[times.size() / 2];
  state.counters["p99_us"] = 1e6 * times[std::min(times.size() - 1, times.size() * 99 / 100)];
  state.counters["pad_error_um"] = 1e6 * pad_error;
  state.counters["touching"] = static_cast<double>(touching) / static_cast<double>(times.size());
  state.SetLabel(kNames[object]);
}

void BM_ContactArea(benchmark::State& state)
{
  const Object object = static_cast<Object>(state.range(0));
  Pressing pressing = press(object, 1);
  const InterfaceState& finger = pressing.world->interfaceState(0);
  if (finger.contact_count == 0)
  {
    state.SkipWithError("the finger touches nothing");
    return;
  }
  const WorldContactArea& contact = finger.contacts[0];
  const Eigen::Isometry3d to_object = pressing.world->bodyState(contact.body).pose.inverse();
  const TrueSurface& surface = trueSurface(object);
  const Eigen::Vector3d point = to_object * contact.point;
  const Eigen::Vector3d normal = to_object.linear() * contact.normal;
  ContactParams params;
  ContactAreaResult area;
  for (auto _ : state)
  {
    ContactQuery query;
    query.location = surface.locator->closest(point);
    query.normal = normal;
    query.depth = contact.depth;
    query.coupling = -3.0 * params.distance_constant * normal;
    computeContactArea(surface.mesh, query, params, &area);
    benchmark::DoNotOptimize(area);
  }
  state.counters["triangles"] = surface.mesh.triangleCount();
  state.counters["sgo_active"] = area.active;
  state.SetLabel(kNames[object]);
}
}  // namespace

BENCHMARK(BM_Load)
    ->ArgsProduct({{kMug, kBowl, kBrick, kScan}, {0}})
    ->ArgNames({"object", "cached"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK(BM_Load)
    ->ArgsProduct({{kMug, kBowl, kBrick, kScan}, {1}})
    ->ArgNames({"object", "cached"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();
BENCHMARK(BM_Step)
    ->ArgsProduct({{kBox, kMug, kBowl, kBrick, kScan}, {1, 2}, {0, 1}})
    ->ArgNames({"object", "fingers", "god_object"})
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(2000)
    ->UseManualTime();
BENCHMARK(BM_ContactArea)->DenseRange(kMug, kScan)->ArgName("object")->Unit(benchmark::kMicrosecond)->MinTime(0.2);
}  // namespace god_finger

BENCHMARK_MAIN();
