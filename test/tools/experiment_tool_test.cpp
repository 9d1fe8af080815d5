// god_finger_experiment as a user runs it: one JSON object with the documented keys, a CSV
// time series, and one clear line with exit code 2 on bad options.
#include "tool_run.h"

#include "god_finger/physics/contact_model.h"
#include "god_finger/scenarios/experiment.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <regex>
#include <string>

namespace god_finger
{
namespace
{
test::ToolRun runTool(const std::string& arguments)
{
  return test::runTool(GOD_FINGER_EXPERIMENT_TOOL, arguments);
}

TEST(ExperimentTool, PrintsOneJsonObjectWithTheDocumentedKeys)
{
  const std::string csv = ::testing::TempDir() + "experiment_tool.csv";
  const test::ToolRun run = runTool("--scenario lift_one --model god_finger --duration 1 --csv " + csv);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out.front(), '{');
  EXPECT_EQ(run.out.find('\n'), run.out.size() - 1);
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(run.out);
  EXPECT_EQ(json.at("scenario"), "lift_one");
  EXPECT_EQ(json.at("model"), "god_finger");
  EXPECT_DOUBLE_EQ(test::jsonValue(run.out, "duration_s"), 1.0);
  EXPECT_DOUBLE_EQ(test::jsonValue(run.out, "steps"), 1000.0);
  EXPECT_GT(test::jsonValue(run.out, "step_us_median"), 0.0);
  EXPECT_GE(test::jsonValue(run.out, "step_us_p99"), test::jsonValue(run.out, "step_us_median"));
  EXPECT_GE(test::jsonValue(run.out, "max_penetration_m"), 0.0);
  EXPECT_EQ(test::jsonValue(run.out, "nan"), 0.0);
  for (const char* key : {"lift_height_m", "held_s", "max_tilt_rad", "dropped"})
  {
    EXPECT_NE(run.out.find(std::string("\"") + key + "\""), std::string::npos) << key;
  }
  const std::string series = test::readFile(csv);
  EXPECT_EQ(series.rfind("t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz,fx,fy,fz,f0_ix", 0), 0u);
  std::remove(csv.c_str());
}

TEST(ExperimentTool, DtAndDurationSetTheSteps)
{
  const test::ToolRun run = runTool("--scenario slide --model god_object --duration 0.5 --dt 0.0005");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_DOUBLE_EQ(test::jsonValue(run.out, "steps"), 1000.0);
  EXPECT_NE(run.out.find("\"rolling_ratio\""), std::string::npos);
}

TEST(ExperimentTool, BadOptionsGiveOneLineAndExitCode2)
{
  const struct
  {
    const char* arguments;
    const char* message;
  } cases[] = {
      {"--model god_finger", "missing option '--scenario'"},
      {"--scenario slide", "missing option '--model'"},
      {"--scenario roll --model god_finger", "option '--scenario' = 'roll' is not one of"},
      {"--scenario slide --model point", "option '--model' = 'point' is not one of"},
      {"--scenario slide --model god_finger --dt 0", "parameter '--dt' = 0 is out of range [1e-05, 0.1] (s)"},
      {"--scenario slide --model god_finger --dt abc", "parameter '--dt' must be a number (s)"},
      {"--scenario slide --model god_finger --duration -1",
       "parameter '--duration' = -1 is out of range [0, 3600] (s)"},
      {"--scenario slide --model god_finger --seed -3", "option '--seed' = '-3' is not a non-negative integer"},
      {"--scenario slide --model god_finger --push-height 1",
       "parameter '--push-height' = 1 is out of range [0, 0.04] (m)"},
      {"--scenario pinch_thin --model god_finger --overlap-stiffness abc",
       "option '--overlap-stiffness' = 'abc' is not a number (N/m^2)"},
      {"--scenario pinch_thin --model god_finger --overlap-stiffness -1",
       "parameter 'overlap_stiffness' = -1 is out of range [0, 10000000] (N/m^2)"},
      {"--scenario slide --model god_finger --frobnicate 1", "unknown option '--frobnicate'"},
      {"--scenario slide --model god_finger --seed", "option '--seed' needs a value"},
      {"--scenario slide --model god_finger --scenes /nonexistent", "URDF '/nonexistent/table_sphere.urdf'"},
      {"--scenario slide --model god_finger --csv /nonexistent/x.csv", "csv file '/nonexistent/x.csv'"},
  };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.arguments);
    const test::ToolRun run = runTool(c.arguments);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_TRUE(run.out.empty());
    EXPECT_EQ(run.err.rfind("god_finger_experiment: ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
  }
}

TEST(ExperimentTool, HelpPrintsUsage)
{
  const test::ToolRun run = runTool("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out.rfind("usage: god_finger_experiment", 0), 0u);
}

TEST(ExperimentTool, FakeHandRunsTheScenarioThroughTheServoLoop)
{
  // The fake device's handle held by the scripted hand, as a ROS session on the servo loop:
  // the one-finger lift still holds the plate level.
  const test::ToolRun run = runTool("--scenario lift_one --model god_finger --hand fake");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(test::jsonValue(run.out, "dropped"), 0.0);
  EXPECT_NEAR(test::jsonValue(run.out, "lift_height_m"), 0.1, 0.01);
  EXPECT_LT(test::jsonValue(run.out, "max_tilt_rad"), 0.02);
  const test::ToolRun bad = runTool("--scenario lift_one --model god_finger --hand mouse");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("option '--hand' = 'mouse' is not one of ideal, fake"), std::string::npos) << bad.err;
}

TEST(ExperimentTool, RollFingerReportsItsMetricsWithTheIdealAndTheFakeHand)
{
  const test::ToolRun run = runTool("--scenario roll_finger --model soft_finger");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // R_f 8 mm times 40 degrees (oriented_finger_test checks the physics).
  EXPECT_NEAR(test::jsonValue(run.out, "area_centre_travel_m"), 0.008 * 40.0 * M_PI / 180.0, 2e-5);
  EXPECT_GT(test::jsonValue(run.out, "max_force_step_N"), 0.0);
  // The fake device reports the script's orientation through the servo loop: the same roll.
  const test::ToolRun fake = runTool("--scenario roll_finger --model god_finger --hand fake");
  ASSERT_EQ(fake.exit_code, 0) << fake.err;
  EXPECT_NEAR(test::jsonValue(fake.out, "area_centre_travel_m"), 0.008 * 40.0 * M_PI / 180.0, 1e-4);
  EXPECT_NEAR(test::jsonValue(fake.out, "rolled_rad"), 40.0 * M_PI / 180.0, 1e-3);
  EXPECT_EQ(test::jsonValue(fake.out, "contact_lost_steps"), 0.0);
}

// Scripts (scripts/demo, scripts/plot_experiment, the launch test) read the scenarios from the
// tool; the tool's usage and its error name them all.
TEST(ExperimentTool, ListsEveryScenarioFromTheOneList)
{
  const test::ToolRun run = runTool("--list-scenarios");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, scenarioNames("\n") + "\n");
  EXPECT_NE(run.out.find("clutter\n"), std::string::npos);
  EXPECT_NE(runTool("--help").out.find("--scenario " + scenarioNames("|") + "\n"), std::string::npos);
  const test::ToolRun bad = runTool("--scenario juggle --model god_finger");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("is not one of " + scenarioNames()), std::string::npos) << bad.err;
}

TEST(ContactModels, TheCfgAndTheToolsListTheOneListInItsOrder)
{
  // dynamic_reconfigure's enum (cfg/GodFinger.cfg) is Python: it is held to the C++ list here.
  const std::string cfg = test::readFile(std::string(GOD_FINGER_SOURCE_DIR) + "/cfg/GodFinger.cfg");
  const std::regex entry("gen\\.const\\(\"(\\w+)\", str_t, \"(\\w+)\"");
  std::string listed;
  const std::size_t models = cfg.find("models = gen.enum(");
  const std::size_t walks = cfg.find("walks = gen.enum(");
  ASSERT_NE(models, std::string::npos);
  ASSERT_NE(walks, std::string::npos);
  const std::string block = cfg.substr(models, walks - models);
  for (std::sregex_iterator it(block.begin(), block.end(), entry), end; it != end; ++it)
  {
    EXPECT_EQ((*it)[1], (*it)[2]);
    listed += (listed.empty() ? "" : ", ") + (*it)[1].str();
  }
  EXPECT_EQ(listed, contactModelNames());
  std::string usage_list;
  for (ContactModel model : contactModels())
  {
    usage_list += (usage_list.empty() ? "" : "|") + std::string(contactModelName(model));
  }
  EXPECT_NE(runTool("--help").out.find("--model " + usage_list), std::string::npos);
  // Scripts (scripts/demo, scripts/plot_experiment) read the models from the tool.
  std::string lines;
  for (ContactModel model : contactModels())
  {
    lines += std::string(contactModelName(model)) + "\n";
  }
  const test::ToolRun run = runTool("--list-models");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, lines);
}
}  // namespace
}  // namespace god_finger
