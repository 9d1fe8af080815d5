// god_finger_soft as a user runs it (issue 28): the shipped soft block's summary, a pad's press
// against Boussinesq's w0 and a point's, a block volume written and read back, and one line and
// exit code 2 for each bad option or file.
#include "tool_run.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace god_finger
{
namespace
{
const std::string kBlock = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/objects/soft_block.urdf";

double numberAfter(const std::string& text, const std::string& key)
{
  const std::size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos) << key << " in " << text;
  return at == std::string::npos ? -1.0 : std::stod(text.substr(at + key.size()));
}

TEST(SoftTool, SummarisesThePressOfTheShippedBlock)
{
  const test::ToolRun run = test::runTool(GOD_FINGER_SOFT_TOOL, kBlock + " --press 1");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("deformable 'soft_block' (" + std::string(GOD_FINGER_SOURCE_DIR) +
                         "/urdf/objects/soft_block.vtk, neohookean): 1000 nodes, 4374 tetrahedra, 972 surface "
                         "triangles, volume 1000 cm^3, mass 1 kg, E 5e+04 Pa, nu 0.45, damping 0.01 s, friction 0.8"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("press 'soft_block': 100 nodes glued at z = 0 m; 1 N down at (0, 0, 0.1) m"),
            std::string::npos)
      << run.out;
  // w0 = 2 (1 - 0.45^2) (1 N / (pi 1 cm^2)) 1 cm / 50 kPa = 1.015 mm; this mesh sinks 0.90 of it
  // (bench/REPORT.md section 12: the pad's sink converges from below).
  EXPECT_NEAR(numberAfter(run.out, "half-space "), 1.015, 0.0005) << run.out;
  const double ratio = numberAfter(run.out, "(ratio ");
  EXPECT_GT(ratio, 0.85);
  EXPECT_LT(ratio, 0.95);
  const test::ToolRun point = test::runTool(GOD_FINGER_SOFT_TOOL, kBlock + " --press 1 --point");
  ASSERT_EQ(point.exit_code, 0) << point.err;
  // The same force at a point sinks it more than twice as far on this mesh.
  EXPECT_GT(numberAfter(point.out, "point load: sink "), 2.0) << point.out;
}

TEST(SoftTool, WritesABlockVolumeItReadsBack)
{
  const std::string vtk = ::testing::TempDir() + "/soft_tool_block.vtk";
  const test::ToolRun write = test::runTool(GOD_FINGER_SOFT_TOOL, "--block 0.05 --nodes 125 --out " + vtk);
  ASSERT_EQ(write.exit_code, 0) << write.err;
  EXPECT_EQ(write.out, vtk + ": 125 nodes, 384 tetrahedra\n");
  const std::string urdf = ::testing::TempDir() + "/soft_tool_block.urdf";
  FILE* file = std::fopen(urdf.c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fputs(
      "<robot name=\"b\"><deformable name=\"b\"><inertial><mass value=\"0.125\"/></inertial>"
      "<corotated mu=\"1000\" lambda=\"2000\"/><collision filename=\"soft_tool_block.vtk\"/></deformable>"
      "</robot>",
      file);
  std::fclose(file);
  const test::ToolRun read = test::runTool(GOD_FINGER_SOFT_TOOL, urdf);
  ASSERT_EQ(read.exit_code, 0) << read.err;
  EXPECT_NE(read.out.find("corotated): 125 nodes, 384 tetrahedra, 192 surface triangles, volume 125 cm^3, mass "
                          "0.125 kg, E 2667 Pa, nu 0.333"),
            std::string::npos)
      << read.out;
}

TEST(SoftTool, EachBadOptionOrFileGetsOneLineAndExitCode2)
{
  const struct
  {
    std::string arguments;
    std::string err;
  } cases[] = {
      {"", "god_finger_soft: no FILE given\n"},
      {kBlock + " --press -1", "god_finger_soft: option --press '-1' is not a number in [1e-06, 1e+04]\n"},
      {kBlock + " --pres 1", "god_finger_soft: unknown option '--pres'\n"},
      {kBlock + " --radius", "god_finger_soft: option --radius needs a value\n"},
      {"--block 0.1 --out x.vtk", "god_finger_soft: --block needs --nodes and --out, and no FILE\n"},
      {"/nonexistent/soft.urdf", "god_finger_soft: URDF '/nonexistent/soft.urdf': no such file or not readable\n"},
      {std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/objects/stool.urdf",
       "god_finger_soft: URDF '" + std::string(GOD_FINGER_SOURCE_DIR) +
           "/urdf/objects/stool.urdf' holds no <deformable>\n"},
  };
  for (const auto& bad : cases)
  {
    const test::ToolRun run = test::runTool(GOD_FINGER_SOFT_TOOL, bad.arguments);
    EXPECT_EQ(run.exit_code, 2) << bad.arguments;
    EXPECT_EQ(run.err, bad.err) << bad.arguments;
  }
}
}  // namespace
}  // namespace god_finger
