// MuJoCo baseline (issue 12, section 3): the slide, lift_one and pinch_cylinder scenarios built
// in MuJoCo (2.2, Debian's libmujoco) as exactly as it allows, stepped against god_finger's own
// worlds (god_object and god_finger) in ONE binary, so that one run with random interleaving
// and repetitions (scripts/bench) times all systems under the same machine noise.
//
// What it measures: per benchmark iteration one whole scripted run of the scenario, at its full
// length (slide 3.3 s, lift_one 4 s, pinch_cylinder 25 s: the scripts of experiment.cpp, so that
// the metrics are those of runExperiment), building the world excluded. Counters: `steps` (time
// per step = run time / steps, scripts/bench_report) and the scenario's metrics, computed the
// same way for every system (physics/scenario_metrics.h, as runExperiment computes them).
//
// Units SI (m, kg, s, N, rad), world frame z up (REP-103), as the scene descriptions.
//
// The MuJoCo scene (mujocoXml):
//  - bodies: the same geoms (box, sphere, cylinder; the three scenarios have no mesh), poses,
//    masses, inertias (full tensor at the inertial origin) and friction as the ScenarioSetup;
//    static bodies are world geoms, others have a free joint.
//  - proxies: a body per finger with three world-aligned slide joints (x, y, z), a sphere geom
//    of WorldParams().coupling.proxy_radius and proxy_mass (Bullet's proxy: rotation locked). No
//    gravity on them: qfrc_applied carries -m g (MuJoCo 2.2 has no gravcomp).
//  - coupling: core/virtual_coupling.h's couplingForce with WorldParams().coupling, applied on
//    the three slider dofs through qfrc_applied, explicit in time as GodFingerWorld::step():
//    the proxy's state at the start of the step, target velocity = (target - previous target)/dt,
//    target = the script at the end of the step (runExperiment's ideal hand).
//  - time step 1 ms, gravity (0, 0, -9.81), integrator Euler (MuJoCo's semi-implicit Euler,
//    like Bullet's).
//  - contacts: explicit <pair>s only (every geom's contype = conaffinity = 0), so that each pair
//    gets Bullet's combined friction (the product of both bodies' coefficients; MuJoCo would take
//    the max): proxy-body pairs mu = 1.0 (the proxy's) x body mu; body-body pairs mu_a x mu_b.
//    Proxies do not collide with each other (as in GodFingerWorld). Body-body pairs are condim 3
//    in every variant: the scenes give zero spinning and rolling friction (Bullet's product is
//    zero), which is condim 3. The benchmark's condim (3, 4, 6) is the finger contacts'.
//  - finger friction triple: sliding = mu; torsional = (2/3) mu a and rolling = a, with
//    a = ContactParams().max_radius = 1 cm, the pad's contact radius under a few newtons: what
//    god_finger's pad constraint bounds its rows by (pad_constraints.h: twist <= mu N (2/3) a for
//    a uniform disk, tilt <= N a). condim 4 uses the torsional value, condim 6 both.
//  - solver (the fairest we found; stated in the report): Newton (MuJoCo's default and its best
//    for small scenes), iterations 100 and tolerance 1e-8 (MuJoCo's defaults: it stops when
//    converged: 1-2 iterations per step here), elliptic friction cones (MuJoCo's
//    recommendation for grasping; condim 4 and 6 are exact cones, not pyramids), impratio 10
//    (frictional constraints 10 times harder than normal ones: MuJoCo's documented remedy for
//    the slip of soft contacts in grasps; god_finger's friction rows are hard), 3 noslip
//    iterations (MuJoCo's post-pass that removes the creep of its soft friction: without it the
//    pinched cylinder slides down the fingers and drops after 12.7 s of the 21.5 s hold with
//    condim 3, 4 and 6 alike, for about 1 us/step less; god_finger's pad anchors hold it, and
//    it has 2 support passes after its own solver), contact solref and solimp at MuJoCo's
//    defaults (0.02 s, damping ratio 1; 0.9 0.95 0.001), warm start on.
#include "god_finger/core/contact_params.h"
#include "god_finger/core/virtual_coupling.h"
#include "god_finger/physics/experiment.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/physics/scenario_metrics.h"
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

// The scenario's metrics (physics/scenario_metrics.h, as runExperiment computes them) over the
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

std::string number(double value)
{
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

std::string vec(const Eigen::Vector3d& v)
{
  return number(v.x()) + " " + number(v.y()) + " " + number(v.z());
}

// MuJoCo's quaternion order: w x y z.
std::string quat(const Eigen::Matrix3d& rotation)
{
  const Eigen::Quaterniond q(rotation);
  return number(q.w()) + " " + number(q.x()) + " " + number(q.y()) + " " + number(q.z());
}

std::string geomXml(const std::string& name, const BodyDescription& body, const Eigen::Isometry3d& pose)
{
  std::ostringstream out;
  out << "<geom name=\"" << name << "\" contype=\"0\" conaffinity=\"0\" pos=\"" << vec(pose.translation())
      << "\" quat=\"" << quat(pose.linear()) << "\" ";
  const Geometry& geometry = body.geometry;
  switch (geometry.kind)
  {
    case GeometryKind::kBox:
      out << "type=\"box\" size=\"" << vec(0.5 * geometry.size) << "\"";
      break;
    case GeometryKind::kSphere:
      out << "type=\"sphere\" size=\"" << number(geometry.radius) << "\"";
      break;
    case GeometryKind::kCylinder:
      // Both conventions put the axis along the geometry frame's z; MuJoCo's size is r, half length.
      out << "type=\"cylinder\" size=\"" << number(geometry.radius) << " " << number(0.5 * geometry.length) << "\"";
      break;
    case GeometryKind::kMesh:
      throw std::runtime_error("mujoco baseline: body '" + body.name + "' is a mesh (not needed by its scenarios)");
  }
  out << "/>\n";
  return out.str();
}

// Friction of the finger contacts, see the header.
struct FingerFriction
{
  double torsional_per_mu = 2.0 / 3.0 * ContactParams().max_radius;  // m, times mu
  double rolling = ContactParams().max_radius;                       // m
};

std::string mujocoXml(const ScenarioSetup& setup, const WorldParams& params, int condim)
{
  const SceneDescription& scene = setup.scene;
  std::ostringstream xml;
  xml << "<mujoco model=\"" << scene.name << "\">\n"
      << "<compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"0\" boundinertia=\"0\"/>\n"
      << "<option timestep=\"" << number(params.time_step) << "\" gravity=\"" << vec(params.gravity)
      << "\" integrator=\"Euler\" solver=\"Newton\" iterations=\"100\" tolerance=\"1e-8\" cone=\"elliptic\""
      << " impratio=\"10\" noslip_iterations=\"3\"/>\n"
      << "<worldbody>\n";
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    const BodyDescription& body = scene.bodies[i];
    const std::string geom = "g" + std::to_string(i);
    if (body.is_static)
    {
      xml << geomXml(geom, body, body.pose * body.collision_origin);
      continue;
    }
    // The tensor is given in the inertial frame; MuJoCo's fullinertia is in the body (link) frame.
    const Eigen::Matrix3d& R = body.inertial_origin.linear();
    const Eigen::Matrix3d I = R * body.inertia * R.transpose();
    xml << "<body name=\"b" << i << "\" pos=\"" << vec(body.pose.translation()) << "\" quat=\""
        << quat(body.pose.linear()) << "\">\n<freejoint/>\n<inertial pos=\"" << vec(body.inertial_origin.translation())
        << "\" mass=\"" << number(body.mass) << "\" fullinertia=\"" << number(I(0, 0)) << " " << number(I(1, 1)) << " "
        << number(I(2, 2)) << " " << number(I(0, 1)) << " " << number(I(0, 2)) << " " << number(I(1, 2)) << "\"/>\n"
        << geomXml(geom, body, body.collision_origin) << "</body>\n";
  }
  const double r = params.coupling.proxy_radius;
  const double m = params.coupling.proxy_mass;
  for (std::size_t f = 0; f < setup.fingers.size(); ++f)
  {
    // A uniform sphere's inertia; the slide joints never turn it.
    xml << "<body name=\"p" << f << "\" pos=\"" << vec(setup.fingers[f].at(0.0)) << "\">\n"
        << "<joint name=\"p" << f << "x\" type=\"slide\" axis=\"1 0 0\"/>\n"
        << "<joint name=\"p" << f << "y\" type=\"slide\" axis=\"0 1 0\"/>\n"
        << "<joint name=\"p" << f << "z\" type=\"slide\" axis=\"0 0 1\"/>\n"
        << "<inertial pos=\"0 0 0\" mass=\"" << number(m) << "\" diaginertia=\""
        << vec(Eigen::Vector3d::Constant(0.4 * m * r * r)) << "\"/>\n"
        << "<geom name=\"pg" << f << "\" type=\"sphere\" size=\"" << number(r)
        << "\" contype=\"0\" conaffinity=\"0\"/>\n</body>\n";
  }
  xml << "</worldbody>\n<contact>\n";
  const FingerFriction finger;
  for (std::size_t a = 0; a < scene.bodies.size(); ++a)
  {
    for (std::size_t b = a + 1; b < scene.bodies.size(); ++b)
    {
      if (scene.bodies[a].is_static && scene.bodies[b].is_static)
      {
        continue;
      }
      const double mu = scene.bodies[a].material.friction * scene.bodies[b].material.friction;
      xml << "<pair geom1=\"g" << a << "\" geom2=\"g" << b << "\" condim=\"3\" friction=\"" << number(mu) << " "
          << number(mu) << " 0 0 0\"/>\n";
    }
    for (std::size_t f = 0; f < setup.fingers.size(); ++f)
    {
      const double mu = 1.0 * scene.bodies[a].material.friction;
      xml << "<pair geom1=\"pg" << f << "\" geom2=\"g" << a << "\" condim=\"" << condim << "\" friction=\""
          << number(mu) << " " << number(mu) << " " << number(finger.torsional_per_mu * mu) << " "
          << number(finger.rolling) << " " << number(finger.rolling) << "\"/>\n";
    }
  }
  xml << "</contact>\n</mujoco>\n";
  return xml.str();
}

struct ModelDeleter
{
  void operator()(mjModel* model) const
  {
    mj_deleteModel(model);
  }
};
struct DataDeleter
{
  void operator()(mjData* data) const
  {
    mj_deleteData(data);
  }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

ModelPtr loadMujoco(const std::string& xml)
{
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(xml.size())) != 0)
  {
    throw std::runtime_error("mujoco baseline: cannot make the VFS file");
  }
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name)], xml.data(), xml.size());
  char error[1000] = "";
  ModelPtr model(mj_loadXML(name, vfs.get(), error, sizeof(error)));
  mj_deleteVFS(vfs.get());
  if (!model)
  {
    throw std::runtime_error(std::string("mujoco baseline: ") + error + "\n" + xml);
  }
  return model;
}

// The object's sample from MuJoCo's state after mj_step (qpos, qvel are the new state; the
// derived quantities such as xpos are still the step's start, so they are not read). A free
// joint's qpos is the body frame (the link frame) in world, its qvel the frame origin's linear
// velocity (world) and the angular velocity (body frame).
BodyState mujocoSample(const mjModel* model, const mjData* data, int body, Eigen::Vector3d previous_velocity,
                       double mass, Eigen::Vector3d* com_velocity)
{
  const int qpos = model->jnt_qposadr[model->body_jntadr[body]];
  const int dof = model->jnt_dofadr[model->body_jntadr[body]];
  const mjtNum* q = data->qpos + qpos;
  const mjtNum* v = data->qvel + dof;
  BodyState sample;
  sample.pose.linear() = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
  sample.pose.translation() = Eigen::Vector3d(q[0], q[1], q[2]);
  const Eigen::Vector3d com_offset = sample.pose.linear() * Eigen::Vector3d(model->body_ipos + 3 * body);
  sample.center_of_mass = Eigen::Vector3d(q[0], q[1], q[2]) + com_offset;
  sample.angular_velocity = sample.pose.linear() * Eigen::Vector3d(v[3], v[4], v[5]);
  const Eigen::Vector3d velocity = Eigen::Vector3d(v[0], v[1], v[2]) + sample.angular_velocity.cross(com_offset);
  sample.linear_velocity = velocity;
  sample.net_force = mass * (velocity - previous_velocity) / model->opt.timestep;
  *com_velocity = velocity;
  return sample;
}

// The coupling on a 3-DOF slider proxy (its x dof at `dof`, y and z following; its qpos relative
// to `start`), explicit as GodFingerWorld::step(): the proxy's state at the start of the step, the
// target velocity from the previous target; plus the proxy's gravity compensation.
void pullSlider(const WorldParams& params, const Eigen::Vector3d& target, const Eigen::Vector3d& start, int dof,
                int qpos, const Eigen::Vector3d& gravity_compensation, Eigen::Vector3d* previous_target, mjData* data)
{
  const double dt = params.time_step;
  const mjtNum* q = data->qpos + qpos;
  const Eigen::Vector3d position = start + Eigen::Vector3d(q[0], q[1], q[2]);
  const Eigen::Vector3d velocity(data->qvel[dof], data->qvel[dof + 1], data->qvel[dof + 2]);
  const Eigen::Vector3d force =
      couplingForce(params.coupling, target, (target - *previous_target) / dt, position, velocity).on_proxy +
      gravity_compensation;
  for (int k = 0; k < 3; ++k)
  {
    data->qfrc_applied[dof + k] = force[k];
  }
  *previous_target = target;
}

// One scenario in MuJoCo with the finger contacts' condim = range(1).
void BM_MujocoScenarioStep(benchmark::State& state)
{
  const Scenario scenario = kScenarios[state.range(0)];
  const int condim = static_cast<int>(state.range(1));
  const ExperimentOptions options = scenarioOptions(scenario, ContactModel::kGodFinger);
  const ScenarioSetup setup = loadScenario(options);
  const WorldParams params = scenarioParams(options);
  const ModelPtr model = loadMujoco(mujocoXml(setup, params, condim));
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
      iterations += world->solverIterationsUsed();
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
