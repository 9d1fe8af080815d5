// Parameter validation: the defaults are valid; every out-of-range value (including NaN) is
// reported with the parameter's name, the value and the allowed range.
#include "god_finger/contact/contact_params.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

namespace god_finger
{
namespace
{
TEST(ContactParams, DefaultsAreValid)
{
  EXPECT_EQ(validate(ContactParams()), "");
  EXPECT_NO_THROW(validateOrThrow(ContactParams()));
}

TEST(ContactParams, EveryBadValueIsNamedWithItsRange)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case
  {
    std::function<void(ContactParams&)> spoil;
    std::string expected;
  };
  const Case cases[] = {
      {[](ContactParams& p) { p.max_radius = 0.0; }, "parameter 'r_max' = 0 is out of range (0, 1000] (m)"},
      {[&](ContactParams& p) { p.max_radius = nan; }, "parameter 'r_max' = nan is out of range (0, 1000] (m)"},
      {[&](ContactParams& p) { p.max_radius = inf; }, "parameter 'r_max' = inf is out of range (0, 1000] (m)"},
      {[](ContactParams& p) { p.distance_constant = -0.004; }, "parameter 'd0' = -0.004 is out of range (0, 1000] (m)"},
      {[](ContactParams& p) { p.alpha = 0.5; }, "parameter 'alpha' = 0.5 is out of range [1, 100] (dimensionless)"},
      {[](ContactParams& p) { p.sub_god_objects = 2; }, "parameter 'n_sgo' = 2 is out of range [3, 64] (count)"},
      {[](ContactParams& p) { p.sub_god_objects = 65; }, "parameter 'n_sgo' = 65 is out of range [3, 64] (count)"},
      {[](ContactParams& p) { p.max_angle = 4.0; }, "parameter 'tau_a' = 4 is out of range (0, pi] (rad)"},
      {[](ContactParams& p) { p.max_angle = 0.0; }, "parameter 'tau_a' = 0 is out of range (0, pi] (rad)"},
      {[](ContactParams& p) { p.friction = -1.0; },
       "parameter 'friction' = -1 is out of range [0, inf] (dimensionless)"},
      {[&](ContactParams& p) { p.friction = nan; },
       "parameter 'friction' = nan is out of range [0, inf] (dimensionless)"},
      {[](ContactParams& p) { p.max_crossings = 0; },
       "parameter 'max_crossings' = 0 is out of range [1, 1000000] (count)"},
  };
  for (const Case& c : cases)
  {
    ContactParams params;
    c.spoil(params);
    EXPECT_EQ(validate(params), c.expected);
    try
    {
      validateOrThrow(params);
      ADD_FAILURE() << "no exception for " << c.expected;
    }
    catch (const InputError& error)
    {
      EXPECT_EQ(std::string(error.what()), c.expected);
    }
  }
}

TEST(ContactParams, LimitsOfTheRangesAreAccepted)
{
  ContactParams params;
  params.max_angle = M_PI;
  params.friction = std::numeric_limits<double>::infinity();
  params.alpha = 1.0;
  params.sub_god_objects = 3;
  EXPECT_EQ(validate(params), "");
  params.friction = 0.0;
  params.sub_god_objects = 64;
  params.alpha = 100.0;
  EXPECT_EQ(validate(params), "");
}

TEST(ContactParams, WalkVariantNames)
{
  WalkVariant variant = WalkVariant::kUnfold;
  EXPECT_TRUE(parseWalkVariant("project", &variant));
  EXPECT_EQ(variant, WalkVariant::kProject);
  EXPECT_STREQ(walkVariantName(variant), "project");
  EXPECT_TRUE(parseWalkVariant("unfold", &variant));
  EXPECT_EQ(variant, WalkVariant::kUnfold);
  EXPECT_FALSE(parseWalkVariant("sideways", &variant));
  EXPECT_EQ(variant, WalkVariant::kUnfold);
}
}  // namespace
}  // namespace god_finger
