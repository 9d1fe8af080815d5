// The god-finger contact area (paper, section 3): from one contact point, normal, depth and
// the coupling vector v = p_I - p_GO, the positions of n_SGO sub-god-objects on the mesh.
//
// Conventions (all vectors in the mesh frame, metres):
//  - c_n is the unit contact normal pointing OUT of the touched object (towards the finger).
//    Pressing pushes the interface into the object, so v . c_n < 0.
//  - Eq. 1: r = r_max (1 - exp(-s / D0')) with s = max(0, -v . c_n), the coupling spring's
//    compression along the normal. The paper's -v.c_n sign with c_n outward; s is clamped so
//    that r = 0 when the finger pulls away and r is never negative; r -> r_max as s grows.
//  - Eq. 2: d_i = r * alpha^(-(v/|v|) . r_i), with the exponent 0 when |v| = 0 (then d_i = r).
//    r_i is the radial vector orthogonal to c_n, before it is carried onto a face; a
//    tangential push along r_i shortens d_i and lengthens the opposite side (the area spreads
//    backwards, the paper's Fig. 4).
//  - Every sub-god-object has the true contact's normal and depth (the paper, end of 3.2).
//  - Edge and vertex contacts: each radial vector goes to the incident face whose wedge at
//    the contact contains it (chooseStartFace); it is dropped if that face is beyond tau_a
//    or the friction cone (kDropped). Dropped entries stay in the array, flagged.
//  - No heap allocation: the result has a fixed capacity of ContactParams::kMaxSubGodObjects.
#pragma once

#include "god_finger/contact/contact_params.h"
#include "god_finger/contact/surface_walk.h"

#include <array>
#include <cmath>

namespace god_finger
{
struct ContactQuery
{
  SurfaceLocation location;                            // c_p on the mesh (face, barycentric, feature)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // c_n, unit, outward
  double depth = 0.0;                                  // c_d (m), copied to every sub-god-object
  Eigen::Vector3d coupling = Eigen::Vector3d::Zero();  // v = p_I - p_GO (m)
  // The previous step's first radial vector, for a basis continuous in time (radial_frame.h);
  // zero for none.
  Eigen::Vector3d reference_tangent = Eigen::Vector3d::Zero();
};

struct SubGodObject
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, on the mesh
  Eigen::Vector3d radial = Eigen::Vector3d::Zero();    // r_i, unit, orthogonal to c_n
  double target_distance = 0.0;                        // d_i (m)
  WalkResult walk;                                     // where and why the walk ended
  bool dropped() const
  {
    return walk.stop == WalkStop::kDropped;
  }
};

struct ContactAreaResult
{
  bool valid = false;   // false: bad input (non-finite, location off the mesh); count = 0
  double radius = 0.0;  // r (m), Eq. 1
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double depth = 0.0;
  Eigen::Vector3d first_tangent = Eigen::Vector3d::UnitX();  // pass back as reference_tangent
  int count = 0;                                             // entries used in sub_god_objects
  int active = 0;                                            // entries not dropped
  std::array<SubGodObject, ContactParams::kMaxSubGodObjects> sub_god_objects;
};

// Eq. 1. `coupling` is v, `normal` is c_n (unit, outward). Never negative, never NaN for
// finite input.
double contactRadius(const Eigen::Vector3d& coupling, const Eigen::Vector3d& normal, const ContactParams& params);
// Eq. 2 for one unit radial vector.
double radialDistance(double radius, const Eigen::Vector3d& coupling, const Eigen::Vector3d& radial,
                      const ContactParams& params);
// Eq. 2 prepared once per contact area: d_i = r exp(k . r_i) with k = -ln(alpha) v / |v| (one
// exp per sub-god-object instead of a norm and a pow). radialDistance is this.
struct RadialDistances
{
  double radius = 0.0;
  Eigen::Vector3d k = Eigen::Vector3d::Zero();
  RadialDistances(double radius, const Eigen::Vector3d& coupling, const ContactParams& params);
  double operator()(const Eigen::Vector3d& radial) const
  {
    return radius * std::exp(k.dot(radial));
  }
};

// What computing a contact area begins with on any surface: clears `out`; false (and `out`
// invalid and empty) on a non-finite point, coupling or depth or a normal shorter than 1e-9;
// else sets its point, unit normal, depth, radius (Eq. 1) and first tangent. Used by both
// computeContactArea overloads (this one and contact/primitive_walk.h's).
bool beginContactArea(const ContactQuery& query, const ContactParams& params, ContactAreaResult* out);

// The whole method for one contact. `params` must be valid (validate()); `out` is
// overwritten. Never allocates, never throws.
void computeContactArea(const TriangleMesh& mesh, const ContactQuery& query, const ContactParams& params,
                        ContactAreaResult* out);
}  // namespace god_finger
