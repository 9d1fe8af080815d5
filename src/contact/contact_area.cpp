#include "god_finger/contact/contact_area.h"

#include "god_finger/contact/radial_frame.h"

#include <cmath>

namespace god_finger
{
double contactRadius(const Eigen::Vector3d& coupling, const Eigen::Vector3d& normal, const ContactParams& params)
{
  // s: compression of the coupling spring along the outward normal (v points into the object).
  const double compression = std::max(0.0, -coupling.dot(normal));
  // -expm1(-x) = 1 - exp(-x), accurate for small x; exactly r_max once exp underflows.
  return params.max_radius * -std::expm1(-compression / params.distance_constant);
}

RadialDistances::RadialDistances(double radius_in, const Eigen::Vector3d& coupling, const ContactParams& params)
    : radius(radius_in)
{
  // alpha^(-(v/|v|) . r_i) = exp(-ln(alpha) (v/|v|) . r_i); the exponent is 0 when |v| = 0.
  const double length = coupling.norm();
  if (length > 0.0)
  {
    k = coupling * (-std::log(params.alpha) / length);
  }
}

double radialDistance(double radius, const Eigen::Vector3d& coupling, const Eigen::Vector3d& radial,
                      const ContactParams& params)
{
  return RadialDistances(radius, coupling, params)(radial);
}

bool beginContactArea(const ContactQuery& query, const ContactParams& params, ContactAreaResult* out)
{
  out->valid = false;
  out->count = 0;
  out->active = 0;
  out->radius = 0.0;
  const double normal_length = query.normal.norm();
  if (!query.location.point.allFinite() || !std::isfinite(normal_length) || normal_length < 1e-9 ||
      !query.coupling.allFinite() || !std::isfinite(query.depth))
  {
    return false;
  }
  out->point = query.location.point;
  out->normal = query.normal / normal_length;
  out->depth = query.depth;
  out->radius = contactRadius(query.coupling, out->normal, params);
  out->first_tangent = transportTangent(query.reference_tangent, out->normal);
  return true;
}

void computeContactArea(const TriangleMesh& mesh, const ContactQuery& query, const ContactParams& params,
                        ContactAreaResult* out)
{
  const SurfaceLocation& location = query.location;
  const bool on_mesh = location.face >= 0 && location.face < mesh.triangleCount() && location.barycentric.allFinite();
  if (!beginContactArea(query, params, out) || !on_mesh)
  {
    out->radius = 0.0;
    return;
  }
  const Eigen::Vector3d& normal = out->normal;
  const double sign = mesh.normals()[location.face].dot(normal) < 0.0 ? -1.0 : 1.0;
  const WalkLimits limits = makeWalkLimits(params, normal, sign);

  const RadialDistances distances(out->radius, query.coupling, params);
  const int n = params.sub_god_objects;
  for (int i = 0; i < n; ++i)
  {
    SubGodObject& sgo = out->sub_god_objects[i];
    sgo.radial = radialVector(normal, out->first_tangent, i, n);
    sgo.target_distance = distances(sgo.radial);
    SurfaceLocation start;
    Eigen::Vector3d direction;
    WalkStop stop = WalkStop::kDropped;
    if (chooseStartFace(mesh, location, sgo.radial, normal, limits, &start, &direction, &stop))
    {
      sgo.walk = walkSurface(mesh, start, direction, sgo.target_distance, limits);
      ++out->active;
    }
    else
    {
      sgo.walk = WalkResult();
      sgo.walk.location = location;
      sgo.walk.position = location.point;
      sgo.walk.stop = stop;
    }
    sgo.position = sgo.walk.position;
  }
  out->count = n;
  out->valid = true;
}
}  // namespace god_finger
