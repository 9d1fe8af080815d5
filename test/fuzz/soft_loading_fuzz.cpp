// libFuzzer target: soft bodies from arbitrary bytes (issue 28). The first byte picks the form:
// even, a VTK volume (soft/vtk_tet_reader.h); odd, a URDF <deformable> (scene/deformable_object.h)
// whose volume may name /tmp/god_finger_fuzz_soft.vtk, a valid two-tetrahedron file this target
// writes. A bad file must give InputError, never a crash, a hang or a sanitizer report. A mesh
// that loads must keep tet_mesh.h's invariants (finite nodes, every node used, positive and
// not degenerate tetrahedra, a surface whose every edge is shared by faces of both windings, a
// walk mesh of that surface whose vertices are its nodes),
// and a small one must step as a soft body to finite positions, glued and free on a support
// plane (never below it). Run by scripts/fuzz.
#include "god_finger/scene/deformable_object.h"
#include "god_finger/soft/elastic_body.h"
#include "god_finger/soft/soft_surface.h"
#include "god_finger/soft/vtk_tet_reader.h"
#include "god_finger/support/input_error.h"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace
{
void checkMesh(const god_finger::TetMesh& mesh)
{
  std::vector<bool> used(mesh.nodes.size(), false);
  for (const auto& tet : mesh.tets)
  {
    if (!(god_finger::signedTetVolume(mesh.nodes, tet) > 0.0))
    {
      std::abort();
    }
    for (int node : tet)
    {
      used[node] = true;
    }
  }
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    if (!used[n] || !mesh.nodes[n].allFinite())
    {
      std::abort();
    }
  }
  std::map<std::pair<int, int>, int> edges;
  for (const auto& face : god_finger::surfaceTriangles(mesh))
  {
    for (int k = 0; k < 3; ++k)
    {
      ++edges[{face[k], face[(k + 1) % 3]}];
    }
  }
  for (const auto& [edge, count] : edges)
  {
    // Every directed edge of the boundary has its reverse (a boundary of volumes is closed).
    if (edges.count({edge.second, edge.first}) == 0)
    {
      std::abort();
    }
  }
  // Its surface as the physics walks on it: one vertex per surface node, or a clear refusal
  // (surface nodes that coincide: InputError, caught by the caller).
  const god_finger::SoftSurfaceMesh surface = god_finger::makeSoftSurfaceMesh(mesh, "fuzz.vtk");
  for (int v = 0; v < surface.mesh.vertexCount(); ++v)
  {
    const int node = surface.node_of_vertex[v];
    if (node < 0 || node >= static_cast<int>(mesh.nodes.size()) || surface.mesh.vertices()[v] != mesh.nodes[node])
    {
      std::abort();
    }
  }
  if (mesh.nodes.size() <= 64)
  {
    god_finger::SoftMaterial material;
    material.young_modulus = 1e4;
    material.poisson_ratio = 0.3;
    material.density = 1000.0;
    god_finger::ElasticBody body(mesh, material, {0}, 1e-3, Eigen::Vector3d(0, 0, -9.81));
    const Eigen::VectorXd none = Eigen::VectorXd::Zero(3 * body.nodeCount());
    for (int step = 0; step < 5; ++step)
    {
      body.step(none);
    }
    if (!body.displacement().allFinite())
    {
      std::abort();
    }
    // Free, on its support (a resting body): it stays finite and no node goes below the plane by
    // more than the contact solver's tolerance.
    god_finger::ElasticBody free_body(mesh, material, {}, 1e-3, Eigen::Vector3d(0, 0, -9.81));
    god_finger::SupportPlane plane;
    plane.offset = mesh.nodes.front().z();
    for (const Eigen::Vector3d& node : mesh.nodes)
    {
      plane.offset = std::min(plane.offset, node.z());
    }
    plane.friction = 0.5;
    free_body.setSupport(plane);
    for (int step = 0; step < 5; ++step)
    {
      free_body.step(none);
    }
    for (int node = 0; node < free_body.nodeCount(); ++node)
    {
      if (!free_body.position(node).allFinite() || free_body.position(node).z() < plane.offset - 1e-6)
      {
        std::abort();
      }
    }
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  static const bool volume_written = []
  {
    FILE* file = std::fopen("/tmp/god_finger_fuzz_soft.vtk", "wb");
    if (file == nullptr)
    {
      std::abort();
    }
    std::fputs(
        "# vtk DataFile Version 2.0\nfuzz\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n0 0 0\n0.1 0 0\n"
        "0 0.1 0\n0 0 0.1\n0.1 0.1 0.1\nCELLS 2 10\n4 0 1 2 3\n4 1 4 2 3\nCELL_TYPES 2\n10\n10\n",
        file);
    std::fclose(file);
    return true;
  }();
  (void)volume_written;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try
  {
    if (data[0] % 2 == 0)
    {
      checkMesh(god_finger::parseVtkTetMesh(text, "fuzz.vtk"));
    }
    else
    {
      for (const god_finger::DeformableDescription& body : god_finger::parseDeformables(text, "/tmp", "fuzz.urdf"))
      {
        checkMesh(body.mesh);
        god_finger::checkSoftMaterial(body.material, "fuzz");
      }
    }
  }
  catch (const god_finger::InputError&)
  {
  }
  return 0;
}
