// Parameters of the god-finger contact area (paper, section 3), with units, defaults and
// allowed ranges. validate() names the first bad parameter, its value and its range.
#pragma once

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

struct ContactParams
{
  // r_max (m), Eq. 1: radius of the contact area under an infinite pressing force.
  // Range (0, 1e3]. Default 1 cm: a fingertip pad (Barbagli et al. measure 5-10 mm).
  double max_radius = 0.01;
  // D0' (m), Eq. 1: coupling-spring compression at which r reaches 63 % of r_max.
  // Range (0, 1e3]. Default 4 mm: about 4 N on a 1 kN/m coupling.
  double distance_constant = 0.004;
  // alpha (1), Eq. 2: how far a tangential force pushes the area backwards; 1 keeps it round.
  // Range [1, 100]. Default 2 (the paper's Fig. 4).
  double alpha = 2.0;
  // n_SGO (1): radial vectors, hence sub-god-objects. Range [3, 64]. Default 8.
  int sub_god_objects = 8;
  // tau_a (rad): largest angle between the contact normal and a face normal that the area
  // spreads onto. Range (0, pi]. Default pi/3: a finger pad does not wrap further.
  double max_angle = 1.0471975511965976;
  // theta (1): friction coefficient of the friction cone (stop where the face normal leaves
  // atan(theta) around the contact normal). Range [0, +inf]; +inf disables the cone.
  // Default 1.0.
  double friction = 1.0;
  WalkVariant walk = WalkVariant::kUnfold;
  // Hard cap on edges crossed by one walk, so no input can loop forever. Range [1, 1e6].
  int max_crossings = 4096;

  static constexpr int kMaxSubGodObjects = 64;
};

// Empty when every parameter is in range; otherwise one line such as
// "parameter 'alpha' = 0.5 is out of range [1, 100] (dimensionless)".
std::string validate(const ContactParams& params);
// Throws InputError with validate()'s message.
void validateOrThrow(const ContactParams& params);
}  // namespace god_finger
