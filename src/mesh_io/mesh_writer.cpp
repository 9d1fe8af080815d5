#include "god_finger/mesh_io/mesh_writer.h"

#include "god_finger/support/input_error.h"

#include <assimp/scene.h>
#include <Eigen/Geometry>
#include <assimp/Exporter.hpp>

#include <cstdio>
#include <memory>

namespace god_finger
{
namespace
{
std::string extensionOf(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  std::string extension = dot == std::string::npos ? std::string() : path.substr(dot + 1);
  for (char& c : extension)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return extension;
}

struct FileCloser
{
  void operator()(std::FILE* file) const
  {
    std::fclose(file);
  }
};

void writeText(const TriangleSoup& soup, const std::string& path, const std::string& format)
{
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "w"));
  if (!file)
  {
    throw InputError("mesh file '" + path + "': cannot be written");
  }
  std::FILE* f = file.get();
  if (format == "obj")
  {
    std::fprintf(f, "# god_finger\n");
    for (const Eigen::Vector3d& v : soup.vertices)
    {
      std::fprintf(f, "v %.17g %.17g %.17g\n", v.x(), v.y(), v.z());
    }
    for (const auto& t : soup.triangles)
    {
      std::fprintf(f, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
  }
  else if (format == "off")
  {
    std::fprintf(f, "OFF\n%zu %zu 0\n", soup.vertices.size(), soup.triangles.size());
    for (const Eigen::Vector3d& v : soup.vertices)
    {
      std::fprintf(f, "%.17g %.17g %.17g\n", v.x(), v.y(), v.z());
    }
    for (const auto& t : soup.triangles)
    {
      std::fprintf(f, "3 %d %d %d\n", t[0], t[1], t[2]);
    }
  }
  else  // ASCII STL
  {
    std::fprintf(f, "solid god_finger\n");
    for (const auto& t : soup.triangles)
    {
      const Eigen::Vector3d& a = soup.vertices[t[0]];
      const Eigen::Vector3d& b = soup.vertices[t[1]];
      const Eigen::Vector3d& c = soup.vertices[t[2]];
      Eigen::Vector3d n = (b - a).cross(c - a);
      n = n.norm() > 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
      std::fprintf(f, "facet normal %.17g %.17g %.17g\n outer loop\n", n.x(), n.y(), n.z());
      for (const Eigen::Vector3d* v : {&a, &b, &c})
      {
        std::fprintf(f, "  vertex %.17g %.17g %.17g\n", v->x(), v->y(), v->z());
      }
      std::fprintf(f, " endloop\nendfacet\n");
    }
    std::fprintf(f, "endsolid god_finger\n");
  }
  if (std::ferror(f))
  {
    throw InputError("mesh file '" + path + "': write failed");
  }
}

void writeWithAssimp(const TriangleSoup& soup, const std::string& path, const char* format_id)
{
  // aiScene's destructor frees everything below it, so all parts are allocated with new.
  aiScene scene;
  scene.mRootNode = new aiNode();
  scene.mRootNode->mMeshes = new unsigned int[1]{0};
  scene.mRootNode->mNumMeshes = 1;
  scene.mMaterials = new aiMaterial* [1] { new aiMaterial() };
  scene.mNumMaterials = 1;
  aiMesh* mesh = new aiMesh();
  scene.mMeshes = new aiMesh* [1] { mesh };
  scene.mNumMeshes = 1;
  mesh->mMaterialIndex = 0;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = static_cast<unsigned int>(soup.vertices.size());
  mesh->mVertices = new aiVector3D[mesh->mNumVertices];
  for (unsigned int v = 0; v < mesh->mNumVertices; ++v)
  {
    const Eigen::Vector3d& p = soup.vertices[v];
    mesh->mVertices[v] =
        aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()), static_cast<ai_real>(p.z()));
  }
  mesh->mNumFaces = static_cast<unsigned int>(soup.triangles.size());
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned int f = 0; f < mesh->mNumFaces; ++f)
  {
    aiFace& face = mesh->mFaces[f];
    face.mNumIndices = 3;
    face.mIndices = new unsigned int[3];
    for (int k = 0; k < 3; ++k)
    {
      face.mIndices[k] = static_cast<unsigned int>(soup.triangles[f][k]);
    }
  }
  Assimp::Exporter exporter;
  if (exporter.Export(&scene, format_id, path) != AI_SUCCESS)
  {
    throw InputError("mesh file '" + path + "': cannot be written: " + exporter.GetErrorString());
  }
}
}  // namespace

void writeTriangleSoup(const TriangleSoup& soup, const std::string& path)
{
  const std::string extension = extensionOf(path);
  if (extension == "obj" || extension == "off" || extension == "stl")
  {
    writeText(soup, path, extension);
  }
  else if (extension == "ply")
  {
    writeWithAssimp(soup, path, "ply");
  }
  else if (extension == "dae")
  {
    writeWithAssimp(soup, path, "collada");
  }
  else
  {
    throw InputError("mesh file '" + path + "': unknown extension (write .obj, .off, .stl, .ply or .dae)");
  }
}
}  // namespace god_finger
