// How well a soft block's finite elements reproduce the elastic solution under a finger, for a
// pad (god_finger, soft_finger: a pressure over an area) and a point (god_object).
//
// The set-up (issue 28, item 4): a cube of side L (E, nu) glued to the table by its bottom face,
// meshed by blockTetMesh() with about `nodes` nodes graded toward the top face's centre.
//  - Pad: a force F spread as a uniform pressure p = F / (pi a^2) over a disk of radius a at the
//    top face's centre. On an elastic half-space the centre sinks by Boussinesq's
//    w0 = 2 (1 - nu^2) p a / E; the block is finite (L = 10 a by default), so the converged value
//    sits a few per cent below w0 (reported as the finest mesh's).
//  - Point: the same F at the centre point. The half-space's displacement under a point load is
//    infinite; the mesh's grows without bound as it is refined (the curve that shows it).
//  - Plate (a check of the material): the top face pressed down uniformly by a plate with the
//    bottom on rollers: the block shortens by exactly F L / (E A) (linear tetrahedra represent a
//    uniform strain exactly).
// Static solutions (K u = f): what a held press settles to. Units SI; displacements positive
// downward. Not real-time.
#pragma once

#include <string>

namespace god_finger
{
struct SoftPressSetup
{
  double young_modulus = 50e3;  // Pa
  double poisson_ratio = 0.45;
  double block_size = 0.1;   // m, the cube's side
  double pad_radius = 0.01;  // m
  double force = 1.0;        // N, pressing down
  int nodes = 1000;          // about; the cube gets round(cbrt(nodes)) nodes per side
  double grading = 1.6;      // blockTetMesh()'s
};

struct SoftPressResult
{
  int nodes = 0;
  int tets = 0;
  double boussinesq = 0.0;        // w0 (m)
  double pad_centre = 0.0;        // the pad's centre displacement (m)
  double point_centre = 0.0;      // the point load's (m)
  double covered_area = 0.0;      // the pad's area on the mesh (m^2); pi a^2 exactly in the limit
  double plate_shortening = 0.0;  // the plate test's (m)
  double plate_expected = 0.0;    // F L / (E A) (m)
  long factor_nonzeros = 0;       // the implicit step's factor: what a step's solve costs
};

SoftPressResult pressSoftBlock(const SoftPressSetup& setup);

// The result as one JSON object (one line).
std::string softPressJson(const SoftPressSetup& setup, const SoftPressResult& result);
}  // namespace god_finger
