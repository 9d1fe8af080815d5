#include "sleep/world_sleep.h"

#include "bullet_helpers.h"
#include "world_core.h"

#include <algorithm>

namespace god_finger::internal
{
void resetSleep(WorldCore* core)
{
  WorldSleep& sleep = core->sleep;
  const int body_count = static_cast<int>(core->bodies.size());
  sleep.dormant.reset(body_count);
  sleep.awake.clear();
  sleep.awake.reserve(core->bodies.size());
  for (int i = 0; i < body_count; ++i)
  {
    if (!core->scene.bodies[i].is_static)
    {
      sleep.awake.push_back(i);
    }
  }
  sleep.slept_contacts.reset(body_count);
  sleep.falling_asleep.assign(core->bodies.size(), 0);
}

void remapSleep(WorldCore* core, const std::vector<int>& old_of_new,
                const std::vector<const btCollisionObject*>& removed)
{
  WorldSleep& sleep = core->sleep;
  std::vector<int> new_of_old(core->bodies.size(), -1);
  for (std::size_t i = 0; i < old_of_new.size(); ++i)
  {
    if (old_of_new[i] >= 0)
    {
      new_of_old[old_of_new[i]] = static_cast<int>(i);
    }
  }
  sleep.dormant.remap(old_of_new);
  std::vector<int> awake;
  awake.reserve(old_of_new.size());
  for (const int old : sleep.awake)
  {
    if (new_of_old[old] >= 0)
    {
      awake.push_back(new_of_old[old]);  // in the order they were: the wake stage's order
    }
  }
  sleep.awake = std::move(awake);
  sleep.slept_contacts.remap(old_of_new, removed);
  sleep.falling_asleep.assign(old_of_new.size(), 0);
}

void prepareSleep(const WorldCore& core, btRigidBody* rigid)
{
  const SleepParams& sleep = core.params.sleep;
  if (sleep.time <= 0.0 || core.jointed[rigid->getUserIndex2()])
  {
    rigid->setActivationState(DISABLE_DEACTIVATION);
    return;
  }
  rigid->setSleepingThresholds(sleep.speed, sleep.angular_speed);
  const double gravity = core.params.gravity.norm();
  const double settle = gravity > 0.0 ? 2.0 * sleep.speed / gravity : 0.0;
  rigid->setDeactivationTime(std::max(0.0, sleep.time - settle));
}

void wakeBody(WorldCore* core, int index, bool by_proxy)
{
  btRigidBody* rigid = core->bodies[index].rigid.get();
  core->world->addRigidBody(rigid, kBodyGroup, btBroadphaseProxy::AllFilter);
  rigid->activate(true);
  if (!by_proxy)
  {
    prepareSleep(*core, rigid);
  }
  core->sleep.awake.push_back(index);
  core->sleep.slept_contacts.woke(index);
}

void wakeNearFingersAndMovers(WorldCore* core)
{
  WorldSleep& sleep = core->sleep;
  // Broadphase boxes include Bullet's contact threshold already (btCollisionWorld::updateAabbs).
  const btVector3 margin(0.0, 0.0, 0.0);
  const auto by_proxy = [core](int index) { wakeBody(core, index, true); };
  const auto by_body = [core](int index) { wakeBody(core, index, false); };
  for (const Proxy& proxy : core->proxies)
  {
    const btBroadphaseProxy* handle = proxy.rigid->getBroadphaseHandle();
    sleep.dormant.wakeOverlapping(handle->m_aabbMin - margin, handle->m_aabbMax + margin, by_proxy);
  }
  // Awake bodies moving faster than they may sleep (one settling slower does not reach a
  // neighbour before it sleeps itself).
  const double speed2 = core->params.sleep.speed * core->params.sleep.speed;
  const double angular2 = core->params.sleep.angular_speed * core->params.sleep.angular_speed;
  for (std::size_t k = 0; k < sleep.awake.size(); ++k)
  {
    const btRigidBody* rigid = core->bodies[sleep.awake[k]].rigid.get();
    if (rigid->isActive() &&
        (rigid->getLinearVelocity().length2() >= speed2 || rigid->getAngularVelocity().length2() >= angular2))
    {
      const btBroadphaseProxy* handle = rigid->getBroadphaseHandle();
      sleep.dormant.wakeOverlapping(handle->m_aabbMin - margin, handle->m_aabbMax + margin, by_body);
    }
  }
}

void putSleepersAway(WorldCore* core)
{
  WorldSleep& sleep = core->sleep;
  bool any = false;
  for (const int index : sleep.awake)
  {
    const bool sleeping = core->bodies[index].rigid->getActivationState() == ISLAND_SLEEPING;
    sleep.falling_asleep[index] = sleeping ? 1 : 0;
    any = any || sleeping;
  }
  if (!any)
  {
    return;
  }
  sleep.slept_contacts.save(core->dispatcher.get(), sleep.falling_asleep);
  for (std::size_t k = 0; k < sleep.awake.size();)
  {
    const int index = sleep.awake[k];
    btRigidBody* rigid = core->bodies[index].rigid.get();
    if (rigid->getActivationState() != ISLAND_SLEEPING)
    {
      ++k;
      continue;
    }
    const int tag = rigid->getIslandTag();
    const bool tagged = tag >= 0 && tag < static_cast<int>(sleep.group_of_tag.size());
    btVector3 min;
    btVector3 max;
    rigid->getAabb(min, max);
    core->world->removeRigidBody(rigid);
    sleep.dormant.add(index, min, max, tagged ? sleep.group_of_tag[tag] : -1);
    if (tagged && sleep.group_of_tag[tag] < 0)
    {
      sleep.group_of_tag[tag] = index;
    }
    core->bodies[index].net_force.setZero();
    sleep.falling_asleep[index] = 0;
    sleep.awake[k] = sleep.awake.back();
    sleep.awake.pop_back();
  }
  std::fill(sleep.group_of_tag.begin(), sleep.group_of_tag.end(), -1);
}

void wakeAll(WorldCore* core)
{
  core->sleep.dormant.wakeAll([core](int index) { wakeBody(core, index, false); });
  for (const int index : core->sleep.awake)
  {
    core->bodies[index].rigid->activate(true);
    prepareSleep(*core, core->bodies[index].rigid.get());
  }
}

bool bodyAsleep(const WorldCore& core, int body)
{
  const SceneBody& b = core.bodies[body];
  return b.soft ? b.soft->elastic->sleeping()
                : core.sleep.dormant.dormant(body) || b.rigid->getActivationState() == ISLAND_SLEEPING;
}

int awakeBodyCount(const WorldCore& core)
{
  int awake = 0;
  for (const int index : core.sleep.awake)
  {
    awake += core.bodies[index].rigid->isActive() ? 1 : 0;
  }
  return awake;
}
}  // namespace god_finger::internal
