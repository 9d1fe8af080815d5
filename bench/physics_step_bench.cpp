// Cost of a physics step (Bullet + proxies + contact areas): per paper scenario and contact
// model, and on a generated scene against the number of interfaces (1, 2, 4 fingers on one
// ball) and of objects (1, 10, 100 balls on a table, one finger). One benchmark iteration is
// one whole scripted run (the hand's motion included, the world's construction not); the
// counter `steps` gives steps per run, so time per step = time / steps (scripts/bench_report).
// Also what the step's profile costs (BM_StepProfileClock).
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scenarios/experiment.h"
#include "stages/stage_clock.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>

namespace god_finger
{
namespace
{
// The model argument: 0 god_object, 1 god_finger (the default pad solver, the pad
// constraint), 2 soft_finger, 3 god_finger with the paper's points (scripts/bench_report reads
// them in this order).
struct Layout
{
  ContactModel model;
  PadSolver pad_solver;
  const char* label;
};
const Layout kModels[] = {{ContactModel::kGodObject, PadSolver::kConstraint, "god_object"},
                          {ContactModel::kGodFinger, PadSolver::kConstraint, "god_finger"},
                          {ContactModel::kSoftFinger, PadSolver::kConstraint, "soft_finger"},
                          {ContactModel::kGodFinger, PadSolver::kPoints, "god_finger/points"}};
const Scenario kScenarios[] = {Scenario::kSlide, Scenario::kLiftOne, Scenario::kLiftTwo, Scenario::kPinchCylinder};

// Runs `fingers` through `world` for `duration` (s); returns the steps taken and adds the
// solver's iterations and rows of every step to `iterations` and `rows`, and the stages of every
// timed step (one in profile_every) to `stages` (ns; stages->step counts them).
long runScript(GodFingerWorld* world, const std::vector<WaypointPath>& fingers, double duration, double* iterations,
               double* rows, StepProfile* stages)
{
  const double dt = world->params().time_step;
  const long steps = std::lround(duration / dt);
  for (long i = 0; i < steps; ++i)
  {
    for (std::size_t f = 0; f < fingers.size(); ++f)
    {
      world->setInterfaceTarget(static_cast<int>(f), fingers[f].at((i + 1) * dt));
    }
    world->step();
    const WorldCounters counters = world->counters();
    *iterations += counters.solver_iterations;
    *rows += counters.solver_contact_rows;
    const StepProfile& profile = world->stepProfile();
    if (profile.step == world->steps())
    {
      ++stages->step;
      for (int s = 0; s < kStepStageCount; ++s)
      {
        stages->stage_ns[s] += profile.stage_ns[s];
      }
    }
  }
  return steps;
}

void runWorlds(benchmark::State& state, const SceneDescription& scene, const WorldParams& params,
               const std::vector<WaypointPath>& fingers, double duration)
{
  long steps = 0;
  double iterations = 0.0;
  double rows = 0.0;
  StepProfile stages;
  for (auto _ : state)
  {
    state.PauseTiming();
    auto world = std::make_unique<GodFingerWorld>(scene, params);
    for (const WaypointPath& finger : fingers)
    {
      world->addInterface(finger.at(0.0));
    }
    iterations = 0.0;
    rows = 0.0;
    stages = StepProfile();
    stages.step = 0;
    state.ResumeTiming();
    steps = runScript(world.get(), fingers, duration, &iterations, &rows, &stages);
    state.PauseTiming();
    world.reset();
    state.ResumeTiming();
  }
  state.counters["steps"] = static_cast<double>(steps);
  // Per step, of the last run: solver iterations used and contact rows.
  state.counters["iterations"] = iterations / std::max(1L, steps);
  state.counters["rows"] = rows / std::max(1L, steps);
  // Per timed step of the last run, each stage's time (us): where the step goes (step_profile.h).
  for (int s = 0; s < kStepStageCount; ++s)
  {
    state.counters[std::string(stepStageName(static_cast<StepStage>(s))) + "_us"] =
        1e-3 * static_cast<double>(stages.stage_ns[s]) / std::max(1L, stages.step);
  }
}

// The paper's scenarios as the experiments run them (pinch cut to 6 s: approach, lift, hold).
void BM_ScenarioStep(benchmark::State& state)
{
  ExperimentOptions options;
  options.scenario = kScenarios[state.range(0)];
  options.model = kModels[state.range(1)].model;
  options.pad_solver = kModels[state.range(1)].pad_solver;
  options.scenes_dir = GOD_FINGER_SCENES_DIR;
  const ScenarioSetup setup = loadScenario(options);
  runWorlds(state, setup.scene, scenarioParams(options), setup.fingers, std::min(setup.duration, 6.0));
  state.SetLabel(std::string(scenarioName(options.scenario)) + "/" + kModels[state.range(1)].label);
}

BodyDescription table()
{
  BodyDescription body;
  body.name = "table";
  body.is_static = true;
  body.geometry.kind = GeometryKind::kBox;
  body.geometry.size = Eigen::Vector3d(2.0, 2.0, 0.05);
  body.pose.translation() = Eigen::Vector3d(0.0, 0.0, -0.025);
  return body;
}

BodyDescription ball(int index, const Eigen::Vector3d& position)
{
  BodyDescription body;
  body.name = "ball" + std::to_string(index);
  body.geometry.kind = GeometryKind::kSphere;
  body.geometry.radius = 0.04;
  body.mass = 0.1;
  body.inertia = Eigen::Matrix3d::Identity() * 0.4 * 0.1 * 0.04 * 0.04;
  body.pose.translation() = position;
  body.material.friction = 0.8;
  return body;
}

// One finger per entry of `tops`: from 2 cm above the ball's top it presses 5 mm in (0.3 s),
// slides 2 cm along x (1 s), holds (0.2 s).
std::vector<WaypointPath> pressAndSlide(const std::vector<Eigen::Vector3d>& tops)
{
  std::vector<WaypointPath> fingers;
  for (const Eigen::Vector3d& top : tops)
  {
    const Eigen::Vector3d pressed = top - Eigen::Vector3d(0.0, 0.0, 0.005);
    fingers.emplace_back(std::vector<Waypoint>{{0.0, top + Eigen::Vector3d(0.0, 0.0, 0.02)},
                                               {0.3, pressed},
                                               {1.3, pressed + Eigen::Vector3d(0.02, 0.0, 0.0)},
                                               {1.5, pressed + Eigen::Vector3d(0.02, 0.0, 0.0)}});
  }
  return fingers;
}

WorldParams generatedParams(const Layout& layout)
{
  ExperimentOptions options;
  options.model = layout.model;
  options.pad_solver = layout.pad_solver;
  return scenarioParams(options);
}

// 1, 2 or 4 fingers on one ball (spots 1 cm apart around its top).
void BM_InterfacesStep(benchmark::State& state)
{
  const int interfaces = static_cast<int>(state.range(0));
  SceneDescription scene;
  scene.bodies = {table(), ball(0, Eigen::Vector3d(0.0, 0.0, 0.04))};
  std::vector<Eigen::Vector3d> tops;
  const Eigen::Vector3d spots[] = {{0.0, 0.0, 0.0}, {0.01, 0.0, 0.0}, {0.0, 0.01, 0.0}, {-0.01, -0.01, 0.0}};
  for (int i = 0; i < interfaces; ++i)
  {
    const Eigen::Vector3d on_sphere = (Eigen::Vector3d(0.0, 0.0, 0.04) + spots[i]).normalized() * 0.04;
    tops.push_back(Eigen::Vector3d(0.0, 0.0, 0.04) + on_sphere + Eigen::Vector3d(0.0, 0.0, 0.003));
  }
  runWorlds(state, scene, generatedParams(kModels[state.range(1)]), pressAndSlide(tops), 1.5);
  state.SetLabel(kModels[state.range(1)].label);
}

// 1, 10 or 100 balls on a table (10 cm grid), one finger on the first.
void BM_ObjectsStep(benchmark::State& state)
{
  const int objects = static_cast<int>(state.range(0));
  SceneDescription scene;
  scene.bodies.push_back(table());
  for (int i = 0; i < objects; ++i)
  {
    scene.bodies.push_back(ball(i, Eigen::Vector3d(0.1 * (i % 10), 0.1 * (i / 10), 0.04)));
  }
  runWorlds(state, scene, generatedParams(kModels[state.range(1)]), pressAndSlide({Eigen::Vector3d(0.0, 0.0, 0.083)}),
            1.5);
  state.SetLabel(kModels[state.range(1)].label);
}

// What timing one step costs (step_profile.h): the clock started, one mark per stage, finished,
// as GodFingerWorld::step does on a timed step (one in WorldParams::profile_every).
void BM_StepProfileClock(benchmark::State& state)
{
  StepProfile profile;
  internal::StageClock clock(&profile);
  for (auto _ : state)
  {
    clock.start(true);
    for (int s = 0; s < kStepStageCount; ++s)
    {
      clock.mark(static_cast<StepStage>(s));
    }
    clock.finish(0);
    benchmark::DoNotOptimize(profile);
  }
}
}  // namespace

BENCHMARK(BM_StepProfileClock)->Unit(benchmark::kNanosecond)->Repetitions(3);
BENCHMARK(BM_ScenarioStep)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2, 3}})
    ->ArgNames({"scenario", "model"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->UseRealTime();
BENCHMARK(BM_InterfacesStep)
    ->ArgsProduct({{1, 2, 4}, {0, 1, 2, 3}})
    ->ArgNames({"interfaces", "model"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->UseRealTime();
BENCHMARK(BM_ObjectsStep)
    ->ArgsProduct({{1, 10, 100}, {0, 1, 2, 3}})
    ->ArgNames({"objects", "model"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->UseRealTime();
}  // namespace god_finger

BENCHMARK_MAIN();
