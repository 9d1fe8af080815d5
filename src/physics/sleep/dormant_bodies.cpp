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
}  // namespace god_finger::internal
