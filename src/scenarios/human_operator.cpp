#include "god_finger/scenarios/human_operator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

namespace god_finger
{
namespace
{
// Uniform in [low, high), drawn by hand from the raw bits: the same on every standard library.
double uniform(std::mt19937_64* generator, double low, double high)
{
  const double unit = static_cast<double>((*generator)() >> 11) / 9007199254740992.0;
  return low + (high - low) * unit;
}
constexpr double kTwoPi = 6.283185307179586;
}  // namespace

OperatorTraits perfectOperator()
{
  return OperatorTraits();
}

OperatorTraits drawOperator(std::uint64_t seed, const Eigen::Vector3d& pinch_axis, double max_misalignment)
{
  std::mt19937_64 generator(seed);
  OperatorTraits traits;
  traits.tremor_amplitude = uniform(&generator, 1e-4, 1e-3);
  traits.tremor_frequency = uniform(&generator, 8.0, 12.0);
  for (int axis = 0; axis < 3; ++axis)
  {
    traits.tremor_phase[axis] = uniform(&generator, 0.0, kTwoPi);
  }
  const Eigen::Vector3d axis = pinch_axis.normalized();
  const Eigen::Vector3d across = axis.unitOrthogonal();
  const double direction = uniform(&generator, 0.0, kTwoPi);
  const double size = uniform(&generator, 0.0, max_misalignment);
  traits.misalignment = Eigen::AngleAxisd(direction, axis) * across * size;
  traits.grip_fluctuation = 0.25;
  traits.fluctuation_frequency = uniform(&generator, 0.8, 1.2);
  traits.fluctuation_phase = uniform(&generator, 0.0, kTwoPi);
  traits.reaction_delay = uniform(&generator, 0.1, 0.15);
  traits.wrist_tremor = uniform(&generator, 0.002, 0.01);
  return traits;
}

namespace
{
// The tremor's phase per axis of finger `finger` at time t (s): rad.
Eigen::Array3d tremorPhases(const OperatorTraits& traits, double t, int finger)
{
  Eigen::Array3d phases;
  for (int axis = 0; axis < 3; ++axis)
  {
    phases[axis] = kTwoPi * traits.tremor_frequency * t + traits.tremor_phase[axis] + finger;
  }
  return phases;
}
}  // namespace

Eigen::Vector3d tremorAt(const OperatorTraits& traits, double t, int finger)
{
  const Eigen::Array3d phases = tremorPhases(traits, t, finger);
  return traits.tremor_amplitude * Eigen::Vector3d(std::sin(phases[0]), std::sin(phases[1]), std::sin(phases[2]));
}

Eigen::Vector3d wristTremorAt(const OperatorTraits& traits, double t, int finger)
{
  const Eigen::Array3d phases = tremorPhases(traits, t, finger);
  return traits.wrist_tremor * Eigen::Vector3d(std::cos(phases[0]), std::cos(phases[1]), std::cos(phases[2]));
}

double fluctuationAt(const OperatorTraits& traits, double t)
{
  return 1.0 + traits.grip_fluctuation * std::sin(kTwoPi * traits.fluctuation_frequency * t + traits.fluctuation_phase);
}

double GripReflex::update(double t, double slip_speed)
{
  if (!(delay_ > 0.0))
  {
    return 0.0;
  }
  if (pending_at_ >= 0.0 && t >= pending_at_)
  {
    extra_ = std::min(kReflexMax, extra_ + kReflexStep);
    pending_at_ = -1.0;
  }
  if (pending_at_ < 0.0 && slip_speed > kSlipSpeed && extra_ < kReflexMax)
  {
    pending_at_ = t + delay_;
  }
  return extra_;
}
}  // namespace god_finger
