// Our PLY and OFF readers (mesh_io/ply_reader.h, off_reader.h): every encoding and the
// variants real exporters write give the same mesh, and every corrupt file gives one clear
// line, without allocating more than the file can hold.
#include "god_finger/support/input_error.h"
#include "god_finger/mesh_io/mesh_loader.h"
#include "god_finger/mesh_io/off_reader.h"
#include "god_finger/mesh_io/ply_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
// A unit square pyramid: 5 vertices, a square base (one 4-corner face) and 4 triangles.
const std::vector<Eigen::Vector3d> kCorners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0.75}};
const std::vector<std::vector<int>> kFaces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

void expectPyramid(const PolygonSoup& soup)
{
  ASSERT_EQ(soup.vertices.size(), kCorners.size());
  for (std::size_t v = 0; v < kCorners.size(); ++v)
  {
    EXPECT_EQ(soup.vertices[v], kCorners[v]) << v;
  }
  ASSERT_EQ(soup.faceCount(), static_cast<int>(kFaces.size()));
  for (int f = 0; f < soup.faceCount(); ++f)
  {
    const std::vector<long long> corners(soup.corners.begin() + soup.face_starts[f],
                                         soup.corners.begin() + soup.face_starts[f + 1]);
    EXPECT_EQ(corners, std::vector<long long>(kFaces[f].begin(), kFaces[f].end())) << f;
  }
}

std::string errorOf(PolygonSoup (*reader)(const std::string&, const DeclaredSizeCheck&), const std::string& bytes)
{
  try
  {
    reader(bytes, nullptr);
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return std::string();
}

// --- PLY ---

std::string asciiPly(const std::string& extra_header = "")
{
  std::string text = "ply\nformat ascii 1.0\ncomment made by hand\n" + extra_header +
                     "element vertex 5\nproperty float x\nproperty float y\nproperty double z\n"
                     "property uchar red\nelement face 5\nproperty list uchar int vertex_indices\n"
                     "element edge 1\nproperty list uchar uint vertex_pair\nend_header\n";
  const int red[] = {255, 0, 0, 10, 20};
  for (std::size_t v = 0; v < kCorners.size(); ++v)
  {
    char line[128];
    std::snprintf(line, sizeof(line), "%g %g %g %d\n", kCorners[v].x(), kCorners[v].y(), kCorners[v].z(), red[v]);
    text += line;
  }
  for (const std::vector<int>& face : kFaces)
  {
    text += std::to_string(face.size());
    for (int index : face)
    {
      text += " " + std::to_string(index);
    }
    text += "\n";
  }
  return text + "2 0 4\n";
}

template <typename T>
void put(std::string* bytes, T value, bool big_endian)
{
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian)
  {
    std::reverse(raw, raw + sizeof(T));  // this test runs on little-endian hosts (x86, arm64)
  }
  bytes->append(raw, sizeof(T));
}

std::string binaryPly(bool big_endian)
{
  std::string bytes = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\nelement vertex 5\nproperty float32 x\nproperty float32 y\nproperty float64 z\n"
                      "property uint8 red\nelement face 5\nproperty list uint8 int32 vertex_indices\n"
                      "element edge 1\nproperty list int16 uint16 vertex_pair\nend_header\n";
  for (const Eigen::Vector3d& corner : kCorners)
  {
    put(&bytes, static_cast<float>(corner.x()), big_endian);
    put(&bytes, static_cast<float>(corner.y()), big_endian);
    put(&bytes, corner.z(), big_endian);
    put(&bytes, std::uint8_t{7}, big_endian);
  }
  for (const std::vector<int>& face : kFaces)
  {
    put(&bytes, static_cast<std::uint8_t>(face.size()), big_endian);
    for (int index : face)
    {
      put(&bytes, static_cast<std::int32_t>(index), big_endian);
    }
  }
  put(&bytes, std::int16_t{2}, big_endian);
  put(&bytes, std::uint16_t{0}, big_endian);
  put(&bytes, std::uint16_t{4}, big_endian);
  return bytes;
}

TEST(PlyReader, AsciiAndBothBinaryEndiansGiveTheSameMesh)
{
  expectPyramid(readPly(asciiPly()));
  expectPyramid(readPly(binaryPly(false)));
  expectPyramid(readPly(binaryPly(true)));
}

TEST(PlyReader, AcceptsWhatRealExportersWrite)
{
  // Free text in the header (an older Blender exporter), obj_info, CRLF line ends, the
  // vertex_index spelling, blank lines.
  std::string text = asciiPly("Created by Blender 2.49 - www.blender.org, source file: 'finger.blend'\nobj_info x\n\n");
  expectPyramid(readPly(text));
  std::string crlf;
  for (char c : asciiPly())
  {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  }
  expectPyramid(readPly(crlf));
  std::string index_spelling = asciiPly();
  index_spelling.replace(index_spelling.find("vertex_indices"), 14, "vertex_index");
  expectPyramid(readPly(index_spelling));
}

TEST(PlyReader, CorruptFilesGiveOneClearLine)
{
  const std::string good = asciiPly();
  const auto replaced = [&](const std::string& from, const std::string& to)
  {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  EXPECT_EQ(errorOf(readPly, "solid cube\n"), "not a PLY file (its first line is not 'ply')");
  EXPECT_EQ(errorOf(readPly, "ply\nformat ascii 1.0\nelement vertex 1\n"), "PLY header has no end_header line");
  EXPECT_EQ(errorOf(readPly, "ply\nelement vertex 0\nend_header\n"), "PLY header has no format line");
  EXPECT_EQ(errorOf(readPly, replaced("format ascii", "format utf8")),
            "PLY header line 2: unknown format (ascii, binary_little_endian or binary_big_endian)");
  EXPECT_EQ(errorOf(readPly, replaced("property float x", "property quad x")),
            "PLY header line 5: unknown property type 'quad'");
  EXPECT_EQ(errorOf(readPly, replaced("element vertex 5", "element vertex -5")),
            "PLY header line 4: element count '-5' is not a whole number");
  EXPECT_EQ(errorOf(readPly, replaced("element vertex 5", "element vertex 0")),
            "PLY file declares no vertices (element vertex 0)");
  EXPECT_EQ(errorOf(readPly, replaced("property float x", "property float w")),
            "PLY vertex element lacks an x, y or z property");
  EXPECT_EQ(errorOf(readPly, replaced("vertex_indices", "corners")), "PLY face element has no vertex_indices list");
  // Counts larger than the file are refused before anything is allocated for them.
  EXPECT_EQ(errorOf(readPly, replaced("element vertex 5", "element vertex 4000000000"))
                .rfind("PLY element 'vertex' claims 4000000000 entries, more than the ", 0),
            0u);
  const std::string huge_list = replaced("\n3 0 1 4\n", "\n3000000000 0 1 4\n");
  EXPECT_NE(errorOf(readPly, huge_list).find("a list of 3000000000 entries, more than the bytes left can hold"),
            std::string::npos)
      << errorOf(readPly, huge_list);
  EXPECT_EQ(errorOf(readPly, good.substr(0, good.size() - 4)),
            "PLY body at byte 341: a list of 2 entries, more than the bytes left can hold");
  EXPECT_EQ(errorOf(readPly, replaced("\n2 0 4\n", "\n2 0      \n")),
            "PLY body ends early (a value is missing at its end)");
  EXPECT_EQ(errorOf(readPly, binaryPly(false).substr(0, binaryPly(false).size() - 1)),
            "PLY body ends early (a value is missing at its end)");
  EXPECT_NE(errorOf(readPly, replaced("0.75", "0.7x5")).find("'0.7x5' is not a number"), std::string::npos);
}

TEST(PlyReader, OutOfRangeIndexNamesTheFaceThroughTheLoader)
{
  std::string text = asciiPly();
  text.replace(text.find("\n3 0 1 4\n"), 9, "\n3 0 1 9\n");
  const std::string path = ::testing::TempDir() + "god_finger_bad_index.PLY";
  std::ofstream(path, std::ios::binary) << text;
  try
  {
    loadTriangleSoup(path);
    ADD_FAILURE() << "no error";
  }
  catch (const InputError& error)
  {
    EXPECT_EQ(std::string(error.what()), "mesh file '" + path + "': face 1 refers to vertex 9 of 5");
  }
  std::remove(path.c_str());
}

// --- OFF ---
std::string off(const std::string& header, const std::string& vertex_suffix = "", const std::string& face_suffix = "")
{
  std::string text = header + "# a comment line\n5 5 8\n";
  for (const Eigen::Vector3d& corner : kCorners)
  {
    char line[128];
    std::snprintf(line, sizeof(line), "%g %g %g%s\n", corner.x(), corner.y(), corner.z(), vertex_suffix.c_str());
    text += line;
  }
  for (const std::vector<int>& face : kFaces)
  {
    text += std::to_string(face.size());
    for (int index : face)
    {
      text += " " + std::to_string(index);
    }
    text += face_suffix + "  # trailing comment\n";
  }
  return text;
}

TEST(OffReader, HeaderVariantsColoursNormalsAndComments)
{
  expectPyramid(readOff(off("OFF\n")));
  expectPyramid(readOff(off("COFF\n", " 0.5 0.5 0.5 1", " 255 0 0")));
  expectPyramid(readOff(off("NOFF\n", " 0 0 1")));
  expectPyramid(readOff(off("")));  // the keyword is optional
  std::string counts_on_header = off("OFF\n");
  counts_on_header.replace(0, std::string("OFF\n# a comment line\n5 5 8\n").size(), "OFF 5 5 8\n");
  expectPyramid(readOff(counts_on_header));
}

TEST(OffReader, CorruptFilesGiveOneClearLine)
{
  EXPECT_EQ(errorOf(readOff, ""), "OFF file is empty");
  EXPECT_EQ(errorOf(readOff, "OFF\n"), "OFF file ends before its vertex and face counts");
  EXPECT_EQ(errorOf(readOff, "4OFF\n1 0 0\n0 0 0 0\n"), "OFF line 1: only 3-D OFF files are read ('4OFF')");
  EXPECT_EQ(errorOf(readOff, "OFF BINARY\n"), "OFF line 1: binary OFF files are not read");
  EXPECT_EQ(errorOf(readOff, "OFF\nfive 1 0\n"),
            "OFF line 2: expected the vertex and face counts (two whole numbers >= 0)");
  EXPECT_EQ(errorOf(readOff, "OFF\n2000000000 1 0\n0 0 0\n"),
            "OFF line 2: counts of 2000000000 vertices and 1 faces, more than the 6 bytes left can hold");
  EXPECT_EQ(errorOf(readOff, "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n"), "OFF line 4: vertex 1 is not three numbers");
  EXPECT_EQ(errorOf(readOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n"),
            "OFF line 6: face 0 is not a corner count followed by that many vertex indices");
  EXPECT_EQ(errorOf(readOff, "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "OFF file ends after 1 of its 2 faces");
  EXPECT_EQ(errorOf(readOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 x\n"),
            "OFF line 6: face 0: 'x' is not a vertex index");
}

TEST(OwnReaders, LoadThroughTheLoaderAsExactTriangles)
{
  for (const std::string extension : {"ply", "off", "OFF"})
  {
    const std::string path = ::testing::TempDir() + "god_finger_pyramid." + extension;
    std::ofstream(path, std::ios::binary) << (extension == "ply" ? binaryPly(true) : off("OFF\n"));
    const TriangleMesh mesh = loadTriangleMesh(path, Eigen::Vector3d(2.0, 2.0, 2.0));
    EXPECT_EQ(mesh.triangleCount(), 6) << extension;  // the square base in two
    EXPECT_EQ(mesh.health().boundary_edges, 0) << extension;
    EXPECT_EQ(mesh.health().flipped_triangles, 0) << extension;
    EXPECT_NEAR(mesh.boundingBoxDiagonal(), 2.0 * std::sqrt(2.0 + 0.75 * 0.75), 1e-12) << extension;
    std::remove(path.c_str());
  }
}
}  // namespace
}  // namespace god_finger
