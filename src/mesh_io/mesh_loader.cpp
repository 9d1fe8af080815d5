#include "god_finger/mesh_io/mesh_loader.h"
#include "god_finger/mesh_io/assimp_scene.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/memory_budget.h"
#include "god_finger/mesh_io/off_reader.h"
#include "god_finger/mesh_io/ply_reader.h"
#include "god_finger/mesh_io/polygon_soup.h"

#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace god_finger
{
namespace
{
void scaleVertices(const Eigen::Vector3d& scale, PolygonSoup* polygons)
{
  for (Eigen::Vector3d& vertex : polygons->vertices)
  {
    vertex = vertex.cwiseProduct(scale);
  }
}

// Adds the node's own meshes to `soup` through appendTriangulated (polygons ear-clipped),
// `transform` taking the node's coordinates to the file's, times `scale`. assimp's own
// triangulation and validation are not used, because Debian's assimp 5.2 aborts the process
// (ai_assert) on some malformed files (found by test/fuzz/mesh_loading_fuzz).
void appendNodeMeshes(const aiScene& scene, const aiNode& node, const aiMatrix4x4& transform,
                      const Eigen::Vector3d& scale, TriangleSoup* soup)
{
  for (unsigned int m = 0; m < node.mNumMeshes; ++m)
  {
    if (node.mMeshes == nullptr || scene.mMeshes == nullptr || node.mMeshes[m] >= scene.mNumMeshes ||
        scene.mMeshes[node.mMeshes[m]] == nullptr)
    {
      throw InputError("a node refers to a mesh that is not in the file");
    }
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const std::string name = "mesh " + std::to_string(node.mMeshes[m]) + " has ";
    if (mesh.mNumVertices > 0 && mesh.mVertices == nullptr)
    {
      throw InputError(name + std::to_string(mesh.mNumVertices) + " vertices but no positions");
    }
    if (mesh.mNumFaces > 0 && mesh.mFaces == nullptr)
    {
      throw InputError(name + std::to_string(mesh.mNumFaces) + " faces but no face list");
    }
    PolygonSoup polygons;
    polygons.vertices.reserve(mesh.mNumVertices);
    for (unsigned int v = 0; v < mesh.mNumVertices; ++v)
    {
      const aiVector3D p = transform * mesh.mVertices[v];
      polygons.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned int f = 0; f < mesh.mNumFaces; ++f)
    {
      const aiFace& face = mesh.mFaces[f];
      if (face.mIndices != nullptr)
      {
        polygons.corners.insert(polygons.corners.end(), face.mIndices, face.mIndices + face.mNumIndices);
      }
      polygons.endFace();
    }
    scaleVertices(scale, &polygons);
    appendTriangulated(polygons, soup);
  }
}

void checkChildren(const aiNode& node)
{
  if (node.mNumChildren > 0 && node.mChildren == nullptr)
  {
    throw InputError("a node has " + std::to_string(node.mNumChildren) + " children but no list of them");
  }
}

// The node's meshes and its descendants', `transform` as in appendNodeMeshes.
void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& transform, const Eigen::Vector3d& scale,
             TriangleSoup* soup, int depth)
{
  if (depth > 1000)
  {
    throw InputError("node hierarchy deeper than 1000");
  }
  appendNodeMeshes(scene, node, transform, scale, soup);
  checkChildren(node);
  for (unsigned int c = 0; c < node.mNumChildren; ++c)
  {
    if (node.mChildren[c] != nullptr)
    {
      collect(scene, *node.mChildren[c], transform * node.mChildren[c]->mTransformation, scale, soup, depth + 1);
    }
  }
}

// What rviz shows (its mesh_loader.cpp; Gazebo's and MoveIt's loaders do the same): the root
// node's transformation, which assimp sets to turn a COLLADA file's Z_UP into Y_UP and to apply
// its <unit>, is not applied to the nodes below the root, so that a Z_UP file stays Z up as ROS
// expects; its unit scale is kept (rviz applies <unit> itself). Meshes of the root node itself
// take its whole transformation, as in rviz. For STL and OBJ the root's transformation is the
// identity.
void collectFromRoot(const aiScene& scene, const Eigen::Vector3d& scale, TriangleSoup* soup)
{
  const aiNode& root = *scene.mRootNode;
  appendNodeMeshes(scene, root, root.mTransformation, scale, soup);
  checkChildren(root);
  const ai_real unit = static_cast<ai_real>(std::cbrt(std::abs(root.mTransformation.Determinant())));
  aiMatrix4x4 below_root;
  below_root.a1 = below_root.b2 = below_root.c3 = unit;
  for (unsigned int c = 0; c < root.mNumChildren; ++c)
  {
    if (root.mChildren[c] != nullptr)
    {
      collect(scene, *root.mChildren[c], below_root * root.mChildren[c]->mTransformation, scale, soup, 1);
    }
  }
}

std::string lowerCaseExtension(const std::string& path)
{
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return std::string();
  }
  std::string extension = path.substr(dot + 1);
  for (char& c : extension)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return extension;
}

std::string readWholeFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

// Bytes of a text mesh file (OBJ, ASCII STL, DAE...) per triangle, at the fewest: an OBJ
// "f 1 2 3" line and half a "v x y z" line. A file's size over this bounds its triangle count
// before assimp reads it (assimp allocates as it parses, with no limit of its own).
constexpr std::uint64_t kTextBytesPerTriangle = 24;

// Refuses, before assimp allocates anything, a file too large to load (support/memory_budget.h):
// a binary STL by the triangle count in its header (84 + 50 n bytes), any other file by its
// size. assimp's own copy of the mesh (about its file's size again) counts too.
void checkAssimpFileFits(const std::string& path, const std::string& extension)
{
  std::error_code error;
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error)
  {
    return;  // the reader says why
  }
  if (extension == "stl" && size >= 84)
  {
    char header[84];
    std::ifstream(path, std::ios::binary).read(header, sizeof(header));
    std::uint32_t triangles = 0;
    std::memcpy(&triangles, header + 80, sizeof(triangles));
    if (std::strncmp(header, "solid", 5) != 0 || size == 84 + 50 * std::uint64_t(triangles))
    {
      checkMeshFits(3 * std::uint64_t(triangles), triangles, size);
      return;
    }
  }
  const std::uint64_t triangles = size / kTextBytesPerTriangle;
  checkMeshFits(triangles / 2, triangles, 2 * size,
                "is " + std::to_string(size) + " bytes, up to about " + std::to_string(triangles) + " triangles");
}

// PLY and OFF through our own readers; everything else through assimp.
void loadInto(const std::string& path, const Eigen::Vector3d& scale, TriangleSoup* soup)
{
  const std::string extension = lowerCaseExtension(path);
  if (extension == "ply" || extension == "off")
  {
    PolygonSoup polygons;
    const std::string bytes = readWholeFile(path);
    const DeclaredSizeCheck fits = [&bytes](std::uint64_t vertices, std::uint64_t faces)
    { checkMeshFits(vertices, faces, bytes.size()); };
    try
    {
      polygons = extension == "ply" ? readPly(bytes, fits) : readOff(bytes, fits);
    }
    catch (const ResourceLimitError&)
    {
      throw;
    }
    catch (const InputError& error)
    {
      throw InputError(std::string("unreadable: ") + error.what());
    }
    scaleVertices(scale, &polygons);
    appendTriangulated(polygons, soup);
    return;
  }
  checkAssimpFileFits(path, extension);
  Assimp::Importer importer;
  // No post-processing (see collect()); no welding here either: TriangleMesh::build welds and
  // reports it, and the file's triangle order is kept.
  const aiScene* scene = importer.ReadFile(path, 0);
  if (scene == nullptr)
  {
    std::string reason = importer.GetErrorString();
    throw InputError("unreadable: " + (reason.empty() ? std::string("assimp could not read it") : reason));
  }
  appendAssimpScene(*scene, scale, soup);
}
}  // namespace

void appendAssimpScene(const aiScene& scene, const Eigen::Vector3d& scale, TriangleSoup* soup)
{
  if (scene.mRootNode != nullptr)
  {
    collectFromRoot(scene, scale, soup);
  }
}

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
  TriangleSoup soup;
  try
  {
    loadInto(path, scale, &soup);
  }
  catch (const ResourceLimitError& error)
  {
    throw ResourceLimitError(name + error.what());
  }
  catch (const InputError& error)
  {
    throw InputError(name + error.what());
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
