#include "stages/impulse_record.h"

#include "bullet_helpers.h"
#include "world_core.h"

namespace god_finger::internal
{
void beforeSolve(WorldCore* core)
{
  for (const int index : core->sleep.awake)
  {
    core->bodies[index].previous_velocity = toEigen(core->bodies[index].rigid->getLinearVelocity());
  }
  core->solver->resetCounts();
}

void recordImpulses(WorldCore* core)
{
  const double dt = core->params.time_step;
  core->injector->recordImpulses(&core->proxies, core->steps);
  core->pads.recordImpulses(core->steps);
  for (Proxy& proxy : core->proxies)
  {
    if (!proxy.orientation.oriented)
    {
      continue;
    }
    for (const PadState& pad : proxy.pads)
    {
      if (pad.linear.step == core->steps)
      {
        proxy.state.user_torque -= pad.object_side * pad.torque_impulse / dt;
      }
    }
  }
}

void recordNetForces(WorldCore* core)
{
  const double dt = core->params.time_step;
  for (const int index : core->sleep.awake)
  {
    SceneBody& body = core->bodies[index];
    body.net_force =
        core->scene.bodies[index].mass * (toEigen(body.rigid->getLinearVelocity()) - body.previous_velocity) / dt;
  }
}
}  // namespace god_finger::internal
