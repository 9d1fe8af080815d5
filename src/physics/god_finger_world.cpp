#include "god_finger/physics/god_finger_world.h"

#include "bullet_helpers.h"
#include "contact_response.h"
#include "god_finger/contact/primitive_walk.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/haptics/orientation_path.h"
#include "god_finger/physics/joint_measure.h"
#include "god_finger/scene/scene_budget.h"
#include "god_finger/scene/scene_description.h"
#include "god_finger/support/input_error.h"
#include "near_callback.h"
#include "overlap_push.h"
#include "proxy.h"
#include "proxy_touches.h"
#include "scene_body.h"
#include "scene_joints.h"
#include "sleep/dormant_bodies.h"
#include "sleep/hooked_world.h"
#include "sleep/slept_contacts.h"
#include "solver/contact_solver.h"
#include "solver/finger_contact_friction.h"
#include "solver/pad_constraints.h"
#include "solver/sub_god_object_injection.h"
#include "sphere_mesh_algorithm.h"
#include "start_overlaps.h"
#include "world_bounds.h"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

namespace god_finger
{
using namespace internal;  // the physics' private pieces (src/physics)
namespace
{
// Sub-god-objects closer than this to the contact point (m) duplicate it and are not added.
constexpr double kCoincident = 1e-7;
}  // namespace

struct PreparedObject::Impl
{
  SceneDescription object;
  std::vector<SceneBody> bodies;  // by object body index; empty once added
  double max_edge = 0.0;          // m: the walk edge the primitives were made with
};

PreparedObject::PreparedObject() : impl_(new Impl) {}
PreparedObject::~PreparedObject() = default;

const SceneDescription& PreparedObject::object() const
{
  return impl_->object;
}

struct GodFingerWorld::Impl
{
  using Body = SceneBody;
  WorldParams params;
  Eigen::AlignedBox3d bounds;  // world_bounds.h: set by buildWorld
  SceneDescription scene;
  std::shared_ptr<const SceneDescription> shared_scene;  // a copy of `scene` for snapshots
  std::vector<Body> bodies;
  std::vector<std::string> start_warnings;  // startWarnings()
  // The scene's joints' constraints (scene_joints.h), by joint index; jointed[body]: a joint's
  // parent or child, which never sleeps (a sleeping body leaves Bullet's world, its constraint
  // cannot).
  std::vector<std::unique_ptr<btTypedConstraint>> joints;
  std::vector<char> jointed;
  // The world's own fixed body, a joint's parent when it is the world (not Bullet's process-wide
  // btTypedConstraint::getFixedBody(), which every world's constraints would share).
  std::unique_ptr<btRigidBody> world_anchor =
      std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0.0, nullptr, nullptr));

  BodyState bodyState(int body) const
  {
    const Body& b = bodies.at(body);
    BodyState state;
    const Eigen::Isometry3d com = toEigen(b.rigid->getWorldTransform());
    state.pose = com * b.com_in_link.inverse();
    state.center_of_mass = com.translation();
    state.linear_velocity = toEigen(b.rigid->getLinearVelocity());
    state.angular_velocity = toEigen(b.rigid->getAngularVelocity());
    state.net_force = b.net_force;
    state.asleep = b.soft ? b.soft->elastic->sleeping()
                          : dormant.dormant(body) || b.rigid->getActivationState() == ISLAND_SLEEPING;
    state.left_world = b.left_world;
    state.left_world_at = b.left_world_at;
    return state;
  }

  JointState jointState(int index) const
  {
    const JointDescription& joint = scene.joints.at(index);
    if (joint.parent < 0)
    {
      return measureJoint(joint, nullptr, bodyState(joint.child));
    }
    const BodyState parent = bodyState(joint.parent);
    return measureJoint(joint, &parent, bodyState(joint.child));
  }

  // The joints' constraints, between bodies already in the world.
  void buildJoints()
  {
    for (const JointDescription& joint : scene.joints)
    {
      joints.push_back(makeJointConstraint(joint, joint.parent < 0 ? nullptr : &bodies[joint.parent],
                                           bodies[joint.child], world_anchor.get()));
      world->addConstraint(joints.back().get(), true);  // no contacts between a joint's two bodies
    }
  }

  // Before each step: every joint's friction and damping at its current speed.
  void resistJoints()
  {
    for (std::size_t i = 0; i < joints.size(); ++i)
    {
      resistJointMotion(scene.joints[i], jointState(static_cast<int>(i)), params.time_step, joints[i].get());
    }
  }
  std::vector<Proxy> proxies;
  std::unique_ptr<btDefaultCollisionConfiguration> configuration;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<ContactSolver> solver;
  std::unique_ptr<HookedWorld> world;
  std::unique_ptr<SubGodObjectInjector> injector;
  // This step's pads (pad_solver: constraint); the solver reads them.
  PadConstraints pads;
  // Every model's response, made once; `response` is the current model's (a model change
  // while running allocates nothing).
  std::vector<std::pair<ContactModel, std::unique_ptr<ContactResponse>>> responses;
  const ContactResponse* response = nullptr;

  void chooseResponse()
  {
    if (responses.empty())
    {
      for (const ContactModel model : contactModels())
      {
        responses.emplace_back(model, makeContactResponse(model));
      }
    }
    for (const auto& [model, candidate] : responses)
    {
      response = model == params.model ? candidate.get() : response;
    }
  }
  ContactAreaResult scratch;
  // Sleeping bodies out of Bullet's world (dormant_bodies.h); the dynamic bodies in it; scratch:
  // island tag -> the first body of that island falling asleep this step.
  DormantBodies dormant;
  std::vector<int> awake;
  std::vector<int> group_of_tag;
  // The contacts sleeping bodies slept on, put back when they wake (slept_contacts.h); by body,
  // the bodies falling asleep this step.
  SleptContacts slept_contacts;
  std::vector<char> falling_asleep;
  // This step's proxy-body touches (proxy_touches.h).
  ProxyTouches touches;
  // The push apart of fingers whose areas overlap (overlap_push.h), one per proxy.
  OverlapPush overlap;
  // The soft bodies (soft_body.h), by scene index; per proxy, its velocity (m/s) and the force
  // applied to it (N) before this step's solve: what the solver did to it is the rest of its
  // change of momentum, the soft bodies feel the opposite.
  std::vector<int> soft_bodies;
  std::vector<Eigen::Vector3d> proxy_velocity_before;
  std::vector<Eigen::Vector3d> proxy_force_before;
  double time = 0.0;
  double deepest_penetration = 0.0;
  long steps = 0;
  long rejected_targets = 0;

  void buildBodies()
  {
    const double max_edge = params.walk_edge_per_max_radius * params.contact.max_radius;
    for (const BodyDescription& description : scene.bodies)
    {
      bodies.push_back(makeSceneBody(description, max_edge));
    }
  }

  void buildWorld()
  {
    configuration = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher = std::make_unique<btCollisionDispatcher>(configuration.get());
    dispatcher->setNearCallback(&worldNearCallback);
    registerSphereMeshAlgorithm(dispatcher.get());
    broadphase = std::make_unique<btDbvtBroadphase>();
    solver = std::make_unique<ContactSolver>(params.support_passes, &pads);
    world = std::make_unique<HookedWorld>(dispatcher.get(), broadphase.get(), solver.get(), configuration.get());
    world->setGravity(toBullet(params.gravity));
    world->getSolverInfo().m_numIterations = params.solver_iterations;
    // Bullet stops iterating once an iteration's largest velocity correction (squared) is below
    // this.
    world->getSolverInfo().m_leastSquaresResidualThreshold = params.solver_tolerance * params.solver_tolerance;
    // Two friction directions per point: an area resists twisting only if each of its points
    // resists sliding in every tangential direction (Bullet's default is one direction, along
    // the sliding velocity).
    world->getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
    world->after_collision = [this]() { injectContactAreas(); };
    world->sleep_time = params.sleep.time;
    // Sleeping bodies keep their bounding boxes (static ones never move).
    world->setForceUpdateAllAabbs(false);
    injector = std::make_unique<SubGodObjectInjector>(dispatcher.get());
    chooseResponse();
    jointed.assign(bodies.size(), 0);
    for (const JointDescription& joint : scene.joints)
    {
      jointed[joint.child] = 1;
      if (joint.parent >= 0 && !scene.bodies[joint.parent].is_static)
      {
        jointed[joint.parent] = 1;  // a static parent (a cabinet) is never simulated anyway
      }
    }
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      Body& body = bodies[i];
      buildRigidBody(scene.bodies[i], static_cast<int>(i), &body);
      if (body.soft)
      {
        makeSoftVolume(scene.bodies[i], params.time_step, params.gravity, &body);
      }
      prepareSleep(body.rigid.get());
      world->addRigidBody(body.rigid.get(), kBodyGroup, btBroadphaseProxy::AllFilter);
      body.previous_velocity = Eigen::Vector3d::Zero();
      body.net_force = Eigen::Vector3d::Zero();
    }
    buildJoints();
    Eigen::AlignedBox3d scene_box;
    for (const Body& body : bodies)
    {
      btVector3 min;
      btVector3 max;
      body.rigid->getAabb(min, max);
      scene_box.extend(toEigen(min)).extend(toEigen(max));
    }
    bounds = worldBounds(scene_box, params.world_margin);
    placeSoftSupports();
    for (std::size_t i = 0; i < proxies.size(); ++i)
    {
      addProxyToWorld(static_cast<int>(i));
    }
    dormant.reset(static_cast<int>(bodies.size()));
    awake.clear();
    awake.reserve(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      if (!scene.bodies[i].is_static)
      {
        awake.push_back(static_cast<int>(i));
      }
    }
    soft_bodies.clear();
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      if (bodies[i].soft)
      {
        soft_bodies.push_back(static_cast<int>(i));
      }
    }
    sizeProxyScratch();
    slept_contacts.reset(static_cast<int>(bodies.size()));
    falling_asleep.assign(bodies.size(), 0);
  }

  // Back into Bullet's world, at rest where it slept. Woken by a proxy or a wrench, it stays awake
  // for at least sleep_time (its timer restarts); woken by a moving neighbour, it keeps the timer
  // of a body placed at rest: if the neighbour does not reach it, it sleeps again within a few
  // steps.
  void addAwake(int index, bool by_proxy)
  {
    btRigidBody* rigid = bodies[index].rigid.get();
    world->addRigidBody(rigid, kBodyGroup, btBroadphaseProxy::AllFilter);
    rigid->activate(true);
    if (!by_proxy)
    {
      prepareSleep(rigid);
    }
    awake.push_back(index);
    slept_contacts.woke(index);
  }

  // Before the step's collision detection: every dormant group within Bullet's contact threshold
  // of a proxy or of an awake body (those it wakes included) wakes, so that its contacts are
  // found in this step.
  void wakeNearAwake()
  {
    // Broadphase boxes include Bullet's contact threshold already (btCollisionWorld::updateAabbs).
    const btVector3 margin(0.0, 0.0, 0.0);
    const auto by_proxy = [this](int index) { addAwake(index, true); };
    const auto by_body = [this](int index) { addAwake(index, false); };
    for (const Proxy& proxy : proxies)
    {
      const btBroadphaseProxy* handle = proxy.rigid->getBroadphaseHandle();
      dormant.wakeOverlapping(handle->m_aabbMin - margin, handle->m_aabbMax + margin, by_proxy);
    }
    // Awake bodies moving faster than they may sleep (one settling slower does not reach a
    // neighbour before it sleeps itself).
    const double speed2 = params.sleep.speed * params.sleep.speed;
    const double angular2 = params.sleep.angular_speed * params.sleep.angular_speed;
    for (std::size_t k = 0; k < awake.size(); ++k)
    {
      const btRigidBody* rigid = bodies[awake[k]].rigid.get();
      if (rigid->isActive() &&
          (rigid->getLinearVelocity().length2() >= speed2 || rigid->getAngularVelocity().length2() >= angular2))
      {
        const btBroadphaseProxy* handle = rigid->getBroadphaseHandle();
        dormant.wakeOverlapping(handle->m_aabbMin - margin, handle->m_aabbMax + margin, by_body);
      }
    }
  }

  // After the step: the islands that fell asleep leave Bullet's world, each as one group.
  void removeSleepers()
  {
    bool any = false;
    for (const int index : awake)
    {
      const bool sleeping = bodies[index].rigid->getActivationState() == ISLAND_SLEEPING;
      falling_asleep[index] = sleeping ? 1 : 0;
      any = any || sleeping;
    }
    if (!any)
    {
      return;
    }
    slept_contacts.save(dispatcher.get(), falling_asleep);
    for (std::size_t k = 0; k < awake.size();)
    {
      const int index = awake[k];
      btRigidBody* rigid = bodies[index].rigid.get();
      if (rigid->getActivationState() != ISLAND_SLEEPING)
      {
        ++k;
        continue;
      }
      const int tag = rigid->getIslandTag();
      const bool tagged = tag >= 0 && tag < static_cast<int>(group_of_tag.size());
      btVector3 min;
      btVector3 max;
      rigid->getAabb(min, max);
      world->removeRigidBody(rigid);
      dormant.add(index, min, max, tagged ? group_of_tag[tag] : -1);
      if (tagged && group_of_tag[tag] < 0)
      {
        group_of_tag[tag] = index;
      }
      bodies[index].net_force.setZero();
      falling_asleep[index] = 0;
      awake[k] = awake.back();
      awake.pop_back();
    }
    std::fill(group_of_tag.begin(), group_of_tag.end(), -1);
  }

  // After the step: an awake body outside the world's bounds goes back to its start (world_bounds.h).
  // The resting soft bodies' supports end where the static bodies under them do
  // (soft_body.h setSoftSupportExtent).
  void placeSoftSupports()
  {
    std::vector<Eigen::AlignedBox3d> static_boxes;
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      if (scene.bodies[i].is_static && !bodies[i].soft)
      {
        btVector3 min;
        btVector3 max;
        bodies[i].rigid->getAabb(min, max);
        static_boxes.emplace_back(toEigen(min), toEigen(max));
      }
    }
    for (Body& body : bodies)
    {
      if (body.soft)
      {
        setSoftSupportExtent(static_boxes, &body);
      }
    }
  }

  void catchEscapees()
  {
    // A resting soft body pushed off its support falls; past the bounds it is put back where it
    // started, settled, as a reset puts it.
    for (const int index : soft_bodies)
    {
      Body& body = bodies[index];
      if (body.soft->resting && outsideBounds(bounds, toEigen(body.rigid->getWorldTransform().getOrigin())))
      {
        resetSoftVolume(world.get(), &body);
        countLeftWorld(&body);
      }
    }
    for (const int index : awake)
    {
      Body& body = bodies[index];
      const btTransform start = toBullet(scene.bodies[index].pose * body.com_in_link);
      if (catchIfOutside(bounds, start, body.rigid.get(), world.get()))
      {
        prepareSleep(body.rigid.get());
        body.net_force.setZero();
        countLeftWorld(&body);
      }
    }
  }

  // A body caught past the bounds (BodyState::left_world), now.
  void countLeftWorld(Body* body) const
  {
    ++body->left_world;
    body->left_world_at = time;
  }

  // A dynamic body starts with a full sleep timer, less the time a free fall from rest takes to
  // exceed twice the sleep speed: placed at rest it sleeps within that time (its island with it),
  // placed in the air it falls.
  void prepareSleep(btRigidBody* rigid) const
  {
    const SleepParams& sleep = params.sleep;
    if (sleep.time <= 0.0 || jointed[rigid->getUserIndex2()])
    {
      rigid->setActivationState(DISABLE_DEACTIVATION);
      return;
    }
    rigid->setSleepingThresholds(sleep.speed, sleep.angular_speed);
    const double gravity = params.gravity.norm();
    const double settle = gravity > 0.0 ? 2.0 * sleep.speed / gravity : 0.0;
    rigid->setDeactivationTime(std::max(0.0, sleep.time - settle));
  }

  // Wakes every dynamic body (a parameter or model change: what rests under the old contact may
  // not under the new one), with the timer a body placed at rest starts with: what still rests
  // sleeps again within a few steps.
  void wakeAll()
  {
    dormant.wakeAll([this](int index) { addAwake(index, false); });
    for (const int index : awake)
    {
      bodies[index].rigid->activate(true);
      prepareSleep(bodies[index].rigid.get());
    }
  }

  // The per-proxy and per-island scratch, sized for the proxies and bodies there are now.
  void sizeProxyScratch()
  {
    proxy_velocity_before.assign(proxies.size(), Eigen::Vector3d::Zero());
    proxy_force_before.assign(proxies.size(), Eigen::Vector3d::Zero());
    group_of_tag.assign(bodies.size() + proxies.size(), -1);
  }

  void addProxyToWorld(int index)
  {
    Proxy& proxy = proxies[index];
    buildProxyBody(params.coupling, params.pad, index, static_cast<int>(bodies.size()), &proxy);
    world->addRigidBody(proxy.rigid.get(), kProxyGroup, kBodyGroup);
    proxy.rigid->setGravity(btVector3(0, 0, 0));
    sizeProxyScratch();
    response->configureProxy(params, proxy.rigid.get());
    overlap.resize(static_cast<int>(proxies.size()));
  }

  // The body the proxy's sphere at `position` would start deepest in, and how deep (m): -1 when
  // it overlaps none. Every body is probed, awake or dormant (contactPairTest needs no broadphase).
  std::pair<int, double> deepestOverlap(const Eigen::Vector3d& position)
  {
    btSphereShape sphere(static_cast<btScalar>(params.coupling.proxy_radius));
    btCollisionObject probe;
    probe.setCollisionShape(&sphere);
    probe.setWorldTransform(btTransform(btQuaternion::getIdentity(), toBullet(position)));
    probe.setUserIndex(kKindProxy);  // tested as a finger: against a body's true surface (a cup's hollow)
    std::pair<int, double> deepest(-1, 0.0);
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      const double depth = deepestPenetrationAsCollided(world.get(), &probe, bodies[i].rigid.get());
      if (depth > deepest.second)
      {
        deepest = {static_cast<int>(i), depth};
      }
    }
    return deepest;
  }

  Eigen::Isometry3d geometryToWorld(const Body& body) const
  {
    return toEigen(body.rigid->getWorldTransform()) * body.geometry_in_com;
  }

  // Between collision detection and the solver: contact areas for every (proxy, body) pair in
  // contact; with kGodFinger their sub-god-objects join the solver.
  void injectContactAreas()
  {
    slept_contacts.restore(dispatcher.get());
    injector->release();
    pads.clear();
    touches.clear();
    for (Proxy& proxy : proxies)
    {
      proxy.state.contact_count = 0;
    }
    const int manifold_count = dispatcher->getNumManifolds();
    deepest_penetration = 0.0;
    for (int m = 0; m < manifold_count; ++m)
    {
      btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      if (!manifold->getBody0()->isActive() && !manifold->getBody1()->isActive())
      {
        continue;  // a sleeping body on a static or sleeping one: not detected this step
      }
      for (int p = 0; p < manifold->getNumContacts(); ++p)
      {
        deepest_penetration = std::max(deepest_penetration, -double(manifold->getContactPoint(p).getDistance()));
      }
      const btCollisionObject* a = manifold->getBody0();
      const btCollisionObject* b = manifold->getBody1();
      const bool proxy_is_a = a->getUserIndex() == kKindProxy && b->getUserIndex() == kKindBody;
      const bool proxy_is_b = b->getUserIndex() == kKindProxy && a->getUserIndex() == kKindBody;
      if (!proxy_is_a && !proxy_is_b)
      {
        continue;
      }
      int deepest = -1;
      for (int p = 0; p < manifold->getNumContacts(); ++p)
      {
        // Touching, not only penetrating: the solver keeps a resting contact at a distance
        // of about zero on either side, and skipping the positive side would make the
        // contact area flicker from one step to the next.
        if (manifold->getContactPoint(p).getDistance() <= manifold->getContactBreakingThreshold() &&
            (deepest < 0 ||
             manifold->getContactPoint(p).getDistance() < manifold->getContactPoint(deepest).getDistance()))
        {
          deepest = p;
        }
      }
      if (deepest < 0)
      {
        continue;
      }
      touches.add({manifold, deepest, proxy_is_a, (proxy_is_a ? a : b)->getUserIndex2(),
                   (proxy_is_a ? b : a)->getUserIndex2()});
    }
    // In the dispatcher's order (a scene where each finger touches each body once is unchanged
    // bit for bit); a touch that another, deeper touch of the same finger and body covers is
    // no area of its own, and its manifold leaves the solver for this step.
    for (std::size_t i = 0; i < touches.size(); ++i)
    {
      const ProxyTouch& touch = touches[i];
      btManifoldPoint& contact = touch.manifold->getContactPoint(touch.point);
      if (touches.coveredByDeeperTouch(i, params.contact.max_radius))
      {
        touch.manifold->clearManifold();
        continue;
      }
      addContactArea(touch.manifold, contact, touch.proxy_is_a, touch.proxy, touch.body);
    }
  }

  void addContactArea(btPersistentManifold* manifold, btManifoldPoint& contact, bool proxy_is_a, int proxy_index,
                      int body_index)
  {
    Proxy& proxy = proxies[proxy_index];
    InterfaceState& state = proxy.state;
    if (state.contact_count >= InterfaceState::kMaxContacts)
    {
      return;
    }
    const Body& body = bodies[body_index];
    // Bullet's normal points from B to A: out of the object when the object is B.
    const Eigen::Vector3d normal_world = (proxy_is_a ? 1.0 : -1.0) * toEigen(contact.m_normalWorldOnB);
    Eigen::Vector3d point_world = toEigen(proxy_is_a ? contact.getPositionWorldOnB() : contact.getPositionWorldOnA());
    const Eigen::Isometry3d to_world = geometryToWorld(body);
    const Eigen::Isometry3d to_local = to_world.inverse();
    ContactQuery query;
    if (body.primitive)
    {
      query.location.point = to_local * point_world;
    }
    else
    {
      query.location = body.locator->closest(to_local * point_world);
    }
    query.normal = to_local.linear() * normal_world;
    query.depth = -contact.getDistance();
    query.coupling = to_local.linear() * (proxy.target - toEigen(proxy.rigid->getWorldTransform().getOrigin()));
    query.reference_tangent = proxy.reference_tangents[body_index];
    // An oriented finger: the pad on its pulp (oriented_finger.h) scales r_max (so Eq. 1's r)
    // and moves the area's centre, and the solver's true contact with it, along the surface.
    const ContactParams* contact_params = &params.contact;
    ContactParams pulp_params;
    if (proxy.orientation.oriented)
    {
      const PulpContact pulp = pulpContact(proxy.orientation.proxy, normal_world, params.finger);
      pulp_params = params.contact;
      pulp_params.max_radius *= pulp.radius_scale;
      contact_params = &pulp_params;
      point_world += pulp.offset;
      contact.m_positionWorldOnA += toBullet(pulp.offset);
      contact.m_positionWorldOnB += toBullet(pulp.offset);
      if (body.primitive)
      {
        query.location.point = to_local * point_world;
      }
      else
      {
        query.location = body.locator->closest(to_local * point_world);
      }
    }
    if (body.primitive)
    {
      computeContactArea(*body.primitive, query, *contact_params, &scratch);
    }
    else
    {
      computeContactArea(*body.walk, query, *contact_params, &scratch);
    }
    if (!scratch.valid)
    {
      return;
    }
    proxy.reference_tangents[body_index] = scratch.first_tangent;
    // The object's rotation relative to the pad since the contact began.
    const Eigen::Matrix3d object_to_pad =
        objectTurnSinceContact(to_world, steps, proxy.orientation.oriented, &proxy.pads[body_index]);

    WorldContactArea& area = state.contacts[state.contact_count++];
    area.body = body_index;
    area.point = point_world;
    area.normal = normal_world;
    area.depth = query.depth;
    area.radius = scratch.radius;
    area.feature = query.location.feature;
    area.sub_god_object_count = 0;
    std::array<int, ContactParams::kMaxSubGodObjects> radial_index;
    for (int i = 0; i < scratch.count; ++i)
    {
      const SubGodObject& sgo = scratch.sub_god_objects[i];
      if (sgo.dropped() || (sgo.position - query.location.point).norm() < kCoincident)
      {
        continue;
      }
      radial_index[area.sub_god_object_count] = i;
      area.positions[area.sub_god_object_count++] = to_world * sgo.position;
    }
    AreaSolverInput area_contact;
    area_contact.manifold = manifold;
    area_contact.contact = &contact;
    area_contact.proxy_is_a = proxy_is_a;
    area_contact.proxy_index = proxy_index;
    area_contact.body_index = body_index;
    area_contact.point_world = point_world;
    area_contact.normal_world = normal_world;
    area_contact.object_to_pad = object_to_pad;
    area_contact.area = &area;
    area_contact.radial_index = radial_index.data();
    response->respond(params, area_contact, &proxy, steps, {injector.get(), &pads});
  }

  // An oriented finger's hand feels what its pads' rows gave the objects, turned back on it
  // (pad_state.h: the pad turns with the finger, so what it holds resists the finger's turn).
  void feelPadTorques(double dt)
  {
    for (Proxy& proxy : proxies)
    {
      if (!proxy.orientation.oriented)
      {
        continue;
      }
      for (const PadState& pad : proxy.pads)
      {
        if (pad.linear.step == steps)
        {
          proxy.state.user_torque -= pad.object_side * pad.torque_impulse / dt;
        }
      }
    }
  }

  // The oriented proxy's body cannot turn through what its tip touched at the last step
  // (oriented_finger.h, limitFingerByContacts).
  static void limitByLastContacts(Proxy* proxy)
  {
    std::array<Eigen::Vector3d, InterfaceState::kMaxContacts> normals;
    const int count = proxy->state.contact_count;
    for (int c = 0; c < count; ++c)
    {
      normals[c] = proxy->state.contacts[c].normal;
    }
    limitFingerByContacts(normals.data(), count, &proxy->orientation);
  }

  void step()
  {
    const double dt = params.time_step;
    for (Proxy& proxy : proxies)
    {
      const Eigen::Vector3d position = toEigen(proxy.rigid->getWorldTransform().getOrigin());
      const Eigen::Vector3d velocity = toEigen(proxy.rigid->getLinearVelocity());
      const Eigen::Vector3d target_velocity = (proxy.target - proxy.previous_target) / dt;
      const CouplingForce coupled = couplingForce(proxy.coupling, proxy.target, target_velocity, position, velocity);
      const Eigen::Vector3d& force = coupled.on_proxy;
      proxy.state.saturated = coupled.saturated;
      proxy.state.user_force = -force;
      if (proxy.let_go_steps > 0)
      {
        // Letting go of a removed object: the proxy follows a target that reaches the hand
        // over let_go_time, the hand feels the coupling to its own target (above).
        const double left = double(proxy.let_go_steps--) / proxy.let_go_total;
        const Eigen::Vector3d pull = proxy.target + left * proxy.let_go_offset;
        proxy.rigid->applyCentralForce(
            toBullet(couplingForce(proxy.coupling, pull, target_velocity, position, velocity).on_proxy));
      }
      else
      {
        proxy.rigid->applyCentralForce(toBullet(force));
      }
      proxy.state.interface_position = proxy.target;
      proxy.previous_target = proxy.target;
      if (proxy.orientation.oriented)
      {
        proxy.state.interface_orientation = proxy.orientation.target;
        proxy.state.user_torque = -stepFingerOrientation(params.finger, dt, &proxy.orientation);
        limitByLastContacts(&proxy);
        proxy.state.proxy_orientation = proxy.orientation.proxy;
      }
    }
    for (std::size_t i = 0; i < proxies.size(); ++i)
    {
      const Eigen::Vector3d& push = overlap.push(static_cast<int>(i));
      if (!push.isZero(0.0))
      {
        proxies[i].rigid->applyCentralForce(toBullet(push));
      }
    }
    wakeNearAwake();
    for (const int index : awake)
    {
      bodies[index].previous_velocity = toEigen(bodies[index].rigid->getLinearVelocity());
    }
    resistJoints();
    solver->resetCounts();
    if (!soft_bodies.empty())
    {
      for (std::size_t i = 0; i < proxies.size(); ++i)
      {
        proxy_velocity_before[i] = toEigen(proxies[i].rigid->getLinearVelocity());
        proxy_force_before[i] = toEigen(proxies[i].rigid->getTotalForce());
      }
    }
    world->stepSimulation(dt, 0);
    injector->recordImpulses(&proxies, steps);
    pads.recordImpulses(steps);
    feelPadTorques(dt);
    time = (steps + 1) * dt;
    ++steps;
    for (const int index : awake)
    {
      Body& body = bodies[index];
      body.net_force =
          scene.bodies[index].mass * (toEigen(body.rigid->getLinearVelocity()) - body.previous_velocity) / dt;
    }
    stepSoftBodies();
    removeSleepers();
    catchEscapees();
    for (Proxy& proxy : proxies)
    {
      proxy.state.proxy_position = toEigen(proxy.rigid->getWorldTransform().getOrigin());
      proxy.state.proxy_velocity = toEigen(proxy.rigid->getLinearVelocity());
    }
    overlap.update(params, &proxies);
  }

  // The fingers' friction anchors on soft body `index` (material points of it, kept in its
  // centre-of-mass frame: WarmStart::anchor_on_object) go where its surface took them in the
  // step it just made (soft_body.h materialMotion): the anchors of this step, the only ones the
  // next step may hold (pad_constraints.cpp, sub_god_object_injection.cpp: step - 1). Left in
  // place, a glued body's anchor stays where the surface was: the friction rows then see the
  // material slide under the pad by the dimple's own motion.
  void carryFrictionAnchors(int index)
  {
    const Body& body = bodies[index];
    const auto carry = [&](WarmStart* warm)
    {
      if (warm->step == steps - 1)
      {
        warm->anchor_on_object += materialMotion(body, warm->anchor_on_object);
      }
    };
    for (Proxy& proxy : proxies)
    {
      carry(&proxy.pads[index].linear);
      for (WarmStart& warm : proxy.warm_starts[index])
      {
        carry(&warm);
      }
    }
  }

  // After the solve: each finger's contact force loads the soft bodies it touches, and they step.
  // The force the solver put on proxy i is m dv/dt minus what was applied to it; a finger touching
  // one body gives it all (reversed), one touching several gives each soft body the part along
  // that contact's normal that presses into it.
  void stepSoftBodies()
  {
    if (soft_bodies.empty())
    {
      return;
    }
    const double dt = params.time_step;
    const bool as_pad = params.model != ContactModel::kGodObject;
    for (std::size_t i = 0; i < proxies.size(); ++i)
    {
      proxies[i].state.contact_stiffness = std::numeric_limits<double>::infinity();
      const Proxy& proxy = proxies[i];
      const InterfaceState& state = proxy.state;
      const Eigen::Vector3d on_proxy =
          params.coupling.proxy_mass * (toEigen(proxy.rigid->getLinearVelocity()) - proxy_velocity_before[i]) / dt -
          proxy_force_before[i];
      bool loaded_soft = false;
      for (int c = 0; c < state.contact_count; ++c)
      {
        const WorldContactArea& area = state.contacts[c];
        SoftVolume* volume = bodies[area.body].soft.get();
        if (volume == nullptr)
        {
          continue;
        }
        const double pressing = on_proxy.dot(area.normal);  // > 0: the body pushes the proxy out
        const Eigen::Vector3d measured = state.contact_count == 1
                                             ? Eigen::Vector3d(-on_proxy)
                                             : Eigen::Vector3d(-std::max(0.0, pressing) * area.normal);
        // One contact: under-relaxed (soft_body.h, kSoftLoadRelaxation), from the last load on the
        // same body (none on another).
        Eigen::Vector3d on_body = measured;
        if (state.contact_count == 1 && measured.allFinite())
        {
          Proxy& loading = proxies[i];
          if (loading.soft_load_body != area.body)
          {
            loading.soft_load.setZero();
          }
          on_body = loading.soft_load + kSoftLoadRelaxation * (measured - loading.soft_load);
          loading.soft_load = on_body;
          loading.soft_load_body = area.body;
          loaded_soft = true;
        }
        if (on_body.allFinite() && !on_body.isZero(0.0))
        {
          addSoftContactLoad(area, on_body, as_pad, volume);
          // Before this step's motion: the sink that this force (the last step's, reversed) made.
          proxies[i].state.contact_stiffness = softContactStiffness(area, on_body, volume);
          proxies[i].state.contact_normal = area.normal;
        }
      }
      if (!loaded_soft)
      {
        proxies[i].soft_load.setZero();
        proxies[i].soft_load_body = -1;
      }
    }
    bool moved = false;
    for (const int index : soft_bodies)
    {
      if (stepSoftVolume(world.get(), &bodies[index]))
      {
        moved = true;
        carryFrictionAnchors(index);
      }
    }
    if (!moved)
    {
      return;
    }
    // A manifold keeps its points where they were found on a body that does not move, refreshed
    // by the bodies' transforms only: on a moved surface they would be points of the old one (a
    // rim that holds the proxy above the dimple). The next detection finds them again.
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m)
    {
      btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      const btCollisionObject* pair[] = {manifold->getBody0(), manifold->getBody1()};
      for (const btCollisionObject* object : pair)
      {
        if (object->getUserIndex() == kKindBody && bodies[object->getUserIndex2()].soft)
        {
          manifold->clearManifold();
          break;
        }
      }
    }
  }

  // The world around `next` (addObject, removeObject): old_of_new[i] is the body of now that
  // becomes next's body i, or -1 for a new one (made here). Bodies and proxies keep their
  // motion; proxies that pressed a body that goes let go (WorldParams::let_go_time). InputError
  // before anything changes when a new body cannot be made.
  // `prepared`: the new bodies already made (in next's order), or null to make them here.
  void changeScene(SceneDescription next, const std::vector<int>& old_of_new, std::vector<Body>* prepared = nullptr)
  {
    const double max_edge = params.walk_edge_per_max_radius * params.contact.max_radius;
    std::vector<Body> made(next.bodies.size());
    std::size_t taken = 0;
    for (std::size_t i = 0; i < next.bodies.size(); ++i)
    {
      if (old_of_new[i] < 0)
      {
        made[i] = prepared != nullptr ? std::move((*prepared)[taken++]) : makeSceneBody(next.bodies[i], max_edge);
      }
    }
    std::vector<char> kept(bodies.size(), 0);
    for (const int old : old_of_new)
    {
      if (old >= 0)
      {
        kept[old] = 1;
      }
    }
    struct Motion
    {
      btTransform transform;
      btVector3 linear;
      btVector3 angular;
    };
    std::vector<Motion> motions;
    for (const Body& body : bodies)
    {
      motions.push_back(
          {body.rigid->getWorldTransform(), body.rigid->getLinearVelocity(), body.rigid->getAngularVelocity()});
    }
    std::vector<Proxy> saved;
    std::vector<btVector3> proxy_velocities;
    for (Proxy& proxy : proxies)
    {
      Proxy copy;
      copy.initial = proxy.initial;
      copy.target = proxy.target;
      copy.previous_target = proxy.previous_target;
      copy.orientation = proxy.orientation;
      copy.state = proxy.state;
      copy.let_go_offset = proxy.let_go_offset;
      copy.let_go_steps = proxy.let_go_steps;
      copy.let_go_total = proxy.let_go_total;
      const Eigen::Vector3d position = toEigen(proxy.rigid->getWorldTransform().getOrigin());
      for (int c = 0; c < proxy.state.contact_count; ++c)
      {
        const int body = proxy.state.contacts[c].body;
        if (!kept[body] && params.let_go_time > 0.0)
        {
          copy.let_go_total = std::max(1, int(std::lround(params.let_go_time / params.time_step)));
          copy.let_go_steps = copy.let_go_total;
          copy.let_go_offset = position - proxy.target;
        }
      }
      proxy_velocities.push_back(proxy.rigid->getLinearVelocity());
      proxy.initial = position;  // buildWorld puts it there
      saved.push_back(std::move(copy));
    }
    const OverlapPush saved_overlap = overlap;  // buildWorld restarts it; the pushes go on
    teardownWorld();
    for (std::size_t i = 0; i < next.bodies.size(); ++i)
    {
      if (old_of_new[i] >= 0)
      {
        made[i] = std::move(bodies[old_of_new[i]]);
      }
    }
    bodies = std::move(made);
    scene = std::move(next);
    shared_scene = std::make_shared<const SceneDescription>(scene);
    buildWorld();
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      if (old_of_new[i] < 0 || scene.bodies[i].is_static)
      {
        continue;
      }
      const Motion& motion = motions[old_of_new[i]];
      btRigidBody* rigid = bodies[i].rigid.get();
      rigid->setWorldTransform(motion.transform);
      rigid->setInterpolationWorldTransform(motion.transform);
      rigid->setLinearVelocity(motion.linear);
      rigid->setAngularVelocity(motion.angular);
      rigid->setInterpolationLinearVelocity(motion.linear);
      rigid->setInterpolationAngularVelocity(motion.angular);
      world->updateSingleAabb(rigid);
    }
    for (std::size_t i = 0; i < proxies.size(); ++i)
    {
      Proxy& proxy = proxies[i];
      const Proxy& before = saved[i];
      proxy.initial = before.initial;
      proxy.target = before.target;
      proxy.previous_target = before.previous_target;
      proxy.orientation = before.orientation;
      proxy.state = before.state;
      // Its contacts were numbered in the old scene: none until the next step finds them.
      proxy.state.contact_count = 0;
      proxy.let_go_offset = before.let_go_offset;
      proxy.let_go_steps = before.let_go_steps;
      proxy.let_go_total = before.let_go_total;
      proxy.rigid->setLinearVelocity(proxy_velocities[i]);
      proxy.rigid->setInterpolationLinearVelocity(proxy_velocities[i]);
    }
    overlap = saved_overlap;
  }

  void teardownWorld()
  {
    if (!world)
    {
      return;
    }
    injector->release();
    pads.clear();
    for (const std::unique_ptr<btTypedConstraint>& joint : joints)
    {
      world->removeConstraint(joint.get());
    }
    joints.clear();
    for (Proxy& proxy : proxies)
    {
      world->removeRigidBody(proxy.rigid.get());
      proxy.rigid.reset();
      proxy.shape.reset();
    }
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      Body& body = bodies[i];
      if (!dormant.dormant(static_cast<int>(i)))
      {
        world->removeRigidBody(body.rigid.get());
      }
      body.rigid.reset();
      body.placed.reset();
    }
    dormant.reset(static_cast<int>(bodies.size()));
    world.reset();
    solver.reset();
    broadphase.reset();
    dispatcher.reset();
    configuration.reset();
  }
};

GodFingerWorld::GodFingerWorld(const SceneDescription& scene, const WorldParams& params) : impl_(new Impl)
{
  validateOrThrow(params);
  checkSceneFits(scene, params.walk_edge_per_max_radius * params.contact.max_radius);
  checkJoints(scene);
  useFingerRollingFriction();
  impl_->params = params;
  impl_->scene = scene;
  impl_->shared_scene = std::make_shared<const SceneDescription>(scene);
  impl_->buildBodies();
  impl_->buildWorld();
  impl_->start_warnings = startOverlaps(impl_->world.get(), impl_->bodies, impl_->scene);
}

const std::vector<std::string>& GodFingerWorld::startWarnings() const
{
  return impl_->start_warnings;
}

GodFingerWorld::~GodFingerWorld()
{
  impl_->teardownWorld();
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
  const std::pair<int, double> overlap = impl_->deepestOverlap(position);
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
  impl_->addProxyToWorld(index);
  return index;
}

void GodFingerWorld::setInterfaceTarget(int interface, const Eigen::Vector3d& position)
{
  if (!position.allFinite())
  {
    ++impl_->rejected_targets;
    return;
  }
  impl_->proxies.at(interface).target = position;
}

void GodFingerWorld::setInterfaceTarget(int interface, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity)
{
  if (!position.allFinite() || !velocity.allFinite())
  {
    ++impl_->rejected_targets;
    return;
  }
  auto& proxy = impl_->proxies.at(interface);
  proxy.target = position;
  proxy.previous_target = position - velocity * impl_->params.time_step;
}

void GodFingerWorld::setInterfaceTarget(int interface, const Eigen::Vector3d& position,
                                        const Eigen::Quaterniond& orientation)
{
  if (!position.allFinite() || !usableOrientation(orientation))
  {
    ++impl_->rejected_targets;
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

void GodFingerWorld::step()
{
  impl_->step();
}

void GodFingerWorld::reset()
{
  // Rebuilding Bullet's objects (not the shapes or walk meshes) is the only way to clear
  // every cache (broadphase pairs, manifolds, warm starts), so that a reset run repeats the
  // first one bit for bit.
  impl_->teardownWorld();
  impl_->time = 0.0;
  impl_->steps = 0;
  for (const int index : impl_->soft_bodies)
  {
    resetSoftVolume(nullptr, &impl_->bodies[index]);
  }
  impl_->buildWorld();
}

bool GodFingerWorld::carryFreeProxy(int interface, const Eigen::Vector3d& by)
{
  Impl& impl = *impl_;
  Proxy& proxy = impl.proxies.at(interface);
  const btBroadphaseProxy* handle = proxy.rigid->getBroadphaseHandle();
  if (!carriable(proxy, by) || handle == nullptr)
  {
    return false;
  }
  // Sleeping bodies are out of Bullet's world: those in the swept box wake first (as a proxy
  // near them would wake them in the step), so that the sweep sees them.
  const btVector3 shift = toBullet(by);
  btVector3 low = handle->m_aabbMin;
  btVector3 high = handle->m_aabbMax;
  low.setMin(handle->m_aabbMin + shift);
  high.setMax(handle->m_aabbMax + shift);
  impl.dormant.wakeOverlapping(low, high, [&impl](int index) { impl.addAwake(index, true); });
  return internal::carryFreeProxy(impl.world.get(), by, &proxy);
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
  Impl& impl = *impl_;
  const SceneDescription& object = prepared->impl_->object;
  if (object.bodies.empty() || prepared->impl_->bodies.size() != object.bodies.size())
  {
    throw InputError("object '" + object.name + "' has no body (or was added already)");
  }
  SceneDescription next = impl.scene;
  std::vector<int> old_of_new(next.bodies.size());
  for (std::size_t i = 0; i < old_of_new.size(); ++i)
  {
    old_of_new[i] = static_cast<int>(i);
  }
  const int first = static_cast<int>(next.bodies.size());
  for (const BodyDescription& body : object.bodies)
  {
    if (next.find(body.name) >= 0)
    {
      throw InputError("the scene has a body named '" + body.name + "' already (give the object another name)");
    }
    next.bodies.push_back(body);
    old_of_new.push_back(-1);
  }
  for (JointDescription joint : object.joints)
  {
    for (const JointDescription& existing : next.joints)
    {
      if (existing.name == joint.name)
      {
        throw InputError("the scene has a joint named '" + joint.name + "' already (give the object a name)");
      }
    }
    joint.child += first;
    joint.parent = joint.parent < 0 ? -1 : joint.parent + first;
    next.joints.push_back(joint);
  }
  const double max_edge = impl.params.walk_edge_per_max_radius * impl.params.contact.max_radius;
  checkSceneFits(next, max_edge);
  checkJoints(next);
  next.warnings.insert(next.warnings.end(), object.warnings.begin(), object.warnings.end());
  // Made for another walk edge (the contact radius changed since): made again here.
  const bool usable = prepared->impl_->max_edge == max_edge;
  impl.changeScene(std::move(next), old_of_new, usable ? &prepared->impl_->bodies : nullptr);
  prepared->impl_->bodies.clear();
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < impl.proxies.size(); ++i)
  {
    const std::pair<int, double> inside = impl.deepestOverlap(impl.proxies[i].state.proxy_position);
    if (inside.first >= first && inside.second > kStartOverlapDepth)
    {
      warnings.push_back("finger " + std::to_string(i) + " starts " + std::to_string(inside.second) + " m inside '" +
                         impl.scene.bodies[inside.first].name +
                         "': the solver pushes its proxy out (the hand feels it)");
    }
  }
  for (const std::string& line : startOverlaps(impl.world.get(), impl.bodies, impl.scene))
  {
    for (const BodyDescription& body : object.bodies)
    {
      if (line.find("'" + body.name + "'") != std::string::npos)
      {
        warnings.push_back(line);
        break;
      }
    }
  }
  return warnings;
}

int GodFingerWorld::removeObject(const std::string& name)
{
  Impl& impl = *impl_;
  const auto named = [&name](const std::string& body)
  { return body == name || (body.size() > name.size() && body.compare(0, name.size() + 1, name + "/") == 0); };
  SceneDescription next;
  next.name = impl.scene.name;
  next.warnings = impl.scene.warnings;
  std::vector<int> old_of_new;
  std::vector<int> new_of_old(impl.scene.bodies.size(), -1);
  for (std::size_t i = 0; i < impl.scene.bodies.size(); ++i)
  {
    if (!named(impl.scene.bodies[i].name))
    {
      new_of_old[i] = static_cast<int>(next.bodies.size());
      old_of_new.push_back(static_cast<int>(i));
      next.bodies.push_back(impl.scene.bodies[i]);
    }
  }
  const int removed = static_cast<int>(impl.scene.bodies.size() - next.bodies.size());
  if (removed == 0 || name.empty())
  {
    throw InputError("the scene has no body named '" + name + "'");
  }
  for (JointDescription joint : impl.scene.joints)
  {
    if (new_of_old[joint.child] < 0 || (joint.parent >= 0 && new_of_old[joint.parent] < 0))
    {
      continue;  // a joint holding a body that goes goes with it
    }
    joint.child = new_of_old[joint.child];
    joint.parent = joint.parent < 0 ? -1 : new_of_old[joint.parent];
    next.joints.push_back(joint);
  }
  impl.changeScene(std::move(next), old_of_new);
  return removed;
}

void GodFingerWorld::setContactModel(ContactModel model)
{
  impl_->params.model = model;
  impl_->chooseResponse();
  for (Proxy& proxy : impl_->proxies)
  {
    impl_->response->configureProxy(impl_->params, proxy.rigid.get());
  }
  impl_->wakeAll();
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
  if (impl_->dormant.dormant(body))
  {
    impl_->dormant.wakeOverlapping(impl_->bodies[body].rigid->getWorldTransform().getOrigin(),
                                   impl_->bodies[body].rigid->getWorldTransform().getOrigin(),
                                   [this](int index) { impl_->addAwake(index, true); });
  }
  btRigidBody& rigid = *impl_->bodies[body].rigid;
  rigid.activate(true);
  rigid.applyCentralForce(toBullet(force));
  rigid.applyTorque(toBullet(torque));
}

ContactModel GodFingerWorld::contactModel() const
{
  return impl_->params.model;
}

void GodFingerWorld::setContactParams(const ContactParams& params)
{
  validateOrThrow(params);
  impl_->params.contact = params;
  impl_->wakeAll();
}

void GodFingerWorld::setPadSolver(PadSolver solver)
{
  if (solver != PadSolver::kPoints && solver != PadSolver::kConstraint)
  {
    throw InputError("pad solver " + std::to_string(static_cast<int>(solver)) + " is not one of " + padSolverNames());
  }
  impl_->params.pad_solver = solver;
  impl_->wakeAll();
}

const WorldParams& GodFingerWorld::params() const
{
  return impl_->params;
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
  return impl_->bodyState(body);
}

int GodFingerWorld::jointCount() const
{
  return static_cast<int>(impl_->scene.joints.size());
}

JointState GodFingerWorld::jointState(int joint) const
{
  return impl_->jointState(joint);
}

void GodFingerWorld::snapshot(WorldSnapshot* out) const
{
  out->scene = impl_->shared_scene;
  out->time = impl_->time;
  out->steps = impl_->steps;
  out->model = impl_->params.model;
  out->bodies.resize(impl_->bodies.size());
  for (std::size_t i = 0; i < impl_->bodies.size(); ++i)
  {
    out->bodies[i] = bodyState(static_cast<int>(i));
  }
  out->interfaces.resize(impl_->proxies.size());
  for (std::size_t i = 0; i < impl_->proxies.size(); ++i)
  {
    out->interfaces[i] = impl_->proxies[i].state;
  }
  out->soft_surfaces.resize(impl_->soft_bodies.size());
  for (std::size_t i = 0; i < impl_->soft_bodies.size(); ++i)
  {
    const int index = impl_->soft_bodies[i];
    snapshotSoftSurface(impl_->bodies[index], index, &out->soft_surfaces[i]);
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

int GodFingerWorld::awakeBodyCount() const
{
  int awake = 0;
  for (const int index : impl_->awake)
  {
    awake += impl_->bodies[index].rigid->isActive() ? 1 : 0;
  }
  return awake;
}

int GodFingerWorld::solverContactRows() const
{
  return impl_->solver->rows();
}

int GodFingerWorld::solverIterationsUsed() const
{
  return impl_->solver->iterationsUsed();
}

int GodFingerWorld::solverProxyContactPoints() const
{
  return impl_->solver->proxyPoints();
}

double GodFingerWorld::deepestPenetration() const
{
  return impl_->deepest_penetration;
}

double GodFingerWorld::time() const
{
  return impl_->time;
}

long GodFingerWorld::steps() const
{
  return impl_->steps;
}

long GodFingerWorld::rejectedTargets() const
{
  return impl_->rejected_targets;
}
}  // namespace god_finger
