#include "god_finger/physics/oriented_finger.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace god_finger
{
namespace
{
// The rotation vector (axis times angle, angle in [0, pi]) of a unit quaternion.
Eigen::Vector3d rotationVector(const Eigen::Quaterniond& q)
{
  const Eigen::Quaterniond shortest = q.w() < 0.0 ? Eigen::Quaterniond(-q.w(), -q.x(), -q.y(), -q.z()) : q;
  const double sine = shortest.vec().norm();
  if (sine < 1e-12)
  {
    return 2.0 * shortest.vec();  // first order: exact as the angle goes to 0
  }
  return (2.0 * std::atan2(sine, shortest.w()) / sine) * shortest.vec();
}

Eigen::Quaterniond fromRotationVector(const Eigen::Vector3d& v)
{
  const double angle = v.norm();
  if (angle < 1e-12)
  {
    return Eigen::Quaterniond(1.0, 0.5 * v.x(), 0.5 * v.y(), 0.5 * v.z()).normalized();
  }
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle));
}
}  // namespace

void FingerOrientation::restart()
{
  target = initial;
  previous_target = initial;
  proxy = initial;
  angular_velocity.setZero();
}

Eigen::Vector3d stepFingerOrientation(const OrientedFingerParams& params, double dt, FingerOrientation* state)
{
  const Eigen::Vector3d target_velocity = rotationVector(state->target * state->previous_target.conjugate()) / dt;
  const Eigen::Vector3d torque =
      params.orientation_stiffness * rotationVector(state->target * state->proxy.conjugate()) +
      params.orientation_damping * (target_velocity - state->angular_velocity);
  state->angular_velocity += torque * (dt / params.proxy_inertia);
  state->proxy = (fromRotationVector(state->angular_velocity * dt) * state->proxy).normalized();
  state->previous_target = state->target;
  return torque;
}

bool limitFingerByContacts(const Eigen::Vector3d* normals, int count, FingerOrientation* state)
{
  constexpr int kPasses = 3;
  const double bound = std::sin(kFingerBodyClearance);
  bool turned = false;
  for (int pass = 0; pass < kPasses; ++pass)
  {
    bool inside = false;
    for (int i = 0; i < count; ++i)
    {
      const Eigen::Vector3d& normal = normals[i];
      const Eigen::Vector3d axis = state->proxy * Eigen::Vector3d::UnitX();
      const double into = axis.dot(normal);  // sin of the angle the body went into the surface
      if (!(into > bound))
      {
        continue;
      }
      inside = true;
      turned = true;
      Eigen::Vector3d on_plane = axis - into * normal;  // then tilted back in by the clearance
      if (on_plane.norm() < 1e-9)
      {
        // The body straight into the surface (a finger arriving backwards): lay it down
        // along its own pulp's side of the plane.
        on_plane = state->proxy * Eigen::Vector3d::UnitZ();
        on_plane -= on_plane.dot(normal) * normal;
        if (on_plane.norm() < 1e-9)
        {
          on_plane = normal.unitOrthogonal();
        }
      }
      const Eigen::Vector3d allowed = std::sqrt(1.0 - bound * bound) * on_plane.normalized() + bound * normal;
      state->proxy = (Eigen::Quaterniond::FromTwoVectors(axis, allowed) * state->proxy).normalized();
      // d(x . n)/dt = w . (x x n): keep none of w that turns the body further in.
      const Eigen::Vector3d lever = (state->proxy * Eigen::Vector3d::UnitX()).cross(normal);
      const double lever_norm2 = lever.squaredNorm();
      const double inward = state->angular_velocity.dot(lever);
      if (lever_norm2 > 1e-18 && inward > 0.0)
      {
        state->angular_velocity -= (inward / lever_norm2) * lever;
      }
    }
    if (!inside)
    {
      break;
    }
  }
  return turned;
}

PulpContact pulpContact(const Eigen::Quaterniond& finger, const Eigen::Vector3d& surface_normal,
                        const OrientedFingerParams& params)
{
  PulpContact contact;
  const Eigen::Vector3d pulp = finger * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d inward = -surface_normal;
  contact.tilt = std::atan2(pulp.cross(inward).norm(), pulp.dot(inward));
  if (!(contact.tilt < params.nail_angle))
  {
    contact.radius_scale = 0.0;
    return contact;
  }
  contact.radius_scale = std::cos(0.5 * M_PI * contact.tilt / params.nail_angle);
  const Eigen::Vector3d tangent = pulp - pulp.dot(surface_normal) * surface_normal;
  const double length = tangent.norm();
  if (length > 1e-12)
  {
    contact.offset = (params.fingertip_radius * contact.tilt / length) * tangent;
  }
  return contact;
}

std::string orientationStabilityError(const OrientedFingerParams& params, double time_step)
{
  const double stability =
      (params.orientation_stiffness * time_step + 2.0 * params.orientation_damping) * time_step / params.proxy_inertia;
  if (stability < 4.0)
  {
    return "";
  }
  std::ostringstream message;
  message << "orientation coupling unstable at this time step: (orientation_stiffness * dt + 2 orientation_damping) * "
             "dt / proxy_inertia = "
          << stability << " must be < 4 (orientation_stiffness " << params.orientation_stiffness
          << " N m/rad, orientation_damping " << params.orientation_damping << " N m s/rad, proxy_inertia "
          << params.proxy_inertia << " kg m^2, dt " << time_step
          << " s): lower the stiffness, damping or time step, or raise proxy_inertia";
  return message.str();
}
}  // namespace god_finger
