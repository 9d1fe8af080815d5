// Time to load a scanned-size concave object as a dynamic body (issue 17, "Real objects load in
// seconds"): a 100,000-triangle torus (R = 6 cm, r = 2 cm, written to a binary PLY) on a table,
// through GodFingerWorld, as a user's scene does. First load: an empty hull cache folder and an
// empty process cache, so the file is read, the walk mesh built, the mesh simplified to
// 1500 triangles and decomposed by HACD, and the hulls written. Cached load: the hulls come
// from the disk cache (the process cache is cleared before each iteration). Targets:
// bench/targets.yaml's scene_load.first and scene_load.cached. One iteration is one whole world
// construction; counters: triangles of the file, hull files in the cache folder afterwards.
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/mesh_io/mesh_writer.h"
#include "god_finger/scene/convex_decomposition.h"
#include "god_finger/physics/god_finger_world.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace god_finger
{
namespace
{
constexpr int kMajorSegments = 250;
constexpr int kMinorSegments = 200;  // 2 * 250 * 200 = 100,000 triangles

// The folder holding the mesh file and the hull cache, made once and removed at exit.
const std::string& workFolder()
{
  static const std::string folder = []
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "god_finger_scene_load_XXXXXX").string();
    const std::string made = mkdtemp(pattern.data());
    writeTriangleSoup(makeTorus(0.06, 0.02, kMajorSegments, kMinorSegments), made + "/torus.ply");
    std::atexit([] { std::filesystem::remove_all(workFolder()); });
    return made;
  }();
  return folder;
}

SceneDescription torusScene()
{
  SceneDescription scene;
  scene.name = "scanned_torus";
  BodyDescription table;
  table.name = "table";
  table.is_static = true;
  table.geometry.size = Eigen::Vector3d(1.0, 1.0, 0.04);
  table.pose.translation().z() = -0.02;
  scene.bodies.push_back(table);
  BodyDescription torus;
  torus.name = "torus";
  torus.geometry.kind = GeometryKind::kMesh;
  torus.geometry.mesh_path = workFolder() + "/torus.ply";
  torus.mass = 0.1;
  torus.inertia = Eigen::Vector3d(2.0e-4, 2.0e-4, 3.9e-4).asDiagonal();
  torus.pose.translation().z() = 0.0205;
  scene.bodies.push_back(torus);
  return scene;
}

int hullFiles(const std::string& folder)
{
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
  {
    count += entry.path().extension() == ".hulls";
  }
  return count;
}

void load(benchmark::State& state, bool cached)
{
  const SceneDescription scene = torusScene();
  const std::string cache = workFolder() + (cached ? "/cached" : "/first");
  setenv("GOD_FINGER_CACHE_DIR", cache.c_str(), 1);
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
      std::filesystem::remove_all(cache);
    }
    state.ResumeTiming();
    GodFingerWorld world(scene, WorldParams());
    benchmark::DoNotOptimize(world.bodyCount());
  }
  state.counters["triangles"] = 2.0 * kMajorSegments * kMinorSegments;
  state.counters["hull_files"] = hullFiles(cache);
  unsetenv("GOD_FINGER_CACHE_DIR");
}

void BM_SceneLoadFirst(benchmark::State& state)
{
  load(state, false);
}
void BM_SceneLoadCached(benchmark::State& state)
{
  load(state, true);
}
}  // namespace

BENCHMARK(BM_SceneLoadFirst)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_SceneLoadCached)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
}  // namespace god_finger

BENCHMARK_MAIN();
