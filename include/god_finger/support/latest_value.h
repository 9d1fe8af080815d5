// A lock-free "latest value" mailbox between exactly one writer thread and one reader thread
// (a triple buffer): the writer never waits and never touches the slot the reader holds; the
// reader gets the newest complete value and skips the older ones. How the servo loop's haptic
// thread and its physics thread hand each other device targets and step results.
//
// Invariants: three slots fixed at construction (the only allocation; each starts as a copy of
// `initial`, so a T whose assignment into an equally sized T does not allocate, such as
// vectors of one length, keeps writing and reading allocation-free); a value the reader got
// stays unchanged until its next take(). back()/publish() only from the writer, take()/front()
// only from the reader. Real-time safe on both sides (two atomic exchanges, no lock, no
// system call).
#pragma once

#include <atomic>

namespace god_finger
{
template <class T>
class LatestValue
{
 public:
  explicit LatestValue(const T& initial = T()) : slots_{initial, initial, initial} {}
  LatestValue(const LatestValue&) = delete;
  LatestValue& operator=(const LatestValue&) = delete;

  // Writer: the slot to fill next (it holds an older value, not necessarily the last one).
  T& back()
  {
    return slots_[back_];
  }
  // Writer: makes back() the newest value; back() is another slot afterwards.
  void publish()
  {
    back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex;
  }

  // Reader: true when a value newer than front() was published; front() is then that value.
  bool take()
  {
    if (!(middle_.load(std::memory_order_acquire) & kFresh))
    {
      return false;
    }
    front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
    return true;
  }
  // Reader: the value of the last successful take() (`initial` before the first).
  const T& front() const
  {
    return slots_[front_];
  }

 private:
  static constexpr unsigned kIndex = 3u;
  static constexpr unsigned kFresh = 4u;
  T slots_[3];
  unsigned back_ = 0;   // the writer's
  unsigned front_ = 1;  // the reader's
  alignas(64) std::atomic<unsigned> middle_{2u};
};
}  // namespace god_finger
