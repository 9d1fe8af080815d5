#include "stages/escapees.h"

#include "bullet_helpers.h"
#include "world_bounds.h"
#include "world_core.h"

namespace god_finger::internal
{
namespace
{
// A body caught past the bounds (BodyState::left_world), now.
void countLeftWorld(double time, SceneBody* body)
{
  ++body->left_world;
  body->left_world_at = time;
}
}  // namespace

void catchEscapees(WorldCore* core)
{
  // A resting soft body pushed off its support falls; past the bounds it is put back where it
  // started, settled, as a reset puts it.
  for (const int index : core->soft_bodies)
  {
    SceneBody& body = core->bodies[index];
    if (body.soft->resting && outsideBounds(core->bounds, toEigen(body.rigid->getWorldTransform().getOrigin())))
    {
      resetSoftVolume(core->world.get(), &body);
      countLeftWorld(core->time, &body);
    }
  }
  for (const int index : core->sleep.awake)
  {
    SceneBody& body = core->bodies[index];
    const btTransform start = toBullet(core->scene.bodies[index].pose * body.com_in_link);
    if (catchIfOutside(core->bounds, start, body.rigid.get(), core->world.get()))
    {
      prepareSleep(*core, body.rigid.get());
      body.net_force.setZero();
      countLeftWorld(core->time, &body);
    }
  }
}

void placeSoftSupports(WorldCore* core)
{
  std::vector<Eigen::AlignedBox3d> static_boxes;
  for (std::size_t i = 0; i < core->bodies.size(); ++i)
  {
    if (core->scene.bodies[i].is_static && !core->bodies[i].soft)
    {
      btVector3 min;
      btVector3 max;
      core->bodies[i].rigid->getAabb(min, max);
      static_boxes.emplace_back(toEigen(min), toEigen(max));
    }
  }
  for (SceneBody& body : core->bodies)
  {
    if (body.soft)
    {
      setSoftSupportExtent(static_boxes, &body);
    }
  }
}
}  // namespace god_finger::internal
