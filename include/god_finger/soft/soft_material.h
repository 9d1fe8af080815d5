// The material of a soft body: isotropic linear elasticity (Young's modulus and Poisson's ratio,
// or Lamé's mu and lambda as PyBullet's <neohookean>/<corotated> give them), density and
// Rayleigh damping (C = alpha M + beta K). Units SI: Pa, kg/m^3, s.
// Invariants after checkSoftMaterial(): every value finite and in softMaterialRanges()' ranges
// (Poisson's ratio below 0.5: an incompressible material has no finite bulk modulus).
#pragma once

#include <string>

namespace god_finger
{
struct SoftMaterial
{
  double young_modulus = 0.0;      // E (Pa)
  double poisson_ratio = 0.0;      // nu
  double density = 0.0;            // rho (kg/m^3)
  double stiffness_damping = 0.0;  // Rayleigh beta (s)
  double mass_damping = 0.0;       // Rayleigh alpha (1/s)

  double shearModulus() const;  // Lamé mu = E / (2 (1 + nu)) (Pa)
  double lameLambda() const;    // Lamé lambda = E nu / ((1 + nu)(1 - 2 nu)) (Pa)
};

// One entry of the material's ranges (what checkSoftMaterial() enforces, and the docs list).
struct SoftMaterialRange
{
  const char* name;
  double SoftMaterial::*member;
  double low;
  double high;
  const char* unit;
};
// The ranges, one per member of SoftMaterial.
const SoftMaterialRange* softMaterialRanges(int* count);

// E and nu of Lamé's mu (> 0) and lambda (>= 0): E = mu (3 lambda + 2 mu) / (lambda + mu),
// nu = lambda / (2 (lambda + mu)). Density and damping are left 0.
SoftMaterial materialFromLame(double mu, double lambda);

// Throws InputError naming `source`, the value and its range for the first value out of range.
void checkSoftMaterial(const SoftMaterial& material, const std::string& source);
}  // namespace god_finger
