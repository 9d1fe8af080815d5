// Novint Falcon backend. Everything that is not a libnifalcon call lives here, behind FalconIo
// (the seam): frames and units, firmware loading with retries, homing, force clamping, I/O
// failure handling. The libnifalcon calls go in one source file implementing FalconIo, built
// only when CMake finds libnifalcon (this build did not: see the README).
//
// Frames: libnifalcon reports the grip position in metres in the Falcon's frame, x to the
// user's right, y up, z towards the user, with the workspace centre at z = center_z (about
// 0.11 m). The device frame (haptic_device.h) is REP-103 as the user sees it: x away from the
// user, y to the left, z up, origin at the workspace centre. So
//   device = (-(z_f - center_z), -x_f, y_f),   falcon force = (-f_y, f_z, -f_x).
// Invariants: the force sent to the motors never exceeds max_force; non-finite forces are sent
// as zero.
#pragma once

#include "god_finger/devices/device_signals.h"
#include "god_finger/devices/haptic_device.h"
#include "god_finger/support/parameter_source.h"
#include "god_finger/support/parameter_table.h"

#include <array>
#include <functional>
#include <memory>
#include <string>

namespace god_finger
{
// The libnifalcon calls god_finger needs, one method each.
class FalconIo
{
 public:
  virtual ~FalconIo() = default;
  virtual int deviceCount() = 0;
  // False with a reason in lastError().
  virtual bool open(int index) = 0;
  virtual bool isFirmwareLoaded() = 0;
  virtual bool loadFirmware() = 0;
  virtual void setHomingMode(bool on) = 0;
  virtual bool isHomed() = 0;
  // One USB exchange: sends the last force, reads encoders and buttons. False on failure.
  virtual bool runIoLoop() = 0;
  virtual std::array<double, 3> position() = 0;                   // m, Falcon frame
  virtual void setForce(const std::array<double, 3>& force) = 0;  // N, Falcon frame
  virtual unsigned buttons() = 0;
  virtual std::string lastError() = 0;
};

struct FalconParams
{
  int index = 0;                 // which Falcon
  int firmware_attempts = 10;    // loading fails now and then over USB
  double homing_timeout = 30.0;  // s: time the user has to home it
  double max_force = 8.9;        // N, (0, 8.9]: the profile's limit, capped at the Falcon's rated peak
  double center_z = 0.11;        // m: Falcon z of the workspace centre
  int io_failures_allowed = 50;  // consecutive failed USB cycles before giving up
};
// index, firmware_attempts, homing_timeout, center_z: units, ranges, meanings.
const ParameterTable<FalconParams>& falconParameterTable();

// The table's rows from `source`; max_force is the profile's limit, capped at the Falcon's
// rating. InputError on a bad one.
FalconParams readFalconParams(const ParameterSource& source, double max_force);

// libnifalcon's error code (FalconDevice::getErrorCode(), 0: none) with its name and meaning, as
// libnifalcon's headers give them (the same in 1.0.1, 1.1 and git master), e.g. "libnifalcon error
// 2004: device index out of range of the Falcons found (FALCON_COMM_DEVICE_INDEX_OUT_OF_RANGE_ERROR)";
// a code it does not define: "libnifalcon error N".
std::string nifalconErrorText(int code);

class FalconDevice : public HapticDevice
{
 public:
  // `now` gives seconds (monotonic), `wait` sleeps a little; injected so that tests run
  // homing without a clock.
  FalconDevice(std::unique_ptr<FalconIo> io, const FalconParams& params, std::function<double()> now,
               std::function<void()> wait);
  std::string name() const override
  {
    return "falcon";
  }
  // Opens, loads the firmware (retrying), homes (the user pulls the grip out and pushes it
  // back). Throws DeviceError saying what to do.
  void start() override;
  DeviceReading update(double time, const Eigen::Vector3d& force) override;

  static Eigen::Vector3d falconToDevice(const std::array<double, 3>& falcon, double center_z);
  int firmwareAttempts() const
  {
    return firmware_attempts_;
  }

 private:
  std::unique_ptr<FalconIo> io_;
  FalconParams params_;
  std::function<double()> now_;
  std::function<void()> wait_;
  int firmware_attempts_ = 0;
  IoFailureCounter io_failures_;
  VelocityEstimator velocity_;
};
}  // namespace god_finger
