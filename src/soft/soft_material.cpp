#include "god_finger/soft/soft_material.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"

#include <cmath>

namespace god_finger
{
namespace
{
const SoftMaterialRange kRanges[] = {
    {"young_modulus", &SoftMaterial::young_modulus, 1.0, 1e10, "Pa"},
    {"poisson_ratio", &SoftMaterial::poisson_ratio, 0.0, 0.49, ""},
    {"density", &SoftMaterial::density, 1e-3, 1e5, "kg/m^3"},
    {"stiffness_damping", &SoftMaterial::stiffness_damping, 0.0, 1.0, "s"},
    {"mass_damping", &SoftMaterial::mass_damping, 0.0, 1000.0, "1/s"},
};
}  // namespace

double SoftMaterial::shearModulus() const
{
  return young_modulus / (2.0 * (1.0 + poisson_ratio));
}

double SoftMaterial::lameLambda() const
{
  return young_modulus * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
}

const SoftMaterialRange* softMaterialRanges(int* count)
{
  *count = static_cast<int>(sizeof(kRanges) / sizeof(kRanges[0]));
  return kRanges;
}

SoftMaterial materialFromLame(double mu, double lambda)
{
  SoftMaterial material;
  material.young_modulus = mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
  material.poisson_ratio = lambda / (2.0 * (lambda + mu));
  return material;
}

void checkSoftMaterial(const SoftMaterial& material, const std::string& source)
{
  for (const SoftMaterialRange& range : kRanges)
  {
    const double value = material.*range.member;
    if (!(value >= range.low && value <= range.high))
    {
      throw InputError(source + ": " + range.name + " = " + roundedNumber(value) + " is out of range [" +
                       roundedNumber(range.low) + ", " + roundedNumber(range.high) + "]" +
                       (range.unit[0] != '\0' ? std::string(" (") + range.unit + ")" : std::string()));
    }
  }
}
}  // namespace god_finger
