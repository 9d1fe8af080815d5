// Large concave meshes as dynamic bodies: simplification keeps the shape within its stated
// tolerance, the decomposition of the simplified mesh still covers the object, a finger rests
// on it where the true surface is, and the disk cache hits, survives corrupt files and
// unwritable folders.
#include "god_finger/scene/convex_decomposition.h"

#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/mesh_io/mesh_writer.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/mesh_simplification.h"

#include <LinearMath/btConvexHullComputer.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

namespace god_finger
{
namespace
{
constexpr double kMajor = 0.06;  // m, the torus of urdf/scenes/table_torus.urdf
constexpr double kMinor = 0.02;

// Distance from `p` to the analytic torus's surface (m), negative inside.
double torusDistance(const Eigen::Vector3d& p)
{
  const double ring = std::hypot(p.x(), p.y()) - kMajor;
  return std::hypot(ring, p.z()) - kMinor;
}

// 2 * major * minor triangles.
TriangleMesh torus(int major_segments, int minor_segments)
{
  return TriangleMesh::build(makeTorus(kMajor, kMinor, major_segments, minor_segments));
}

// A fresh empty folder under the system's temporary folder, used as GOD_FINGER_CACHE_DIR.
class CacheFolder
{
 public:
  CacheFolder()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "god_finger_hulls_XXXXXX").string();
    path_ = mkdtemp(pattern.data());
    setenv("GOD_FINGER_CACHE_DIR", path_.c_str(), 1);
    clearProcessDecompositionCache();
  }
  ~CacheFolder()
  {
    unsetenv("GOD_FINGER_CACHE_DIR");
    std::filesystem::remove_all(path_);
    clearProcessDecompositionCache();
  }
  const std::string& path() const
  {
    return path_;
  }
  std::vector<std::string> files() const
  {
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(path_))
    {
      found.push_back(entry.path().string());
    }
    return found;
  }

 private:
  std::string path_;
};

// The half-spaces of a hull: n . x <= d.
std::vector<Eigen::Vector4d> hullPlanes(const std::vector<Eigen::Vector3d>& points)
{
  std::vector<double> coordinates;
  for (const Eigen::Vector3d& p : points)
  {
    coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  }
  btConvexHullComputer hull;
  hull.compute(coordinates.data(), 3 * sizeof(double), static_cast<int>(points.size()), 0.0, 0.0);
  std::vector<Eigen::Vector4d> planes;
  for (int face = 0; face < hull.faces.size(); ++face)
  {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[face]];
    const btConvexHullComputer::Edge* second = first->getNextEdgeOfFace();
    const btVector3& a = hull.vertices[first->getSourceVertex()];
    const btVector3& b = hull.vertices[second->getSourceVertex()];
    const btVector3& c = hull.vertices[second->getTargetVertex()];
    const btVector3 n = (b - a).cross(c - a).normalized();
    planes.emplace_back(n.x(), n.y(), n.z(), n.dot(a));
  }
  return planes;
}

bool insideAny(const std::vector<std::vector<Eigen::Vector4d>>& hulls, const Eigen::Vector3d& p)
{
  for (const std::vector<Eigen::Vector4d>& planes : hulls)
  {
    bool inside = true;
    for (const Eigen::Vector4d& plane : planes)
    {
      inside = inside && plane.head<3>().dot(p) <= plane.w();
    }
    if (inside)
    {
      return true;
    }
  }
  return false;
}

TEST(MeshSimplification, ATorusOf100kTrianglesKeepsItsShapeAt1500)
{
  const TriangleMesh full = torus(250, 200);
  ASSERT_EQ(full.triangleCount(), 100000);
  const double tolerance = kSimplificationTolerance * full.boundingBoxDiagonal();
  const SimplifiedMesh simplified = simplifyMesh(full, kDecompositionTriangles, tolerance);
  const TriangleMesh coarse = TriangleMesh::build(simplified.soup);
  EXPECT_LE(coarse.triangleCount(), kDecompositionTriangles);
  EXPECT_GT(coarse.triangleCount(), kDecompositionTriangles / 2);
  EXPECT_LE(simplified.error, tolerance);
  // Still a closed torus: one component, no holes, genus 1 (Euler characteristic 0).
  EXPECT_EQ(coarse.health().boundary_edges, 0);
  EXPECT_EQ(coarse.health().components, 1);
  EXPECT_EQ(coarse.vertexCount() - 3 * coarse.triangleCount() / 2 + coarse.triangleCount(), 0);
  // Within the tolerance both ways: the coarse vertices are on the torus (collapse keeps
  // input vertices), and every input vertex is near the coarse surface (the tolerance bounds
  // meshoptimizer's estimate, which is 2-3 times lower than this true distance: the check
  // holds here because the triangle target, not the tolerance, stopped the collapse).
  for (const Eigen::Vector3d& v : coarse.vertices())
  {
    ASSERT_NEAR(torusDistance(v), 0.0, 1e-9);
  }
  const SurfaceLocator locator(coarse);
  double farthest = 0.0;
  for (const Eigen::Vector3d& v : full.vertices())
  {
    farthest = std::max(farthest, (locator.closest(v).point - v).norm());
  }
  EXPECT_LE(farthest, tolerance);
  std::cout << "100000 -> " << coarse.triangleCount() << " triangles, reported error " << simplified.error * 1e3
            << " mm, farthest input vertex " << farthest * 1e3 << " mm, tolerance " << tolerance * 1e3 << " mm\n";
}

TEST(MeshSimplification, SmallMeshesAreKeptWhole)
{
  const TriangleMesh small = torus(20, 10);
  const SimplifiedMesh same = simplifyMesh(small, kDecompositionTriangles, 1e-3);
  EXPECT_EQ(same.soup.triangles.size(), 400u);
  EXPECT_EQ(same.error, 0.0);
}

TEST(ConvexDecomposition, TheSimplifiedTorusHullsCoverItsVolumeWithin15Percent)
{
  const TriangleMesh full = torus(250, 200);
  const auto start = std::chrono::steady_clock::now();
  const ConvexDecomposition decomposition = decomposeConcaveMesh(full, "a 100k-triangle torus");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(decomposition.source, DecompositionSource::kComputed);
  EXPECT_LE(decomposition.decomposed_triangles, kDecompositionTriangles);
  ASSERT_GE(decomposition.hulls->size(), 4u);  // a torus needs several hulls to keep its hole
  std::vector<std::vector<Eigen::Vector4d>> hulls;
  for (const std::vector<Eigen::Vector3d>& hull : *decomposition.hulls)
  {
    hulls.push_back(hullPlanes(hull));
  }
  // Monte Carlo over the bounding box: the union's volume and how much of the torus it covers.
  std::mt19937 random(17);
  std::uniform_real_distribution<double> xy(-kMajor - kMinor, kMajor + kMinor);
  std::uniform_real_distribution<double> z(-kMinor, kMinor);
  const int samples = 200000;
  int in_torus = 0;
  int in_union = 0;
  int covered = 0;
  int hole = 0;
  for (int i = 0; i < samples; ++i)
  {
    const Eigen::Vector3d p(xy(random), xy(random), z(random));
    const bool torus_inside = torusDistance(p) < 0.0;
    const bool union_inside = insideAny(hulls, p);
    in_torus += torus_inside;
    in_union += union_inside;
    covered += torus_inside && union_inside;
    hole += union_inside && std::hypot(p.x(), p.y()) < 0.5 * (kMajor - kMinor);
  }
  const double box = 4.0 * (kMajor + kMinor) * (kMajor + kMinor) * 2.0 * kMinor;
  const double torus_volume = 2.0 * M_PI * M_PI * kMajor * kMinor * kMinor;
  EXPECT_NEAR(box * in_torus / samples, torus_volume, 0.02 * torus_volume);  // the estimator itself
  const double ratio = double(in_union) / in_torus;
  const double coverage = double(covered) / in_torus;
  EXPECT_LT(ratio, 1.15);
  EXPECT_GT(coverage, 0.97);
  EXPECT_EQ(hole, 0);  // the hole stays open
  std::cout << "decomposition: " << decomposition.input_triangles << " -> " << decomposition.decomposed_triangles
            << " triangles, " << decomposition.hulls->size() << " hulls in " << seconds
            << " s; hull union / torus volume " << ratio << ", torus covered " << coverage << "\n";
}

TEST(ConvexDecomposition, DiskCacheMissesThenHitsAndSurvivesCorruptFiles)
{
  CacheFolder folder;
  const TriangleMesh mesh = torus(24, 12);  // small: HACD takes 0.1 s
  const ConvexDecomposition first = cachedConvexDecomposition(mesh, "torus");
  EXPECT_EQ(first.source, DecompositionSource::kComputed);
  EXPECT_EQ(first.decomposed_triangles, 576);
  ASSERT_EQ(folder.files().size(), 1u);
  EXPECT_EQ(cachedConvexDecomposition(mesh, "torus").source, DecompositionSource::kProcessCache);

  clearProcessDecompositionCache();
  const ConvexDecomposition second = cachedConvexDecomposition(mesh, "torus");
  EXPECT_EQ(second.source, DecompositionSource::kDiskCache);
  ASSERT_EQ(second.hulls->size(), first.hulls->size());
  for (std::size_t h = 0; h < first.hulls->size(); ++h)
  {
    EXPECT_EQ((*second.hulls)[h], (*first.hulls)[h]);  // bit for bit
  }

  // Truncated, then overwritten with garbage, then a flipped byte: one warning and a
  // recomputation each time, and the file is replaced by a good one.
  const std::string file = folder.files().front();
  const auto size = std::filesystem::file_size(file);
  for (int damage = 0; damage < 3; ++damage)
  {
    SCOPED_TRACE(damage);
    if (damage == 0)
    {
      std::filesystem::resize_file(file, size / 2);
    }
    else if (damage == 1)
    {
      std::ofstream(file, std::ios::binary | std::ios::trunc) << "not hulls at all";
    }
    else
    {
      std::fstream patch(file, std::ios::in | std::ios::out | std::ios::binary);
      patch.seekp(static_cast<std::streamoff>(size / 2));
      patch.put('\x5a');
    }
    clearProcessDecompositionCache();
    testing::internal::CaptureStderr();
    const ConvexDecomposition again = cachedConvexDecomposition(mesh, "torus");
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_EQ(again.source, DecompositionSource::kComputed);
    EXPECT_EQ(again.hulls->size(), first.hulls->size());
    EXPECT_NE(log.find("warning: hull cache file '" + file + "' is "), std::string::npos) << log;
    EXPECT_EQ(log.find("warning"), log.rfind("warning")) << log;  // one warning
    EXPECT_EQ(std::filesystem::file_size(file), size);
    clearProcessDecompositionCache();
    EXPECT_EQ(cachedConvexDecomposition(mesh, "torus").source, DecompositionSource::kDiskCache);
  }
}

TEST(ConvexDecomposition, AnUnwritableCacheFolderWarnsOnceAndStillDecomposes)
{
  CacheFolder folder;
  // A folder below a regular file can be neither created nor written, even by root.
  const std::string blocker = folder.path() + "/file";
  std::ofstream(blocker) << "x";
  setenv("GOD_FINGER_CACHE_DIR", (blocker + "/hulls").c_str(), 1);
  testing::internal::CaptureStderr();
  for (int i = 0; i < 2; ++i)
  {
    clearProcessDecompositionCache();
    const ConvexDecomposition decomposition = cachedConvexDecomposition(torus(24, 12), "torus");
    EXPECT_EQ(decomposition.source, DecompositionSource::kComputed);
    EXPECT_GE(decomposition.hulls->size(), 4u);
  }
  const std::string log = testing::internal::GetCapturedStderr();
  EXPECT_NE(log.find("warning: cannot write the hull cache in '" + blocker + "/hulls'"), std::string::npos) << log;
  EXPECT_EQ(log.find("warning"), log.rfind("warning")) << log;
}

TEST(ConvexDecomposition, TheKeyIsTheContentNotTheFile)
{
  const TriangleMesh a = torus(30, 20);
  EXPECT_EQ(decompositionKey(a), decompositionKey(torus(30, 20)));
  EXPECT_EQ(decompositionKey(a).size(), 32u);
  const TriangleMesh scaled = TriangleMesh::build(makeTorus(1.001 * kMajor, kMinor, 30, 20));
  EXPECT_NE(decompositionKey(a), decompositionKey(scaled));
}

// The world: a dynamic 20k-triangle torus (simplified, decomposed, cached) on a table; a finger
// pressing the top of its ring rests on the true surface to within a millimetre.
TEST(ConvexDecomposition, AFingerRestsOnTheSimplifiedTorusWithinAMillimetreOfItsSurface)
{
  CacheFolder folder;
  const std::string path = folder.path() + "/torus.off";
  writeTriangleSoup(makeTorus(kMajor, kMinor, 125, 80), path);
  SceneDescription scene;
  BodyDescription table;
  table.name = "table";
  table.is_static = true;
  table.geometry.size = Eigen::Vector3d(1.0, 1.0, 0.04);
  table.pose.translation().z() = -0.02;
  table.material.friction = 0.6;
  scene.bodies.push_back(table);
  BodyDescription ring;
  ring.name = "torus";
  ring.geometry.kind = GeometryKind::kMesh;
  ring.geometry.mesh_path = path;
  ring.mass = 0.1;
  ring.inertia = Eigen::Vector3d(2.0e-4, 2.0e-4, 3.9e-4).asDiagonal();
  ring.pose.translation().z() = kMinor + 0.0005;
  scene.bodies.push_back(ring);

  for (const DecompositionSource expected : {DecompositionSource::kComputed, DecompositionSource::kDiskCache})
  {
    clearProcessDecompositionCache();
    const auto start = std::chrono::steady_clock::now();
    GodFingerWorld world(scene, WorldParams());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(folder.files().size(), 2u);  // the mesh and its hulls
    std::cout << decompositionSourceName(expected) << ": world of a 20000-triangle torus in " << seconds << " s\n";
    const BodyState start_state = world.bodyState(1);
    const Eigen::Vector3d top = start_state.pose * Eigen::Vector3d(kMajor, 0, kMinor);
    const int finger = world.addInterface(top + Eigen::Vector3d(0, 0, 0.01));
    world.setInterfaceTarget(finger, top - Eigen::Vector3d(0, 0, 0.005));
    for (int i = 0; i < 1000; ++i)
    {
      world.step();
    }
    const BodyState end = world.bodyState(1);
    EXPECT_NEAR(end.center_of_mass.z(), start_state.center_of_mass.z(), 1e-3);
    const InterfaceState& state = world.interfaceState(finger);
    ASSERT_EQ(state.contact_count, 1);
    const Eigen::Vector3d in_body = end.pose.inverse() * state.proxy_position;
    const double gap = torusDistance(in_body) - world.params().coupling.proxy_radius;
    EXPECT_LT(std::abs(gap), 1e-3) << "proxy at " << in_body.transpose();
    std::cout << "proxy rests " << gap * 1e3 << " mm off the true surface\n";
  }
}
}  // namespace
}  // namespace god_finger
