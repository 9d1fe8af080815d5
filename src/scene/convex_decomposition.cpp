#include "god_finger/scene/convex_decomposition.h"

#include "god_finger/scene/mesh_simplification.h"
#include "hull_cache.h"

#include <HACD/hacdHACD.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <mutex>

namespace god_finger
{
namespace
{
// Below this many triangles HACD takes under half a second: no progress line.
constexpr int kAnnounceAbove = 1000;

// Two independent 64-bit hashes (FNV-1a, and a splitmix64 chain) of the same bytes.
struct Hash128
{
  std::uint64_t fnv = 1469598103934665603ull;
  std::uint64_t mix = 0x9e3779b97f4a7c15ull;
  void add(const void* data, std::size_t size)
  {
    const unsigned char* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i)
    {
      fnv = (fnv ^ bytes[i]) * 1099511628211ull;
    }
    for (std::size_t i = 0; i < size; i += 8)
    {
      std::uint64_t word = 0;
      std::memcpy(&word, bytes + i, std::min<std::size_t>(8, size - i));
      std::uint64_t z = (mix ^ word) + 0x9e3779b97f4a7c15ull;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
      mix = z ^ (z >> 31);
    }
  }
};

HullSet runHacd(const TriangleSoup& soup)
{
  std::vector<HACD::Vec3<HACD::Real>> points;
  std::vector<HACD::Vec3<long>> triangles;
  points.reserve(soup.vertices.size());
  for (const Eigen::Vector3d& v : soup.vertices)
  {
    points.emplace_back(v.x(), v.y(), v.z());
  }
  for (const std::array<int, 3>& t : soup.triangles)
  {
    triangles.emplace_back(t[0], t[1], t[2]);
  }
  HACD::HACD hacd;
  hacd.SetPoints(points.data());
  hacd.SetNPoints(points.size());
  hacd.SetTriangles(triangles.data());
  hacd.SetNTriangles(triangles.size());
  // Bullet's ConvexDecompositionDemo settings: concavity in HACD's normalised units.
  hacd.SetCompacityWeight(0.1);
  hacd.SetVolumeWeight(0.0);
  hacd.SetNClusters(2);
  hacd.SetNVerticesPerCH(100);
  hacd.SetConcavity(100);
  hacd.SetAddExtraDistPoints(false);
  hacd.SetAddNeighboursDistPoints(false);
  hacd.SetAddFacesPoints(false);
  hacd.Compute();
  HullSet hulls;
  for (std::size_t c = 0; c < hacd.GetNClusters(); ++c)
  {
    std::vector<HACD::Vec3<HACD::Real>> hull_points(hacd.GetNPointsCH(c));
    std::vector<HACD::Vec3<long>> hull_triangles(hacd.GetNTrianglesCH(c));
    hacd.GetCH(c, hull_points.data(), hull_triangles.data());
    std::vector<Eigen::Vector3d> hull;
    for (const auto& p : hull_points)
    {
      hull.emplace_back(p.X(), p.Y(), p.Z());
    }
    if (hull.size() >= 4)
    {
      hulls.push_back(std::move(hull));
    }
  }
  return hulls;
}

std::string hex(std::uint64_t value)
{
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(value));
  return text;
}
}  // namespace

const char* decompositionSourceName(DecompositionSource source)
{
  switch (source)
  {
    case DecompositionSource::kComputed:
      return "computed";
    case DecompositionSource::kProcessCache:
      return "process cache";
    case DecompositionSource::kDiskCache:
      return "disk cache";
    case DecompositionSource::kGiven:
      return "as given";
  }
  return "?";
}

std::string decompositionKey(const TriangleMesh& mesh)
{
  Hash128 hash;
  const std::int32_t header[3] = {kDecompositionVersion, mesh.vertexCount(), mesh.triangleCount()};
  hash.add(header, sizeof(header));
  for (const Eigen::Vector3d& v : mesh.vertices())
  {
    const double xyz[3] = {v.x(), v.y(), v.z()};
    hash.add(xyz, sizeof(xyz));
  }
  for (const Eigen::Vector3i& t : mesh.triangles())
  {
    const std::int32_t corners[3] = {t[0], t[1], t[2]};
    hash.add(corners, sizeof(corners));
  }
  return hex(hash.fnv) + hex(hash.mix);
}

ConvexDecomposition decomposeConcaveMesh(const TriangleMesh& mesh, const std::string& label, const std::string& note)
{
  const double tolerance = kSimplificationTolerance * mesh.boundingBoxDiagonal();
  SimplifiedMesh simplified = simplifyMesh(mesh, kDecompositionTriangles, tolerance);
  const int triangles = static_cast<int>(simplified.soup.triangles.size());
  if (triangles >= kAnnounceAbove)
  {
    std::cerr << "god_finger: decomposing " << label << ": " << mesh.triangleCount() << " -> " << triangles
              << " triangles (" << note << ")" << std::endl;
  }
  ConvexDecomposition result;
  result.hulls = std::make_shared<const HullSet>(runHacd(simplified.soup));
  result.source = DecompositionSource::kComputed;
  result.input_triangles = mesh.triangleCount();
  result.decomposed_triangles = triangles;
  result.simplification_error = simplified.error;
  return result;
}

namespace
{
std::mutex process_mutex;
std::map<std::string, std::shared_ptr<const HullSet>> process_cache;
}  // namespace

namespace
{
// Each connected component's triangles (components joined through shared vertices).
std::vector<std::vector<int>> componentTriangles(const TriangleMesh& mesh)
{
  std::vector<int> parent(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    parent[v] = v;
  }
  const auto root = [&parent](int v)
  {
    while (parent[v] != v)
    {
      parent[v] = parent[parent[v]];
      v = parent[v];
    }
    return v;
  };
  for (const Eigen::Vector3i& t : mesh.triangles())
  {
    parent[root(t[1])] = root(t[0]);
    parent[root(t[2])] = root(t[0]);
  }
  std::map<int, std::vector<int>> by_root;
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    by_root[root(mesh.triangles()[t][0])].push_back(t);
  }
  std::vector<std::vector<int>> components;
  for (auto& entry : by_root)
  {
    components.push_back(std::move(entry.second));
  }
  return components;
}

// The corners of `triangles` when they bound a convex solid: no corner lies in front of any of
// their planes by more than `tolerance` (m); none otherwise.
std::optional<std::vector<Eigen::Vector3d>> convexPiece(const TriangleMesh& mesh, const std::vector<int>& triangles,
                                                        double tolerance)
{
  std::vector<int> corners;
  for (const int t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      corners.push_back(mesh.triangles()[t][k]);
    }
  }
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  for (const int t : triangles)
  {
    const Eigen::Vector3d a = mesh.corner(t, 0);
    const Eigen::Vector3d normal = (mesh.corner(t, 1) - a).cross(mesh.corner(t, 2) - a);
    const double length = normal.norm();
    if (length <= 0.0)
    {
      continue;  // a degenerate triangle has no plane
    }
    for (const int v : corners)
    {
      if ((mesh.vertices()[v] - a).dot(normal) / length > tolerance)
      {
        return std::nullopt;
      }
    }
  }
  std::vector<Eigen::Vector3d> points;
  for (const int v : corners)
  {
    points.push_back(mesh.vertices()[v]);
  }
  return points;
}
}  // namespace

std::optional<HullSet> givenConvexPieces(const TriangleMesh& mesh)
{
  const MeshHealth& health = mesh.health();
  if (health.boundary_edges != 0 || health.non_manifold_edges != 0)
  {
    return std::nullopt;  // pieces must be closed solids
  }
  const std::vector<std::vector<int>> components = componentTriangles(mesh);
  if (components.size() < 2 || components.size() > static_cast<std::size_t>(kMaxGivenPieces))
  {
    return std::nullopt;
  }
  const double tolerance = kGivenPieceTolerance * mesh.boundingBoxDiagonal();
  HullSet pieces;
  for (const std::vector<int>& triangles : components)
  {
    if (triangles.size() > static_cast<std::size_t>(kMaxGivenPieceTriangles))
    {
      return std::nullopt;
    }
    std::optional<std::vector<Eigen::Vector3d>> piece = convexPiece(mesh, triangles, tolerance);
    if (!piece)
    {
      return std::nullopt;
    }
    pieces.push_back(std::move(*piece));
  }
  return pieces;
}

ConvexDecomposition cachedConvexDecomposition(const TriangleMesh& mesh, const std::string& label)
{
  if (std::optional<HullSet> given = givenConvexPieces(mesh))
  {
    ConvexDecomposition result;
    result.input_triangles = mesh.triangleCount();
    result.hulls = std::make_shared<const HullSet>(std::move(*given));
    result.source = DecompositionSource::kGiven;
    return result;
  }
  const std::string key = decompositionKey(mesh);
  // One decomposition at a time: two bodies of one mesh then compute it once.
  std::lock_guard<std::mutex> lock(process_mutex);
  ConvexDecomposition result;
  result.input_triangles = mesh.triangleCount();
  const auto found = process_cache.find(key);
  if (found != process_cache.end())
  {
    result.hulls = found->second;
    result.source = DecompositionSource::kProcessCache;
    return result;
  }
  const std::string directory = hullCacheDirectory();
  if (std::optional<HullSet> stored = readHullCache(directory, key))
  {
    result.hulls = std::make_shared<const HullSet>(std::move(*stored));
    result.source = DecompositionSource::kDiskCache;
  }
  else
  {
    result = decomposeConcaveMesh(
        mesh, label, directory.empty() ? "first load; no cache folder" : "first load; cached in " + directory);
    if (!result.hulls->empty())
    {
      writeHullCache(directory, key, *result.hulls);
    }
  }
  process_cache[key] = result.hulls;
  return result;
}

void clearProcessDecompositionCache()
{
  std::lock_guard<std::mutex> lock(process_mutex);
  process_cache.clear();
}
}  // namespace god_finger
