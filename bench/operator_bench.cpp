// The human-like operator benchmark (bench/REPORT.md, "Human-like operator"): a two-finger
// pick and place of a bar gripped 3 cm off its centre (scenarios/grip_task.h) by operators drawn
// per seed (scenarios/human_operator.h: tremor, misalignment up to 3 mm, grip fluctuating
// +-25 % at ~1 Hz, a grip reflex 100-150 ms late), for each contact layout and squeeze.
// Not a timing: every line is deterministic.
//
// First, per layout, the pick and place (operator_pick_place.h): its twist limit, the smallest
// squeeze at which a perfect hand lifts and holds the bar still, then `--seeds` pick and places
// per squeeze in the list and at the layout's target squeeze.
// Second, the paper's pencil-versus-finger example (scenarios/sheet_push_task.h): `--seeds`
// operators drag a sheet by its corner per press in the list.
// Third, a cylinder pinched and turned 90 degrees about its axis (scenarios/cylinder_turn_task.h),
// by 3-DOF fingers and then by oriented ones turning with the hand ("oriented": true, the
// operator's wrist tremor on), and a mug lifted by three fingers (scenarios/mug_grasp_task.h): `--seeds` operators per
// squeeze in their lists. Prints one JSON line per layout ({"kind":"limit"}) and per run ({"kind":"run"}, with its
// "task": "pick_place", "sheet_push", "cylinder_turn" or "mug_grasp"), in that order.
//
// usage: operator_bench [--seeds N] [--squeezes MM[,MM...]] [--presses MM[,MM...]]
//                       [--turn-squeezes MM[,MM...]] [--mug-squeezes MM[,MM...]]
#include "god_finger/scenarios/cylinder_turn_task.h"
#include "god_finger/scenarios/grip_task.h"
#include "god_finger/scenarios/mug_grasp_task.h"
#include "god_finger/scenarios/pad_fidelity.h"
#include "god_finger/scenarios/sheet_push_task.h"
#include "god_finger/support/text_numbers.h"
#include "operator_pick_place.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace god_finger;

int fail(const std::string& message)
{
  std::cerr << "operator_bench: " << message
            << "\nusage: operator_bench [--seeds N] [--squeezes MM[,MM...]] [--presses MM[,MM...]]\n"
               "                      [--turn-squeezes MM[,MM...]] [--mug-squeezes MM[,MM...]]\n";
  return 2;
}
}  // namespace

int main(int argc, char** argv)
{
  int seeds = 20;
  std::vector<double> squeezes = kPickPlaceSqueezes;
  std::vector<double> presses = {0.0025, 0.005, 0.01};
  std::vector<double> turn_squeezes = {0.0025, 0.005, 0.01, 0.02};
  std::vector<double> mug_squeezes = {0.003, 0.004, 0.006};
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
    else if (option == "--squeezes" || option == "--presses" || option == "--turn-squeezes" ||
             option == "--mug-squeezes")
    {
      std::vector<double>* list = option == "--squeezes"        ? &squeezes
                                  : option == "--presses"       ? &presses
                                  : option == "--turn-squeezes" ? &turn_squeezes
                                                                : &mug_squeezes;
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
    else
    {
      return fail("unknown option '" + option + "'");
    }
  }
  for (const PadLayout& layout : kPadLayouts)
  {
    GripTaskOptions base;
    base.model = layout.model;
    base.params.pad_solver = layout.pad_solver;
    pickPlaceRuns(layout.name, runGripTask, base, squeezes, seeds);
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
  for (const bool oriented : {false, true})
  {
    for (const PadLayout& layout : kPadLayouts)
    {
      for (const double squeeze : turn_squeezes)
      {
        for (int seed = 1; seed <= seeds; ++seed)
        {
          CylinderTurnOptions options;
          options.model = layout.model;
          options.params.pad_solver = layout.pad_solver;
          options.squeeze = squeeze;
          options.hand = drawOperator(static_cast<std::uint64_t>(seed), Eigen::Vector3d::UnitY());
          options.oriented = oriented;
          const CylinderTurnResult r = runCylinderTurn(options);
          std::cout << nlohmann::json{{"kind", "run"},
                                      {"task", "cylinder_turn"},
                                      {"layout", layout.name},
                                      {"oriented", oriented},
                                      {"squeeze_m", squeeze},
                                      {"seed", seed},
                                      {"held", r.held},
                                      {"turned", r.turned},
                                      {"turn_rad", r.turn_rad},
                                      {"final_tilt_rad", r.final_tilt_rad},
                                      {"max_tilt_rad", r.max_tilt_rad},
                                      {"max_slip_m", r.max_slip_m},
                                      {"mean_grip_force_N", r.mean_grip_force_N}}
                           .dump()
                    << std::endl;
        }
      }
    }
  }
  for (const PadLayout& layout : kPadLayouts)
  {
    for (const double squeeze : mug_squeezes)
    {
      for (int seed = 1; seed <= seeds; ++seed)
      {
        MugGraspOptions options;
        options.scenes_dir = GOD_FINGER_SCENES_DIR;
        options.model = layout.model;
        options.params.pad_solver = layout.pad_solver;
        options.squeeze = squeeze;
        // The misaligned finger (at 180 degrees) closes along x.
        options.hand = drawOperator(static_cast<std::uint64_t>(seed), Eigen::Vector3d::UnitX());
        const MugGraspResult r = runMugGrasp(options);
        std::cout << nlohmann::json{{"kind", "run"},
                                    {"task", "mug_grasp"},
                                    {"layout", layout.name},
                                    {"squeeze_m", squeeze},
                                    {"seed", seed},
                                    {"held", r.held},
                                    {"lifted", r.lifted},
                                    {"lift_height_m", r.lift_height_m},
                                    {"max_tilt_rad", r.max_tilt_rad},
                                    {"max_slip_m", r.max_slip_m},
                                    {"mean_grip_force_N", r.mean_grip_force_N}}
                         .dump()
                  << std::endl;
      }
    }
  }
  return 0;
}
