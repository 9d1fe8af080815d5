// The soft scenarios (experiment.h: press_soft, stroke_soft on urdf/scenes/soft_block.urdf), each
// contact model with identical scripted input: a pad's dimple is the elastic solution's within
// the 1,000-node mesh's discretisation (the fidelity study's 0.76-0.82 of Boussinesq's w0 at
// this mesh), a point digs deeper (a point load's dimple has no finite limit), the proxy never
// sinks into the deformed surface by more than the 1 mm (AMBF's users see rigid bodies
// sink through soft ones), a stroke sticks, then slides, within the pair's friction, and a pinch
// lifts a free soft ball off the table and holds it (pinch_soft).
#include "god_finger/scenarios/experiment.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace god_finger
{
namespace
{
ExperimentResult run(Scenario scenario, ContactModel model)
{
  ExperimentOptions options;
  options.scenario = scenario;
  options.model = model;
  options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
  const ExperimentResult result = runExperiment(options);
  EXPECT_EQ(result.nan, 0);
  std::printf("%s\n", toJson(result).c_str());
  return result;
}

TEST(SoftScenarios, APadsDimpleIsTheElasticSolutionsAndAPointDigsDeeper)
{
  const ExperimentResult pad = run(Scenario::kPressSoft, ContactModel::kGodFinger);
  const ExperimentResult point = run(Scenario::kPressSoft, ContactModel::kGodObject);
  const ExperimentResult soft = run(Scenario::kPressSoft, ContactModel::kSoftFinger);
  for (const ExperimentResult* result : {&pad, &point, &soft})
  {
    const std::map<std::string, double>& m = result->metrics;
    EXPECT_GT(m.at("hand_force_N"), 3.0) << result->model;  // 1.5 cm of target past the top
    EXPECT_LE(m.at("penetration_p99_m"), 1e-3) << result->model;
    EXPECT_GT(m.at("sink_m"), 2e-3) << result->model;
  }
  // The pad: within 15 % of w0, the target (the study's 0.90 at 1,000 nodes,
  // bench/REPORT.md section 12); soft_finger loads the same pad.
  EXPECT_GT(pad.metrics.at("sink_over_w0"), 0.85);
  EXPECT_LT(pad.metrics.at("sink_over_w0"), 0.95);
  EXPECT_NEAR(soft.metrics.at("sink_over_w0"), pad.metrics.at("sink_over_w0"), 0.02);
  // The point: more than 1.5 times the pad's share of w0 under the same coupling.
  EXPECT_GT(point.metrics.at("sink_over_w0"), 1.5 * pad.metrics.at("sink_over_w0"));
}

TEST(SoftScenarios, AStrokeSticksThenSlidesWithinThePairsFriction)
{
  std::map<ContactModel, std::map<std::string, double>> metrics;
  for (const ContactModel model : {ContactModel::kGodFinger, ContactModel::kGodObject, ContactModel::kSoftFinger})
  {
    const ExperimentResult result = run(Scenario::kStrokeSoft, model);
    const std::map<std::string, double>& m = result.metrics;
    metrics[model] = m;
    EXPECT_GE(m.at("stick_slip_events"), 1.0) << result.model;
    EXPECT_LE(m.at("penetration_p99_m"), 1e-3) << result.model;
    EXPECT_GT(m.at("hand_force_N"), 3.0) << result.model;
    if (model != ContactModel::kGodObject)
    {
      // A pad slides most of the 3 cm, after sticking while the block sheared.
      EXPECT_GT(m.at("trace_m"), 0.015) << result.model;
      EXPECT_LT(m.at("trace_m"), 0.035) << result.model;
    }
  }
  // A point ploughs: its load digs a pit more than twice as deep as the pad's (a point load's
  // sink has no limit) and holds it back, so it travels less than either pad.
  const auto& point = metrics[ContactModel::kGodObject];
  for (const ContactModel pad : {ContactModel::kGodFinger, ContactModel::kSoftFinger})
  {
    EXPECT_GT(point.at("sink_m"), 2.0 * metrics[pad].at("sink_m"));
    EXPECT_LT(point.at("trace_m"), metrics[pad].at("trace_m"));
  }
}

TEST(SoftScenarios, APinchLiftsAFreeSoftBallOffTheTableAndHoldsIt)
{
  for (const ContactModel model : {ContactModel::kGodFinger, ContactModel::kGodObject, ContactModel::kSoftFinger})
  {
    const ExperimentResult result = run(Scenario::kPinchSoft, model);
    const std::map<std::string, double>& m = result.metrics;
    // The ball turns a little in every grip as it is lifted (its best-fit rotation, its Bullet
    // body only translating); god_finger's pads hold the material they stick to (their anchors
    // go with the ball's surface, physics/soft_body.h materialMotion): 0.09 rad, where anchored
    // to the ball's translating frame they let it turn 0.17 rad (god_object 0.18, soft_finger
    // 0.15: Bullet's own points on a soft body are found afresh each step, with no anchor).
    EXPECT_LT(m.at("turn_rad"), 0.3) << result.model;
    if (model == ContactModel::kGodFinger)
    {
      EXPECT_LT(m.at("turn_rad"), 0.12) << result.model;
    }
    EXPECT_EQ(m.at("held"), 1.0) << result.model;
    // The hands rise 5 cm; the ball's frame (its mean displacement) within 2 mm of that: it left
    // the table (whose support would hold it at 0) and hangs between the pads.
    EXPECT_GT(m.at("lift_height_m"), 0.048) << result.model;
    EXPECT_LT(m.at("lift_height_m"), 0.05) << result.model;
    EXPECT_LT(m.at("slip_m"), 1e-3) << result.model;
    // Squeezed by about 3 N a side: a few per cent across the fingers, not crushed.
    EXPECT_GT(m.at("squash"), 0.02) << result.model;
    EXPECT_LT(m.at("squash"), 0.15) << result.model;
    EXPECT_GT(m.at("hand_force_N"), 2.0) << result.model;
    EXPECT_LE(m.at("penetration_p99_m"), 1e-3) << result.model;
  }
}

TEST(SoftScenarios, AtAFrictionTooLowForItsWeightThePadsDropTheBall)
{
  // The same scene with the ball's friction 0.1: two pads squeezing about 3.4 N hold at most
  // 2 x 0.1 x 3.4 = 0.68 N, less than its 0.98 N. A scene folder of its own (its volume by path).
  char folder[] = "/tmp/god_finger_soft_scenarios_XXXXXX";
  ASSERT_NE(mkdtemp(folder), nullptr);
  std::ifstream in(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/soft_ball.urdf");
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  const auto replace = [&scene](const std::string& from, const std::string& to)
  {
    const std::size_t at = scene.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    scene.replace(at, from.size(), to);
  };
  replace("<friction value=\"0.8\"/>", "<friction value=\"0.1\"/>");
  replace("../objects/soft_ball.vtk", std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/objects/soft_ball.vtk");
  std::ofstream(std::string(folder) + "/soft_ball.urdf") << scene;
  for (const ContactModel model : {ContactModel::kGodFinger, ContactModel::kSoftFinger})
  {
    ExperimentOptions options;
    options.scenario = Scenario::kPinchSoft;
    options.model = model;
    options.scenes_dir = folder;
    const ExperimentResult result = runExperiment(options);
    std::printf("friction 0.1: %s\n", toJson(result).c_str());
    EXPECT_EQ(result.metrics.at("held"), 0.0) << result.model;
    EXPECT_LT(result.metrics.at("lift_height_m"), 0.005) << result.model;
  }
  std::remove((std::string(folder) + "/soft_ball.urdf").c_str());
  rmdir(folder);
}
}  // namespace
}  // namespace god_finger
