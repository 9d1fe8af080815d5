// Parameters of the god-finger contact area (paper, section 3): the struct with its defaults
// and the one table of their names, units, ranges and meanings (support/parameter_table.h).
// validate() names the first bad parameter, its value and its range.
#pragma once

#include "god_finger/support/parameter_table.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace god_finger
{
// How a walk carries its direction onto the next face (Algorithm 1, "projection of r_i on f").
enum class WalkVariant : std::uint8_t
{
  // The paper: the direction is projected orthogonally onto the new face's plane and
  // renormalised. Bends the path towards the steepest direction of a fold; cannot cross a
  // fold of 90 degrees or more (the projection no longer enters the face).
  kProject = 0,
  // The direction is rotated about the crossed edge onto the new face (the face is unfolded
  // into the plane of the old one): the walk is a straight line of the unfolded strip, the
  // exact geodesic of the polyhedron.
  kUnfold = 1,
};
const char* walkVariantName(WalkVariant variant);
// Parses "project" / "unfold"; returns false on anything else.
bool parseWalkVariant(const std::string& text, WalkVariant* variant);

// Defaults here, names, units, ranges and meanings in contactParameterTable().
struct ContactParams
{
  double max_radius = 0.01;          // r_max (m), Eq. 1: a fingertip pad (Barbagli et al.: 5-10 mm)
  double distance_constant = 0.001;  // D0' (m), Eq. 1: r reaches 63 % of r_max at 0.4 N on 400 N/m
  double alpha = 2.0;                // alpha (1), Eq. 2: the paper's Fig. 4
  int sub_god_objects = 8;           // n_SGO
  double max_angle = M_PI / 3.0;     // tau_a (rad): a finger pad does not wrap further
  double friction = 1.0;             // theta (1): +inf disables the cone
  WalkVariant walk = WalkVariant::kUnfold;
  int max_crossings = 4096;  // so that no input can loop forever

  static constexpr int kMaxSubGodObjects = 64;
};

// r_max, d0, alpha, n_sgo, tau_a, friction, walk, max_crossings.
const ParameterTable<ContactParams>& contactParameterTable();

// Empty when every parameter is in range; otherwise one line such as
// "parameter 'alpha' = 0.5 is out of range [1, 100] (dimensionless)".
std::string validate(const ContactParams& params);
// Throws InputError with validate()'s message.
void validateOrThrow(const ContactParams& params);
}  // namespace god_finger
