#include "god_finger/contact/primitive_walk.h"

#include "god_finger/contact/radial_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace god_finger
{
namespace
{
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A rim is reached when closer than this (m); a walk that stops within it of its start is
// dropped.
constexpr double kOnRim = 1e-12;
// Most rims one walk may cross (a long walk around a short, wide cylinder with tau_a >= 90).
constexpr int kMaxRims = 64;

// The first parameter u > 0 where rho cos(u - delta) falls to `level`, the walk starting at
// u = 0 inside the allowed region (rho cos(-delta) > level): delta + acos(level / rho); never
// (infinite) if the whole circle is allowed. Zero when even the start is not allowed.
double firstExit(double rho, double delta, double level)
{
  if (rho < 0.0)
  {
    // -|rho| cos(u - delta) = |rho| cos(u - delta - pi).
    rho = -rho;
    delta = std::remainder(delta + M_PI, 2.0 * M_PI);
  }
  if (!(rho * std::cos(delta) > level))
  {
    return 0.0;
  }
  if (!(rho > 0.0) || level / rho <= -1.0)
  {
    return kInfinity;
  }
  return delta + std::acos(std::min(1.0, level / rho));
}

// True when the allowed set of a circle (the normal turning in one plane) is one arc about the
// start no longer than a half turn, so that a walk of at most a half turn that ends inside it
// never left it: each level is at least 0 (limits of at most 90 degrees) or at most -1 (no limit
// but the single antipodal normal).
bool endpointDecides(const WalkLimits& limits)
{
  auto decides = [](double level) { return level >= 0.0 || level <= -1.0; };
  return decides(limits.cos_max_angle) && decides(limits.cos_friction);
}

// The surface normal's cosine to the contact normal is inside both limits.
bool inside(double cosine, const WalkLimits& limits)
{
  return cosine > limits.cos_max_angle && cosine > limits.cos_friction;
}

// Along a circle of parameter u (the normal turning as rho cos(u - delta) against the contact
// normal): the arc length before either limit, `scale` metres per unit of u, and which limit.
double limitedArc(double rho, double delta, double scale, const WalkLimits& limits, WalkStop* stop)
{
  const double s = limits.normal_sign;
  const double angle = scale * firstExit(s * rho, delta, limits.cos_max_angle);
  const double friction = scale * firstExit(s * rho, delta, limits.cos_friction);
  *stop = angle <= friction ? WalkStop::kAngleLimit : WalkStop::kFrictionLimit;
  return std::min(angle, friction);
}

WalkResult finish(const Eigen::Vector3d& position, double walked, int crossings, WalkStop stop)
{
  WalkResult result;
  result.position = position;
  result.location.face = -1;
  result.location.point = position;
  result.walked = walked;
  result.crossings = crossings;
  // A walk that cannot leave its start at all: the radial vector is dropped.
  result.stop = (walked <= kOnRim && stop != WalkStop::kDistanceReached) ? WalkStop::kDropped : stop;
  return result;
}

// From `n0` (unit, the start's outward normal) along `tangent` (unit, orthogonal to n0).
WalkResult walkSphere(double radius, const Eigen::Vector3d& n0, const Eigen::Vector3d& tangent, double distance,
                      const WalkLimits& limits)
{
  if (tangent.isZero())
  {
    // No direction along the surface: dropped, as the mesh walk drops a lost direction.
    return finish(radius * n0, 0.0, 0, WalkStop::kDirectionLost);
  }
  // n(phi) . c = a cos(phi) + b sin(phi) = rho cos(phi - delta).
  const double a = n0.dot(limits.contact_normal);
  const double b = tangent.dot(limits.contact_normal);
  const double reach = distance / radius;
  if (reach <= M_PI && endpointDecides(limits))
  {
    // The usual case, without inverse trigonometry: the end is inside the limits, so is the way.
    const double c = std::cos(reach);
    const double s = std::sin(reach);
    const double sign = limits.normal_sign;
    if (inside(sign * a, limits) && inside(sign * (a * c + b * s), limits))
    {
      WalkResult result;
      result.position = radius * (n0 * c + tangent * s);
      result.location.face = -1;
      result.location.point = result.position;
      result.walked = distance;
      return result;
    }
  }
  WalkStop stop = WalkStop::kDistanceReached;
  const double limit = limitedArc(std::hypot(a, b), std::atan2(b, a), radius, limits, &stop);
  const double walked = std::min(distance, limit);
  const double phi = walked / radius;
  return finish(radius * (n0 * std::cos(phi) + tangent * std::sin(phi)), walked, 0,
                walked < distance ? stop : WalkStop::kDistanceReached);
}

// The unit tangent at `n0` closest to `direction`; zero when `direction` has no tangential part.
Eigen::Vector3d tangentAt(const Eigen::Vector3d& n0, const Eigen::Vector3d& direction)
{
  const Eigen::Vector3d tangent = direction - n0 * n0.dot(direction);
  const double length = tangent.norm();
  return length > 1e-12 * direction.norm() ? Eigen::Vector3d(tangent / length) : Eigen::Vector3d::Zero();
}

// A point of the cylinder walk: on the mantle (angle theta, with its cosine and sine; height z;
// direction (along the circumference, along z)) or on a cap (top: +1, bottom: -1; point and
// direction in its plane).
struct CylinderState
{
  int cap = 0;  // 0: mantle
  double theta = 0.0;
  double cos_theta = 1.0;
  double sin_theta = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector2d along = Eigen::Vector2d::Zero();    // mantle: (circumferential, axial), unit
  Eigen::Vector3d heading = Eigen::Vector3d::Zero();  // cap: unit, z = 0

  void setTheta(double value)
  {
    theta = value;
    cos_theta = std::cos(value);
    sin_theta = std::sin(value);
  }
  Eigen::Vector3d outward() const
  {
    return Eigen::Vector3d(cos_theta, sin_theta, 0.0);
  }
  Eigen::Vector3d circumferential() const
  {
    return Eigen::Vector3d(-sin_theta, cos_theta, 0.0);
  }
};

// Where a walk from `start` begins: on the surface the contact normal faces (a cap if it is
// closer to the axis than to the radial plane), `start` projected onto it. Once per contact.
CylinderState cylinderStart(double radius, double half_length, const Eigen::Vector3d& start, const WalkLimits& limits)
{
  CylinderState state;
  const double planar = std::hypot(limits.contact_normal.x(), limits.contact_normal.y());
  if (std::abs(limits.contact_normal.z()) >= planar)
  {
    state.cap = limits.contact_normal.z() * limits.normal_sign >= 0.0 ? 1 : -1;
    Eigen::Vector3d on_cap(start.x(), start.y(), state.cap * half_length);
    const double r = std::hypot(on_cap.x(), on_cap.y());
    if (r > radius)
    {
      on_cap.head<2>() *= radius / r;
    }
    state.point = on_cap;
  }
  else
  {
    // On the axis the start's own angle is undefined: the contact normal's is used.
    const bool on_axis = std::hypot(start.x(), start.y()) < 1e-12 * radius;
    state.setTheta(on_axis ? std::atan2(limits.contact_normal.y(), limits.contact_normal.x())
                           : std::atan2(start.y(), start.x()));
    state.point = Eigen::Vector3d(radius * state.cos_theta, radius * state.sin_theta,
                                  std::clamp(start.z(), -half_length, half_length));
  }
  return state;
}

// From `state` (cylinderStart) along `direction`, projected onto the start's tangent plane.
WalkResult walkCylinder(double radius, double half_length, CylinderState state, const Eigen::Vector3d& direction,
                        double distance, const WalkLimits& limits)
{
  // The start's own surface may be beyond the limits (a contact normal far from it): dropped,
  // as the mesh walk drops a start face beyond them.
  if (const std::optional<WalkStop> start_blocked =
          surfaceLimit(state.cap != 0 ? Eigen::Vector3d(0.0, 0.0, state.cap) : state.outward(), limits))
  {
    return finish(state.point, 0.0, 0, *start_blocked);
  }
  // The direction along the surface; none (a direction along the normal): dropped.
  const Eigen::Vector2d on_cap(direction.x(), direction.y());
  const Eigen::Vector2d on_mantle(direction.dot(state.circumferential()), direction.z());
  const double length = state.cap != 0 ? on_cap.norm() : on_mantle.norm();
  if (!(length > 1e-12 * direction.norm()))
  {
    return finish(state.point, 0.0, 0, WalkStop::kDirectionLost);
  }
  if (state.cap != 0)
  {
    state.heading = Eigen::Vector3d(on_cap.x() / length, on_cap.y() / length, 0.0);
  }
  else
  {
    state.along = on_mantle / length;
  }
  const double sign = limits.normal_sign;
  const Eigen::Vector2d c_xy = limits.contact_normal.head<2>();
  double walked = 0.0;
  int crossings = 0;
  while (true)
  {
    const double remaining = distance - walked;
    if (state.cap == 0)
    {
      // Mantle: theta(s) = theta0 + along.x s / R, z(s) = z0 + along.y s.
      const double turn = state.along.x() / radius;
      const double to_rim = state.along.y() > 0.0   ? (half_length - state.point.z()) / state.along.y()
                            : state.along.y() < 0.0 ? (-half_length - state.point.z()) / state.along.y()
                                                    : kInfinity;
      const double candidate = std::min(remaining, std::max(0.0, to_rim));
      // The end of this stretch, by angle addition (one sine and cosine).
      const double delta = turn * candidate;
      const double cos_delta = std::cos(delta);
      const double sin_delta = std::sin(delta);
      const double cos_end = state.cos_theta * cos_delta - state.sin_theta * sin_delta;
      const double sin_end = state.sin_theta * cos_delta + state.cos_theta * sin_delta;
      WalkStop limit_stop = WalkStop::kDistanceReached;
      double limit = kInfinity;
      const bool decided = std::abs(delta) <= M_PI && endpointDecides(limits) &&
                           inside(sign * (c_xy.x() * state.cos_theta + c_xy.y() * state.sin_theta), limits) &&
                           inside(sign * (c_xy.x() * cos_end + c_xy.y() * sin_end), limits);
      if (decided)
      {
        // The end of this stretch is inside the limits, so is the way: no limit before it.
        state.theta += delta;
        state.cos_theta = cos_end;
        state.sin_theta = sin_end;
      }
      else
      {
        if (turn != 0.0)
        {
          const double beta = std::atan2(c_xy.y(), c_xy.x());
          // Measured along the turn: u = |turn| s, the normal's angle from beta is
          // sign(turn) (theta - beta).
          const double from = std::remainder(state.theta - beta, 2.0 * M_PI);
          limit = limitedArc(c_xy.norm(), turn > 0.0 ? -from : from, 1.0 / std::abs(turn), limits, &limit_stop);
        }
        else if (const std::optional<WalkStop> blocked = surfaceLimit(state.outward(), limits))
        {
          limit = 0.0;
          limit_stop = *blocked;
        }
        state.setTheta(state.theta + turn * std::min(candidate, limit));
      }
      const double step = std::min(candidate, limit);
      state.point = Eigen::Vector3d(radius * state.cos_theta, radius * state.sin_theta,
                                    std::clamp(state.point.z() + state.along.y() * step, -half_length, half_length));
      walked += step;
      if (step >= remaining)
      {
        return finish(state.point, distance, crossings, WalkStop::kDistanceReached);
      }
      if (step >= limit)
      {
        return finish(state.point, walked, crossings, limit_stop);
      }
      // The rim: onto the cap, if it may be entered and rims are left.
      const int cap = state.along.y() > 0.0 ? 1 : -1;
      const std::optional<WalkStop> blocked = surfaceLimit(Eigen::Vector3d(0.0, 0.0, cap), limits);
      if (blocked || crossings >= kMaxRims)
      {
        return finish(state.point, walked, crossings, blocked ? *blocked : WalkStop::kCrossingCap);
      }
      state.heading = state.along.x() * state.circumferential() - std::abs(state.along.y()) * state.outward();
      state.cap = cap;
      ++crossings;
    }
    else
    {
      // Cap: a straight line to the rim |p + s u| = R.
      const Eigen::Vector2d p = state.point.head<2>();
      const Eigen::Vector2d u = state.heading.head<2>();
      const double pu = p.dot(u);
      const double to_rim = -pu + std::sqrt(std::max(0.0, pu * pu + radius * radius - p.squaredNorm()));
      const double step = std::min(remaining, to_rim);
      state.point.head<2>() = p + u * step;
      walked += step;
      if (step >= remaining)
      {
        return finish(state.point, distance, crossings, WalkStop::kDistanceReached);
      }
      // The rim: onto the mantle, going away from the cap.
      state.setTheta(std::atan2(state.point.y(), state.point.x()));
      const std::optional<WalkStop> blocked = surfaceLimit(state.outward(), limits);
      if (blocked || crossings >= kMaxRims)
      {
        return finish(state.point, walked, crossings, blocked ? *blocked : WalkStop::kCrossingCap);
      }
      state.along = Eigen::Vector2d(state.heading.dot(state.circumferential()),
                                    -state.cap * std::max(0.0, state.heading.dot(state.outward())))
                        .normalized();
      state.point = Eigen::Vector3d(radius * state.cos_theta, radius * state.sin_theta, state.cap * half_length);
      state.cap = 0;
      ++crossings;
    }
  }
}
}  // namespace

WalkResult walkPrimitive(const PrimitiveSurface& surface, const Eigen::Vector3d& start,
                         const Eigen::Vector3d& direction, double distance, const WalkLimits& limits)
{
  if (!start.allFinite() || !direction.allFinite() || !std::isfinite(distance) || !(start.norm() > 0.0))
  {
    WalkResult invalid;
    invalid.stop = WalkStop::kInvalidInput;
    invalid.location.face = -1;
    return invalid;
  }
  if (surface.kind == PrimitiveSurface::Kind::kSphere)
  {
    const Eigen::Vector3d n0 = start.normalized();
    return walkSphere(surface.radius, n0, tangentAt(n0, direction), std::max(0.0, distance), limits);
  }
  const double half_length = 0.5 * surface.length;
  return walkCylinder(surface.radius, half_length, cylinderStart(surface.radius, half_length, start, limits), direction,
                      std::max(0.0, distance), limits);
}

void computeContactArea(const PrimitiveSurface& surface, const ContactQuery& query, const ContactParams& params,
                        ContactAreaResult* out)
{
  if (!beginContactArea(query, params, out) || !(surface.radius > 0.0))
  {
    out->radius = 0.0;
    return;
  }
  const Eigen::Vector3d& normal = out->normal;
  const WalkLimits limits = makeWalkLimits(params, normal, 1.0);
  const bool sphere = surface.kind == PrimitiveSurface::Kind::kSphere;
  const Eigen::Vector3d n0 = query.location.point.normalized();
  if (sphere && !n0.allFinite())
  {
    return;
  }
  const double half_length = 0.5 * surface.length;
  const CylinderState cylinder =
      sphere ? CylinderState() : cylinderStart(surface.radius, half_length, query.location.point, limits);
  const RadialDistances distances(out->radius, query.coupling, params);
  const int n = params.sub_god_objects;
  for (int i = 0; i < n; ++i)
  {
    SubGodObject& sgo = out->sub_god_objects[i];
    sgo.radial = radialVector(normal, out->first_tangent, i, n);
    sgo.target_distance = distances(sgo.radial);
    sgo.walk = sphere ? walkSphere(surface.radius, n0, tangentAt(n0, sgo.radial), sgo.target_distance, limits)
                      : walkCylinder(surface.radius, half_length, cylinder, sgo.radial, sgo.target_distance, limits);
    sgo.position = sgo.walk.position;
    if (!sgo.dropped())
    {
      ++out->active;
    }
  }
  out->count = n;
  out->valid = true;
}
}  // namespace god_finger
