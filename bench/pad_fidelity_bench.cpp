// The pad's fidelity against soft-finger physics, for the bench report (scripts/bench_report,
// "Pad fidelity"): one JSON object per line on stdout.
//
// - kind "capacity": for each layout (god_object, soft_finger, god_finger with the pad
//   constraint and with the paper's points) and load (twist about the normal, tilt about a
//   tangent), at normal forces 0.5-5 N, the largest torque held (< 1 mrad in 1 s;
//   scenarios/pad_fidelity.h), with the contact radius a and the force N it was measured at.
// - kind "creep": for both pad solvers and solver iterations 10-120, the pinch_cylinder
//   scenario's turn about the pinch normal over its 25 s and its median step, and the twist
//   set-up's turn in 3 s holding 70 % of the layout's analytic capacity at 2 N (the ring's
//   (8/9) mu N a for points, the uniform disk's (2/3) mu N a for the constraint).
// Units: SI (N, m, N m, rad, us). Not real-time; about a minute.
#include "god_finger/scenarios/experiment.h"
#include "god_finger/scenarios/pad_fidelity.h"

#include <cstdio>
#include <string>

namespace god_finger
{
namespace
{

void capacities()
{
  for (const PadLoad load : {PadLoad::kTwist, PadLoad::kTilt})
  {
    for (const PadLayout& layout : kPadLayouts)
    {
      for (const double normal_force : {0.5, 1.0, 2.0, 3.0, 4.0, 5.0})
      {
        PadLoadSetup setup;
        setup.load = load;
        setup.model = layout.model;
        setup.params.pad_solver = layout.pad_solver;
        setup.normal_force = normal_force;
        const double r_max = setup.params.contact.max_radius;
        const double upper = 2.0 * normal_force * r_max * (load == PadLoad::kTwist ? setup.friction : 1.0);
        const PadLoadMeasurement pressed = measurePadHold(setup, 0.0, 0.01);
        const double torque = measurePadCapacity(setup, upper);
        std::printf(
            "{\"kind\": \"capacity\", \"load\": \"%s\", \"layout\": \"%s\", \"nominal_force\": %.2f, \"normal_force\": "
            "%.4f, "
            "\"contact_radius\": %.6f, \"friction\": %.3f, \"torque\": %.6g}\n",
            load == PadLoad::kTwist ? "twist" : "tilt", layout.name, normal_force, pressed.normal_force,
            pressed.contact_radius, setup.friction, torque);
        std::fflush(stdout);
      }
    }
  }
}

void creep(const std::string& scenes_dir)
{
  for (const PadLayout& layout : {kPadLayouts[2], kPadLayouts[3]})
  {
    for (const int iterations : {10, 20, 30, 60, 120})
    {
      ExperimentOptions options;
      options.scenario = Scenario::kPinchCylinder;
      options.model = layout.model;
      options.pad_solver = layout.pad_solver;
      options.solver_iterations = iterations;
      options.scenes_dir = scenes_dir;
      const ExperimentResult pinch = runExperiment(options);

      PadLoadSetup setup;
      setup.model = layout.model;
      setup.params.pad_solver = layout.pad_solver;
      setup.params.solver_iterations = iterations;
      const PadLoadMeasurement pressed = measurePadHold(setup, 0.0, 0.01);
      const double n = setup.params.contact.sub_god_objects;
      const double capacity = layout.pad_solver == PadSolver::kPoints
                                  ? n / (n + 1.0) * setup.friction * pressed.normal_force * pressed.contact_radius
                                  : uniformPadTorque(setup.friction, pressed.normal_force, pressed.contact_radius);
      const PadLoadMeasurement hold = measurePadHold(setup, 0.7 * capacity, 3.0);
      std::printf(
          "{\"kind\": \"creep\", \"layout\": \"%s\", \"iterations\": %d, \"pinch_rotation\": %.6g, "
          "\"pinch_held_s\": %.3f, \"pinch_step_us\": %.3f, \"twist_hold_rotation\": %.6g}\n",
          layout.name, iterations, pinch.metrics.at("rotation_about_normal_rad"), pinch.metrics.at("held_s"),
          pinch.step_us_median, hold.rotation);
      std::fflush(stdout);
    }
  }
}
}  // namespace
}  // namespace god_finger

int main()
{
  god_finger::capacities();
  god_finger::creep(GOD_FINGER_SCENES_DIR);
  return 0;
}
