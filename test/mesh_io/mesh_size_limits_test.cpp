// Mesh files too large for the memory left are refused before anything is allocated for them,
// with one line naming the file, the count, the estimate and the limit (support/memory_budget.h).
#include "god_finger/support/memory_budget.h"
#include "god_finger/mesh_io/mesh_loader.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace god_finger
{
namespace
{
// A file in a fresh temporary folder, removed with it; GOD_FINGER_MEMORY_LIMIT unset at the end.
class Scratch : public testing::Test
{
 protected:
  void SetUp() override
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "god_finger_size_XXXXXX").string();
    folder_ = mkdtemp(pattern.data());
  }
  void TearDown() override
  {
    unsetenv("GOD_FINGER_MEMORY_LIMIT");
    std::filesystem::remove_all(folder_);
  }
  std::string write(const std::string& name, const std::string& content)
  {
    const std::string path = folder_ + "/" + name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  // The message of the ResourceLimitError that loading `path` throws, "" if none.
  static std::string refusal(const std::string& path)
  {
    try
    {
      loadTriangleMesh(path);
    }
    catch (const ResourceLimitError& error)
    {
      return error.what();
    }
    catch (const InputError& error)
    {
      ADD_FAILURE() << "not a ResourceLimitError: " << error.what();
    }
    return std::string();
  }
  std::string folder_;
};

std::string plyHeader(std::uint64_t vertices, std::uint64_t faces)
{
  return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST_F(Scratch, APlyHeaderOfFiveMillionFacesIsRefusedUnderAOneGigabyteLimit)
{
  setenv("GOD_FINGER_MEMORY_LIMIT", "1e9", 1);
  const std::string path = write("scan.ply", plyHeader(2500000, 5000000));
  const std::string message = refusal(path);
  EXPECT_EQ(message, "mesh file '" + path +
                         "': declares 5000000 faces and 2500000 vertices: loading them needs about 2.1 GiB, more "
                         "than the limit of 954 MiB (GOD_FINGER_MEMORY_LIMIT=1e9)");
}

TEST_F(Scratch, APlyHeaderOfThreeBillionFacesIsRefusedOnThisMachine)
{
  const std::string path = write("huge.ply", plyHeader(1500000000, 3000000000));
  const std::string message = refusal(path);
  EXPECT_NE(message.find("mesh file '" + path +
                         "': declares 3000000000 faces and 1500000000 vertices: loading "
                         "them needs about 1.23 TiB, more than the limit of "),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("of MemAvailable"), std::string::npos) << message;
}

TEST_F(Scratch, AnOffHeaderIsCheckedToo)
{
  setenv("GOD_FINGER_MEMORY_LIMIT", "1e9", 1);
  const std::string path = write("scan.off", "OFF\n2500000 5000000 0\n");
  EXPECT_NE(refusal(path).find("declares 5000000 faces and 2500000 vertices"), std::string::npos);
}

TEST_F(Scratch, ABinaryStlIsCheckedByItsHeaderAndOtherFilesByTheirSize)
{
  setenv("GOD_FINGER_MEMORY_LIMIT", "1e9", 1);
  // Sparse files: their size is what is checked, nothing is read.
  const std::uint32_t triangles = 5000000;
  std::string header(80, ' ');
  header.append(reinterpret_cast<const char*>(&triangles), 4);
  const std::string stl = write("scan.stl", header);
  std::filesystem::resize_file(stl, 84 + 50ull * triangles);
  EXPECT_NE(refusal(stl).find("declares 5000000 faces and 15000000 vertices"), std::string::npos);
  const std::string obj = write("scan.obj", "v 0 0 0\n");
  std::filesystem::resize_file(obj, 2000000000ull);
  EXPECT_NE(refusal(obj).find("': is 2000000000 bytes, up to about 83333333 triangles: loading them needs about "),
            std::string::npos)
      << refusal(obj);
}

TEST_F(Scratch, ASmallMeshLoadsUnderTheLimit)
{
  setenv("GOD_FINGER_MEMORY_LIMIT", "1e9", 1);
  const std::string path =
      write("tetra.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  EXPECT_EQ(loadTriangleMesh(path).triangleCount(), 4);
}

TEST(MemoryBudget, TheLimitIsTheSmallerOfAvailableMemoryAndTheVariable)
{
  unsetenv("GOD_FINGER_MEMORY_LIMIT");
  const MemoryLimit machine = memoryLimit();
  EXPECT_GT(machine.bytes, 0u);
  setenv("GOD_FINGER_MEMORY_LIMIT", "1e18", 1);  // larger: ignored
  EXPECT_EQ(memoryLimit().source.substr(0, 4), "80 %");
  setenv("GOD_FINGER_MEMORY_LIMIT", "garbage", 1);
  EXPECT_EQ(memoryLimit().source.substr(0, 4), "80 %");
  setenv("GOD_FINGER_MEMORY_LIMIT", "2e6", 1);
  EXPECT_EQ(memoryLimit().bytes, 2000000u);
  unsetenv("GOD_FINGER_MEMORY_LIMIT");
  EXPECT_EQ(formatBytes(512), "512 B");
  EXPECT_EQ(formatBytes(1.5 * 1024 * 1024 * 1024), "1.5 GiB");
}
}  // namespace
}  // namespace god_finger
