// The contact points a body had when it fell asleep (with the body on the other side), put back
// into its new manifolds in the step it wakes: a woken body rests on the contacts and impulses it
// slept on, instead of finding them anew one point a step (GJK gives one), which made woken
// piles wobble, wake their neighbours and never sleep. Internal to physics.
//
// Bodies are the scene's (collision objects with user index kKindBody, user index 2 the body's
// index). Frames: as Bullet's manifold points (local points in each body's frame). Sleep and
// wake transitions only allocate; a step without them does not.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace god_finger::internal
{
class SleptContacts
{
 public:
  // Forgets every saved contact; bodies 0 .. body_count - 1.
  void reset(int body_count);
  // After a step: saves every contact point of the bodies flagged in `falling_asleep` (by body).
  void save(btCollisionDispatcher* dispatcher, const std::vector<char>& falling_asleep);
  // `body` woke this step: its contacts go back in the next restore().
  void woke(int body)
  {
    woken_.push_back(body);
  }
  // The bodies renumbered for a scene edit (scene_edit.h): body i is old_of_new[i] of before (-1:
  // a new body, nothing saved); the contacts saved with a body that goes (`removed`, not in
  // Bullet's world any more), on either side, are forgotten. Allocates.
  void remap(const std::vector<int>& old_of_new, const std::vector<const btCollisionObject*>& removed);
  // After the narrow phase, before the islands and the solver: the step's woken bodies get back
  // the contacts they slept on, where the new manifold lacks them and they still touch; their
  // saved contacts are then forgotten.
  void restore(btCollisionDispatcher* dispatcher);

 private:
  struct SavedContact
  {
    const btCollisionObject* other = nullptr;
    btManifoldPoint point;  // with this body as A
  };
  std::vector<std::vector<SavedContact>> saved_;  // by body
  std::vector<int> woken_;                        // this step, until their contacts are back
};
}  // namespace god_finger::internal
