#include "god_finger/scenarios/soft_contact_metrics.h"

#include "god_finger/scene/deformable_object.h"
#include "god_finger/soft/surface_load.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace god_finger
{
namespace
{
constexpr double kMeasuredHold = 0.5;  // s: press_soft's metrics come from the run's last 0.5 s
constexpr double kStuckSpeed = 1e-3;   // m/s
constexpr double kSlipSpeed = 5e-3;    // m/s

// The best-fit rigid motion (Eigen's umeyama, no scaling) taking `from` onto `to` (same vertices).
Eigen::Isometry3d bestFitMotion(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to)
{
  const auto n = static_cast<Eigen::Index>(from.size());
  const Eigen::Map<const Eigen::Matrix3Xd> a(from.front().data(), 3, n);
  const Eigen::Map<const Eigen::Matrix3Xd> b(to.front().data(), 3, n);
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.matrix() = Eigen::umeyama(a, b, false);
  return motion;
}
}  // namespace

SoftContactMetrics::SoftContactMetrics(Scenario scenario, int object, const ScenarioTimes& times,
                                       const GodFingerWorld& world)
    : scenario_(scenario), object_(object), times_(times)
{
  const BodyDescription& body = world.scene().bodies.at(object);
  if (!body.soft)
  {
    throw InputError("body '" + body.name + "' is not a soft body");
  }
  young_modulus_ = body.soft->material.young_modulus;
  poisson_ratio_ = body.soft->material.poisson_ratio;
  untouched_ = world.walkMesh(object).vertices();
  locator_ = std::make_unique<SurfaceLocator>(world.walkMesh(object));
  untouched_width_ = widthAlongX(untouched_);
  start_height_ = world.bodyState(object).pose.translation().z();
}

double SoftContactMetrics::widthAlongX(const std::vector<Eigen::Vector3d>& vertices)
{
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  for (const Eigen::Vector3d& vertex : vertices)
  {
    lowest = std::min(lowest, vertex.x());
    highest = std::max(highest, vertex.x());
  }
  return highest - lowest;
}

double SoftContactMetrics::deepestSink(const GodFingerWorld& world) const
{
  const std::vector<Eigen::Vector3d>& now = world.walkMesh(object_).vertices();
  double deepest = 0.0;
  for (std::size_t v = 0; v < now.size(); ++v)
  {
    deepest = std::max(deepest, (now[v] - untouched_[v]).norm());
  }
  return deepest;
}

double SoftContactMetrics::deepestDeformation(const GodFingerWorld& world) const
{
  const std::vector<Eigen::Vector3d>& now = world.walkMesh(object_).vertices();
  const Eigen::Isometry3d motion = bestFitMotion(untouched_, now);
  double deepest = 0.0;
  for (std::size_t v = 0; v < now.size(); ++v)
  {
    deepest = std::max(deepest, (now[v] - motion * untouched_[v]).norm());
  }
  return deepest;
}

void SoftContactMetrics::add(double time, const GodFingerWorld& world)
{
  // Every finger on the body: how far its proxy reached into the surface.
  bool refitted = false;
  double radius = 0.0;
  for (int i = 0; i < world.interfaceCount(); ++i)
  {
    const InterfaceState& finger = world.interfaceState(i);
    bool touching = false;
    for (int c = 0; c < finger.contact_count; ++c)
    {
      if (finger.contacts[c].body == object_)
      {
        touching = true;
        radius = i == 0 ? finger.contacts[c].radius : radius;
      }
    }
    if (touching)
    {
      if (!refitted)
      {
        locator_->refit();
        refitted = true;
      }
      const Eigen::Isometry3d to_body = world.bodyState(object_).pose.inverse();
      const double distance = locator_->closest(to_body * finger.proxy_position).distance;
      penetrations_.push_back(std::max(0.0, world.params().coupling.proxy_radius - distance));
    }
  }
  const InterfaceState& finger = world.interfaceState(0);
  const Eigen::Vector3d& force = finger.user_force;
  if (scenario_ == Scenario::kPinchSoft)
  {
    squash_ = std::max(squash_, 1.0 - widthAlongX(world.walkMesh(object_).vertices()) / untouched_width_);
    if (time > times_.lift_end)
    {
      for (int i = 0; i < world.interfaceCount(); ++i)
      {
        force_sum_ += world.interfaceState(i).user_force.norm();
        ++samples_;
      }
      sink_ = std::max(sink_, deepestDeformation(world));
    }
    if (time >= times_.lift_start)
    {
      const std::vector<Eigen::Vector3d>& now = world.walkMesh(object_).vertices();
      if (grip_vertices_.empty())
      {
        grip_vertices_ = now;
      }
      turn_ = std::max(turn_, Eigen::AngleAxisd(bestFitMotion(grip_vertices_, now).linear()).angle());
    }
    lift_ = world.bodyState(object_).pose.translation().z() - start_height_;
  }
  if (scenario_ == Scenario::kPressSoft && time > times_.duration - kMeasuredHold)
  {
    ++samples_;
    force_sum_ += force.norm();
    radius_sum_ += radius;
    sink_ = std::max(sink_, deepestSink(world));
  }
  if (scenario_ == Scenario::kStrokeSoft && time > times_.lift_start && time <= times_.lift_end)
  {
    if (tracing_)
    {
      trace_ += (finger.proxy_position - last_proxy_).norm();
    }
    tracing_ = true;
    last_proxy_ = finger.proxy_position;
    const double speed = finger.proxy_velocity.head<2>().norm();
    if (stuck_ && speed > kSlipSpeed)
    {
      stuck_ = false;
      ++stick_slips_;
    }
    else if (!stuck_ && speed < kStuckSpeed)
    {
      stuck_ = true;
    }
    const double normal = std::abs(force.z());
    if (normal > 0.1)
    {
      friction_ratio_ = std::max(friction_ratio_, force.head<2>().norm() / normal);
    }
    ++samples_;
    force_sum_ += normal;
    sink_ = std::max(sink_, deepestSink(world));
  }
}

std::map<std::string, double> SoftContactMetrics::metrics() const
{
  std::map<std::string, double> result;
  result["penetration_max_m"] =
      penetrations_.empty() ? 0.0 : *std::max_element(penetrations_.begin(), penetrations_.end());
  result["penetration_p99_m"] = penetrations_.empty() ? 0.0 : percentile(penetrations_, 0.99);
  result["sink_m"] = sink_;
  result["hand_force_N"] = samples_ > 0 ? force_sum_ / samples_ : 0.0;
  if (scenario_ == Scenario::kPressSoft)
  {
    const double radius = samples_ > 0 ? radius_sum_ / samples_ : 0.0;
    const double w0 =
        radius > 0.0 ? boussinesqCentreSink(result["hand_force_N"], radius, young_modulus_, poisson_ratio_) : 0.0;
    result["area_radius_m"] = radius;
    result["w0_m"] = w0;
    result["sink_over_w0"] = w0 > 0.0 ? sink_ / w0 : 0.0;
  }
  else if (scenario_ == Scenario::kPinchSoft)
  {
    result["squash"] = squash_;
    result["lift_height_m"] = lift_;
    result["turn_rad"] = turn_;
  }
  else
  {
    result["trace_m"] = trace_;
    result["stick_slip_events"] = stick_slips_;
    result["friction_ratio_max"] = friction_ratio_;
  }
  return result;
}
}  // namespace god_finger
