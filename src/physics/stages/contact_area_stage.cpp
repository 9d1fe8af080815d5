#include "stages/contact_area_stage.h"

#include "bullet_helpers.h"
#include "world_core.h"
#include "world_queries.h"

#include "god_finger/contact/primitive_walk.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/physics/oriented_finger.h"
#include "god_finger/support/contract.h"

#include <algorithm>
#include <array>

namespace god_finger::internal
{
namespace
{
// Sub-god-objects closer than this to the contact point (m) duplicate it and are not added.
constexpr double kCoincident = 1e-7;

// The touches of this step, in the dispatcher's order (the deepest point of each proxy-body
// manifold), and the step's deepest penetration.
void collectTouches(WorldCore* core)
{
  btCollisionDispatcher* dispatcher = core->dispatcher.get();
  const int manifold_count = dispatcher->getNumManifolds();
  double deepest_penetration = 0.0;
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
      // Touching, not only penetrating: the solver keeps a resting contact at a distance of
      // about zero on either side, and skipping the positive side would make the contact area
      // flicker from one step to the next.
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
    core->touches.add(
        {manifold, deepest, proxy_is_a, (proxy_is_a ? a : b)->getUserIndex2(), (proxy_is_a ? b : a)->getUserIndex2()});
  }
  core->counters.deepest_penetration = deepest_penetration;
}

// Where Algorithm 1 starts on the body: the located point on its walk mesh (or the point itself
// on an exact primitive), in the geometry frame.
SurfaceLocation locate(const SceneBody& body, const Eigen::Isometry3d& to_local, const Eigen::Vector3d& point_world)
{
  if (body.primitive)
  {
    SurfaceLocation location;
    location.point = to_local * point_world;
    return location;
  }
  return body.locator->closest(to_local * point_world);
}

void addContactArea(WorldCore* core, const ProxyTouch& touch)
{
  Proxy& proxy = core->proxies[touch.proxy];
  InterfaceState& state = proxy.state;
  if (state.contact_count >= InterfaceState::kMaxContacts)
  {
    ++core->counters.dropped_contacts;
    return;
  }
  const WorldParams& params = core->params;
  const int body_index = touch.body;
  GOD_FINGER_EXPECTS(body_index >= 0 && body_index < static_cast<int>(core->bodies.size()) &&
                         proxy.reference_tangents.size() == core->bodies.size() &&
                         proxy.warm_starts.size() == core->bodies.size() && proxy.pads.size() == core->bodies.size(),
                     "a proxy's per-body state has one entry per body of the scene (sizeProxyScratch, remapBodies)");
  const bool proxy_is_a = touch.proxy_is_a;
  btManifoldPoint& contact = touch.manifold->getContactPoint(touch.point);
  const SceneBody& body = core->bodies[body_index];
  // Bullet's normal points from B to A: out of the object when the object is B.
  const Eigen::Vector3d normal_world = (proxy_is_a ? 1.0 : -1.0) * toEigen(contact.m_normalWorldOnB);
  Eigen::Vector3d point_world = toEigen(proxy_is_a ? contact.getPositionWorldOnB() : contact.getPositionWorldOnA());
  const Eigen::Isometry3d to_world = geometryToWorld(body);
  const Eigen::Isometry3d to_local = to_world.inverse();
  ContactQuery query;
  query.location = locate(body, to_local, point_world);
  query.normal = to_local.linear() * normal_world;
  query.depth = -contact.getDistance();
  query.coupling = to_local.linear() * (proxy.target - toEigen(proxy.rigid->getWorldTransform().getOrigin()));
  query.reference_tangent = proxy.reference_tangents[body_index];
  // An oriented finger: the pad on its pulp (oriented_finger.h) scales r_max (so Eq. 1's r) and
  // moves the area's centre, and the solver's true contact with it, along the surface.
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
    query.location = locate(body, to_local, point_world);
  }
  ContactAreaResult& scratch = core->scratch;
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
      objectTurnSinceContact(to_world, core->steps, proxy.orientation.oriented, &proxy.pads[body_index]);

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
  area_contact.manifold = touch.manifold;
  area_contact.contact = &contact;
  area_contact.proxy_is_a = proxy_is_a;
  area_contact.proxy_index = touch.proxy;
  area_contact.body_index = body_index;
  area_contact.point_world = point_world;
  area_contact.normal_world = normal_world;
  area_contact.object_to_pad = object_to_pad;
  area_contact.area = &area;
  area_contact.radial_index = radial_index.data();
  core->response->respond(params, area_contact, &proxy, core->steps, {core->injector.get(), &core->pads});
}
}  // namespace

void computeContactAreas(WorldCore* core)
{
  core->sleep.slept_contacts.restore(core->dispatcher.get());
  core->injector->release();
  core->pads.clear();
  core->touches.clear();
  core->counters.dropped_contacts = 0;
  for (Proxy& proxy : core->proxies)
  {
    proxy.state.contact_count = 0;
  }
  collectTouches(core);
  // In the dispatcher's order (a scene where each finger touches each body once is unchanged
  // bit for bit); a touch that another, deeper touch of the same finger and body covers is no
  // area of its own, and its manifold leaves the solver for this step.
  for (std::size_t i = 0; i < core->touches.size(); ++i)
  {
    const ProxyTouch& touch = core->touches[i];
    if (core->touches.coveredByDeeperTouch(i, core->params.contact.max_radius))
    {
      touch.manifold->clearManifold();
      continue;
    }
    addContactArea(core, touch);
  }
  core->counters.dropped_contacts_total += core->counters.dropped_contacts;
}
}  // namespace god_finger::internal
