// The operator benchmark's pick and place in MuJoCo (bench/REPORT.md, "Human-like operator"):
// the same bar, hand and operators as bench/operator_bench.cpp (scenarios/grip_task.h's targets,
// measured by its GripTaskMeter), in the MuJoCo baseline's scene (bench/mujoco_scene.h: the
// proxies are spheres on three slide joints pulled by the same coupling, the finger contacts of
// condim 4 (torsional friction (2/3) mu a) or 6 (and rolling friction a), a = 1 cm). Layouts
// "mujoco_condim4" and "mujoco_condim6": a twist limit line and the runs per squeeze, in
// operator_bench's format (operator_pick_place.h), for scripts/bench to append to operator.jsonl.
// The finger contacts' solref is 2 time steps (see main), MuJoCo's other settings the baseline's.
// Deterministic on one machine and MuJoCo build.
//
// usage: operator_mujoco_bench [--seeds N]
#include "god_finger/support/text_numbers.h"
#include "god_finger/scenarios/grip_task.h"
#include "mujoco_scene.h"
#include "operator_pick_place.h"

#include <iostream>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
// The grip task (runGripTask's script and measures) stepped in MuJoCo with finger contacts of
// `condim`.
GripTaskResult runMujocoGripTask(const GripTaskOptions& options, int condim, double finger_solref)
{
  const SceneDescription scene = gripBarScene();
  const WorldParams& params = options.params;
  std::vector<Eigen::Vector3d> starts(2);
  gripTargets(options, 0.0, 1.0, &starts[0], &starts[1]);
  const ModelPtr model = loadMujoco(mujocoXml(scene, starts, params, condim, finger_solref));
  const DataPtr data(mj_makeData(model.get()));
  const int bar_index = scene.find("bar");
  const int bar = mj_name2id(model.get(), mjOBJ_BODY, ("b" + std::to_string(bar_index)).c_str());
  const double bar_mass = scene.bodies[bar_index].mass;
  int dof[2];
  int qpos[2];
  for (int f = 0; f < 2; ++f)
  {
    const int joint = mj_name2id(model.get(), mjOBJ_JOINT, ("p" + std::to_string(f) + "x").c_str());
    dof[f] = model->jnt_dofadr[joint];
    qpos[f] = model->jnt_qposadr[joint];
  }
  const Eigen::Vector3d gravity_compensation = -params.coupling.proxy_mass * params.gravity;
  std::vector<Eigen::Vector3d> previous_target = starts;
  Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();
  BodyState sample = mujocoSample(model.get(), data.get(), bar, com_velocity, bar_mass, &com_velocity);
  GripTaskMeter meter(options, sample.pose, sample.center_of_mass);
  const double dt = params.time_step;
  std::vector<Eigen::Vector3d> targets(2);
  Eigen::Vector3d force[2];
  Eigen::Vector3d proxy[2];
  for (long i = 0; i < std::lround(gripTaskDuration(options) / dt); ++i)
  {
    const double t = (i + 1) * dt;
    const double factor = meter.squeezeFactor(t);
    gripTargets(options, t, factor, &targets[0], &targets[1]);
    for (int f = 0; f < 2; ++f)
    {
      force[f] = pullSlider(params, targets[f], starts[f], dof[f], qpos[f], gravity_compensation, &previous_target[f],
                            data.get());
    }
    mj_step(model.get(), data.get());
    sample = mujocoSample(model.get(), data.get(), bar, com_velocity, bar_mass, &com_velocity);
    for (int f = 0; f < 2; ++f)
    {
      const mjtNum* q = data->qpos + qpos[f];
      proxy[f] = starts[f] + Eigen::Vector3d(q[0], q[1], q[2]);
    }
    meter.add(t, factor, sample.pose, sample.center_of_mass, proxy[0], proxy[1], force[0], force[1]);
  }
  return meter.finish(sample.pose, sample.center_of_mass);
}

int fail(const std::string& message)
{
  std::cerr << "operator_mujoco_bench: " << message << "\nusage: operator_mujoco_bench [--seeds N]\n";
  return 2;
}
}  // namespace
}  // namespace god_finger

int main(int argc, char** argv)
{
  using namespace god_finger;
  int seeds = 20;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    long long number = 0;
    if (option != "--seeds" || !parseInteger(argv[i + 1], &number) || number < 1 || number > 10000)
    {
      return fail("bad option '" + option + " " + argv[i + 1] + "'");
    }
    seeds = static_cast<int>(number);
  }
  // The finger contacts' solref time constant: 2 time steps, the stiffest MuJoCo documents as
  // stable. At its default (0.02 s) a 20 g proxy pressed by 8 N or more sinks through the 3 cm bar.
  const double solref = 2.0 * WorldParams().time_step;
  for (const int condim : {4, 6})
  {
    const GripRunner run = [condim, solref](const GripTaskOptions& options)
    { return runMujocoGripTask(options, condim, solref); };
    pickPlaceRuns("mujoco_condim" + std::to_string(condim), run, GripTaskOptions(), kPickPlaceSqueezes, seeds);
  }
  return 0;
}
