// The human-like operator benchmark (bench/REPORT.md, "Human-like operator"): a two-finger
// pick and place of a bar gripped 3 cm off its centre (physics/grip_task.h) by operators drawn
// per seed (physics/human_operator.h: tremor, misalignment up to 3 mm, grip fluctuating
// +-25 % at ~1 Hz, a grip reflex 100-150 ms late), for each contact layout and squeeze.
// Not a timing: every line is deterministic.
//
// First, per layout, its twist limit: the smallest squeeze (m) at which a perfect hand lifts
// and holds the bar turning at most 0.05 rad (bisection to 0.1 mm in [0.5, 60] mm; 0 when the
// layout holds it at 0.5 mm, -1 when it never does). Then `--seeds` pick and places per squeeze
// in the list and at the target squeeze, whose low point (0.75 of it) is 1.2 twist limits.
// Second, the paper's pencil-versus-finger example (physics/sheet_push_task.h): `--seeds`
// operators drag a sheet by its corner per press in the list.
// With `--grasp aggregate`, god_finger with the grasp constraint (WorldParams::grasp_constraint) is
// one more pick-and-place layout, "god_finger/aggregate", after the other layouts; every other line
// prints as without it.
// Prints one JSON line per layout ({"kind":"limit"}) and per run ({"kind":"run"}, with its
// "task": "pick_place" or "sheet_push").
//
// usage: operator_bench [--seeds N] [--squeezes MM[,MM...]] [--presses MM[,MM...]] [--grasp off|aggregate]
#include "god_finger/core/text_numbers.h"
#include "god_finger/physics/grip_task.h"
#include "god_finger/physics/pad_fidelity.h"
#include "god_finger/physics/sheet_push_task.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace god_finger;

constexpr double kTurnLimit = 0.05;  // rad
constexpr PadLayout kAggregateLayout = {"god_finger/aggregate", ContactModel::kGodFinger, PadSolver::kConstraint};

GripTaskOptions optionsFor(const PadLayout& layout, double squeeze)
{
  GripTaskOptions options;
  options.model = layout.model;
  options.params.pad_solver = layout.pad_solver;
  if (std::strcmp(layout.name, kAggregateLayout.name) == 0)
  {
    options.params.grasp_constraint = GraspConstraint::kAggregate;
  }
  options.squeeze = squeeze;
  return options;
}

bool holdsStill(const PadLayout& layout, double squeeze)
{
  const GripTaskResult result = runGripTask(optionsFor(layout, squeeze));
  return result.held && result.max_turn_rad <= kTurnLimit;
}

double twistLimit(const PadLayout& layout)
{
  double low = 0.0005;
  double high = 0.06;
  if (holdsStill(layout, low))
  {
    return 0.0;
  }
  if (!holdsStill(layout, high))
  {
    return -1.0;
  }
  while (high - low > 1e-4)
  {
    const double middle = 0.5 * (low + high);
    (holdsStill(layout, middle) ? high : low) = middle;
  }
  return high;
}

int fail(const std::string& message)
{
  std::cerr
      << "operator_bench: " << message
      << "\nusage: operator_bench [--seeds N] [--squeezes MM[,MM...]] [--presses MM[,MM...]] [--grasp off|aggregate]\n";
  return 2;
}
}  // namespace

int main(int argc, char** argv)
{
  int seeds = 20;
  std::vector<double> squeezes = {0.008, 0.012, 0.016, 0.02, 0.03};
  std::vector<double> presses = {0.0025, 0.005, 0.01};
  std::vector<PadLayout> grip_layouts(std::begin(kPadLayouts), std::end(kPadLayouts));
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    const std::string value = argv[i + 1];
    if (option == "--seeds")
    {
      long long number = 0;
      if (!parseInteger(value, &number) || number < 1 || number > 10000)
      {
        return fail("--seeds '" + value + "' is not a whole number in [1, 10000]");
      }
      seeds = static_cast<int>(number);
    }
    else if (option == "--squeezes" || option == "--presses")
    {
      std::vector<double>* list = option == "--squeezes" ? &squeezes : &presses;
      list->clear();
      std::stringstream items(value);
      std::string item;
      while (std::getline(items, item, ','))
      {
        double millimetres = 0.0;
        if (!parseDouble(item, &millimetres) || !(millimetres > 0.0 && millimetres <= 50.0))
        {
          return fail(option + " item '" + item + "' is not a length in (0, 50] mm");
        }
        list->push_back(millimetres * 1e-3);
      }
    }
    else if (option == "--grasp")
    {
      GraspConstraint grasp = GraspConstraint::kOff;
      if (!parseGraspConstraint(value, &grasp))
      {
        return fail("--grasp '" + value + "' is not one of " + graspConstraintNames());
      }
      if (grasp == GraspConstraint::kAggregate)
      {
        grip_layouts.push_back(kAggregateLayout);
      }
    }
    else
    {
      return fail("unknown option '" + option + "'");
    }
  }
  for (const PadLayout& layout : grip_layouts)
  {
    const double limit = twistLimit(layout);
    std::cout << nlohmann::json{{"kind", "limit"}, {"layout", layout.name}, {"twist_limit_squeeze_m", limit}}.dump()
              << std::endl;
    std::vector<double> layout_squeezes = squeezes;
    if (limit > 0.0)
    {
      layout_squeezes.push_back(1.2 * limit / 0.75);
    }
    for (std::size_t k = 0; k < layout_squeezes.size(); ++k)
    {
      const bool target = k + 1 == layout_squeezes.size() && limit > 0.0;
      for (int seed = 1; seed <= seeds; ++seed)
      {
        GripTaskOptions options = optionsFor(layout, layout_squeezes[k]);
        options.carry = true;
        options.hand = drawOperator(static_cast<std::uint64_t>(seed), Eigen::Vector3d::UnitY());
        const GripTaskResult r = runGripTask(options);
        std::cout << nlohmann::json{{"kind", "run"},
                                    {"task", "pick_place"},
                                    {"layout", layout.name},
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
  for (const PadLayout& layout : kPadLayouts)
  {
    for (const double press : presses)
    {
      for (int seed = 1; seed <= seeds; ++seed)
      {
        SheetPushOptions options;
        options.model = layout.model;
        options.params.pad_solver = layout.pad_solver;
        options.press = press;
        options.hand = drawOperator(static_cast<std::uint64_t>(seed), Eigen::Vector3d::UnitZ());
        const SheetPushResult r = runSheetPush(options);
        std::cout << nlohmann::json{{"kind", "run"},
                                    {"task", "sheet_push"},
                                    {"layout", layout.name},
                                    {"press_m", press},
                                    {"seed", seed},
                                    {"translated", r.translated},
                                    {"translation_m", r.translation_m},
                                    {"turn_rad", r.turn_rad},
                                    {"max_slip_m", r.max_slip_m},
                                    {"mean_press_N", r.mean_press_N}}
                         .dump()
                  << std::endl;
      }
    }
  }
  return 0;
}
