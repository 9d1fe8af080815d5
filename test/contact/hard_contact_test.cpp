// Contact areas on hard meshes (issue 5): a vertex with 32 incident faces, needle triangles,
// a mesh with holes and non-manifold edges. 2000 random contacts each (RandomContacts) must
// all be sound (contactAreaDefect: finite, on the mesh, no farther than walked, not beyond the
// target), every walk must end within the crossing cap, and the batch must finish.
#include "god_finger/contact/contact_sampling.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <map>

namespace god_finger
{
namespace
{
struct Outcome
{
  int defects = 0;
  std::string first_defect;
  int contacts_with_area = 0;
  std::map<WalkStop, int> stops;
};

Outcome sampleContacts(const TriangleMesh& mesh, ContactParams params, int samples = 2000)
{
  const SurfaceLocator locator(mesh);
  RandomContacts contacts(mesh, params, 5);
  const double tolerance = 1e-9 * mesh.boundingBoxDiagonal();
  Outcome outcome;
  ContactAreaResult area;
  for (int i = 0; i < samples; ++i)
  {
    const ContactQuery query = contacts.next();
    computeContactArea(mesh, query, params, &area);
    const std::string defect = area.valid ? contactAreaDefect(locator, query, area, tolerance) : "invalid";
    if (!defect.empty() && outcome.defects++ == 0)
    {
      outcome.first_defect = defect;
    }
    outcome.contacts_with_area += area.active > 0 ? 1 : 0;
    for (int k = 0; k < area.count; ++k)
    {
      ++outcome.stops[area.sub_god_objects[k].walk.stop];
      EXPECT_LE(area.sub_god_objects[k].walk.crossings, params.max_crossings);
    }
  }
  return outcome;
}

ContactParams unitParams()
{
  ContactParams params;  // meshes of about 1 m: a pad of 0.3 m crosses many faces
  params.max_radius = 0.3;
  params.distance_constant = 0.1;
  return params;
}

TEST(HardContact, VertexWithThirtyTwoIncidentFaces)
{
  const TriangleMesh mesh = TriangleMesh::build(test::highValenceConeSoup(32));
  for (WalkVariant walk : {WalkVariant::kProject, WalkVariant::kUnfold})
  {
    ContactParams params = unitParams();
    params.walk = walk;
    params.sub_god_objects = 64;
    const Outcome outcome = sampleContacts(mesh, params);
    EXPECT_EQ(outcome.defects, 0) << walkVariantName(walk) << ": " << outcome.first_defect;
    EXPECT_GT(outcome.contacts_with_area, 1900);
  }
}

TEST(HardContact, NeedleTriangles)
{
  // A 1 m x 1 m square cut into 400 needles of aspect 1:2000 (fans from two far corners).
  TriangleSoup soup;
  const int needles = 200;
  soup.vertices.emplace_back(0.0, 0.0, 0.0);
  soup.vertices.emplace_back(1.0, 1.0, 0.0);
  for (int i = 0; i <= needles; ++i)
  {
    const double s = static_cast<double>(i) / needles;
    soup.vertices.emplace_back(s, 1.0 - s, 0.0);  // the diagonal from (0, 1) to (1, 0)
  }
  for (int i = 0; i < needles; ++i)
  {
    soup.triangles.push_back({0, 2 + i + 1, 2 + i});
    soup.triangles.push_back({1, 2 + i, 2 + i + 1});
  }
  const TriangleMesh mesh = TriangleMesh::build(soup);
  ASSERT_EQ(mesh.triangleCount(), 2 * needles);
  for (WalkVariant walk : {WalkVariant::kProject, WalkVariant::kUnfold})
  {
    ContactParams params = unitParams();
    params.walk = walk;
    const Outcome outcome = sampleContacts(mesh, params);
    EXPECT_EQ(outcome.defects, 0) << walkVariantName(walk) << ": " << outcome.first_defect;
    // Open square: walks that reach the border stop there; the rest reach their distance.
    EXPECT_GT(outcome.stops.count(WalkStop::kDistanceReached) ? outcome.stops.at(WalkStop::kDistanceReached) : 0, 0);
    EXPECT_GT(outcome.stops.count(WalkStop::kBoundaryEdge) ? outcome.stops.at(WalkStop::kBoundaryEdge) : 0, 0);
  }
}

TEST(HardContact, HolesAndNonManifoldEdges)
{
  // A cube with its top face missing (a hole), plus a fin sharing one bottom edge (a
  // non-manifold edge: three faces on it).
  TriangleSoup soup = makeBox(Eigen::Vector3d::Constant(0.5));
  TriangleSoup open;
  open.vertices = soup.vertices;
  for (const auto& t : soup.triangles)
  {
    const double z = (soup.vertices[t[0]].z() + soup.vertices[t[1]].z() + soup.vertices[t[2]].z()) / 3.0;
    if (z < 0.49)
    {
      open.triangles.push_back(t);
    }
  }
  const int a = static_cast<int>(open.vertices.size());
  open.vertices.emplace_back(-0.5, -0.5, -0.5);
  open.vertices.emplace_back(0.5, -0.5, -0.5);
  open.vertices.emplace_back(0.0, -1.2, -0.9);
  open.triangles.push_back({a, a + 1, a + 2});
  const TriangleMesh mesh = TriangleMesh::build(open);
  EXPECT_GT(mesh.health().boundary_edges, 0);
  EXPECT_GT(mesh.health().non_manifold_edges, 0);
  Outcome outcome = sampleContacts(mesh, unitParams());
  EXPECT_EQ(outcome.defects, 0) << outcome.first_defect;
  EXPECT_GT(outcome.stops[WalkStop::kBoundaryEdge], 0);
  EXPECT_GT(outcome.stops[WalkStop::kNonManifoldEdge], 0);
}
}  // namespace
}  // namespace god_finger
