#include "god_finger/geometry/triangle_mesh.h"

#include "god_finger/support/input_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <sstream>
#include <tuple>
#include <unordered_map>

namespace god_finger
{
namespace
{
struct EdgeRecord
{
  int low;
  int high;
  int triangle;
  int local;  // edge k of the triangle: corner k -> corner k+1
  bool operator<(const EdgeRecord& other) const
  {
    return std::tie(low, high, triangle, local) < std::tie(other.low, other.high, other.triangle, other.local);
  }
};

std::vector<EdgeRecord> sortedEdges(const std::vector<Eigen::Vector3i>& triangles)
{
  std::vector<EdgeRecord> edges;
  edges.reserve(3 * triangles.size());
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = triangles[t][k];
      const int b = triangles[t][(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), t, k});
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

// Welds vertices closer than `tolerance` (grid hashing; the first vertex of a cluster wins).
std::vector<int> weld(const std::vector<Eigen::Vector3d>& vertices, double tolerance,
                      std::vector<Eigen::Vector3d>* kept)
{
  std::vector<int> map(vertices.size());
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  const double cell = tolerance > 0.0 ? tolerance : 1.0;
  // Unsigned arithmetic: the hash may wrap (signed overflow would be undefined; found by
  // test/fuzz/walk_fuzz with coordinates far larger than the tolerance).
  auto key = [](std::int64_t x, std::int64_t y, std::int64_t z)
  {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(x) * 73856093u) ^
                                     (static_cast<std::uint64_t>(y) * 19349663u) ^
                                     (static_cast<std::uint64_t>(z) * 83492791u));
  };
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const Eigen::Vector3d& v = vertices[i];
    // Clamped so that the conversion is defined for any finite coordinate (cells that far out
    // are shared, which costs only comparisons).
    auto cellOf = [cell](double coordinate)
    { return static_cast<std::int64_t>(std::clamp(std::floor(coordinate / cell), -4e18, 4e18)); };
    const std::int64_t cx = cellOf(v.x());
    const std::int64_t cy = cellOf(v.y());
    const std::int64_t cz = cellOf(v.z());
    int found = -1;
    for (int dx = -1; dx <= 1 && found < 0; ++dx)
    {
      for (int dy = -1; dy <= 1 && found < 0; ++dy)
      {
        for (int dz = -1; dz <= 1 && found < 0; ++dz)
        {
          const auto bucket = grid.find(key(cx + dx, cy + dy, cz + dz));
          if (bucket == grid.end())
          {
            continue;
          }
          for (int candidate : bucket->second)
          {
            if (((*kept)[candidate] - v).norm() <= tolerance)
            {
              found = candidate;
              break;
            }
          }
        }
      }
    }
    if (found < 0)
    {
      found = static_cast<int>(kept->size());
      kept->push_back(v);
      grid[key(cx, cy, cz)].push_back(found);
    }
    map[i] = found;
  }
  return map;
}

// True when triangle t has the directed edge a -> b.
bool hasDirectedEdge(const Eigen::Vector3i& t, int a, int b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (t[k] == a && t[(k + 1) % 3] == b)
    {
      return true;
    }
  }
  return false;
}

struct BoundingBox
{
  Eigen::Vector3d lower;
  Eigen::Vector3d upper;
};

// Stage 1: the soup's checks (finite coordinates, indices in range, some triangle); its
// bounding box.
BoundingBox checkedBoundingBox(const TriangleSoup& soup)
{
  BoundingBox box;
  box.lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  box.upper = -box.lower;
  for (std::size_t i = 0; i < soup.vertices.size(); ++i)
  {
    const Eigen::Vector3d& v = soup.vertices[i];
    if (!v.allFinite())
    {
      std::ostringstream message;
      message << "vertex " << i << " has a non-finite coordinate (" << v.x() << ", " << v.y() << ", " << v.z() << ")";
      throw InputError(message.str());
    }
    box.lower = box.lower.cwiseMin(v);
    box.upper = box.upper.cwiseMax(v);
  }
  const int vertex_count = static_cast<int>(soup.vertices.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int index = soup.triangles[t][k];
      if (index < 0 || index >= vertex_count)
      {
        std::ostringstream message;
        message << "triangle " << t << " refers to vertex " << index << ", out of range [0, " << vertex_count << ")";
        throw InputError(message.str());
      }
    }
  }
  if (soup.triangles.empty())
  {
    throw InputError("no triangles");
  }
  return box;
}

// The triangles kept so far (corners index the welded vertices) and, per kept triangle, its
// index in the input.
struct KeptTriangles
{
  std::vector<Eigen::Vector3i> triangles;
  std::vector<int> source;
};

// Stage 3: the soup's triangles on the welded vertices (`remap`: input vertex -> welded one),
// without degenerate ones (a repeated corner, or too little area for their longest edge).
KeptTriangles dropDegenerate(const TriangleSoup& soup, const std::vector<int>& remap,
                             const std::vector<Eigen::Vector3d>& welded, const MeshBuildOptions& options,
                             MeshHealth* health)
{
  KeptTriangles kept;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const Eigen::Vector3i corners(remap[soup.triangles[t][0]], remap[soup.triangles[t][1]],
                                  remap[soup.triangles[t][2]]);
    if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2])
    {
      ++health->degenerate_triangles;
      continue;
    }
    const Eigen::Vector3d& a = welded[corners[0]];
    const Eigen::Vector3d& b = welded[corners[1]];
    const Eigen::Vector3d& c = welded[corners[2]];
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if (!((b - a).cross(c - a).norm() >= options.relative_area_tolerance * longest) || longest == 0.0)
    {
      ++health->degenerate_triangles;
      continue;
    }
    kept.triangles.push_back(corners);
    kept.source.push_back(static_cast<int>(t));
  }
  return kept;
}

// Stage 4: drops triangles on the same three vertices as an earlier one (whatever their
// winding); throws when none is left.
void dropDuplicates(KeptTriangles* kept, MeshHealth* health)
{
  std::vector<Eigen::Vector3i>& triangles = kept->triangles;
  std::vector<int>& source = kept->source;
  std::vector<std::array<int, 4>> keys;  // sorted corners + index
  keys.reserve(triangles.size());
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
  {
    std::array<int, 3> sorted = {triangles[t][0], triangles[t][1], triangles[t][2]};
    std::sort(sorted.begin(), sorted.end());
    keys.push_back({sorted[0], sorted[1], sorted[2], t});
  }
  std::sort(keys.begin(), keys.end());
  std::vector<bool> duplicate(triangles.size(), false);
  for (std::size_t i = 1; i < keys.size(); ++i)
  {
    if (keys[i][0] == keys[i - 1][0] && keys[i][1] == keys[i - 1][1] && keys[i][2] == keys[i - 1][2])
    {
      duplicate[keys[i][3]] = true;  // keys sorted by index last: the first one is kept
    }
  }
  std::vector<Eigen::Vector3i> unique_triangles;
  std::vector<int> unique_source;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (duplicate[t])
    {
      ++health->duplicate_triangles;
      continue;
    }
    unique_triangles.push_back(triangles[t]);
    unique_source.push_back(source[t]);
  }
  triangles.swap(unique_triangles);
  source.swap(unique_source);
  if (triangles.empty())
  {
    throw InputError("no non-degenerate triangles (" + std::to_string(health->input_triangles) +
                     " in the input, all degenerate or repeated)");
  }
}

// The neighbour table (TriangleMesh::neighbours()) of `triangles`, and its edge counts.
struct Adjacency
{
  std::vector<Eigen::Vector3i> neighbours;
  int boundary = 0;
  int non_manifold = 0;
};

Adjacency adjacencyOf(const std::vector<Eigen::Vector3i>& triangles)
{
  Adjacency adjacency;
  std::vector<Eigen::Vector3i>& neighbours = adjacency.neighbours;
  neighbours.assign(triangles.size(), Eigen::Vector3i(TriangleMesh::kBoundaryEdge, TriangleMesh::kBoundaryEdge,
                                                      TriangleMesh::kBoundaryEdge));
  const std::vector<EdgeRecord> edges = sortedEdges(triangles);
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i;
    while (j < edges.size() && edges[j].low == edges[i].low && edges[j].high == edges[i].high)
    {
      ++j;
    }
    const std::size_t count = j - i;
    if (count == 1)
    {
      ++adjacency.boundary;
    }
    else if (count == 2)
    {
      neighbours[edges[i].triangle][edges[i].local] = edges[i + 1].triangle;
      neighbours[edges[i + 1].triangle][edges[i + 1].local] = edges[i].triangle;
    }
    else
    {
      ++adjacency.non_manifold;
      for (std::size_t e = i; e < j; ++e)
      {
        neighbours[edges[e].triangle][edges[e].local] = TriangleMesh::kNonManifoldEdge;
      }
    }
    i = j;
  }
  return adjacency;
}

// The components connected through manifold edges: per triangle, its component.
struct Components
{
  std::vector<int> of_triangle;
  int count = 0;
};

// Stage 5: consistent winding by breadth-first search over the manifold edges of each
// component (its seed's winding wins); `flipped` records each triangle's reversals.
Components windConsistently(std::vector<Eigen::Vector3i>* triangles_in, std::vector<Eigen::Vector3i>* neighbours_in,
                            std::vector<bool>* flipped)
{
  std::vector<Eigen::Vector3i>& triangles = *triangles_in;
  std::vector<Eigen::Vector3i>& neighbours = *neighbours_in;
  const int n = static_cast<int>(triangles.size());
  Components components;
  std::vector<int>& component = components.of_triangle;
  component.assign(n, -1);
  for (int seed = 0; seed < n; ++seed)
  {
    if (component[seed] >= 0)
    {
      continue;
    }
    std::queue<int> queue;
    queue.push(seed);
    component[seed] = components.count;
    while (!queue.empty())
    {
      const int t = queue.front();
      queue.pop();
      for (int k = 0; k < 3; ++k)
      {
        const int u = neighbours[t][k];
        if (u < 0 || component[u] >= 0)
        {
          continue;
        }
        const int a = triangles[t][k];
        const int b = triangles[t][(k + 1) % 3];
        // Consistent neighbours run the shared edge the other way (b -> a).
        if (hasDirectedEdge(triangles[u], a, b))
        {
          // Swapping corners 1 and 2 reverses the triangle: its edge 0 becomes the old edge 2
          // and edge 2 the old edge 0, so the neighbour row is permuted alike.
          std::swap(triangles[u][1], triangles[u][2]);
          std::swap(neighbours[u][0], neighbours[u][2]);
          (*flipped)[u] = !(*flipped)[u];
        }
        component[u] = components.count;
        queue.push(u);
      }
    }
    ++components.count;
  }
  return components;
}

// Stage 6: closed components with negative volume (relative to `origin`, so that far-away
// meshes keep their precision) are inside out: flips them whole. True if any was.
bool flipInsideOut(const std::vector<Eigen::Vector3d>& welded, const Eigen::Vector3d& origin,
                   const Components& components, const std::vector<Eigen::Vector3i>& neighbours,
                   std::vector<Eigen::Vector3i>* triangles_in, std::vector<bool>* flipped)
{
  std::vector<Eigen::Vector3i>& triangles = *triangles_in;
  const std::vector<int>& component = components.of_triangle;
  const int n = static_cast<int>(triangles.size());
  std::vector<double> volume(components.count, 0.0);
  std::vector<bool> closed(components.count, true);
  for (int t = 0; t < n; ++t)
  {
    const Eigen::Vector3d& a = welded[triangles[t][0]];
    const Eigen::Vector3d& b = welded[triangles[t][1]];
    const Eigen::Vector3d& c = welded[triangles[t][2]];
    volume[component[t]] += (a - origin).dot((b - origin).cross(c - origin)) / 6.0;
    for (int k = 0; k < 3; ++k)
    {
      if (neighbours[t][k] < 0)
      {
        closed[component[t]] = false;
      }
    }
  }
  bool any_inverted = false;
  for (int t = 0; t < n; ++t)
  {
    if (closed[component[t]] && volume[component[t]] < 0.0)
    {
      std::swap(triangles[t][1], triangles[t][2]);
      (*flipped)[t] = !(*flipped)[t];
      any_inverted = true;
    }
  }
  return any_inverted;
}

// Manifold edges whose two triangles still run them the same way (a non-orientable surface).
int inconsistentWindingEdges(const std::vector<Eigen::Vector3i>& triangles,
                             const std::vector<Eigen::Vector3i>& neighbours)
{
  int conflicts = 0;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int u = neighbours[t][k];
      if (u > t && hasDirectedEdge(triangles[u], triangles[t][k], triangles[t][(k + 1) % 3]))
      {
        ++conflicts;
      }
    }
  }
  return conflicts;
}

// Stage 7 (first half): only the vertices that `triangles` use, in their first-use order; the
// triangles' corners renumbered to them.
std::vector<Eigen::Vector3d> usedVertices(const std::vector<Eigen::Vector3d>& welded,
                                          std::vector<Eigen::Vector3i>* triangles)
{
  std::vector<Eigen::Vector3d> vertices;
  std::vector<int> compact(welded.size(), -1);
  for (Eigen::Vector3i& t : *triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (compact[t[k]] < 0)
      {
        compact[t[k]] = static_cast<int>(vertices.size());
        vertices.push_back(welded[t[k]]);
      }
      t[k] = compact[t[k]];
    }
  }
  return vertices;
}
}  // namespace

// Seven stages: checks (1), welding (2), degenerate (3) and duplicate (4) triangles dropped,
// consistent (5) and outward (6) winding, and the tables (7).
TriangleMesh TriangleMesh::build(const TriangleSoup& soup, const MeshBuildOptions& options)
{
  TriangleMesh mesh;
  MeshHealth& health = mesh.health_;
  health.input_vertices = static_cast<int>(soup.vertices.size());
  health.input_triangles = static_cast<int>(soup.triangles.size());
  const BoundingBox box = checkedBoundingBox(soup);
  mesh.bounding_box_diagonal_ = (box.upper - box.lower).norm();

  // Weld duplicate vertices.
  std::vector<Eigen::Vector3d> welded;
  const std::vector<int> remap =
      weld(soup.vertices, options.relative_weld_tolerance * mesh.bounding_box_diagonal_, &welded);
  health.welded_vertices = health.input_vertices - static_cast<int>(welded.size());

  KeptTriangles kept = dropDegenerate(soup, remap, welded, options, &health);
  dropDuplicates(&kept, &health);
  std::vector<Eigen::Vector3i>& triangles = kept.triangles;

  // Manifold adjacency, then consistent winding by breadth-first search over it, then outward.
  const int n = static_cast<int>(triangles.size());
  std::vector<bool> flipped(n, false);
  Adjacency adjacency = adjacencyOf(triangles);
  const Components components = windConsistently(&triangles, &adjacency.neighbours, &flipped);
  adjacency = adjacencyOf(triangles);
  if (flipInsideOut(welded, box.lower, components, adjacency.neighbours, &triangles, &flipped))
  {
    adjacency = adjacencyOf(triangles);
  }
  health.flipped_triangles = static_cast<int>(std::count(flipped.begin(), flipped.end(), true));
  health.boundary_edges = adjacency.boundary;
  health.non_manifold_edges = adjacency.non_manifold;
  health.components = components.count;
  health.inconsistent_winding_edges = inconsistentWindingEdges(triangles, adjacency.neighbours);

  mesh.vertices_ = usedVertices(welded, &triangles);
  mesh.triangles_ = std::move(triangles);
  mesh.neighbours_ = std::move(adjacency.neighbours);
  mesh.source_triangle_ = std::move(kept.source);
  mesh.buildTables();
  return mesh;
}

void TriangleMesh::buildTables()
{
  const int n = static_cast<int>(triangles_.size());
  normals_.resize(n);
  gradients_.resize(n);
  for (int t = 0; t < n; ++t)
  {
    updateTriangleFrame(t);  // build() dropped triangles of no area
  }
  const int used_vertices = static_cast<int>(vertices_.size());
  vertex_face_offsets_.assign(used_vertices + 1, 0);
  for (const Eigen::Vector3i& t : triangles_)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++vertex_face_offsets_[t[k] + 1];
    }
  }
  for (int v = 0; v < used_vertices; ++v)
  {
    vertex_face_offsets_[v + 1] += vertex_face_offsets_[v];
  }
  vertex_faces_.resize(vertex_face_offsets_[used_vertices]);
  std::vector<int> fill(vertex_face_offsets_.begin(), vertex_face_offsets_.end() - 1);
  for (int t = 0; t < n; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      vertex_faces_[fill[triangles_[t][k]]++] = t;
    }
  }
}

bool TriangleMesh::updateTriangleFrame(int t)
{
  const Eigen::Vector3d& a = corner(t, 0);
  const Eigen::Vector3d& b = corner(t, 1);
  const Eigen::Vector3d& c = corner(t, 2);
  const Eigen::Vector3d area_normal = (b - a).cross(c - a);
  if (!(area_normal.squaredNorm() > 0.0))
  {
    return false;
  }
  const Eigen::Vector3d n_t = area_normal.normalized();  // build()'s arithmetic, bit for bit
  const double twice_area = area_normal.dot(n_t);
  normals_[t] = n_t;
  // The gradient of lambda_j is normal x (edge opposite j, from j+1 to j+2) / (2 area).
  gradients_[t].first = n_t.cross(c - b) / twice_area;
  gradients_[t].second = n_t.cross(a - c) / twice_area;
  return true;
}

void TriangleMesh::moveVertices(const std::vector<Eigen::Vector3d>& positions)
{
  if (positions.size() != vertices_.size())
  {
    throw InputError("moveVertices: " + std::to_string(positions.size()) + " positions for a mesh of " +
                     std::to_string(vertices_.size()) + " vertices");
  }
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d upper = -lower;
  for (const Eigen::Vector3d& p : positions)
  {
    if (!p.allFinite())
    {
      throw InputError("moveVertices: a position is not finite");
    }
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  std::copy(positions.begin(), positions.end(), vertices_.begin());
  for (int t = 0; t < triangleCount(); ++t)
  {
    updateTriangleFrame(t);
  }
  bounding_box_diagonal_ = (upper - lower).norm();
}

std::size_t TriangleMesh::memoryBytes() const
{
  return vertices_.capacity() * sizeof(Eigen::Vector3d) + triangles_.capacity() * sizeof(Eigen::Vector3i) +
         normals_.capacity() * sizeof(Eigen::Vector3d) + neighbours_.capacity() * sizeof(Eigen::Vector3i) +
         gradients_.capacity() * sizeof(BarycentricGradients) + vertex_face_offsets_.capacity() * sizeof(int) +
         vertex_faces_.capacity() * sizeof(int) + source_triangle_.capacity() * sizeof(int) + sizeof(*this);
}
}  // namespace god_finger
