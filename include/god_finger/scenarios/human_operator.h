// A human-like operator for scripted hands: what a person's pinch adds to a perfect script.
// - physiological tremor: a sinusoid per axis and finger, 8-12 Hz, 0.1-1 mm amplitude; an
//   oriented finger's wrist shakes with it, 2-10 mrad per axis (at a finger's 5-10 cm from the
//   wrist, the same 0.1-1 mm);
// - misalignment: the second finger off the first's line by up to 3 mm;
// - grip force fluctuating about its nominal value by +-25 % at about 1 Hz;
// - a grip reflex with a 100-150 ms reaction delay: when the held object slips against the
//   fingers faster than kSlipSpeed, the squeeze rises by kReflexStep of its nominal value (at
//   most kReflexMax in all), reaction_delay later.
// The numbers are drawn per seed (drawOperator), uniformly in those ranges, the same on every
// standard library. Units SI, frames world (z up). Real-time safe (no allocation), pure.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace god_finger
{
struct OperatorTraits
{
  double tremor_amplitude = 0.0;                           // m, per axis
  double tremor_frequency = 10.0;                          // Hz
  Eigen::Vector3d tremor_phase = Eigen::Vector3d::Zero();  // rad per axis (finger k adds k)
  Eigen::Vector3d misalignment = Eigen::Vector3d::Zero();  // m, the second finger's offset
  double grip_fluctuation = 0.0;                           // relative amplitude of the squeeze
  double fluctuation_frequency = 1.0;                      // Hz
  double fluctuation_phase = 0.0;                          // rad
  double reaction_delay = 0.0;                             // s; 0: no grip reflex
  double wrist_tremor = 0.0;                               // rad, per axis (oriented fingers)
};

// A perfect hand: no tremor, no misalignment, a steady squeeze, no reflex.
OperatorTraits perfectOperator();
// Tremor 0.1-1 mm at 8-12 Hz, misalignment up to `max_misalignment` (m) in a random direction
// across the pinch (the plane normal to `pinch_axis`), fluctuation +-25 % at 0.8-1.2 Hz, delay
// 100-150 ms, wrist tremor 2-10 mrad (drawn last: the earlier draws are the same as without it).
OperatorTraits drawOperator(std::uint64_t seed, const Eigen::Vector3d& pinch_axis, double max_misalignment = 0.003);

// The tremor's displacement of finger `finger` at time t (s).
Eigen::Vector3d tremorAt(const OperatorTraits& traits, double t, int finger);
// The wrist tremor's turn of finger `finger` at time t (s): a rotation vector (rad, world), at
// the tremor's frequency, a quarter period after the displacement's phase.
Eigen::Vector3d wristTremorAt(const OperatorTraits& traits, double t, int finger);
// The squeeze's factor on its nominal value at time t, without the reflex: 1 + a sin(2 pi f t + phi).
double fluctuationAt(const OperatorTraits& traits, double t);

// The grip reflex: fed the slip speed every step, gives the squeeze's extra factor.
class GripReflex
{
 public:
  static constexpr double kSlipSpeed = 0.005;  // m/s of slip that triggers the reflex
  static constexpr double kReflexStep = 0.2;   // of the nominal squeeze, per reaction
  static constexpr double kReflexMax = 0.6;    // of the nominal squeeze, in all

  explicit GripReflex(double reaction_delay) : delay_(reaction_delay) {}
  // Call once per step with the time (s) and the slip speed (m/s); returns the extra factor.
  double update(double t, double slip_speed);

 private:
  double delay_ = 0.0;
  double extra_ = 0.0;
  double pending_at_ = -1.0;  // s, when the scheduled increase takes effect; < 0: none
};
}  // namespace god_finger
