#include "sleep/dormant_bodies.h"

namespace god_finger::internal
{
DormantBodies::~DormantBodies()
{
  tree_.clear();
}

void DormantBodies::reset(int body_count)
{
  tree_.clear();
  leaves_.assign(body_count, nullptr);
  next_.assign(body_count, -1);
  hits_.clear();
  hits_.reserve(body_count);
  stack_.reserve(2 * body_count + 64);
}

void DormantBodies::add(int body, const btVector3& min, const btVector3& max, int group)
{
  leaves_[body] = tree_.insert(btDbvtVolume::FromMM(min, max), reinterpret_cast<void*>(static_cast<std::size_t>(body)));
  if (group >= 0 && dormant(group))
  {
    next_[body] = next_[group];
    next_[group] = body;
  }
  else
  {
    next_[body] = body;
  }
}

void DormantBodies::remap(const std::vector<int>& old_of_new)
{
  const int count = static_cast<int>(old_of_new.size());
  std::vector<int> new_of_old(leaves_.size(), -1);
  for (int i = 0; i < count; ++i)
  {
    if (old_of_new[i] >= 0)
    {
      new_of_old[old_of_new[i]] = i;
    }
  }
  std::vector<btDbvtNode*> leaves(count, nullptr);
  std::vector<int> next(count, -1);
  for (int i = 0; i < count; ++i)
  {
    const int old = old_of_new[i];
    if (old < 0 || leaves_[old] == nullptr)
    {
      continue;
    }
    leaves[i] = leaves_[old];
    leaves[i]->data = reinterpret_cast<void*>(static_cast<std::size_t>(i));  // the tree's hits name bodies
    next[i] = new_of_old[next_[old]];  // a group's bodies all stay (a removed one's group woke)
  }
  leaves_ = std::move(leaves);
  next_ = std::move(next);
  hits_.clear();
  hits_.reserve(count);
  stack_.reserve(2 * count + 64);
}
}  // namespace god_finger::internal
