// Random contacts over a mesh, and the check that a computed contact area is sound; shared by
// the contact tool (god_finger_contact), the hard-case tests and the fuzz target.
//
// RandomContacts: faces drawn by area, points uniform on the face, the contact normal the
// face's; coupling v = -c n + t (c uniform in [0, 3 D0'], |t| uniform in [0, c], direction
// uniform), depth c. Deterministic for a seed on every standard library (raw generator bits).
// contactAreaDefect: "" when the area is sound, else why: a non-finite value, or a kept
// sub-god-object off the mesh (farther than `tolerance`, m), farther in a straight line from
// the contact point than it walked, or having walked beyond its target distance.
#pragma once

#include "god_finger/contact/contact_area.h"
#include "god_finger/geometry/surface_locator.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace god_finger
{
class RandomContacts
{
 public:
  // Throws InputError when the mesh has no area.
  RandomContacts(const TriangleMesh& mesh, const ContactParams& params, std::uint64_t seed);
  ContactQuery next();

 private:
  double unit();  // uniform in [0, 1)

  const TriangleMesh* mesh_;
  double distance_constant_;
  std::vector<double> cumulative_area_;
  std::mt19937_64 random_;
};

std::string contactAreaDefect(const SurfaceLocator& locator, const ContactQuery& query, const ContactAreaResult& area,
                              double tolerance);
}  // namespace god_finger
