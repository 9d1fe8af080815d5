// A network link made in user space (issue 29: the kernel here has no netem), for testing a
// set-up across machines: each message that enters the link at time t is lost with probability
// `loss`, else leaves it at t + delay + a Gaussian jitter of standard deviation `jitter`
// (never before t). Without `reorder`, no message leaves before one that entered earlier (a
// FIFO link: jitter bunches messages but keeps their order); with it, they leave in the order
// their own delays give.
//
// Deterministic: the same seed and the same entry times give the same schedule, bit for bit, on
// every run of one build (the draws come from the generator's raw bits, not from a library
// distribution), so a run on simulated time repeats exactly. Units: seconds. Not real-time safe to construct; release()
// is (no allocation).
#pragma once

#include "god_finger/support/parameter_table.h"

#include <cstdint>
#include <random>

namespace god_finger
{
struct DelayLineParams
{
  double delay = 0.0;   // s: the one-way delay
  double jitter = 0.0;  // s: the standard deviation of the delay's Gaussian spread
  double loss = 0.0;    // the probability that a message is lost
  int reorder = 0;      // 1: messages may overtake each other; 0: first in, first out
  int seed = 1;         // the random draws' seed
};
// delay, jitter, loss, reorder, seed: names, units, ranges, meanings (the delay node's
// parameters, docs/nodes.md).
const ParameterTable<DelayLineParams>& delayLineParameterTable();
// Empty on success, else one line naming the first bad value and its range.
std::string validate(const DelayLineParams& params);

class DelaySchedule
{
 public:
  // InputError on bad parameters (validate()).
  explicit DelaySchedule(const DelayLineParams& params);

  // When a message entering at `entry` (s, non-decreasing from call to call) leaves the link (s,
  // >= entry), or a negative number when it is lost.
  double release(double entry);

  long entered() const
  {
    return entered_;
  }
  long lost() const
  {
    return lost_;
  }

 private:
  double uniform();   // [0, 1)
  double gaussian();  // standard normal (Box-Muller)

  DelayLineParams params_;
  std::mt19937_64 generator_;
  double last_release_ = 0.0;
  long entered_ = 0;
  long lost_ = 0;
};
}  // namespace god_finger
