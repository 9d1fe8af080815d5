#include "god_finger/scenarios/sheet_push_task.h"
#include "task_world.h"

#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/support/input_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace god_finger
{
namespace
{
constexpr double kLanded = 0.5;     // s
constexpr double kDragStart = 0.8;  // s
constexpr double kDragEnd = 2.8;    // s
constexpr double kEnd = 3.3;        // s
constexpr double kThickness = 0.002;
const Eigen::Vector2d kSheetSize(0.2, 0.15);
constexpr double kInset = 0.02;  // m, where the finger lands inside the corner

}  // namespace

SceneDescription sheetScene()
{
  SceneDescription scene;
  scene.name = "sheet";
  BodyDescription table = boxBody("table", Eigen::Vector3d(0.8, 0.6, 0.04), 0.0, Eigen::Vector3d(0, 0, -0.02));
  table.material.friction = 0.3;
  BodyDescription sheet = boxBody("sheet", Eigen::Vector3d(kSheetSize.x(), kSheetSize.y(), kThickness), 0.02,
                                  Eigen::Vector3d(0, 0, 0.5 * kThickness));
  sheet.material.friction = 0.8;
  scene.bodies = {table, sheet};
  return scene;
}

SheetPushResult runSheetPush(const SheetPushOptions& options)
{
  TaskWorld task("sheet push", "press", options.press, 0.05, sheetScene, options.params, options.model, "sheet");
  GodFingerWorld& world = task.world;
  const int sheet = task.object;
  const OperatorTraits& traits = options.hand;
  const double radius = options.params.coupling.proxy_radius;
  // Where the finger lands: inside the corner, moved in the plane by the misalignment.
  const Eigen::Vector3d corner(0.5 * kSheetSize.x() - kInset + traits.misalignment.x(),
                               0.5 * kSheetSize.y() - kInset + traits.misalignment.y(), kThickness + radius);
  const double above = 0.01;
  GripReflex reflex(traits.reaction_delay);
  double extra = 0.0;
  auto target = [&](double t) -> Eigen::Vector3d
  {
    const double press = options.press * (fluctuationAt(traits, t) + extra);
    const double down = (above + press) * minimumJerkRamp(t, 0.0, kLanded);
    return Eigen::Vector3d(corner.x() + kSheetDrag * minimumJerkRamp(t, kDragStart, kDragEnd), corner.y(),
                           corner.z() + above - down) +
           tremorAt(traits, t, 0);
  };
  const int finger = world.addInterface(target(0.0));
  const Eigen::Vector3d start = world.bodyState(sheet).center_of_mass;
  const double dt = world.params().time_step;
  SheetPushResult result;
  Eigen::Vector3d touch_on_sheet = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_slip = Eigen::Vector3d::Zero();
  double press_sum = 0.0;
  long press_samples = 0;
  bool dragging = false;
  for (long i = 0; i < std::lround(kEnd / dt); ++i)
  {
    const double t = (i + 1) * dt;
    world.setInterfaceTarget(finger, target(t));
    world.step();
    const BodyState state = world.bodyState(sheet);
    const Eigen::Vector3d proxy = world.interfaceState(finger).proxy_position;
    if (!dragging && t >= kDragStart)
    {
      dragging = true;
      touch_on_sheet = state.pose.inverse() * proxy;
    }
    if (!dragging || t > kDragEnd)
    {
      continue;
    }
    Eigen::Vector3d slip = state.pose * touch_on_sheet - proxy;
    slip.z() = 0.0;  // in the plane: tremor moves the finger up and down on a held sheet
    result.max_slip_m = std::max(result.max_slip_m, slip.norm());
    extra = reflex.update(t, (slip - previous_slip).norm() / dt);
    previous_slip = slip;
    const Eigen::Vector3d x_axis = state.pose.linear().col(0);
    result.turn_rad = std::max(result.turn_rad, std::abs(std::atan2(x_axis.y(), x_axis.x())));
    press_sum += std::abs(world.interfaceState(finger).user_force.z());
    ++press_samples;
  }
  result.translation_m = world.bodyState(sheet).center_of_mass.x() - start.x();
  result.mean_press_N = press_samples > 0 ? press_sum / press_samples : 0.0;
  result.translated = result.translation_m >= 0.08 && result.turn_rad <= 0.1;
  return result;
}
}  // namespace god_finger
