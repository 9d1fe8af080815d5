// The report of bodies that left the world (runtime/left_world_report.h): one warning per catch,
// naming the body and the session time; the diagnostics value lists each body caught so far.
#include "god_finger/runtime/left_world_report.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace god_finger
{
namespace
{
TEST(LeftWorldReport, OneWarningPerCatchWithTheBodyAndTheSessionTime)
{
  SceneDescription scene;
  scene.bodies.resize(3);
  scene.bodies[0].name = "table";
  scene.bodies[1].name = "ball";
  scene.bodies[2].name = "box";
  WorldSnapshot snapshot;
  snapshot.bodies.resize(3);
  LeftWorldReport report;
  std::vector<std::string> warnings;
  const auto warn = [&warnings](const std::string& line) { warnings.push_back(line); };

  report.update(scene, snapshot, 100.0, warn);  // the session starts at stamp 100 s
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(report.diagnosticValue(), "none");

  snapshot.bodies[1].left_world = 1;
  report.update(scene, snapshot, 152.0134, warn);
  report.update(scene, snapshot, 152.03, warn);  // the same catch: no second warning
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "body 'ball' left the world at t = 52.013 s: put back at its start (world_margin)");
  EXPECT_EQ(report.diagnosticValue(), "ball (1) at 52.013 s");

  snapshot.bodies[1].left_world = 2;
  snapshot.bodies[2].left_world = 1;
  report.update(scene, snapshot, 160.5, warn);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[1], "body 'ball' left the world at t = 60.500 s: put back at its start (world_margin)");
  EXPECT_EQ(warnings[2], "body 'box' left the world at t = 60.500 s: put back at its start (world_margin)");
  EXPECT_EQ(report.diagnosticValue(), "ball (2) at 60.500 s; box (1) at 60.500 s");
}
}  // namespace
}  // namespace god_finger
