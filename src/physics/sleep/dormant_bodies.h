// The sleeping bodies taken out of Bullet's world ("dormant"), with their bounding boxes in a tree
// of their own. Internal to physics (god_finger_world.cpp).
//
// Bullet keeps a sleeping body in every per-step pass (pair visits, islands, motion prediction,
// integration, gravity, forces): about 80 ns per body a step, so 1000 resting boxes cost four
// times what 10 do although the fingers touch the same two. A dormant body is in none of them:
// the world removes it when its island falls asleep and adds it back, with every body of that
// island (its group: what rests on it and what it rests on wakes with it), when a proxy or a
// body moving faster than the sleep speed comes within Bullet's contact threshold of its box,
// before the step's collision detection; the world then puts back the contact points and impulses
// the group slept on (slept_contacts.h).
//
// Units: m (boxes in world). Real-time: lookups and overlap queries allocate nothing; putting a
// group to sleep and waking one do (a tree node per body, as Bullet's broadphase does on adding
// and removing a body): they happen when a scene comes to rest or a finger arrives.
#pragma once

#include <BulletCollision/BroadphaseCollision/btDbvt.h>

#include <vector>

namespace god_finger::internal
{
class DormantBodies
{
 public:
  DormantBodies() = default;
  ~DormantBodies();
  DormantBodies(const DormantBodies&) = delete;
  DormantBodies& operator=(const DormantBodies&) = delete;

  // Forgets every dormant body and makes room for `body_count` (allocates).
  void reset(int body_count);
  bool dormant(int body) const
  {
    return leaves_[body] != nullptr;
  }
  // `body` (m, world box [min, max]) sleeps in the group of `group` (a dormant body), or in a
  // group of its own when `group` < 0.
  void add(int body, const btVector3& min, const btVector3& max, int group);
  // Every dormant body whose box overlaps [min, max], and every body of its group, leaves the
  // set; each is passed to `woken` (body index) once.
  template <class Woken>
  void wakeOverlapping(const btVector3& min, const btVector3& max, Woken woken)
  {
    hits_.clear();
    Collector collector(&hits_);
    tree_.collideTVNoStackAlloc(tree_.m_root, btDbvtVolume::FromMM(min, max), stack_, collector);
    for (const int hit : hits_)
    {
      wakeGroup(hit, woken);
    }
  }
  // Dormant `body` and every body of its group leave the set, each passed to `woken`.
  template <class Woken>
  void wakeGroupOf(int body, Woken woken)
  {
    wakeGroup(body, woken);
  }
  // The bodies renumbered for a scene edit (scene_edit.h): body i is old_of_new[i] of before
  // (-1: a new body, awake). A body that goes must not be dormant (wake it first). Allocates.
  void remap(const std::vector<int>& old_of_new);
  // Every dormant body leaves the set, passed to `woken`.
  template <class Woken>
  void wakeAll(Woken woken)
  {
    for (int body = 0; body < static_cast<int>(leaves_.size()); ++body)
    {
      if (dormant(body))
      {
        wakeGroup(body, woken);
      }
    }
  }

 private:
  struct Collector : btDbvt::ICollide
  {
    explicit Collector(std::vector<int>* hits) : hits(hits) {}
    void Process(const btDbvtNode* leaf) override
    {
      if (static_cast<int>(hits->size()) < static_cast<int>(hits->capacity()))
      {
        hits->push_back(static_cast<int>(reinterpret_cast<std::size_t>(leaf->data)));
      }
    }
    std::vector<int>* hits;
  };
  template <class Woken>
  void wakeGroup(int body, Woken& woken)
  {
    if (!dormant(body))
    {
      return;  // woken already, with an earlier hit's group
    }
    int member = body;
    do
    {
      const int following = next_[member];
      tree_.remove(leaves_[member]);
      leaves_[member] = nullptr;
      next_[member] = -1;
      woken(member);
      member = following;
    } while (member != body);
  }

  btDbvt tree_;
  btAlignedObjectArray<const btDbvtNode*> stack_;
  std::vector<btDbvtNode*> leaves_;  // by body; null when awake
  std::vector<int> next_;            // the next body of the group (a ring); -1 when awake
  std::vector<int> hits_;
};
}  // namespace god_finger::internal
