// The paper's pencil-versus-finger example: one finger presses a sheet near its corner and
// drags it along the table. "With the pencil tip, the paper will most likely rotate, while with
// a fingertip it will most likely translate." A task of the operator benchmark
// (bench/operator_bench.cpp), by a perfect or a human-like hand (human_operator.h: its tremor,
// its misalignment as an offset of where the finger lands, its fluctuation on the press, its
// reflex pressing harder when the sheet slips under the finger).
//
// Scene (sheetScene): a static table (top at z = 0, mu 0.3 against the sheet: Bullet multiplies
// the two coefficients) and a sheet of 0.2 x 0.15 x 0.002 m (20 g, mu 0.8) lying on it, centred
// at the origin. The finger lands 2 cm inside the corner (+x, +y), presses down with the
// coupling stretch `press` (N = k press), and drags the sheet 10 cm along +x in 2 s (minimum-jerk
// profiles: land in 0.5 s, wait 0.3 s, drag, hold 0.5 s). Deterministic. Units SI, world frame
// (z up). Not real-time (builds a world).
#pragma once

#include "god_finger/physics/contact_model.h"
#include "god_finger/scenarios/human_operator.h"
#include "god_finger/scene/scene_description.h"
#include "god_finger/physics/world_params.h"

namespace god_finger
{
constexpr double kSheetDrag = 0.1;  // m along +x

SceneDescription sheetScene();

struct SheetPushOptions
{
  ContactModel model = ContactModel::kGodFinger;
  double press = 0.005;  // m, nominal coupling stretch into the sheet
  OperatorTraits hand = perfectOperator();
  WorldParams params;
};

struct SheetPushResult
{
  double translation_m = 0.0;  // of the sheet's centre, along the drag, at the end
  double turn_rad = 0.0;       // the sheet's largest rotation about z during the drag
  double max_slip_m = 0.0;     // the finger's point on the sheet against the finger, in the plane
  double mean_press_N = 0.0;   // the finger's vertical coupling force, mean over the drag
  bool translated = false;     // moved at least 8 cm, turning at most 0.1 rad
};

// Throws InputError on a press outside (0, 0.05] m or bad world parameters.
SheetPushResult runSheetPush(const SheetPushOptions& options);
}  // namespace god_finger
