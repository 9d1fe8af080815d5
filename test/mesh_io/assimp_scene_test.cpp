// Issue 18: what assimp returns is checked before it is read. A scene with a missing array (a
// node's mesh list, the scene's meshes, a mesh's vertices or faces, a node's children) gives
// one clear line, not a crash; a whole scene gives its triangles.
#include "god_finger/mesh_io/assimp_scene.h"
#include "god_finger/support/input_error.h"

#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace god_finger
{
namespace
{
// A scene as assimp builds one: a root node with one triangle mesh (arrays allocated with new,
// which ~aiScene deletes).
aiScene* oneTriangle()
{
  aiScene* scene = new aiScene();
  scene->mRootNode = new aiNode();
  scene->mRootNode->mNumMeshes = 1;
  scene->mRootNode->mMeshes = new unsigned int[1]{0};
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh*[1];
  aiMesh* mesh = scene->mMeshes[0] = new aiMesh();
  mesh->mNumVertices = 3;
  mesh->mVertices = new aiVector3D[3]{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->mNumFaces = 1;
  mesh->mFaces = new aiFace[1];
  mesh->mFaces[0].mNumIndices = 3;
  mesh->mFaces[0].mIndices = new unsigned int[3]{0, 1, 2};
  return scene;
}

std::string errorOf(const std::function<void(aiScene*)>& damage)
{
  aiScene* scene = oneTriangle();
  damage(scene);
  std::string error;
  try
  {
    TriangleSoup soup;
    appendAssimpScene(*scene, Eigen::Vector3d::Ones(), &soup);
  }
  catch (const InputError& e)
  {
    error = e.what();
  }
  delete scene;
  return error;
}

TEST(AssimpScene, AWholeSceneGivesItsTriangles)
{
  aiScene* scene = oneTriangle();
  TriangleSoup soup;
  appendAssimpScene(*scene, Eigen::Vector3d(2, 2, 2), &soup);
  delete scene;
  ASSERT_EQ(soup.vertices.size(), 3u);
  ASSERT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.vertices[1], Eigen::Vector3d(2, 0, 0));
}

TEST(AssimpScene, MissingArraysGiveOneClearLine)
{
  EXPECT_EQ(errorOf(
                [](aiScene* s)
                {
                  delete[] s->mRootNode->mMeshes;
                  s->mRootNode->mMeshes = nullptr;
                }),
            "a node refers to a mesh that is not in the file");
  EXPECT_EQ(errorOf(
                [](aiScene* s)
                {
                  delete s->mMeshes[0];
                  delete[] s->mMeshes;
                  s->mMeshes = nullptr;
                  s->mNumMeshes = 0;
                }),
            "a node refers to a mesh that is not in the file");
  EXPECT_EQ(errorOf(
                [](aiScene* s)
                {
                  delete[] s->mMeshes[0]->mVertices;
                  s->mMeshes[0]->mVertices = nullptr;
                }),
            "mesh 0 has 3 vertices but no positions");
  EXPECT_EQ(errorOf(
                [](aiScene* s)
                {
                  delete[] s->mMeshes[0]->mFaces;
                  s->mMeshes[0]->mFaces = nullptr;
                }),
            "mesh 0 has 1 faces but no face list");
  EXPECT_EQ(errorOf([](aiScene* s) { s->mRootNode->mNumChildren = 2; }), "a node has 2 children but no list of them");
  // A scene without a root node has nothing to give: no triangles, no error.
  EXPECT_EQ(errorOf(
                [](aiScene* s)
                {
                  delete s->mRootNode;
                  s->mRootNode = nullptr;
                }),
            "");
}
}  // namespace
}  // namespace god_finger
