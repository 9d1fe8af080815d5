#include "god_finger/mesh_io/mesh_loader.h"

#include "god_finger/core/input_error.h"
#include "god_finger/core/polygon_triangulation.h"

#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <fstream>
#include <string>

namespace god_finger
{
namespace
{
// Adds the node's meshes (and its children's) to `soup`, in world units times `scale`.
// Polygons, convex or not, are ear-clipped on their best-fit plane (core/polygon_triangulation.h;
// a self-intersecting one is an error naming the face); points and lines are skipped (so that a file of lines says "no
// triangles"). Indices are checked: assimp's own triangulation and validation are not used, because Debian's assimp 5.2
// aborts the process (ai_assert) on some malformed files (found by test/fuzz/mesh_loading_fuzz).
void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, const Eigen::Vector3d& scale,
             const std::string& name, TriangleSoup* soup, int depth = 0)
{
  if (depth > 1000)
  {
    throw InputError(name + "node hierarchy deeper than 1000");
  }
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned int m = 0; m < node.mNumMeshes; ++m)
  {
    if (node.mMeshes[m] >= scene.mNumMeshes || scene.mMeshes[node.mMeshes[m]] == nullptr)
    {
      throw InputError(name + "a node refers to a mesh that is not in the file");
    }
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const int base = static_cast<int>(soup->vertices.size());
    std::vector<Eigen::Vector3d> corners;
    std::vector<std::array<int, 3>> polygon_triangles;
    for (unsigned int v = 0; v < mesh.mNumVertices; ++v)
    {
      const aiVector3D p = transform * mesh.mVertices[v];
      soup->vertices.emplace_back(scale.x() * p.x, scale.y() * p.y, scale.z() * p.z);
    }
    for (unsigned int f = 0; f < mesh.mNumFaces; ++f)
    {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices < 3 || face.mIndices == nullptr)
      {
        continue;
      }
      for (unsigned int k = 0; k < face.mNumIndices; ++k)
      {
        if (face.mIndices[k] >= mesh.mNumVertices)
        {
          throw InputError(name + "face " + std::to_string(f) + " refers to vertex " +
                           std::to_string(face.mIndices[k]) + " of " + std::to_string(mesh.mNumVertices));
        }
      }
      if (face.mNumIndices == 3)
      {
        soup->triangles.push_back({base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                                   base + static_cast<int>(face.mIndices[2])});
        continue;
      }
      corners.clear();
      for (unsigned int k = 0; k < face.mNumIndices; ++k)
      {
        corners.push_back(soup->vertices[base + face.mIndices[k]]);
      }
      const std::string problem = triangulatePolygon(corners, &polygon_triangles);
      if (!problem.empty())
      {
        throw InputError(name + "face " + std::to_string(f) + ": " + problem);
      }
      for (const std::array<int, 3>& t : polygon_triangles)
      {
        soup->triangles.push_back({base + static_cast<int>(face.mIndices[t[0]]),
                                   base + static_cast<int>(face.mIndices[t[1]]),
                                   base + static_cast<int>(face.mIndices[t[2]])});
      }
    }
  }
  for (unsigned int c = 0; c < node.mNumChildren; ++c)
  {
    if (node.mChildren[c] != nullptr)
    {
      collect(scene, *node.mChildren[c], transform, scale, name, soup, depth + 1);
    }
  }
}
// "" unless `head` (a file's first bytes) starts like a PLY file whose header is malformed:
// every header line must be a known keyword, and end_header must come within `head`.
std::string plyHeaderProblem(const std::string& head)
{
  if (head.rfind("ply", 0) != 0)
  {
    return std::string();
  }
  std::size_t start = 0;
  int line_number = 0;
  while (start < head.size())
  {
    const std::size_t end = head.find('\n', start);
    if (end == std::string::npos)
    {
      break;
    }
    std::string line = head.substr(start, end - start);
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    ++line_number;
    const std::string keyword = line.substr(0, line.find(' '));
    if (keyword == "end_header")
    {
      return std::string();
    }
    if (keyword != "ply" && keyword != "format" && keyword != "comment" && keyword != "obj_info" &&
        keyword != "element" && keyword != "property")
    {
      return "PLY header line " + std::to_string(line_number) + " is not a header keyword";
    }
    start = end + 1;
  }
  return "PLY header without end_header in its first 64 KiB";
}
}  // namespace

TriangleSoup loadTriangleSoup(const std::string& path, const Eigen::Vector3d& scale)
{
  const std::string name = "mesh file '" + path + "': ";
  if (!std::ifstream(path).good())
  {
    throw InputError(name + "no such file or not readable");
  }
  if (!scale.allFinite() || !(scale.cwiseAbs().minCoeff() > 0.0))
  {
    throw InputError(name + "scale must be finite and non-zero");
  }
  // assimp 5.2 loops forever on some malformed PLY headers (found by
  // test/fuzz/mesh_loading_fuzz): a PLY header is checked line by line before assimp sees it.
  {
    std::ifstream file(path, std::ios::binary);
    std::string head(65536, '\0');
    file.read(&head[0], static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(file.gcount()));
    const std::string problem = plyHeaderProblem(head);
    if (!problem.empty())
    {
      throw InputError(name + "unreadable: " + problem);
    }
  }
  Assimp::Importer importer;
  // No post-processing (see collect()); no welding here either: TriangleMesh::build welds and
  // reports it, and the file's triangle order is kept.
  const aiScene* scene = importer.ReadFile(path, 0);
  if (scene == nullptr)
  {
    std::string reason = importer.GetErrorString();
    if (reason.empty())
    {
      reason = "assimp could not read it";
    }
    throw InputError(name + "unreadable: " + reason);
  }
  TriangleSoup soup;
  if (scene->mRootNode != nullptr)
  {
    collect(*scene, *scene->mRootNode, aiMatrix4x4(), scale, name, &soup);
  }
  if (soup.triangles.empty())
  {
    throw InputError(name + "has no triangles");
  }
  return soup;
}

TriangleMesh loadTriangleMesh(const std::string& path, const Eigen::Vector3d& scale, const MeshBuildOptions& options)
{
  const TriangleSoup soup = loadTriangleSoup(path, scale);
  try
  {
    return TriangleMesh::build(soup, options);
  }
  catch (const InputError& error)
  {
    throw InputError("mesh file '" + path + "': " + error.what());
  }
}
}  // namespace god_finger
