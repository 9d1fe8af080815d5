// The servo loop's parameter table (runtime/servo_loop.h): the docs show it as generated,
// its defaults are valid and each bound is enforced with the parameter named.
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/support/input_error.h"

#include "docs_text.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace god_finger
{
namespace
{
TEST(LoopParameters, TheDocsShowTheTableAsGenerated)
{
  const std::string table = markdownTable(servoLoopParameterTable());
  EXPECT_NE(test::docsText().find(table), std::string::npos) << "the docs lack the servo loop's table:\n" << table;
}

TEST(LoopParameters, DefaultsAreValidAndBoundsNamed)
{
  EXPECT_EQ(validate(ServoLoopParams{}), "");
  ServoLoopParams params;
  params.rate = 5.0;
  EXPECT_EQ(validate(params), "parameter 'rate' = 5 is out of range [10, 10000] (Hz)");
  MapParameterSource source("/servo/");
  source.set("realtime_priority", ParameterValue::ofInteger(120));
  ServoLoopParams read;
  try
  {
    readRows(source, servoLoopParameterTable(), &read);
    FAIL() << "accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "parameter '/servo/realtime_priority' = 120 is out of range [0, 99] (count)");
  }
}
}  // namespace
}  // namespace god_finger
