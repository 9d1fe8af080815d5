// The operator benchmark's pick and place (scenarios/grip_task.h) for any simulator that runs the
// grip task: a layout's twist limit and its runs per squeeze and seed, printed as JSON lines
// (bench/operator_bench.cpp has the format; bench/operator_mujoco_bench.cpp runs MuJoCo through
// it). Deterministic when the runner is.
#pragma once

#include "god_finger/scenarios/grip_task.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace god_finger
{
// Runs the grip task with these options (GodFingerWorld's runGripTask or another simulator's).
using GripRunner = std::function<GripTaskResult(const GripTaskOptions&)>;

constexpr double kOperatorTurnLimit = 0.05;  // rad, "holds still"
// The pick and place's squeezes (m), every layout's and simulator's (operator_bench's default).
inline const std::vector<double> kPickPlaceSqueezes = {0.008, 0.012, 0.016, 0.02, 0.03};

// The smallest squeeze (m) at which a perfect hand lifts and holds the bar turning at most
// kOperatorTurnLimit: bisection to 0.1 mm in [0.5, 60] mm; 0 when it holds at 0.5 mm, -1 when
// never. `base` gives everything but the squeeze, the hand (perfect) and the carry (none).
inline double twistLimit(const GripRunner& run, const GripTaskOptions& base)
{
  auto holdsStill = [&](double squeeze)
  {
    GripTaskOptions options = base;
    options.squeeze = squeeze;
    const GripTaskResult result = run(options);
    return result.held && result.max_turn_rad <= kOperatorTurnLimit;
  };
  double low = 0.0005;
  double high = 0.06;
  if (holdsStill(low))
  {
    return 0.0;
  }
  if (!holdsStill(high))
  {
    return -1.0;
  }
  while (high - low > 1e-4)
  {
    const double middle = 0.5 * (low + high);
    (holdsStill(middle) ? high : low) = middle;
  }
  return high;
}

// Prints the layout's twist limit ({"kind":"limit"}) and `seeds` pick and places per squeeze and
// at the target squeeze (whose low point, 0.75 of it, is 1.2 twist limits) ({"kind":"run"}).
inline void pickPlaceRuns(const std::string& layout, const GripRunner& run, const GripTaskOptions& base,
                          std::vector<double> squeezes, int seeds)
{
  const double limit = twistLimit(run, base);
  std::cout << nlohmann::json{{"kind", "limit"}, {"layout", layout}, {"twist_limit_squeeze_m", limit}}.dump()
            << std::endl;
  if (limit > 0.0)
  {
    squeezes.push_back(1.2 * limit / 0.75);
  }
  for (std::size_t k = 0; k < squeezes.size(); ++k)
  {
    const bool target = k + 1 == squeezes.size() && limit > 0.0;
    for (int seed = 1; seed <= seeds; ++seed)
    {
      GripTaskOptions options = base;
      options.squeeze = squeezes[k];
      options.carry = true;
      options.hand = drawOperator(static_cast<std::uint64_t>(seed), Eigen::Vector3d::UnitY());
      const GripTaskResult r = run(options);
      std::cout << nlohmann::json{{"kind", "run"},
                                  {"task", "pick_place"},
                                  {"layout", layout},
                                  {"squeeze_m", options.squeeze},
                                  {"target", target},
                                  {"seed", seed},
                                  {"held", r.held},
                                  {"placed", r.placed},
                                  {"placed_error_m", r.placed_error_m},
                                  {"max_turn_rad", r.max_turn_rad},
                                  {"max_tilt_rad", r.max_tilt_rad},
                                  {"max_slip_m", r.max_slip_m},
                                  {"mean_grip_force_N", r.mean_grip_force_N},
                                  {"min_squeeze_m", r.min_squeeze_m},
                                  {"final_rotation_rad", r.final_rotation_rad},
                                  {"misalignment_m", options.hand.misalignment.norm()},
                                  {"tremor_m", options.hand.tremor_amplitude},
                                  {"tremor_hz", options.hand.tremor_frequency}}
                       .dump()
                << std::endl;
    }
  }
}
}  // namespace god_finger
