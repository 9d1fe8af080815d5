#include "god_finger/core/contact_params.h"

#include "god_finger/core/input_error.h"

#include <cmath>
#include <sstream>

namespace god_finger
{
const char* walkVariantName(WalkVariant variant)
{
  return variant == WalkVariant::kProject ? "project" : "unfold";
}

bool parseWalkVariant(const std::string& text, WalkVariant* variant)
{
  if (text == "project")
  {
    *variant = WalkVariant::kProject;
    return true;
  }
  if (text == "unfold")
  {
    *variant = WalkVariant::kUnfold;
    return true;
  }
  return false;
}

std::string validate(const ContactParams& params)
{
  // Written as !(in range) so that NaN is out of range.
  if (!(params.max_radius > 0.0 && params.max_radius <= 1e3))
  {
    return outOfRange("r_max", params.max_radius, "(0, 1000]", "m");
  }
  if (!(params.distance_constant > 0.0 && params.distance_constant <= 1e3))
  {
    return outOfRange("d0", params.distance_constant, "(0, 1000]", "m");
  }
  if (!(params.alpha >= 1.0 && params.alpha <= 100.0))
  {
    return outOfRange("alpha", params.alpha, "[1, 100]", "dimensionless");
  }
  if (!(params.sub_god_objects >= 3 && params.sub_god_objects <= ContactParams::kMaxSubGodObjects))
  {
    return outOfRange("n_sgo", params.sub_god_objects, "[3, 64]", "count");
  }
  if (!(params.max_angle > 0.0 && params.max_angle <= M_PI))
  {
    return outOfRange("tau_a", params.max_angle, "(0, pi]", "rad");
  }
  if (!(params.friction >= 0.0))
  {
    return outOfRange("friction", params.friction, "[0, inf]", "dimensionless");
  }
  if (!(params.max_crossings >= 1 && params.max_crossings <= 1000000))
  {
    return outOfRange("max_crossings", params.max_crossings, "[1, 1000000]", "count");
  }
  if (params.walk != WalkVariant::kProject && params.walk != WalkVariant::kUnfold)
  {
    return "parameter 'walk' = " + std::to_string(static_cast<int>(params.walk)) + " is not 'project' or 'unfold'";
  }
  return std::string();
}

void validateOrThrow(const ContactParams& params)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
}
}  // namespace god_finger
