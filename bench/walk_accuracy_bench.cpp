// Speed against error of the walk: sub-god-object positions on tessellated spheres and
// cylinders of increasing resolution, per walk variant, against the exact geodesic on the
// smooth surface; time per contact (location + contact area) is the benchmark's time.
//
// The exact walks (contact/primitive_walk.h) run on the same contacts (BM_WalkSphereExact,
// BM_WalkCylinderExact), checked against the same closed forms written independently here.
//
// Counter error_um: mean distance (micrometres) between each sub-god-object and the point the
// exact geodesic reaches on the smooth surface, from the contact point pushed onto that
// surface, along the same radial direction made tangent there, over the same walked length.
// It includes the tessellation's sag (the mesh lies inside the smooth surface). Contacts: 256
// per case, a 1 cm pad (r_max 1 cm, 3 D0' of press: r = 9.5 mm) on a 4 cm ball or on the side
// of a 3 cm cylinder (the demo objects); no friction cone or angle limit, so walks run their
// full length.
#include "god_finger/contact/contact_area.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/contact/primitive_walk.h"
#include "god_finger/geometry/surface_locator.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

namespace god_finger
{
namespace
{
constexpr int kContacts = 256;
constexpr double kSphereRadius = 0.04;    // m
constexpr double kCylinderRadius = 0.03;  // m
constexpr double kCylinderLength = 0.12;  // m

ContactParams walkParams(WalkVariant walk)
{
  ContactParams params;
  params.walk = walk;
  params.distance_constant = 0.001;
  params.max_angle = M_PI;
  params.friction = std::numeric_limits<double>::infinity();
  return params;
}

// Exact geodesic endpoints on the smooth surfaces.
struct SmoothSphere
{
  double radius;
  Eigen::Vector3d endpoint(const Eigen::Vector3d& start, const Eigen::Vector3d& direction, double length) const
  {
    const Eigen::Vector3d p = start.normalized();
    const Eigen::Vector3d t = (direction - direction.dot(p) * p).normalized();
    return radius * (std::cos(length / radius) * p + std::sin(length / radius) * t);
  }
};

struct SmoothCylinder  // axis z
{
  double radius;
  Eigen::Vector3d endpoint(const Eigen::Vector3d& start, const Eigen::Vector3d& direction, double length) const
  {
    const double theta = std::atan2(start.y(), start.x());
    const Eigen::Vector3d around(-std::sin(theta), std::cos(theta), 0.0);
    const Eigen::Vector3d tangent = (direction.dot(around) * around + direction.z() * Eigen::Vector3d::UnitZ());
    const double a = tangent.dot(around) / tangent.norm();
    const double b = tangent.z() / tangent.norm();
    const double end_theta = theta + a * length / radius;
    return Eigen::Vector3d(radius * std::cos(end_theta), radius * std::sin(end_theta), start.z() + b * length);
  }
};

template <typename Smooth>
void runWalkCase(benchmark::State& state, const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& probes,
                 const Smooth& smooth)
{
  const SurfaceLocator locator(mesh);
  const ContactParams params = walkParams(state.range(1) == 0 ? WalkVariant::kProject : WalkVariant::kUnfold);
  ContactAreaResult area;
  auto contactAt = [&](int i)
  {
    const SurfaceLocation location = locator.closest(probes[i]);
    ContactQuery query;
    query.location = location;
    query.normal = mesh.normals()[location.face];
    query.coupling = -3.0 * params.distance_constant * query.normal;
    query.depth = 1e-4;
    computeContactArea(mesh, query, params, &area);
  };
  // Error, measured once outside the timed loop.
  double error_sum = 0.0;
  long sub_god_objects = 0;
  for (int i = 0; i < kContacts; ++i)
  {
    contactAt(i);
    for (int k = 0; k < area.count; ++k)
    {
      const SubGodObject& sgo = area.sub_god_objects[k];
      if (sgo.dropped())
      {
        continue;
      }
      error_sum += (sgo.position - smooth.endpoint(area.point, sgo.radial, sgo.walk.walked)).norm();
      ++sub_god_objects;
    }
  }
  int i = 0;
  for (auto _ : state)
  {
    contactAt(i);
    benchmark::DoNotOptimize(area);
    i = (i + 1) % kContacts;
  }
  state.counters["triangles"] = mesh.triangleCount();
  state.counters["error_um"] = sub_god_objects > 0 ? 1e6 * error_sum / sub_god_objects : NAN;
  state.counters["radius_mm"] = 1e3 * area.radius;
}

// The exact walk from the probes pushed onto the smooth surface (no location step).
template <typename Smooth>
void runExactCase(benchmark::State& state, const PrimitiveSurface& surface, const std::vector<Eigen::Vector3d>& probes,
                  const Smooth& smooth)
{
  const ContactParams params = walkParams(WalkVariant::kUnfold);
  std::vector<ContactQuery> queries;
  for (const Eigen::Vector3d& probe : probes)
  {
    ContactQuery query;
    query.normal = surface.kind == PrimitiveSurface::Kind::kSphere
                       ? probe.normalized()
                       : Eigen::Vector3d(probe.x(), probe.y(), 0.0).normalized();
    query.location.point = surface.kind == PrimitiveSurface::Kind::kSphere
                               ? Eigen::Vector3d(surface.radius * query.normal)
                               : Eigen::Vector3d(surface.radius * query.normal + probe.z() * Eigen::Vector3d::UnitZ());
    query.coupling = -3.0 * params.distance_constant * query.normal;
    query.depth = 1e-4;
    queries.push_back(query);
  }
  ContactAreaResult area;
  double error_sum = 0.0;
  long sub_god_objects = 0;
  for (const ContactQuery& query : queries)
  {
    computeContactArea(surface, query, params, &area);
    for (int k = 0; k < area.count; ++k)
    {
      const SubGodObject& sgo = area.sub_god_objects[k];
      error_sum += (sgo.position - smooth.endpoint(area.point, sgo.radial, sgo.walk.walked)).norm();
      ++sub_god_objects;
    }
  }
  int i = 0;
  for (auto _ : state)
  {
    computeContactArea(surface, queries[i], params, &area);
    benchmark::DoNotOptimize(area);
    i = (i + 1) % kContacts;
  }
  state.counters["triangles"] = 0;
  state.counters["error_um"] = sub_god_objects > 0 ? 1e6 * error_sum / sub_god_objects : NAN;
  state.counters["radius_mm"] = 1e3 * area.radius;
}

std::vector<Eigen::Vector3d> sphereProbes()
{
  std::mt19937_64 random(11);
  std::normal_distribution<double> gaussian;
  std::vector<Eigen::Vector3d> probes;
  for (int i = 0; i < kContacts; ++i)
  {
    probes.push_back(Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).normalized() *
                     (kSphereRadius - 0.002));
  }
  return probes;
}

std::vector<Eigen::Vector3d> cylinderProbes()
{
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> probes;
  for (int i = 0; i < kContacts; ++i)
  {
    const double theta = 2.0 * M_PI * unit(random);
    const double z = (unit(random) - 0.5) * 0.5 * kCylinderLength;  // away from the caps
    probes.emplace_back((kCylinderRadius - 0.002) * std::cos(theta), (kCylinderRadius - 0.002) * std::sin(theta), z);
  }
  return probes;
}

void BM_WalkSphereExact(benchmark::State& state)
{
  runExactCase(state, PrimitiveSurface{PrimitiveSurface::Kind::kSphere, kSphereRadius, 0.0}, sphereProbes(),
               SmoothSphere{kSphereRadius});
}

void BM_WalkCylinderExact(benchmark::State& state)
{
  runExactCase(state, PrimitiveSurface{PrimitiveSurface::Kind::kCylinder, kCylinderRadius, kCylinderLength},
               cylinderProbes(), SmoothCylinder{kCylinderRadius});
}

void BM_WalkSphere(benchmark::State& state)
{
  const TriangleMesh mesh = TriangleMesh::build(makeIcosphere(kSphereRadius, static_cast<int>(state.range(0))));
  runWalkCase(state, mesh, sphereProbes(), SmoothSphere{kSphereRadius});
}

void BM_WalkCylinder(benchmark::State& state)
{
  const TriangleMesh mesh =
      TriangleMesh::build(makeCylinder(kCylinderRadius, kCylinderLength, static_cast<int>(state.range(0))));
  runWalkCase(state, mesh, cylinderProbes(), SmoothCylinder{kCylinderRadius});
}
}  // namespace

BENCHMARK(BM_WalkSphere)->ArgsProduct({{2, 3, 4, 5, 6, 7}, {0, 1}})->ArgNames({"level", "walk"});
BENCHMARK(BM_WalkCylinder)->ArgsProduct({{12, 24, 48, 96, 192, 384, 768}, {0, 1}})->ArgNames({"segments", "walk"});
BENCHMARK(BM_WalkSphereExact);
BENCHMARK(BM_WalkCylinderExact);
}  // namespace god_finger

BENCHMARK_MAIN();
