// Cost of one contact: the god-object's closest-point location alone, and the god-finger's
// location + contact area, against mesh size, against n_SGO (3 to 64), per walk variant; plus
// memory per triangle. Google Benchmark; scripts/bench turns the JSON into bench/REPORT.md.
//
// Mesh size: square plates of 2 mm cells from 288 to 1.0 M triangles, contacts near the centre:
// the local resolution, hence the walks' edge crossings, stays the same while the mesh grows, so
// only the location's log(n) may grow. n_SGO and walk variant: a 4 cm ball (the demo's) of 81920
// triangles (0.66 mm edges; the `crossings` counter measures the edges crossed). Each
// iteration handles one of 256 precomputed contacts, pressed 3 D0' deep (r = 9.5 mm) with a
// tangential pull of 0 to 1.5 D0'. Counters: triangles, bytes_per_triangle (mesh + neighbour
// table + tree), sgo_active (sub-god-objects per contact).
#include "god_finger/contact/contact_area.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/contact/primitive_walk.h"
#include "god_finger/contact/radial_frame.h"
#include "god_finger/geometry/surface_locator.h"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <random>
#include <vector>

namespace god_finger
{
namespace
{
constexpr double kRadius = 0.04;  // m
constexpr int kContacts = 256;

struct MeshCase
{
  TriangleMesh mesh;
  std::unique_ptr<SurfaceLocator> locator;
  std::vector<Eigen::Vector3d> probes;  // points just inside the sphere (the proxy's interface)
};

constexpr double kCell = 0.002;  // m, plate cell size

// Meshes are cached across benchmarks: building the 1 M triangle one takes seconds.
// Positive keys: icosphere level; negative: plate of -key cells per side.
const MeshCase& meshCase(int key)
{
  static std::map<int, std::unique_ptr<MeshCase>> cache;
  auto& entry = cache[key];
  if (!entry)
  {
    entry = std::make_unique<MeshCase>();
    std::mt19937_64 random(7);
    std::normal_distribution<double> gaussian;
    if (key > 0)
    {
      entry->mesh = TriangleMesh::build(makeIcosphere(kRadius, key));
      for (int i = 0; i < kContacts; ++i)
      {
        const Eigen::Vector3d direction =
            Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).normalized();
        entry->probes.push_back(direction * (kRadius - 0.002));
      }
    }
    else
    {
      entry->mesh = TriangleMesh::build(makeGrid(0.5 * kCell * -key, -key));
      for (int i = 0; i < kContacts; ++i)
      {
        entry->probes.emplace_back(0.001 * gaussian(random), 0.001 * gaussian(random), -0.002);
      }
    }
    entry->locator = std::make_unique<SurfaceLocator>(entry->mesh);
  }
  return *entry;
}

ContactParams benchParams(int sub_god_objects, WalkVariant walk)
{
  ContactParams params;
  params.sub_god_objects = sub_god_objects;
  params.walk = walk;
  return params;
}

// The query the physics layer builds for a proxy at `probe`'s surface point.
ContactQuery queryAt(const SurfaceLocation& location, const TriangleMesh& mesh, double d0, int index)
{
  ContactQuery query;
  query.location = location;
  query.normal = mesh.normals()[location.face];
  const Eigen::Vector3d tangent = defaultTangent(query.normal);
  const double pull = (index % 4) * 0.5 * d0;  // 0 to 1.5 D0' sideways
  query.coupling = -3.0 * d0 * query.normal + pull * tangent;
  query.depth = 1e-4;
  return query;
}

void setCounters(benchmark::State& state, const MeshCase& sphere_case, double active)
{
  const double triangles = sphere_case.mesh.triangleCount();
  state.counters["triangles"] = triangles;
  state.counters["bytes_per_triangle"] =
      static_cast<double>(sphere_case.mesh.memoryBytes() + sphere_case.locator->memoryBytes()) / triangles;
  state.counters["sgo_active"] = active;
}

// God-object alone: the closest point (location, normal) of the proxy's contact.
void BM_GodObjectLocate(benchmark::State& state)
{
  const MeshCase& sphere_case = meshCase(static_cast<int>(state.range(0)));
  int i = 0;
  for (auto _ : state)
  {
    const SurfaceLocation location = sphere_case.locator->closest(sphere_case.probes[i]);
    benchmark::DoNotOptimize(location);
    i = (i + 1) % kContacts;
  }
  setCounters(state, sphere_case, 0.0);
}

// God-finger: the same location, then the contact area and its walks.
void BM_GodFingerContact(benchmark::State& state)
{
  const MeshCase& sphere_case = meshCase(static_cast<int>(state.range(0)));
  const ContactParams params =
      benchParams(static_cast<int>(state.range(1)), state.range(2) == 0 ? WalkVariant::kProject : WalkVariant::kUnfold);
  ContactAreaResult area;
  int i = 0;
  long active = 0;
  long contacts = 0;
  for (auto _ : state)
  {
    const SurfaceLocation location = sphere_case.locator->closest(sphere_case.probes[i]);
    computeContactArea(sphere_case.mesh, queryAt(location, sphere_case.mesh, params.distance_constant, i), params,
                       &area);
    benchmark::DoNotOptimize(area);
    active += area.active;
    ++contacts;
    i = (i + 1) % kContacts;
  }
  setCounters(state, sphere_case, contacts > 0 ? static_cast<double>(active) / contacts : 0.0);
}

// The contact area alone (location precomputed): what the walk costs.
void BM_ContactAreaOnly(benchmark::State& state)
{
  const MeshCase& sphere_case = meshCase(static_cast<int>(state.range(0)));
  const ContactParams params =
      benchParams(static_cast<int>(state.range(1)), state.range(2) == 0 ? WalkVariant::kProject : WalkVariant::kUnfold);
  std::vector<ContactQuery> queries;
  for (int k = 0; k < kContacts; ++k)
  {
    queries.push_back(
        queryAt(sphere_case.locator->closest(sphere_case.probes[k]), sphere_case.mesh, params.distance_constant, k));
  }
  ContactAreaResult area;
  long crossings = 0;
  for (int k = 0; k < kContacts; ++k)
  {
    computeContactArea(sphere_case.mesh, queries[k], params, &area);
    for (int s = 0; s < area.count; ++s)
    {
      crossings += area.sub_god_objects[s].walk.crossings;
    }
  }
  int i = 0;
  for (auto _ : state)
  {
    computeContactArea(sphere_case.mesh, queries[i], params, &area);
    benchmark::DoNotOptimize(area);
    i = (i + 1) % kContacts;
  }
  setCounters(state, sphere_case, area.active);
  // Edges crossed by all walks of one contact area, averaged over the contacts.
  state.counters["crossings"] = static_cast<double>(crossings) / kContacts;
}

// The exact walks (contact/primitive_walk.h), shape 0: the 4 cm ball's 256 contacts on the sphere
// itself; shape 1: a cylinder of radius 2 cm and length 10 cm, 256 contacts on its mantle and
// caps. Same pressing and pulls as the meshes'; no location needed (the contact point is the
// query).
void BM_ContactAreaExact(benchmark::State& state)
{
  const bool sphere = state.range(0) == 0;
  const PrimitiveSurface surface = sphere ? PrimitiveSurface{PrimitiveSurface::Kind::kSphere, kRadius, 0.0}
                                          : PrimitiveSurface{PrimitiveSurface::Kind::kCylinder, 0.02, 0.1};
  const ContactParams params = benchParams(static_cast<int>(state.range(1)), WalkVariant::kUnfold);
  std::mt19937_64 random(7);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<ContactQuery> queries;
  for (int k = 0; k < kContacts; ++k)
  {
    ContactQuery query;
    if (sphere)
    {
      query.normal = Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).normalized();
      query.location.point = kRadius * query.normal;
    }
    else if (k % 4 == 0)  // a cap
    {
      const double side = uniform(random) < 0.0 ? -1.0 : 1.0;
      query.normal = Eigen::Vector3d(0.0, 0.0, side);
      query.location.point = Eigen::Vector3d(0.01 * uniform(random), 0.01 * uniform(random), 0.05 * side);
    }
    else  // the mantle
    {
      const double theta = M_PI * uniform(random);
      query.normal = Eigen::Vector3d(std::cos(theta), std::sin(theta), 0.0);
      query.location.point = 0.02 * query.normal + Eigen::Vector3d(0.0, 0.0, 0.04 * uniform(random));
    }
    const double pull = (k % 4) * 0.5 * params.distance_constant;
    query.coupling = -3.0 * params.distance_constant * query.normal + pull * defaultTangent(query.normal);
    query.depth = 1e-4;
    queries.push_back(query);
  }
  ContactAreaResult area;
  int i = 0;
  for (auto _ : state)
  {
    computeContactArea(surface, queries[i], params, &area);
    benchmark::DoNotOptimize(area);
    i = (i + 1) % kContacts;
  }
  state.counters["sgo_active"] = area.active;
  state.SetLabel(sphere ? "sphere" : "cylinder");
}

// Plates of 12 to 708 cells per side: 288 to 1,002,528 triangles (keys are negative).
const int kPlateCells[] = {12, 24, 72, 224, 708};
void meshSizes(benchmark::internal::Benchmark* benchmark)
{
  for (int cells : kPlateCells)
  {
    benchmark->Args({-cells, 8, 1});
  }
}
void meshSizesLocate(benchmark::internal::Benchmark* benchmark)
{
  for (int cells : kPlateCells)
  {
    benchmark->Args({-cells});
  }
}
void subGodObjectCounts(benchmark::internal::Benchmark* benchmark)
{
  for (int count : {3, 4, 8, 16, 32, 64})
  {
    for (int walk : {0, 1})
    {
      benchmark->Args({6, count, walk});  // the ball, level 6: 81920 triangles
    }
  }
}
}  // namespace

BENCHMARK(BM_GodObjectLocate)->Apply(meshSizesLocate)->ArgNames({"mesh"});
BENCHMARK(BM_GodFingerContact)->Apply(meshSizes)->ArgNames({"mesh", "n_sgo", "walk"});
BENCHMARK(BM_ContactAreaOnly)->Apply(meshSizes)->ArgNames({"mesh", "n_sgo", "walk"});
BENCHMARK(BM_GodObjectLocate)->Args({6})->ArgNames({"mesh"});
BENCHMARK(BM_GodFingerContact)->Apply(subGodObjectCounts)->ArgNames({"mesh", "n_sgo", "walk"});
BENCHMARK(BM_ContactAreaOnly)->Args({6, 8, 1})->ArgNames({"mesh", "n_sgo", "walk"});
BENCHMARK(BM_ContactAreaExact)->ArgsProduct({{0, 1}, {8}})->ArgNames({"shape", "n_sgo"});
}  // namespace god_finger

BENCHMARK_MAIN();
