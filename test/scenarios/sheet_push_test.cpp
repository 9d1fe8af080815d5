// The paper's pencil-versus-finger example (scenarios/sheet_push_task.h): dragged by its corner
// under a light press, a sheet turns under a point (the god-object, "the pencil tip") and
// translates under a pad ("a fingertip"): god_finger and soft_finger.
#include "god_finger/support/input_error.h"
#include "god_finger/scenarios/sheet_push_task.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace god_finger
{
namespace
{
SheetPushResult push(ContactModel model, double press)
{
  SheetPushOptions options;
  options.model = model;
  options.press = press;
  const SheetPushResult result = runSheetPush(options);
  std::printf("[ sheet %-11s press %.1f mm ] translation %.4f m, turn %.4f rad, press %.2f N\n",
              contactModelName(model), press * 1e3, result.translation_m, result.turn_rad, result.mean_press_N);
  return result;
}

TEST(SheetPush, APencilTurnsTheSheetAFingertipTranslatesIt)
{
  const SheetPushResult pencil = push(ContactModel::kGodObject, 0.0025);
  EXPECT_GT(pencil.turn_rad, 0.2);
  EXPECT_FALSE(pencil.translated);
  for (const ContactModel pad : {ContactModel::kGodFinger, ContactModel::kSoftFinger})
  {
    SCOPED_TRACE(contactModelName(pad));
    const SheetPushResult finger = push(pad, 0.0025);
    EXPECT_LT(finger.turn_rad, 0.02);
    EXPECT_NEAR(finger.translation_m, kSheetDrag, 0.005);
    EXPECT_TRUE(finger.translated);
  }
}

TEST(SheetPush, ABadPressIsRefused)
{
  SheetPushOptions options;
  options.press = 0.0;
  EXPECT_THROW(runSheetPush(options), InputError);
  options.press = 0.06;
  EXPECT_THROW(runSheetPush(options), InputError);
}
}  // namespace
}  // namespace god_finger
