// Concave polygon faces as files carry them, in OBJ, OFF, PLY and DAE: an L, a U, a star, a comb
// and a polygon with collinear runs load as triangles that cover them exactly (area, orientation,
// every triangle inside), and a self-intersecting face is refused with one line naming it.
#include "god_finger/contact/contact_sampling.h"
#include "god_finger/support/input_error.h"
#include "god_finger/mesh_io/mesh_loader.h"
#include "god_finger/mesh_io/polygon_soup.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace god_finger
{
namespace
{
using Outline = std::vector<std::array<double, 2>>;

const Outline kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};  // area 4
const Outline kComb = {{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1},
                       {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};               // area 11
const Outline kU = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};  // area 7
// A five-pointed star, outer radius 2, inner radius 0.8.
const Outline kStar = {{0, 2},    {0.470, 0.647},   {1.902, 0.618},   {0.761, -0.247}, {1.176, -1.618},
                       {0, -0.8}, {-1.176, -1.618}, {-0.761, -0.247}, {-1.902, 0.618}, {-0.470, 0.647}};
// An L whose long sides are split into collinear runs (as CAD exporters write edges shared
// with neighbouring faces).
const Outline kCollinearRuns = {{0, 0}, {1, 0}, {2, 0},   {2, 0.5}, {2, 1}, {1.5, 1}, {1, 1},
                                {1, 2}, {1, 3}, {0.5, 3}, {0, 3},   {0, 2}, {0, 1}};  // area 4
// A square with a square hole as one polygon: the outer ring, a bridge, the hole clockwise, the
// bridge back (area 12; its bridge ends repeat).
const Outline kKeyhole = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}};
const Outline kBowTie = {{0, 0}, {2, 2}, {2, 0}, {0, 2}};

std::string write(const std::string& name, const std::string& text)
{
  const std::string path = "/tmp/god_finger_polygon_" + name;
  std::ofstream(path) << text;
  return path;
}

std::string objOf(const Outline& outline)
{
  std::ostringstream out;
  for (const auto& p : outline)
  {
    out << "v " << p[0] << " " << p[1] << " 0\n";
  }
  out << "f";
  for (std::size_t i = 0; i < outline.size(); ++i)
  {
    out << " " << i + 1;
  }
  out << "\n";
  return out.str();
}

// The body OFF and ASCII PLY share: a line per corner, then "n 0 1 ... n-1".
std::string cornersAndFace(const Outline& outline)
{
  std::ostringstream out;
  for (const auto& p : outline)
  {
    out << p[0] << " " << p[1] << " 0\n";
  }
  out << outline.size();
  for (std::size_t i = 0; i < outline.size(); ++i)
  {
    out << " " << i;
  }
  out << "\n";
  return out.str();
}

std::string offOf(const Outline& outline)
{
  return "OFF\n" + std::to_string(outline.size()) + " 1 0\n" + cornersAndFace(outline);
}

std::string plyOf(const Outline& outline)
{
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(outline.size()) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
         "property list uchar int vertex_indices\nend_header\n" +
         cornersAndFace(outline);
}

std::string daeOf(const Outline& outline)
{
  std::ostringstream points;
  std::ostringstream indices;
  for (std::size_t i = 0; i < outline.size(); ++i)
  {
    points << outline[i][0] << " " << outline[i][1] << " 0 ";
    indices << i << " ";
  }
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">"
         "<asset><up_axis>Z_UP</up_axis></asset><library_geometries><geometry id=\"g\"><mesh>"
         "<source id=\"p\"><float_array id=\"pa\" count=\""
      << 3 * outline.size() << "\">" << points.str()
      << "</float_array><technique_common><accessor source=\"#pa\" count=\"" << outline.size()
      << "\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
         "<param name=\"Z\" type=\"float\"/></accessor></technique_common></source>"
         "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>"
         "<polylist count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><vcount>"
      << outline.size() << "</vcount><p>" << indices.str()
      << "</p></polylist></mesh></geometry></library_geometries><library_visual_scenes><visual_scene id=\"s\">"
         "<node id=\"n\"><instance_geometry url=\"#g\"/></node></visual_scene></library_visual_scenes>"
         "<scene><instance_visual_scene url=\"#s\"/></scene></COLLADA>\n";
  return out.str();
}

bool inside(const Outline& polygon, double x, double y)
{
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
  {
    if ((polygon[i][1] > y) != (polygon[j][1] > y) &&
        x < (polygon[j][0] - polygon[i][0]) * (y - polygon[i][1]) / (polygon[j][1] - polygon[i][1]) + polygon[i][0])
    {
      in = !in;
    }
  }
  return in;
}

// `collinear_corners`: the outline has corners on straight runs, which are kept as triangle
// corners (no T-junction) but are never an ear's tip, so that n - 2 need not hold.
void expectExactCover(const std::string& path, const Outline& outline, double area, bool collinear_corners = false)
{
  SCOPED_TRACE(path);
  const TriangleSoup soup = loadTriangleSoup(path);
  double total = 0.0;
  Eigen::Vector3d first_normal = Eigen::Vector3d::Zero();
  for (const auto& t : soup.triangles)
  {
    const Eigen::Vector3d& a = soup.vertices[t[0]];
    const Eigen::Vector3d& b = soup.vertices[t[1]];
    const Eigen::Vector3d& c = soup.vertices[t[2]];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    ASSERT_GT(normal.norm(), 1e-12) << "degenerate triangle";
    if (first_normal.isZero())
    {
      first_normal = normal.normalized();
    }
    EXPECT_GT(normal.normalized().dot(first_normal), 0.999) << "flipped triangle";
    const Eigen::Vector3d centre = (a + b + c) / 3.0;
    EXPECT_TRUE(inside(outline, centre.x(), centre.y())) << "triangle outside the face";
    total += 0.5 * normal.norm();
  }
  EXPECT_NEAR(total, area, 1e-5);
  if (!collinear_corners)
  {
    EXPECT_EQ(soup.triangles.size(), outline.size() - 2) << "a simple polygon of n corners makes n - 2 triangles";
  }
  // Every corner of the face is a corner of some triangle: nothing is dropped.
  for (const auto& p : outline)
  {
    bool used = false;
    for (const auto& t : soup.triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        used = used || (soup.vertices[t[k]] - Eigen::Vector3d(p[0], p[1], 0.0)).norm() < 1e-6;
      }
    }
    EXPECT_TRUE(used) << "corner (" << p[0] << ", " << p[1] << ") in no triangle";
  }
}

// The polygon's own area (shoelace), the reference the triangles must add up to.
double shoelaceArea(const Outline& outline)
{
  double twice = 0.0;
  for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
  {
    twice += outline[j][0] * outline[i][1] - outline[i][0] * outline[j][1];
  }
  return 0.5 * std::abs(twice);
}

// Issue 18: triangles index the soup's vertices with int; a mesh with more vertices than that
// (here a limit of 5 stands for INT_MAX) is refused with the count, and the soup is unchanged.
TEST(PolygonFaces, MoreVerticesThanTrianglesCanIndexAreRefused)
{
  PolygonSoup quad;
  quad.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.corners = {0, 1, 2, 3};
  quad.endFace();
  TriangleSoup soup;
  soup.vertices = {{5, 5, 5}, {6, 6, 6}};
  try
  {
    appendTriangulated(quad, &soup, 5);
    FAIL() << "6 vertices accepted with a limit of 5";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "mesh has 6 vertices, more than the 5 its triangles can index");
  }
  EXPECT_EQ(soup.vertices.size(), 2u);
  EXPECT_TRUE(soup.triangles.empty());
  appendTriangulated(quad, &soup, 6);
  EXPECT_EQ(soup.vertices.size(), 6u);
  EXPECT_EQ(soup.triangles.size(), 2u);
}

TEST(PolygonFaces, ConcaveFacesLoadAsExactCoversInEveryFormat)
{
  const std::pair<std::string, Outline> shapes[] = {
      {"L", kL}, {"U", kU}, {"star", kStar}, {"comb", kComb}, {"collinear", kCollinearRuns}, {"holed", kKeyhole}};
  for (const auto& [name, outline] : shapes)
  {
    const double area = shoelaceArea(outline);
    const bool collinear_corners = name == "collinear";
    expectExactCover(write(name + ".obj", objOf(outline)), outline, area, collinear_corners);
    expectExactCover(write(name + ".off", offOf(outline)), outline, area, collinear_corners);
    expectExactCover(write(name + ".ply", plyOf(outline)), outline, area, collinear_corners);
    expectExactCover(write(name + ".dae", daeOf(outline)), outline, area, collinear_corners);
  }
  EXPECT_DOUBLE_EQ(shoelaceArea(kL), 4.0);
  EXPECT_DOUBLE_EQ(shoelaceArea(kComb), 11.0);
}

TEST(PolygonFaces, ColladaPolygonsWithHoleElementsAreRefusedWithTheReason)
{
  // COLLADA's own holes (<ph><p>outer</p><h>hole</h></ph>): Debian's assimp 5.2 does not read
  // them; the file is refused with its reason instead of loading the outer ring without its
  // hole. The keyhole form above (one polygon with a bridge) loads in every format.
  const std::string path = write(
      "ph.dae",
      "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">"
      "<library_geometries><geometry id=\"g\"><mesh><source id=\"p\"><float_array id=\"pa\" count=\"24\">0 0 0 4 0 0 4 "
      "4 0 0 4 0 1 1 0 1 3 0 3 3 0 3 1 0</float_array><technique_common><accessor source=\"#pa\" count=\"8\" "
      "stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" "
      "type=\"float\"/></accessor></technique_common></source><vertices id=\"v\"><input semantic=\"POSITION\" "
      "source=\"#p\"/></vertices><polygons count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><ph><p>0 "
      "1 2 3</p><h>4 5 6 7</h></ph></polygons></mesh></geometry></library_geometries><library_visual_scenes>"
      "<visual_scene id=\"s\"><node id=\"n\"><instance_geometry url=\"#g\"/></node></visual_scene>"
      "</library_visual_scenes><scene><instance_visual_scene url=\"#s\"/></scene></COLLADA>\n");
  try
  {
    loadTriangleSoup(path);
    FAIL() << "a polygon with a hole element loaded";
  }
  catch (const InputError& error)
  {
    EXPECT_EQ(std::string(error.what()).rfind("mesh file '" + path + "': unreadable: ", 0), 0u) << error.what();
    EXPECT_NE(std::string(error.what()).find("<h>"), std::string::npos) << error.what();
  }
}

TEST(PolygonFaces, SelfIntersectingFaceIsRefusedWithItsName)
{
  const std::string path = write("bowtie.obj", objOf(kBowTie));
  try
  {
    loadTriangleSoup(path);
    FAIL() << "a self-intersecting face was accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("face 0: polygon of 4 corners crosses itself"), std::string::npos)
        << error.what();
  }
}
// A closed prism of height 1 over `outline`: the bottom and top faces are the polygon itself
// (one face each, concave), the sides are quads; faces turn outward whichever way `given` turns.
std::string prismObj(const Outline& given)
{
  Outline outline = given;
  double twice_signed_area = 0.0;
  for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
  {
    twice_signed_area += outline[j][0] * outline[i][1] - outline[i][0] * outline[j][1];
  }
  if (twice_signed_area < 0.0)
  {
    std::reverse(outline.begin(), outline.end());
  }
  std::ostringstream out;
  for (double z : {0.0, 1.0})
  {
    for (const auto& p : outline)
    {
      out << "v " << p[0] << " " << p[1] << " " << z << "\n";
    }
  }
  const std::size_t n = outline.size();
  out << "f";
  for (std::size_t i = n; i > 0; --i)
  {
    out << " " << i;  // bottom, facing down
  }
  out << "\nf";
  for (std::size_t i = 0; i < n; ++i)
  {
    out << " " << n + i + 1;  // top, facing up
  }
  out << "\n";
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = (i + 1) % n;
    out << "f " << i + 1 << " " << j + 1 << " " << n + j + 1 << " " << n + i + 1 << "\n";
  }
  return out.str();
}

TEST(PolygonFaces, WalksOnConcavePolygonSolidsStayOnTheSurface)
{
  // Before ear clipping, a fan over a concave face put triangles outside the solid: the health
  // report showed non-manifold edges and sub-god-objects walked off the true surface.
  for (const auto& [name, outline] : {std::make_pair(std::string("U"), kU), std::make_pair(std::string("comb"), kComb),
                                      std::make_pair(std::string("star"), kStar)})
  {
    SCOPED_TRACE(name);
    const TriangleMesh mesh = loadTriangleMesh(write(name + "_prism.obj", prismObj(outline)));
    EXPECT_EQ(mesh.health().boundary_edges, 0);
    EXPECT_EQ(mesh.health().non_manifold_edges, 0);
    EXPECT_EQ(mesh.health().flipped_triangles, 0);
    const SurfaceLocator locator(mesh);
    ContactParams params;
    params.max_radius = 0.3;
    params.distance_constant = 0.3;
    RandomContacts contacts(mesh, params, 7);
    ContactAreaResult area;
    int valid = 0;
    for (int i = 0; i < 500; ++i)
    {
      const ContactQuery query = contacts.next();
      computeContactArea(mesh, query, params, &area);
      valid += area.valid ? 1 : 0;
      const std::string defect = contactAreaDefect(locator, query, area, 1e-9);
      ASSERT_TRUE(!area.valid || defect.empty()) << "contact " << i << ": " << defect;
    }
    EXPECT_GT(valid, 400);
  }
}
}  // namespace
}  // namespace god_finger
