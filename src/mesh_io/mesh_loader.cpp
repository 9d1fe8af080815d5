#include "god_finger/mesh_io/mesh_loader.h"

#include "god_finger/core/input_error.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <fstream>

namespace god_finger
{
namespace
{
void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, const Eigen::Vector3d& scale,
             TriangleSoup* soup)
{
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned int m = 0; m < node.mNumMeshes; ++m)
  {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const int base = static_cast<int>(soup->vertices.size());
    for (unsigned int v = 0; v < mesh.mNumVertices; ++v)
    {
      const aiVector3D p = transform * mesh.mVertices[v];
      soup->vertices.emplace_back(scale.x() * p.x, scale.y() * p.y, scale.z() * p.z);
    }
    for (unsigned int f = 0; f < mesh.mNumFaces; ++f)
    {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3)
      {
        continue;  // points and lines left by the importer
      }
      soup->triangles.push_back({base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                                 base + static_cast<int>(face.mIndices[2])});
    }
  }
  for (unsigned int c = 0; c < node.mNumChildren; ++c)
  {
    collect(scene, *node.mChildren[c], transform, scale, soup);
  }
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
  Assimp::Importer importer;
  // Polygons become triangles; points and lines are skipped while collecting (so that a file
  // of lines says "no triangles"). No welding here: TriangleMesh::build welds and reports it,
  // and the file's triangle order is kept.
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate);
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
    collect(*scene, *scene->mRootNode, aiMatrix4x4(), scale, &soup);
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
