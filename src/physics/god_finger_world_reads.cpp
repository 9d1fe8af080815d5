// GodFingerWorld's reads: what its state (world_core.h) says, for output and tests. Real-time
// safe, except snapshot() when its buffers must grow.
#include "bullet_helpers.h"
#include "world_core.h"
#include "world_impl.h"
#include "world_queries.h"

#include "god_finger/physics/god_finger_world.h"

namespace god_finger
{
using namespace internal;

const WorldParams& GodFingerWorld::params() const
{
  return impl_->params;
}

const std::vector<std::string>& GodFingerWorld::startWarnings() const
{
  return impl_->start_warnings;
}

int GodFingerWorld::interfaceCount() const
{
  return static_cast<int>(impl_->proxies.size());
}

const CouplingProfile& GodFingerWorld::coupling(int interface) const
{
  return impl_->proxies.at(interface).coupling;
}

const InterfaceState& GodFingerWorld::interfaceState(int interface) const
{
  return impl_->proxies.at(interface).state;
}

int GodFingerWorld::bodyCount() const
{
  return static_cast<int>(impl_->bodies.size());
}

BodyState GodFingerWorld::bodyState(int body) const
{
  return internal::bodyState(*impl_, body);
}

int GodFingerWorld::jointCount() const
{
  return static_cast<int>(impl_->scene.joints.size());
}

JointState GodFingerWorld::jointState(int joint) const
{
  return internal::jointState(*impl_, joint);
}

void GodFingerWorld::snapshot(WorldSnapshot* out) const
{
  const WorldCore& core = *impl_;
  out->scene = core.shared_scene;
  out->time = core.time;
  out->steps = core.steps;
  out->model = core.params.model;
  out->bodies.resize(core.bodies.size());
  for (std::size_t i = 0; i < core.bodies.size(); ++i)
  {
    out->bodies[i] = internal::bodyState(core, static_cast<int>(i));
  }
  out->interfaces.resize(core.proxies.size());
  for (std::size_t i = 0; i < core.proxies.size(); ++i)
  {
    out->interfaces[i] = core.proxies[i].state;
  }
  out->soft_surfaces.resize(core.soft_bodies.size());
  for (std::size_t i = 0; i < core.soft_bodies.size(); ++i)
  {
    const int index = core.soft_bodies[i];
    snapshotSoftSurface(core.bodies[index], index, &out->soft_surfaces[i]);
  }
}

const SceneDescription& GodFingerWorld::scene() const
{
  return impl_->scene;
}

const TriangleMesh& GodFingerWorld::walkMesh(int body) const
{
  return *impl_->bodies.at(body).walk;
}

GodFingerWorld::BodyCollision GodFingerWorld::bodyCollision(int body) const
{
  const SceneBody& scene_body = impl_->bodies.at(body);
  BodyCollision result;
  const auto add = [&result](const CollisionShape& shape)
  {
    result.convex_hulls += shape.exact ? 0 : shape.convex_parts;
    result.hulls_as_given = result.hulls_as_given || shape.decomposition_source == DecompositionSource::kGiven;
  };
  add(*scene_body.collision);
  for (const std::unique_ptr<CollisionShape>& part : scene_body.part_collisions)
  {
    add(*part);
  }
  result.fingers_touch_walk_mesh = scene_body.finger_surface != nullptr;
  return result;
}

WorldCounters GodFingerWorld::counters() const
{
  WorldCounters counters = impl_->counters;
  counters.awake_bodies = awakeBodyCount(*impl_);
  counters.solver_contact_rows = impl_->solver->rows();
  counters.solver_iterations = impl_->solver->iterationsUsed();
  counters.solver_proxy_points = impl_->solver->proxyPoints();
  return counters;
}

const StepProfile& GodFingerWorld::stepProfile() const
{
  return impl_->profile;
}

double GodFingerWorld::time() const
{
  return impl_->time;
}

long GodFingerWorld::steps() const
{
  return impl_->steps;
}
}  // namespace god_finger
