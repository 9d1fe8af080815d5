// GodFingerWorld: the order of a step's stages and the public calls, over the state in
// world_core.h. Each stage is a piece of its own (step_profile.h lists them and their files);
// building is world_build.h, scene edits scene_edit.h, reads world_queries.h.
#include "god_finger/physics/god_finger_world.h"

#include "bullet_helpers.h"
#include "prepared_object.h"
#include "scene_edit.h"
#include "solver/finger_contact_friction.h"
#include "stages/contact_area_stage.h"
#include "stages/coupling_stage.h"
#include "stages/escapees.h"
#include "stages/impulse_record.h"
#include "start_overlaps.h"
#include "world_build.h"
#include "world_core.h"
#include "world_impl.h"
#include "world_queries.h"

#include "god_finger/haptics/orientation_path.h"
#include "god_finger/scene/scene_budget.h"
#include "god_finger/support/input_error.h"

#include <sstream>

namespace god_finger
{
using namespace internal;  // the physics' private pieces (src/physics)

PreparedObject::PreparedObject() : impl_(new Impl) {}
PreparedObject::~PreparedObject() = default;

const SceneDescription& PreparedObject::object() const
{
  return impl_->object;
}

GodFingerWorld::GodFingerWorld(const SceneDescription& scene, const WorldParams& params) : impl_(new Impl)
{
  validateOrThrow(params);
  checkSceneFits(scene, params.walk_edge_per_max_radius * params.contact.max_radius);
  checkJoints(scene);
  useFingerRollingFriction();
  impl_->params = params;
  impl_->scene = scene;
  impl_->shared_scene = std::make_shared<const SceneDescription>(scene);
  buildBodies(impl_.get());
  buildWorld(impl_.get());
  for (const StartOverlap& overlap : startOverlaps(impl_->world.get(), impl_->bodies, impl_->scene))
  {
    impl_->start_warnings.push_back(describe(overlap, impl_->scene));
  }
}

GodFingerWorld::~GodFingerWorld() = default;  // WorldCore tears Bullet's world down

void GodFingerWorld::step()
{
  WorldCore& core = *impl_;
  const int every = core.params.profile_every;
  core.clock.start(every > 0 && core.steps % every == 0);
  applyCouplings(&core);
  core.clock.mark(StepStage::kCoupling);
  wakeNearFingersAndMovers(&core);
  core.clock.mark(StepStage::kWake);
  beforeSolve(&core);
  core.soft.beforeSolve(&core);
  // Bullet's step: collide, then contact areas (HookedWorld::after_collision marks both), then solve.
  core.world->stepSimulation(core.params.time_step, 0);
  core.clock.mark(StepStage::kSolve);
  recordImpulses(&core);
  core.time = (core.steps + 1) * core.params.time_step;
  ++core.steps;
  recordNetForces(&core);
  core.clock.mark(StepStage::kRecord);
  core.soft.loadAndStep(&core);
  core.clock.mark(StepStage::kSoftBodies);
  putSleepersAway(&core);
  core.clock.mark(StepStage::kSleep);
  catchEscapees(&core);
  core.clock.mark(StepStage::kEscapees);
  for (Proxy& proxy : core.proxies)
  {
    proxy.state.proxy_position = toEigen(proxy.rigid->getWorldTransform().getOrigin());
    proxy.state.proxy_velocity = toEigen(proxy.rigid->getLinearVelocity());
  }
  core.overlap.update(core.params, &core.proxies);
  core.clock.mark(StepStage::kOverlap);
  core.clock.finish(core.steps);
}

void GodFingerWorld::reset()
{
  // Rebuilding Bullet's objects (not the shapes or walk meshes) is the only way to clear every
  // cache (broadphase pairs, manifolds, warm starts), so that a reset run repeats the first one
  // bit for bit.
  teardownWorld(impl_.get());
  impl_->time = 0.0;
  impl_->steps = 0;
  for (const int index : impl_->soft_bodies)
  {
    resetSoftVolume(nullptr, &impl_->bodies[index]);
  }
  buildWorld(impl_.get());
}

void GodFingerWorld::resetAtInterfaces()
{
  for (Proxy& proxy : impl_->proxies)
  {
    proxy.initial = proxy.target;
    proxy.orientation.initial = proxy.orientation.target;
  }
  reset();
}

int GodFingerWorld::addInterface(const Eigen::Vector3d& position)
{
  return addInterface(position, impl_->params.coupling);
}

int GodFingerWorld::addInterface(const Eigen::Vector3d& position, const CouplingProfile& coupling, bool allow_inside)
{
  if (!position.allFinite())
  {
    throw InputError("interface start position must be finite");
  }
  std::string error = validate(coupling);
  if (error.empty())
  {
    error = couplingStabilityError(coupling, impl_->params.coupling.proxy_mass, impl_->params.time_step);
  }
  if (!error.empty())
  {
    throw InputError(error);
  }
  // A proxy is the hand's god-object: it never starts inside a body. One whose centre would lie
  // in a body (the hand starts in the table: a workspace offset too low) is refused rather than
  // lifted out, since lifting it would stretch the coupling at once and throw the hand out of the
  // body at the force limit; the user moves the device or its workspace_offset instead.
  const std::pair<int, double> overlap = deepestOverlap(*impl_, position);
  if (!allow_inside && overlap.first >= 0 && overlap.second >= impl_->params.coupling.proxy_radius)
  {
    std::ostringstream message;
    message << "interface " << impl_->proxies.size() << " would start inside body '"
            << impl_->scene.bodies[overlap.first].name << "': its proxy at (" << position.x() << ", " << position.y()
            << ", " << position.z() << ") m lies " << overlap.second - impl_->params.coupling.proxy_radius
            << " m below its surface; start the hand outside every body (move the device, or its workspace_offset)";
    throw ProxyInsideBodyError(message.str());
  }
  Proxy proxy;
  proxy.initial = position;
  proxy.coupling = coupling;
  impl_->proxies.push_back(std::move(proxy));
  const int index = static_cast<int>(impl_->proxies.size()) - 1;
  addProxyToWorld(impl_.get(), index);
  return index;
}

void GodFingerWorld::setInterfaceTarget(int interface, const Eigen::Vector3d& position)
{
  if (!position.allFinite())
  {
    ++impl_->counters.rejected_targets;
    return;
  }
  impl_->proxies.at(interface).target = position;
}

void GodFingerWorld::setInterfaceTarget(int interface, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity)
{
  if (!position.allFinite() || !velocity.allFinite())
  {
    ++impl_->counters.rejected_targets;
    return;
  }
  Proxy& proxy = impl_->proxies.at(interface);
  proxy.target = position;
  proxy.previous_target = position - velocity * impl_->params.time_step;
}

void GodFingerWorld::setInterfaceTarget(int interface, const Eigen::Vector3d& position,
                                        const Eigen::Quaterniond& orientation)
{
  if (!position.allFinite() || !usableOrientation(orientation))
  {
    ++impl_->counters.rejected_targets;
    return;
  }
  Proxy& proxy = impl_->proxies.at(interface);
  proxy.target = position;
  FingerOrientation& finger = proxy.orientation;
  finger.target = orientation.normalized();
  if (!finger.oriented)
  {
    finger.oriented = true;
    finger.initial = finger.target;
    finger.restart();
    proxy.state.oriented = true;
    proxy.state.interface_orientation = finger.target;
    proxy.state.proxy_orientation = finger.proxy;
  }
}

bool GodFingerWorld::carryFreeProxy(int interface, const Eigen::Vector3d& by)
{
  WorldCore* core = impl_.get();
  Proxy& proxy = core->proxies.at(interface);
  const btBroadphaseProxy* handle = proxy.rigid->getBroadphaseHandle();
  if (!carriable(proxy, by) || handle == nullptr)
  {
    return false;
  }
  // Sleeping bodies are out of Bullet's world: those in the swept box wake first (as a proxy near
  // them would wake them in the step), so that the sweep sees them.
  const btVector3 shift = toBullet(by);
  btVector3 low = handle->m_aabbMin;
  btVector3 high = handle->m_aabbMax;
  low.setMin(handle->m_aabbMin + shift);
  high.setMax(handle->m_aabbMax + shift);
  core->sleep.dormant.wakeOverlapping(low, high, [core](int index) { wakeBody(core, index, true); });
  return internal::carryFreeProxy(core->world.get(), by, &proxy);
}

void GodFingerWorld::applyBodyWrench(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque)
{
  if (body < 0 || body >= bodyCount())
  {
    throw InputError("body " + std::to_string(body) + " does not exist (the scene has " + std::to_string(bodyCount()) +
                     ")");
  }
  if (!force.allFinite() || !torque.allFinite())
  {
    throw InputError("body wrench must be finite");
  }
  if (impl_->scene.bodies[body].is_static)
  {
    return;
  }
  WorldCore* core = impl_.get();
  btRigidBody& rigid = *core->bodies[body].rigid;
  if (core->sleep.dormant.dormant(body))
  {
    const btVector3& at = rigid.getWorldTransform().getOrigin();
    core->sleep.dormant.wakeOverlapping(at, at, [core](int index) { wakeBody(core, index, true); });
  }
  rigid.activate(true);
  rigid.applyCentralForce(toBullet(force));
  rigid.applyTorque(toBullet(torque));
}

std::unique_ptr<PreparedObject> GodFingerWorld::prepareObject(const SceneDescription& object, const WorldParams& params)
{
  if (object.bodies.empty())
  {
    throw InputError("object '" + object.name + "' has no body");
  }
  std::unique_ptr<PreparedObject> prepared(new PreparedObject);
  PreparedObject::Impl& impl = *prepared->impl_;
  impl.max_edge = params.walk_edge_per_max_radius * params.contact.max_radius;
  checkSceneFits(object, impl.max_edge);
  checkJoints(object);
  impl.object = object;
  for (const BodyDescription& body : object.bodies)
  {
    impl.bodies.push_back(makeSceneBody(body, impl.max_edge));
  }
  return prepared;
}

std::vector<std::string> GodFingerWorld::addObject(const SceneDescription& object)
{
  const std::unique_ptr<PreparedObject> prepared = prepareObject(object, impl_->params);
  return addObject(prepared.get());
}

std::vector<std::string> GodFingerWorld::addObject(PreparedObject* prepared)
{
  WorldCore* core = impl_.get();
  PreparedObject::Impl& made = *prepared->impl_;
  if (made.object.bodies.empty() || made.bodies.size() != made.object.bodies.size())
  {
    throw InputError("object '" + made.object.name + "' has no body (or was added already)");
  }
  const int first = bodyCount();
  std::vector<int> old_of_new;
  SceneDescription next = sceneWithObject(*core, made.object, &old_of_new);
  // Made for another walk edge (the contact radius changed since): made again here.
  const bool usable = made.max_edge == walkEdge(*core);
  changeScene(core, std::move(next), old_of_new, usable ? &made.bodies : nullptr);
  made.bodies.clear();
  std::vector<std::string> warnings;
  for (const ProxyInsideAdded& inside : proxiesInsideAdded(*core, first))
  {
    warnings.push_back(describe(inside, core->scene));
  }
  for (const StartOverlap& overlap : startOverlaps(core->world.get(), core->bodies, core->scene))
  {
    if (overlap.other >= first)  // other > body: one of the two is the object's
    {
      warnings.push_back(describe(overlap, core->scene));
    }
  }
  return warnings;
}

int GodFingerWorld::removeObject(const std::string& name)
{
  std::vector<int> old_of_new;
  SceneDescription next = sceneWithout(*impl_, name, &old_of_new);
  const int removed = bodyCount() - static_cast<int>(next.bodies.size());
  changeScene(impl_.get(), std::move(next), old_of_new, nullptr);
  return removed;
}

void GodFingerWorld::setContactModel(ContactModel model)
{
  impl_->params.model = model;
  chooseResponse(impl_.get());
  for (Proxy& proxy : impl_->proxies)
  {
    impl_->response->configureProxy(impl_->params, proxy.rigid.get());
  }
  wakeAll(impl_.get());
}

ContactModel GodFingerWorld::contactModel() const
{
  return impl_->params.model;
}

void GodFingerWorld::setContactParams(const ContactParams& params)
{
  validateOrThrow(params);
  impl_->params.contact = params;
  wakeAll(impl_.get());
}

void GodFingerWorld::setPadSolver(PadSolver solver)
{
  if (solver != PadSolver::kPoints && solver != PadSolver::kConstraint)
  {
    throw InputError("pad solver " + std::to_string(static_cast<int>(solver)) + " is not one of " + padSolverNames());
  }
  impl_->params.pad_solver = solver;
  wakeAll(impl_.get());
}
}  // namespace god_finger
