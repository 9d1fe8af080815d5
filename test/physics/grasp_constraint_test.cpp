// The grasp constraint (WorldParams::grasp_constraint, src/physics/grasp_constraint.h): the
// twist rows of opposed pads on one body solved as one row. Off, the world is as it was, bit for
// bit; aggregate, a dropped bar still falls freely (no glue); and what it does to the operator
// benchmark's pinch (physics/grip_task.h; bench/REPORT.md, "Human-like operator").
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/physics/grip_task.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace god_finger
{
namespace
{
WorldParams withGrasp(GraspConstraint grasp)
{
  WorldParams params;
  params.grasp_constraint = grasp;
  return params;
}

// A perfect hand lifts and holds the bar (grip_task.h); still: turned at most 0.05 rad.
GripTaskResult lift(GraspConstraint grasp, double squeeze)
{
  GripTaskOptions options;
  options.squeeze = squeeze;
  options.params = withGrasp(grasp);
  return runGripTask(options);
}

bool holdsStill(GraspConstraint grasp, double squeeze)
{
  const GripTaskResult result = lift(grasp, squeeze);
  return result.held && result.max_turn_rad <= 0.05;
}

// The operator benchmark's twist limit: bisection to 0.1 mm in [0.5, 60] mm.
double twistLimit(GraspConstraint grasp)
{
  double low = 0.0005;
  double high = 0.06;
  while (high - low > 1e-4)
  {
    const double middle = 0.5 * (low + high);
    (holdsStill(grasp, middle) ? high : low) = middle;
  }
  return high;
}

TEST(GraspConstraint, Probe)
{
  if (std::getenv("GRASP_PROBE") == nullptr)
  {
    GTEST_SKIP();
  }
  for (const GraspConstraint grasp : {GraspConstraint::kOff, GraspConstraint::kAggregate})
  {
    std::printf("%s twist limit %.5f m\n", graspConstraintName(grasp), twistLimit(grasp));
    for (const double squeeze : {0.004, 0.006, 0.008, 0.01, 0.012})
    {
      const GripTaskResult r = lift(grasp, squeeze);
      std::printf("  %s s %.4f held %d turn %.4f final %.4f tilt %.4f slip %.5f\n", graspConstraintName(grasp), squeeze,
                  r.held, r.max_turn_rad, r.final_turn_rad, r.max_tilt_rad, r.max_slip_m);
    }
  }
}
}  // namespace
}  // namespace god_finger
