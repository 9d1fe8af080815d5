#include "sleep/slept_contacts.h"

#include "bullet_helpers.h"

#include <algorithm>

namespace god_finger::internal
{
namespace
{
// The contact point `point` of a manifold whose body A is `a`, as seen with `a` as B instead.
btManifoldPoint swapped(const btManifoldPoint& point)
{
  btManifoldPoint out = point;
  out.m_localPointA = point.m_localPointB;
  out.m_localPointB = point.m_localPointA;
  out.m_positionWorldOnA = point.m_positionWorldOnB;
  out.m_positionWorldOnB = point.m_positionWorldOnA;
  out.m_normalWorldOnB = -point.m_normalWorldOnB;
  out.m_partId0 = point.m_partId1;
  out.m_partId1 = point.m_partId0;
  out.m_index0 = point.m_index1;
  out.m_index1 = point.m_index0;
  return out;
}
}  // namespace

void SleptContacts::reset(int body_count)
{
  saved_.assign(body_count, {});
  woken_.clear();
  woken_.reserve(body_count);
}

void SleptContacts::save(btCollisionDispatcher* dispatcher, const std::vector<char>& falling_asleep)
{
  const int manifold_count = dispatcher->getNumManifolds();
  for (int m = 0; m < manifold_count; ++m)
  {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    for (int p = 0; p < manifold->getNumContacts(); ++p)
    {
      if (a->getUserIndex() == kKindBody && falling_asleep[a->getUserIndex2()])
      {
        saved_[a->getUserIndex2()].push_back({b, manifold->getContactPoint(p)});
      }
      if (b->getUserIndex() == kKindBody && falling_asleep[b->getUserIndex2()])
      {
        saved_[b->getUserIndex2()].push_back({a, swapped(manifold->getContactPoint(p))});
      }
    }
  }
}

void SleptContacts::restore(btCollisionDispatcher* dispatcher)
{
  if (woken_.empty())
  {
    return;
  }
  const int manifold_count = dispatcher->getNumManifolds();
  for (int m = 0; m < manifold_count; ++m)
  {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int side = 0; side < 2; ++side)
    {
      const btCollisionObject* self = side == 0 ? manifold->getBody0() : manifold->getBody1();
      const btCollisionObject* other = side == 0 ? manifold->getBody1() : manifold->getBody0();
      if (self->getUserIndex() != kKindBody)
      {
        continue;
      }
      std::vector<SavedContact>& saved = saved_[self->getUserIndex2()];
      for (const SavedContact& contact : saved)
      {
        if (contact.other != other)
        {
          continue;
        }
        btManifoldPoint point = side == 0 ? contact.point : swapped(contact.point);
        point.m_positionWorldOnA = manifold->getBody0()->getWorldTransform() * point.m_localPointA;
        point.m_positionWorldOnB = manifold->getBody1()->getWorldTransform() * point.m_localPointB;
        point.m_distance1 = (point.m_positionWorldOnA - point.m_positionWorldOnB).dot(point.m_normalWorldOnB);
        if (point.m_distance1 <= manifold->getContactBreakingThreshold() && manifold->getCacheEntry(point) < 0)
        {
          manifold->addManifoldPoint(point);
        }
      }
    }
  }
  for (const int index : woken_)
  {
    saved_[index].clear();
  }
  woken_.clear();
}

void SleptContacts::remap(const std::vector<int>& old_of_new, const std::vector<const btCollisionObject*>& removed)
{
  std::vector<int> new_of_old(saved_.size(), -1);
  std::vector<std::vector<SavedContact>> saved(old_of_new.size());
  for (std::size_t i = 0; i < old_of_new.size(); ++i)
  {
    const int old = old_of_new[i];
    if (old < 0)
    {
      continue;
    }
    new_of_old[old] = static_cast<int>(i);
    saved[i] = std::move(saved_[old]);
    // A body that goes may leave a new one its address: a contact with it would be put back there.
    saved[i].erase(std::remove_if(saved[i].begin(), saved[i].end(),
                                  [&removed](const SavedContact& contact) {
                                    return std::find(removed.begin(), removed.end(), contact.other) != removed.end();
                                  }),
                   saved[i].end());
  }
  saved_ = std::move(saved);
  std::vector<int> woken;
  woken.reserve(saved_.size());
  for (const int old : woken_)
  {
    if (new_of_old[old] >= 0)
    {
      woken.push_back(new_of_old[old]);
    }
  }
  woken_ = std::move(woken);
}
}  // namespace god_finger::internal
