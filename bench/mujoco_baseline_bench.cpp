// MuJoCo baseline (issue 12, section 3): the slide, lift_one and pinch_cylinder scenarios built
// in MuJoCo (2.2, Debian's libmujoco) as exactly as it allows, stepped against god_finger's own
// worlds (god_object and god_finger) in ONE binary, so that one run with random interleaving
// and repetitions (scripts/bench) times all systems under the same machine noise.
//
// What it measures: per benchmark iteration one whole scripted run of the scenario, at its full
// length (slide 3.3 s, lift_one 4 s, pinch_cylinder 25 s: the scripts of experiment.cpp, so that
// the metrics are those of runExperiment), building the world excluded. Counters: `steps` (time
// per step = run time / steps, scripts/bench_report) and the scenario's metrics, computed the
// same way for every system (scenarios/scenario_metrics.h, as runExperiment computes them).
//
// Units SI (m, kg, s, N, rad), world frame z up (REP-103), as the scene descriptions.
//
// The MuJoCo scene: bench/mujoco_scene.h (mujocoXml).
#include "god_finger/contact/contact_params.h"
#include "god_finger/haptics/virtual_coupling.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scenarios/experiment.h"
#include "god_finger/scenarios/scenario_metrics.h"
#include "mujoco_scene.h"
#include "scale_scene.h"

#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
const Scenario kScenarios[] = {Scenario::kSlide, Scenario::kLiftOne, Scenario::kLiftTwo, Scenario::kPinchCylinder};
const ContactModel kModels[] = {ContactModel::kGodObject, ContactModel::kGodFinger, ContactModel::kSoftFinger};

// The scenario's metrics (scenarios/scenario_metrics.h, as runExperiment computes them) over the
// object's states after each step.
std::map<std::string, double> metricsOf(Scenario scenario, const ScenarioSetup& setup, double dt,
                                        const BodyState& initial, const std::vector<BodyState>& samples)
{
  ScenarioMetrics metrics(scenario, setup.times, initial, setup.scene.bodies[setup.object]);
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    metrics.add((i + 1) * dt, dt, samples[i]);
  }
  return metrics.metrics();
}

ExperimentOptions scenarioOptions(Scenario scenario, ContactModel model)
{
  ExperimentOptions options;
  options.scenario = scenario;
  options.model = model;
  options.scenes_dir = GOD_FINGER_SCENES_DIR;
  return options;
}

void setMetricCounters(benchmark::State& state, const std::map<std::string, double>& metrics, long steps)
{
  state.counters["steps"] = static_cast<double>(steps);
  for (const auto& entry : metrics)
  {
    state.counters[entry.first] = entry.second;
  }
}

// --- god_finger's worlds (physics_step_bench's BM_ScenarioStep, whole script, metrics) -----

void BM_ScenarioStep(benchmark::State& state)
{
  const Scenario scenario = kScenarios[state.range(0)];
  const ContactModel model = kModels[state.range(1)];
  const ExperimentOptions options = scenarioOptions(scenario, model);
  const ScenarioSetup setup = loadScenario(options);
  const WorldParams params = scenarioParams(options);
  const double dt = params.time_step;
  const long steps = std::lround(setup.duration / dt);
  std::vector<BodyState> samples;
  samples.reserve(static_cast<std::size_t>(steps));
  BodyState initial;
  for (auto _ : state)
  {
    state.PauseTiming();
    auto world = std::make_unique<GodFingerWorld>(setup.scene, params);
    for (const WaypointPath& finger : setup.fingers)
    {
      world->addInterface(finger.at(0.0));
    }
    initial = world->bodyState(setup.object);
    samples.clear();
    state.ResumeTiming();
    for (long i = 0; i < steps; ++i)
    {
      for (std::size_t f = 0; f < setup.fingers.size(); ++f)
      {
        world->setInterfaceTarget(static_cast<int>(f), setup.fingers[f].at((i + 1) * dt));
      }
      world->step();
      samples.push_back(world->bodyState(setup.object));
    }
    state.PauseTiming();
    world.reset();
    state.ResumeTiming();
  }
  setMetricCounters(state, metricsOf(scenario, setup, dt, initial, samples), steps);
  state.SetLabel(std::string(scenarioName(scenario)) + "/" + contactModelName(model));
}

// --- MuJoCo ---------------------------------------------------------------------------------

// One scenario in MuJoCo with the finger contacts' condim = range(1).
void BM_MujocoScenarioStep(benchmark::State& state)
{
  const Scenario scenario = kScenarios[state.range(0)];
  const int condim = static_cast<int>(state.range(1));
  const ExperimentOptions options = scenarioOptions(scenario, ContactModel::kGodFinger);
  const ScenarioSetup setup = loadScenario(options);
  const WorldParams params = scenarioParams(options);
  std::vector<Eigen::Vector3d> finger_starts;
  for (const WaypointPath& finger : setup.fingers)
  {
    finger_starts.push_back(finger.at(0.0));
  }
  const ModelPtr model = loadMujoco(mujocoXml(setup.scene, finger_starts, params, condim));
  const DataPtr data(mj_makeData(model.get()));
  const int object = mj_name2id(model.get(), mjOBJ_BODY, ("b" + std::to_string(setup.object)).c_str());
  const double object_mass = setup.scene.bodies[setup.object].mass;
  const double dt = params.time_step;
  const long steps = std::lround(setup.duration / dt);
  const int fingers = static_cast<int>(setup.fingers.size());
  std::vector<int> proxy_dof(fingers);
  std::vector<int> proxy_qpos(fingers);
  std::vector<Eigen::Vector3d> proxy_start(fingers);
  for (int f = 0; f < fingers; ++f)
  {
    const int joint = mj_name2id(model.get(), mjOBJ_JOINT, ("p" + std::to_string(f) + "x").c_str());
    proxy_dof[f] = model->jnt_dofadr[joint];  // y and z follow
    proxy_qpos[f] = model->jnt_qposadr[joint];
    proxy_start[f] = setup.fingers[f].at(0.0);
  }
  const Eigen::Vector3d gravity_compensation = -params.coupling.proxy_mass * params.gravity;
  std::vector<Eigen::Vector3d> previous_target(fingers);
  std::vector<BodyState> samples;
  samples.reserve(static_cast<std::size_t>(steps));
  BodyState initial;
  // Per run, for the profile: contacts, constraint rows and solver iterations (Newton and noslip)
  // summed over steps.
  long contacts = 0;
  long rows = 0;
  long solver_iterations = 0;
  for (auto _ : state)
  {
    state.PauseTiming();
    mj_resetData(model.get(), data.get());
    Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();
    initial = mujocoSample(model.get(), data.get(), object, com_velocity, object_mass, &com_velocity);
    for (int f = 0; f < fingers; ++f)
    {
      previous_target[f] = proxy_start[f];
    }
    samples.clear();
    contacts = rows = solver_iterations = 0;
    state.ResumeTiming();
    for (long i = 0; i < steps; ++i)
    {
      for (int f = 0; f < fingers; ++f)
      {
        pullSlider(params, setup.fingers[f].at((i + 1) * dt), proxy_start[f], proxy_dof[f], proxy_qpos[f],
                   gravity_compensation, &previous_target[f], data.get());
      }
      mj_step(model.get(), data.get());
      samples.push_back(mujocoSample(model.get(), data.get(), object, com_velocity, object_mass, &com_velocity));
      contacts += data->ncon;
      rows += data->nefc;
      solver_iterations += data->solver_iter;
    }
  }
  setMetricCounters(state, metricsOf(scenario, setup, dt, initial, samples), steps);
  state.counters["mean_contacts"] = static_cast<double>(contacts) / steps;
  state.counters["mean_rows"] = static_cast<double>(rows) / steps;
  state.counters["mean_solver_iterations"] = static_cast<double>(solver_iterations) / steps;
  state.SetLabel(std::string(scenarioName(scenario)) + "/mujoco_condim" + std::to_string(condim));
}

// --- The scale section (issue 17): boxes on a table, fingers dragging some -------------------

// The (objects, fingers) pairs measured: fingers on the same boxes whatever the clutter.
const std::pair<int, int> kScaleScenes[] = {{1, 1}, {10, 2}, {100, 1}, {100, 2}, {100, 10}, {1000, 2}};

void setScaleCounters(benchmark::State& state, scale::StepTimes* times, long steps, double iterations)
{
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["p50_us"] = times->percentile(0.5);
  state.counters["p99_us"] = times->percentile(0.99);
  state.counters["mean_solver_iterations"] = iterations / std::max(1L, steps);
}

// range(0): index into kScaleScenes; range(1): kModels' index (god_object, god_finger,
// soft_finger), with the world's defaults (sleeping on).
void BM_ScaleStep(benchmark::State& state)
{
  const auto [objects, finger_count] = kScaleScenes[state.range(0)];
  const ContactModel model = kModels[state.range(1)];
  const SceneDescription scene = scale::scene(objects);
  const std::vector<WaypointPath> fingers = scale::fingers(finger_count, objects);
  WorldParams params = scenarioParams(scenarioOptions(Scenario::kSlide, model));
  const double dt = params.time_step;
  const long steps = std::lround(scale::kDuration / dt);
  scale::StepTimes times;
  times.us.reserve(static_cast<std::size_t>(steps));
  double iterations = 0.0;
  for (auto _ : state)
  {
    state.PauseTiming();
    auto world = std::make_unique<GodFingerWorld>(scene, params);
    for (const WaypointPath& finger : fingers)
    {
      world->addInterface(finger.at(0.0));
    }
    times.us.clear();
    iterations = 0.0;
    state.ResumeTiming();
    for (long i = 0; i < steps; ++i)
    {
      const scale::Clock::time_point begin = scale::Clock::now();
      for (std::size_t f = 0; f < fingers.size(); ++f)
      {
        world->setInterfaceTarget(static_cast<int>(f), fingers[f].at((i + 1) * dt));
      }
      world->step();
      times.us.push_back(scale::microseconds(begin, scale::Clock::now()));
      iterations += world->counters().solver_iterations;
    }
    state.PauseTiming();
    world.reset();
    state.ResumeTiming();
  }
  setScaleCounters(state, &times, steps, iterations);
  state.SetLabel("scale/" + std::to_string(objects) + "x" + std::to_string(finger_count) + "/" +
                 contactModelName(model));
}

// The same scene in MuJoCo, finger contacts condim 4. Collisions are MuJoCo's own (contype and
// conaffinity; explicit pairs would be quadratic in the objects): boxes and table collide with
// everything, proxies with boxes only. Friction combines by maximum, hence friction 1 on every
// body; the proxies' geoms carry condim 4 and the pad's torsional friction (2/3) mu a.
std::string mujocoScaleXml(const SceneDescription& scene, const std::vector<WaypointPath>& fingers,
                           const WorldParams& params)
{
  std::ostringstream xml;
  xml << "<mujoco model=\"" << scene.name << "\">\n"
      << "<compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"0\" boundinertia=\"0\"/>\n"
      << "<option timestep=\"" << number(params.time_step) << "\" gravity=\"" << vec(params.gravity)
      << "\" integrator=\"Euler\" solver=\"Newton\" iterations=\"100\" tolerance=\"1e-8\" cone=\"elliptic\""
      << " impratio=\"10\" noslip_iterations=\"3\" jacobian=\"sparse\"/>\n"
      // Room for 4 contacts per body (a box on the table) and 4 rows per contact (condim 4).
      << "<size nconmax=\"" << 4 * scene.bodies.size() + 50 << "\" njmax=\"" << 16 * scene.bodies.size() + 200
      << "\" nstack=\"" << 50000 * scene.bodies.size() + 5000000 << "\"/>\n"
      << "<default><geom contype=\"1\" conaffinity=\"3\" condim=\"3\" friction=\"" << number(scale::kFriction)
      << " 0 0\"/></default>\n<worldbody>\n";
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    const BodyDescription& body = scene.bodies[i];
    const std::string size = vec(0.5 * body.geometry.size);
    if (body.is_static)
    {
      xml << "<geom type=\"box\" size=\"" << size << "\" pos=\"" << vec(body.pose.translation()) << "\"/>\n";
      continue;
    }
    const Eigen::Matrix3d& I = body.inertia;
    xml << "<body pos=\"" << vec(body.pose.translation()) << "\">\n<freejoint/>\n<inertial pos=\"0 0 0\" mass=\""
        << number(body.mass) << "\" diaginertia=\"" << number(I(0, 0)) << " " << number(I(1, 1)) << " "
        << number(I(2, 2)) << "\"/>\n<geom type=\"box\" size=\"" << size << "\"/>\n</body>\n";
  }
  const double r = params.coupling.proxy_radius;
  const double m = params.coupling.proxy_mass;
  const FingerFriction finger;
  for (std::size_t f = 0; f < fingers.size(); ++f)
  {
    xml << "<body name=\"p" << f << "\" pos=\"" << vec(fingers[f].at(0.0)) << "\">\n"
        << "<joint name=\"p" << f << "x\" type=\"slide\" axis=\"1 0 0\"/>\n"
        << "<joint name=\"p" << f << "y\" type=\"slide\" axis=\"0 1 0\"/>\n"
        << "<joint name=\"p" << f << "z\" type=\"slide\" axis=\"0 0 1\"/>\n"
        << "<inertial pos=\"0 0 0\" mass=\"" << number(m) << "\" diaginertia=\""
        << vec(Eigen::Vector3d::Constant(0.4 * m * r * r)) << "\"/>\n"
        << "<geom type=\"sphere\" size=\"" << number(r) << "\" contype=\"2\" conaffinity=\"0\" condim=\"4\" friction=\""
        << number(scale::kFriction) << " " << number(finger.torsional_per_mu * scale::kFriction) << " 0\"/>\n</body>\n";
  }
  xml << "</worldbody>\n</mujoco>\n";
  return xml.str();
}

void BM_MujocoScaleStep(benchmark::State& state)
{
  const auto [objects, finger_count] = kScaleScenes[state.range(0)];
  const SceneDescription scene = scale::scene(objects);
  const std::vector<WaypointPath> fingers = scale::fingers(finger_count, objects);
  const WorldParams params = scenarioParams(scenarioOptions(Scenario::kSlide, ContactModel::kGodFinger));
  const ModelPtr model = loadMujoco(mujocoScaleXml(scene, fingers, params));
  const DataPtr data(mj_makeData(model.get()));
  const double dt = params.time_step;
  const long steps = std::lround(scale::kDuration / dt);
  std::vector<int> proxy_dof(finger_count);
  std::vector<int> proxy_qpos(finger_count);
  for (int f = 0; f < finger_count; ++f)
  {
    const int joint = mj_name2id(model.get(), mjOBJ_JOINT, ("p" + std::to_string(f) + "x").c_str());
    proxy_dof[f] = model->jnt_dofadr[joint];
    proxy_qpos[f] = model->jnt_qposadr[joint];
  }
  const Eigen::Vector3d gravity_compensation = -params.coupling.proxy_mass * params.gravity;
  std::vector<Eigen::Vector3d> previous_target(finger_count);
  scale::StepTimes times;
  times.us.reserve(static_cast<std::size_t>(steps));
  double iterations = 0.0;
  for (auto _ : state)
  {
    state.PauseTiming();
    mj_resetData(model.get(), data.get());
    for (int f = 0; f < finger_count; ++f)
    {
      previous_target[f] = fingers[f].at(0.0);
    }
    times.us.clear();
    iterations = 0.0;
    state.ResumeTiming();
    for (long i = 0; i < steps; ++i)
    {
      const scale::Clock::time_point begin = scale::Clock::now();
      for (int f = 0; f < finger_count; ++f)
      {
        pullSlider(params, fingers[f].at((i + 1) * dt), fingers[f].at(0.0), proxy_dof[f], proxy_qpos[f],
                   gravity_compensation, &previous_target[f], data.get());
      }
      mj_step(model.get(), data.get());
      times.us.push_back(scale::microseconds(begin, scale::Clock::now()));
      iterations += data->solver_iter;
    }
  }
  setScaleCounters(state, &times, steps, iterations);
  state.SetLabel("scale/" + std::to_string(objects) + "x" + std::to_string(finger_count) + "/mujoco_condim4");
}
}  // namespace

// Scenario indices as kScenarios: 0 slide, 1 lift_one, 3 pinch_cylinder.
BENCHMARK(BM_ScenarioStep)
    ->ArgsProduct({{0, 1, 3}, {0, 1}})
    ->ArgNames({"scenario", "model"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(5)
    ->UseRealTime();
BENCHMARK(BM_ScaleStep)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {0, 1, 2}})
    ->ArgNames({"scene", "model"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime();
// Not the 1000-object scene: MuJoCo 2.2 sizes dense constraint matrices as njmax^2, and 1000
// resting boxes need about 12,000 rows (1.2 GB for one of them): mj_makeData fails.
BENCHMARK(BM_MujocoScaleStep)
    ->DenseRange(0, 4)
    ->ArgNames({"scene"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK(BM_MujocoScenarioStep)
    ->ArgsProduct({{0, 1, 3}, {3, 4, 6}})
    ->ArgNames({"scenario", "condim"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(5)
    ->UseRealTime();
}  // namespace god_finger

BENCHMARK_MAIN();
