// god_finger_contact as a user runs it: JSON and CSV on the shipped meshes, results that
// anyone can check, reproducible seeds, and one clear line with exit code 2 on bad input.
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/mesh_io/mesh_loader.h"

#include "tool_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
using test::jsonValue;
using test::readFile;
using test::ToolRun;

ToolRun runTool(const std::string& arguments)
{
  return test::runTool(GOD_FINGER_CONTACT_TOOL, arguments);
}

std::string mesh(const std::string& name)
{
  return std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/meshes/" + name;
}

TEST(ContactTool, ShippedMeshesHaveNoFailureAndDumpsCheckOut)
{
  for (const std::string name : {"box.stl", "sphere.obj", "cylinder.ply", "torus.dae", "l_block.off"})
  {
    for (const std::string walk : {"project", "unfold"})
    {
      const std::string csv = ::testing::TempDir() + "god_finger_dump.csv";
      const ToolRun run = runTool("--mesh " + mesh(name) + " --samples 300 --seed 4 --walk " + walk + " --dump " + csv);
      ASSERT_EQ(run.exit_code, 0) << run.err;
      EXPECT_EQ(jsonValue(run.out, "failures"), 0.0) << name << " " << walk;
      EXPECT_EQ(jsonValue(run.out, "nan"), 0.0) << name;
      EXPECT_EQ(jsonValue(run.out, "samples"), 300.0);
      EXPECT_EQ(jsonValue(run.out, "boundary_edges"), 0.0);
      EXPECT_GT(jsonValue(run.out, "walk_ns_median"), 0.0);
      EXPECT_NE(run.err.find("reported: 0 boundary edges"), std::string::npos) << run.err;

      // Check every dumped sub-god-object with our own reading of the file.
      const TriangleMesh reference = loadTriangleMesh(mesh(name));
      const SurfaceLocator locator(reference);
      std::ifstream dump(csv);
      std::string line;
      std::getline(dump, line);
      EXPECT_EQ(line, "sample,cx,cy,cz,nx,ny,nz,vx,vy,vz,sx,sy,sz,face");
      int rows = 0;
      const double r_max = 0.01;
      const double alpha = 2.0;
      while (std::getline(dump, line))
      {
        double v[14];
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1],
                              &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], &v[8], &v[9], &v[10], &v[11], &v[12], &v[13]),
                  14)
            << line;
        const Eigen::Vector3d contact(v[1], v[2], v[3]);
        const Eigen::Vector3d sgo(v[10], v[11], v[12]);
        EXPECT_LT(locator.closest(sgo).distance, 1e-9 * reference.boundingBoxDiagonal()) << line;
        EXPECT_LE((sgo - contact).norm(), r_max * alpha * (1.0 + 1e-12)) << line;
        EXPECT_GE(v[13], 0.0);
        EXPECT_LT(v[13], reference.health().input_triangles);
        ++rows;
      }
      EXPECT_NEAR(rows, 300 * jsonValue(run.out, "sgo_per_contact_mean"), 0.5) << name;
    }
  }
}

TEST(ContactTool, AMeshPathWithQuotesAndBackslashesGivesValidJson)
{
  // The path goes into the JSON as a string: escaped by the library, it reads back unchanged.
  const std::string path = ::testing::TempDir() + "god_finger \"quoted\" back\\slash.stl";
  {
    std::ofstream copy(path, std::ios::binary);
    copy << readFile(mesh("box.stl"));
  }
  const ToolRun run = runTool("--mesh '" + path + "' --samples 20 --seed 1");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(run.out, nullptr, /*allow_exceptions=*/false);
  ASSERT_FALSE(json.is_discarded()) << run.out;
  EXPECT_EQ(json.at("mesh").at("file").get<std::string>(), path);
  EXPECT_EQ(json.at("samples").get<int>(), 20);
  EXPECT_EQ(json.at("failures").get<int>(), 0);
  // The same keys, in the same order, as the tool always wrote.
  std::vector<std::string> keys;
  for (const auto& entry : json.items())
  {
    keys.push_back(entry.key());
  }
  EXPECT_EQ(keys,
            (std::vector<std::string>{"mesh", "params", "samples", "seed", "failures", "nan", "sgo_per_contact_mean",
                                      "radius_mean_m", "walk_ns_median", "walk_ns_p99", "stops"}));
  EXPECT_EQ(json.at("params").at("r_max").get<double>(), 0.01);
  EXPECT_EQ(json.at("params").at("walk").get<std::string>(), "unfold");
  // Round trip: what the library reads is what it writes.
  EXPECT_EQ(nlohmann::ordered_json::parse(json.dump()), json);
  std::remove(path.c_str());
}

TEST(ContactTool, SeedsAreReproducible)
{
  const std::string a = ::testing::TempDir() + "god_finger_a.csv";
  const std::string b = ::testing::TempDir() + "god_finger_b.csv";
  const std::string c = ::testing::TempDir() + "god_finger_c.csv";
  ASSERT_EQ(runTool("--mesh " + mesh("torus.dae") + " --samples 50 --seed 9 --dump " + a).exit_code, 0);
  ASSERT_EQ(runTool("--mesh " + mesh("torus.dae") + " --samples 50 --seed 9 --dump " + b).exit_code, 0);
  ASSERT_EQ(runTool("--mesh " + mesh("torus.dae") + " --samples 50 --seed 10 --dump " + c).exit_code, 0);
  EXPECT_EQ(readFile(a), readFile(b));
  EXPECT_NE(readFile(a), readFile(c));
  EXPECT_GT(readFile(a).size(), 1000u);
}

TEST(ContactTool, ParametersReachTheComputation)
{
  const ToolRun narrow = runTool("--mesh " + mesh("sphere.obj") + " --samples 200 --r-max 0.002 --n-sgo 16");
  const ToolRun wide = runTool("--mesh " + mesh("sphere.obj") + " --samples 200 --r-max 0.02 --n-sgo 16");
  ASSERT_EQ(narrow.exit_code, 0);
  ASSERT_EQ(wide.exit_code, 0);
  EXPECT_NEAR(jsonValue(wide.out, "radius_mean_m"), 10.0 * jsonValue(narrow.out, "radius_mean_m"), 1e-9);
  EXPECT_EQ(jsonValue(wide.out, "sgo_per_contact_mean"), 16.0);
  // With no friction the cone is empty: every radial vector is dropped.
  const ToolRun frictionless = runTool("--mesh " + mesh("box.stl") + " --samples 20 --friction 0");
  ASSERT_EQ(frictionless.exit_code, 0);
  EXPECT_EQ(jsonValue(frictionless.out, "sgo_per_contact_mean"), 0.0);
  EXPECT_EQ(jsonValue(frictionless.out, "failures"), 0.0);
}

TEST(ContactTool, BadInputGivesOneLineAndExitCodeTwo)
{
  const std::string empty = ::testing::TempDir() + "god_finger_empty.stl";
  std::ofstream(empty).close();
  const std::string cases[][2] = {
      {"--mesh " + mesh("box.stl") + " --samples -3", "--samples = -3 is out of range [1, 10000000]"},
      {"--mesh " + mesh("box.stl") + " --alpha 0.5",
       "parameter '--alpha' = 0.5 is out of range [1, 100] (dimensionless)"},
      {"--mesh " + mesh("box.stl") + " --walk sideways",
       "parameter '--walk' = 'sideways' is not one of project, unfold"},
      {"--mesh " + mesh("box.stl") + " --bogus 1", "unknown option '--bogus' (see --help)"},
      {"--mesh " + mesh("box.stl") + " --r-max", "option --r-max needs a value"},
      {"--mesh " + mesh("box.stl") + " --r-max abc", "parameter '--r-max' must be a number (m)"},
      {"--mesh " + mesh("box.stl") + " --n-sgo 4.5", "parameter '--n-sgo' must be an integer"},
      {"--mesh " + mesh("box.stl") + " --n-sgo 99", "parameter '--n-sgo' = 99 is out of range [3, 64] (count)"},
      {"--samples 10", "--mesh FILE is required (see --help)"},
      {"--mesh /nonexistent.stl", "mesh file '/nonexistent.stl': no such file or not readable"},
      {"--mesh " + empty, "mesh file '" + empty + "': unreadable: "},
  };
  for (const auto& c : cases)
  {
    const ToolRun run = runTool(c[0]);
    EXPECT_EQ(run.exit_code, 2) << c[0];
    EXPECT_EQ(run.out, "") << c[0];
    EXPECT_EQ(run.err.rfind("god_finger_contact: " + c[1], 0), 0u) << c[0] << " gave: " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
  const ToolRun help = runTool("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_EQ(help.out.rfind("usage: god_finger_contact --mesh FILE", 0), 0u);
}
}  // namespace
}  // namespace god_finger
