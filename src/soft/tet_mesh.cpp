#include "god_finger/soft/tet_mesh.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <tuple>

namespace god_finger
{
namespace
{
// The faces of a positively wound tetrahedron (a b c d), each wound outward, listed by the
// corner they are opposite to.
constexpr int kOutwardFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

double longestEdge(const std::vector<Eigen::Vector3d>& nodes, const std::array<int, 4>& tet)
{
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      longest = std::max(longest, (nodes[tet[j]] - nodes[tet[i]]).norm());
    }
  }
  return longest;
}

std::string tetName(const std::string& source, std::size_t index)
{
  return source + ": tetrahedron " + std::to_string(index);
}

// One face of one tetrahedron: its sorted nodes, and whether its outward winding is an even
// permutation of them (two tetrahedra on either side of a face see it with opposite windings).
struct Face
{
  std::array<int, 3> key;
  bool even;
  int tet;
  int corner;
};

// Every face of every (positively wound) tetrahedron, sorted by key, then tetrahedron.
std::vector<Face> sortedFaces(const TetMesh& mesh)
{
  std::vector<Face> faces;
  faces.reserve(mesh.tets.size() * 4);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    for (int corner = 0; corner < 4; ++corner)
    {
      const std::array<int, 3> wound = {mesh.tets[t][kOutwardFaces[corner][0]], mesh.tets[t][kOutwardFaces[corner][1]],
                                        mesh.tets[t][kOutwardFaces[corner][2]]};
      std::array<int, 3> key = wound;
      std::sort(key.begin(), key.end());
      // A cyclic rotation of the sorted triple is even; anything else odd.
      const bool even = wound == key || wound == std::array<int, 3>{key[1], key[2], key[0]} ||
                        wound == std::array<int, 3>{key[2], key[0], key[1]};
      faces.push_back({key, even, static_cast<int>(t), corner});
    }
  }
  std::sort(faces.begin(), faces.end(),
            [](const Face& a, const Face& b)
            { return std::tie(a.key, a.tet, a.corner) < std::tie(b.key, b.tet, b.corner); });
  return faces;
}
}  // namespace

double signedTetVolume(const std::vector<Eigen::Vector3d>& nodes, const std::array<int, 4>& tet)
{
  Eigen::Matrix3d edges;
  edges << nodes[tet[1]] - nodes[tet[0]], nodes[tet[2]] - nodes[tet[0]], nodes[tet[3]] - nodes[tet[0]];
  return edges.determinant() / 6.0;
}

TetMesh checkedTetMesh(TetMesh mesh, const std::string& source, TetMeshRepairs* repairs)
{
  if (mesh.tets.empty())
  {
    throw InputError(source + ": no tetrahedra: a soft body needs a volume mesh");
  }
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    if (!mesh.nodes[n].allFinite())
    {
      throw InputError(source + ": node " + std::to_string(n) + " is not finite (" + roundedNumber(mesh.nodes[n].x()) +
                       " " + roundedNumber(mesh.nodes[n].y()) + " " + roundedNumber(mesh.nodes[n].z()) + ")");
    }
  }
  const int node_count = static_cast<int>(mesh.nodes.size());
  std::size_t positive = 0;
  std::size_t first_positive = 0;
  std::size_t first_negative = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    const std::array<int, 4>& tet = mesh.tets[t];
    for (int corner = 0; corner < 4; ++corner)
    {
      if (tet[corner] < 0 || tet[corner] >= node_count)
      {
        throw InputError(tetName(source, t) + " names node " + std::to_string(tet[corner]) + ", but the mesh has " +
                         std::to_string(node_count) + " nodes");
      }
      for (int other = 0; other < corner; ++other)
      {
        if (tet[other] == tet[corner])
        {
          throw InputError(tetName(source, t) + " names node " + std::to_string(tet[corner]) + " twice");
        }
      }
    }
    const double volume = signedTetVolume(mesh.nodes, tet);
    const double edge = longestEdge(mesh.nodes, tet);
    const double quality = 6.0 * std::abs(volume) / (edge * edge * edge);
    if (!(quality >= kMinTetQuality))
    {
      throw InputError(tetName(source, t) + " is degenerate: 6 V / L^3 = " + roundedNumber(quality) +
                       " (flat or a sliver; at least " + roundedNumber(kMinTetQuality) + ")");
    }
    if (volume > 0.0)
    {
      if (positive == 0)
      {
        first_positive = t;
      }
      ++positive;
    }
    else if (positive == t)
    {
      first_negative = t;
    }
  }
  const std::size_t negative = mesh.tets.size() - positive;
  if (positive > 0 && negative > 0)
  {
    // The minority is the inverted one (a mesh folded over itself); name its first.
    const bool negatives_inverted = negative <= positive;
    const std::size_t inverted = negatives_inverted ? first_negative : first_positive;
    throw InputError(tetName(source, inverted) + " is inverted: its volume's sign is opposite to that of " +
                     std::to_string(negatives_inverted ? positive : negative) + " of the mesh's " +
                     std::to_string(mesh.tets.size()) + " tetrahedra (the mesh folds over itself)");
  }
  TetMeshRepairs done;
  if (positive == 0)
  {
    for (std::array<int, 4>& tet : mesh.tets)
    {
      std::swap(tet[1], tet[2]);
    }
    done.reoriented = true;
  }
  // A face is the boundary (one tetrahedron) or between two, which see it wound oppositely; two
  // on the same side of it overlap, and three or more make the volume non-manifold.
  const std::vector<Face> faces = sortedFaces(mesh);
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key)
    {
      ++j;
    }
    const std::string face_name = "(" + std::to_string(faces[i].key[0]) + " " + std::to_string(faces[i].key[1]) + " " +
                                  std::to_string(faces[i].key[2]) + ")";
    if (j - i > 2)
    {
      throw InputError(source + ": face " + face_name + " is shared by " + std::to_string(j - i) + " tetrahedra (" +
                       std::to_string(faces[i].tet) + ", " + std::to_string(faces[i + 1].tet) + ", " +
                       std::to_string(faces[i + 2].tet) + "): a face bounds at most two");
    }
    if (j - i == 2 && faces[i].even == faces[i + 1].even)
    {
      throw InputError(source + ": tetrahedra " + std::to_string(faces[i].tet) + " and " +
                       std::to_string(faces[i + 1].tet) + " overlap: both lie on the same side of their face " +
                       face_name);
    }
    i = j;
  }
  std::vector<int> renumbered(mesh.nodes.size(), -1);
  for (const std::array<int, 4>& tet : mesh.tets)
  {
    for (int node : tet)
    {
      renumbered[node] = 0;
    }
  }
  int next = 0;
  std::vector<Eigen::Vector3d> used;
  used.reserve(mesh.nodes.size());
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    if (renumbered[n] == 0)
    {
      renumbered[n] = next++;
      used.push_back(mesh.nodes[n]);
    }
  }
  done.dropped_nodes = node_count - next;
  if (done.dropped_nodes > 0)
  {
    for (std::array<int, 4>& tet : mesh.tets)
    {
      for (int& node : tet)
      {
        node = renumbered[node];
      }
    }
    mesh.nodes = std::move(used);
  }
  if (repairs != nullptr)
  {
    *repairs = done;
  }
  return mesh;
}

std::vector<std::array<int, 3>> surfaceTriangles(const TetMesh& mesh)
{
  const std::vector<Face> faces = sortedFaces(mesh);
  std::vector<std::pair<int, int>> boundary;  // (tet, corner): faces that one tetrahedron has
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key)
    {
      ++j;
    }
    if (j == i + 1)
    {
      boundary.emplace_back(faces[i].tet, faces[i].corner);
    }
    i = j;
  }
  std::sort(boundary.begin(), boundary.end());
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(boundary.size());
  for (const auto& [tet, corner] : boundary)
  {
    const std::array<int, 4>& nodes = mesh.tets[tet];
    triangles.push_back(
        {nodes[kOutwardFaces[corner][0]], nodes[kOutwardFaces[corner][1]], nodes[kOutwardFaces[corner][2]]});
  }
  return triangles;
}
}  // namespace god_finger
