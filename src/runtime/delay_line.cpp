#include "god_finger/runtime/delay_line.h"

#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
const ParameterTable<DelayLineParams>& delayLineParameterTable()
{
  using P = DelayLineParams;
  static const ParameterTable<P> table = {
      realRow<P>("delay", "s", closed(0.0, 10.0), "the link's one-way delay", [](P& p) -> double& { return p.delay; }),
      realRow<P>("jitter", "s", closed(0.0, 1.0), "the delay's Gaussian spread (standard deviation)",
                 [](P& p) -> double& { return p.jitter; }),
      realRow<P>("loss", "dimensionless", closed(0.0, 1.0), "the probability that a message is lost",
                 [](P& p) -> double& { return p.loss; }),
      integerRow<P>("reorder", closed(0, 1), "1: messages may overtake each other; 0: first in, first out",
                    [](P& p) -> int& { return p.reorder; }),
      integerRow<P>("seed", closed(0, 2147483647), "the random draws' seed (the same seed, the same schedule)",
                    [](P& p) -> int& { return p.seed; }),
  };
  return table;
}

std::string validate(const DelayLineParams& params)
{
  return validateRows(delayLineParameterTable(), params);
}

DelaySchedule::DelaySchedule(const DelayLineParams& params)
    : params_(params), generator_(static_cast<std::uint64_t>(params.seed))
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
}

double DelaySchedule::uniform()
{
  return static_cast<double>(generator_() >> 11) / 9007199254740992.0;  // 53 bits: [0, 1)
}

double DelaySchedule::gaussian()
{
  const double u = 1.0 - uniform();  // (0, 1]
  const double v = uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v);
}

double DelaySchedule::release(double entry)
{
  ++entered_;
  // Every message draws the same numbers whatever the settings, so that changing one setting
  // does not reshuffle the others' draws.
  const double lose = uniform();
  const double spread = gaussian();
  if (lose < params_.loss)
  {
    ++lost_;
    return -1.0;
  }
  double leaves = std::max(entry, entry + params_.delay + params_.jitter * spread);
  if (params_.reorder == 0)
  {
    leaves = std::max(leaves, last_release_);
  }
  last_release_ = std::max(last_release_, leaves);
  return leaves;
}
}  // namespace god_finger
