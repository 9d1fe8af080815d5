// Stage "contact_areas" of the world's step, between Bullet's collision detection and its solver
// (HookedWorld::after_collision): the contact area (Algorithm 1, contact/contact_area.h) of every
// (proxy, body) pair in contact, from the deepest point of their manifold, handed to the current
// model's response (contact_response.h), which adds what it adds to the solver. Internal to
// physics.
//
// One finger keeps at most InterfaceState::kMaxContacts areas (bodies) a step; a touch beyond
// them is dropped and counted (WorldCounters::dropped_contacts). Also: the contacts woken bodies
// slept on go back into their manifolds first (slept_contacts.h), and the step's deepest
// penetration is measured (WorldCounters::deepest_penetration).
// Units: SI, world frame (the walk in each body's geometry frame). Real-time safe once the
// solver's lists have grown.
#pragma once

namespace god_finger::internal
{
struct WorldCore;

void computeContactAreas(WorldCore* core);
}  // namespace god_finger::internal
