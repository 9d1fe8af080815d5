// The fake device's scripts for the articulated and soft scenarios' launches
// (config/scripts/door.yaml, drawer.yaml, press_soft.yaml, stroke_soft.yaml, pinch_soft_left.yaml and
// pinch_soft_right.yaml) are the offline experiment's own (experiment.cpp, seed 1): every waypoint of the
// file lies on the scenario's path at its time, within a micrometre (the file's 6 decimals), so
// the launch shows what god_finger_experiment measures.
#include "god_finger/scenarios/experiment.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

namespace god_finger
{
namespace
{
void expectScriptFollowsScenario(const std::string& script, Scenario scenario, std::size_t finger = 0,
                                 std::size_t fingers = 1)
{
  ExperimentOptions options;
  options.scenario = scenario;
  options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
  const ScenarioSetup setup = loadScenario(options);
  ASSERT_EQ(setup.fingers.size(), fingers);
  const YAML::Node file = YAML::LoadFile(std::string(GOD_FINGER_SOURCE_DIR) + "/config/scripts/" + script + ".yaml");
  ASSERT_TRUE(file["script"].IsSequence());
  ASSERT_GE(file["script"].size(), 4u);
  double last_time = -1.0;
  for (const YAML::Node& waypoint : file["script"])
  {
    const double t = waypoint[0].as<double>();
    const Eigen::Vector3d position(waypoint[1].as<double>(), waypoint[2].as<double>(), waypoint[3].as<double>());
    EXPECT_LT((position - setup.fingers[finger].at(t)).norm(), 1e-6) << script << " at t = " << t;
    last_time = t;
  }
  EXPECT_NEAR(last_time, setup.duration, 1e-9) << script << " runs as long as the scenario";
}

TEST(ScriptSync, TheDoorAndDrawerLaunchesFollowTheirScenariosScripts)
{
  expectScriptFollowsScenario("door", Scenario::kDoor);
  expectScriptFollowsScenario("drawer", Scenario::kDrawer);
}

TEST(ScriptSync, TheSoftLaunchesFollowTheirScenariosScripts)
{
  expectScriptFollowsScenario("press_soft", Scenario::kPressSoft);
  expectScriptFollowsScenario("stroke_soft", Scenario::kStrokeSoft);
  expectScriptFollowsScenario("pinch_soft_left", Scenario::kPinchSoft, 0, 2);
  expectScriptFollowsScenario("pinch_soft_right", Scenario::kPinchSoft, 1, 2);
}
}  // namespace
}  // namespace god_finger
