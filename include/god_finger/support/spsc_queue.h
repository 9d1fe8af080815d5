// A bounded lock-free queue between exactly one producer thread and one consumer thread: how
// the servo loop hands its outputs (device samples, world snapshots) to the ROS publishers
// and takes their commands, without ever waiting on a lock the other side holds.
//
// Invariants: capacity fixed at construction (the only allocation; elements are copied into
// preallocated slots, so a T whose copy does not allocate keeps push/pop allocation-free);
// tryPush never overwrites an unread element; elements come out in the order they went in.
// tryPush, reserve and commit only from the producer, tryPop only from the consumer; empty and
// capacity from either. Real-time safe.
#pragma once

#include <atomic>
#include <cstddef>
#include <vector>

namespace god_finger
{
template <class T>
class SpscQueue
{
 public:
  // Holds up to `capacity` (>= 1) elements.
  explicit SpscQueue(std::size_t capacity) : slots_(capacity + 1) {}
  SpscQueue(const SpscQueue&) = delete;
  SpscQueue& operator=(const SpscQueue&) = delete;

  // False (and nothing changes) when full.
  [[nodiscard]] bool tryPush(const T& value)
  {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    const std::size_t next = advance(tail);
    if (next == head_.load(std::memory_order_acquire))
    {
      return false;
    }
    slots_[tail] = value;
    tail_.store(next, std::memory_order_release);
    return true;
  }

  // The slot the next tryPush would fill, for a producer that builds a large element in place
  // (nullptr when full); commit() publishes it.
  T* reserve()
  {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (advance(tail) == head_.load(std::memory_order_acquire))
    {
      return nullptr;
    }
    return &slots_[tail];
  }
  void commit()
  {
    tail_.store(advance(tail_.load(std::memory_order_relaxed)), std::memory_order_release);
  }

  // False when empty.
  [[nodiscard]] bool tryPop(T* value)
  {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head == tail_.load(std::memory_order_acquire))
    {
      return false;
    }
    *value = slots_[head];
    head_.store(advance(head), std::memory_order_release);
    return true;
  }

  bool empty() const
  {
    return head_.load(std::memory_order_acquire) == tail_.load(std::memory_order_acquire);
  }
  std::size_t capacity() const
  {
    return slots_.size() - 1;
  }

 private:
  std::size_t advance(std::size_t index) const
  {
    return index + 1 == slots_.size() ? 0 : index + 1;
  }
  std::vector<T> slots_;
  alignas(64) std::atomic<std::size_t> head_{0};
  alignas(64) std::atomic<std::size_t> tail_{0};
};
}  // namespace god_finger
