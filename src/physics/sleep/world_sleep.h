// Sleep, as one piece (Box2D's solver_set.c): which dynamic bodies are awake, which sleep out of
// Bullet's world (dormant_bodies.h) with the contacts they slept on (slept_contacts.h), and the
// rules that move a body from one to the other. Internal to physics; the world's step calls
// wakeNearFingersAndMovers before collision detection and putSleepersAway after the solve.
//
// Rules (WorldParams::sleep): a dynamic body at rest for sleep.time, out of every proxy's reach,
// falls asleep with its island; a proxy's or a moving body's broadphase box reaching a sleeping
// body's box wakes its group. Jointed bodies never sleep. Units: SI.
// Real-time: waking and putting to sleep allocate (a tree node per body), as Bullet's broadphase
// does; the per-step scans do not.
#pragma once

#include "sleep/dormant_bodies.h"
#include "sleep/slept_contacts.h"

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace god_finger::internal
{
struct WorldCore;

struct WorldSleep
{
  DormantBodies dormant;
  std::vector<int> awake;  // the dynamic bodies in Bullet's world
  // The contacts sleeping bodies slept on, put back when they wake; by body, the bodies falling
  // asleep this step; scratch: island tag -> the first body of that island falling asleep.
  SleptContacts slept_contacts;
  std::vector<char> falling_asleep;
  std::vector<int> group_of_tag;
};

// Every dynamic body awake, nothing dormant (a world just built: its bodies are in Bullet's world).
void resetSleep(WorldCore* core);
// Sleep's per-body state renumbered for a scene edit (scene_edit.h), before core->bodies is: body
// i becomes old_of_new[i] of before (-1: a new body, not yet awake: the edit adds it). Bodies that
// go must be awake (not dormant), their contacts saved by sleepers forgotten (`removed`: their
// Bullet bodies). Dormant bodies stay dormant, with their groups and slept contacts.
void remapSleep(WorldCore* core, const std::vector<int>& old_of_new,
                const std::vector<const btCollisionObject*>& removed);
// A dynamic body starts with a full sleep timer, less the time a free fall from rest takes to
// exceed twice the sleep speed: placed at rest it sleeps within that time (its island with it),
// placed in the air it falls. A jointed body, or sleep.time 0: never sleeps.
void prepareSleep(const WorldCore& core, btRigidBody* rigid);
// Dormant body `index` back into Bullet's world, at rest where it slept. Woken by a proxy or a
// wrench (`by_proxy`), it stays awake for at least sleep.time (its timer restarts); woken by a
// moving neighbour, it keeps the timer of a body placed at rest: if the neighbour does not reach
// it, it sleeps again within a few steps.
void wakeBody(WorldCore* core, int index, bool by_proxy);
// Stage "wake", before the step's collision detection: every dormant group within Bullet's
// contact threshold of a proxy or of an awake body moving faster than it may sleep (those it
// wakes included) wakes, so that its contacts are found in this step.
void wakeNearFingersAndMovers(WorldCore* core);
// Stage "sleep", after the solve: the islands that fell asleep leave Bullet's world, each as one
// group, keeping their contacts.
void putSleepersAway(WorldCore* core);
// Wakes every dynamic body (a parameter or model change: what rests under the old contact may
// not under the new one), with the timer of a body placed at rest.
void wakeAll(WorldCore* core);
// Whether scene body `body` sleeps (dormant, or in a sleeping island; a soft body: at rest).
bool bodyAsleep(const WorldCore& core, int body);
// Dynamic bodies awake now.
int awakeBodyCount(const WorldCore& core);
}  // namespace god_finger::internal
