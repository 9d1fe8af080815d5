// Phantom Omni / Geomagic Touch backend. Everything that is not an OpenHaptics HD API call
// lives here, behind OmniIo (the seam): frames and units, calibration, force clamping, I/O
// failure handling. The HD API calls go in one source file implementing OmniIo
// (src/devices/vendor/omni_io_openhaptics.cpp), built only when CMake finds OpenHaptics.
//
// Frames: the HD API reports the stylus tip in millimetres in the Omni's frame, x to the
// user's right, y up, z towards the user. The device frame (haptic_device.h) is REP-103 as
// the user sees it: x away from the user, y to the left, z up, in metres, origin at
// `center_mm` of the Omni frame. So
//   device = (-(z - c_z), -(x - c_x), y - c_y) / 1000,   omni force = (-f_y, f_z, -f_x).
// Orientation: the HD API's stylus transform (HD_CURRENT_TRANSFORM's rotation: the gimbal
// angles through the arm's kinematics) in the Omni frame; its stylus frame at the home pose is
// the Omni frame, the pen along z with its tip towards -z (away from the user). The finger
// held on the pen (physics/oriented_finger.h): x towards the tip = stylus -z, z out of the pulp
// = stylus -y (the index finger on top of the pen, its pulp down on it). So at the home pose the
// finger points away from the user with its pulp down (180 degrees about device x). These axis
// conventions are from the HD API's documentation, not yet checked on a device.
// Invariants: the force sent to the motors never exceeds min(max_force, the device's nominal
// maximum); non-finite forces are sent as zero.
#pragma once

#include "god_finger/devices/device_signals.h"
#include "god_finger/devices/haptic_device.h"
#include "god_finger/support/parameter_source.h"
#include "god_finger/support/parameter_table.h"

#include <Eigen/Geometry>
#include <array>
#include <functional>
#include <memory>
#include <string>

namespace god_finger
{
enum class OmniCalibration
{
  ok,
  needs_update,        // the HD API can update it by itself (HD_CALIBRATION_NEEDS_UPDATE)
  needs_manual_input,  // the user must put the stylus in the inkwell (HD_CALIBRATION_NEEDS_MANUAL_INPUT)
};

struct OmniFrame
{
  std::array<double, 3> position_mm{0.0, 0.0, 0.0};  // mm, Omni frame
  unsigned buttons = 0;                              // bit i: stylus button i
  // The stylus frame's rotation in the Omni frame, column-major 3x3 (HD_CURRENT_TRANSFORM's
  // upper-left block); has_rotation false when the I/O layer does not read it.
  bool has_rotation = false;
  std::array<double, 9> rotation{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
};

// Gives the force (N, Omni frame) to set in the servo frame that read `frame` (OmniIo::exchangeFrame).
// Called in the HD scheduler's servo thread while the caller waits: real-time safe.
class OmniFrameResponder
{
 public:
  virtual ~OmniFrameResponder() = default;
  virtual std::array<double, 3> forceFor(const OmniFrame& frame) = 0;
};

// The HD API calls god_finger needs, one method each.
class OmniIo
{
 public:
  virtual ~OmniIo() = default;
  // hdInitDevice; empty name = the default device. False with a reason in lastError().
  virtual bool open(const std::string& device_name) = 0;
  virtual OmniCalibration calibration() = 0;  // hdCheckCalibration
  virtual bool updateCalibration() = 0;       // hdUpdateCalibration with the device's style
  // hdEnable(HD_FORCE_OUTPUT) and hdStartScheduler. False with a reason in lastError().
  virtual bool startServo() = 0;
  // One servo frame (hdBeginFrame ... hdEndFrame): applies `force` (N, Omni frame), reads the
  // stylus. False on a device fault.
  virtual bool exchange(const std::array<double, 3>& force, OmniFrame* frame) = 0;
  // One servo frame that answers its own reading: hdBeginFrame, read the stylus, set the force
  // `responder` gives for what was read, hdEndFrame. False on a device fault (the responder
  // may or may not have been called).
  virtual bool exchangeFrame(OmniFrameResponder& responder, OmniFrame* frame) = 0;
  virtual double nominalMaxForce() = 0;  // N, HD_NOMINAL_MAX_FORCE
  virtual std::string lastError() = 0;   // hdGetErrorString of the last error
};

struct OmniParams
{
  std::string device_name;                         // "" = OpenHaptics' default device
  double max_force = 3.3;                          // N, range (0, 10]: the profile's limit
  double calibration_timeout = 30.0;               // s: time to put the stylus in the inkwell
  std::array<double, 3> center_mm{0.0, 0.0, 0.0};  // mm, Omni frame: the workspace centre
  int io_failures_allowed = 50;                    // consecutive failed servo frames before giving up
};

// calibration_timeout (its numeric row; device_name and center_mm are a string and a vector).
const ParameterTable<OmniParams>& omniParameterTable();

// device_name, calibration_timeout, center_mm ([x, y, z], mm, Omni frame) from `source`;
// max_force is the profile's limit. InputError on a bad one.
OmniParams readOmniParams(const ParameterSource& source, double max_force);

class OmniDevice : public HapticDevice
{
 public:
  // `now` gives seconds (monotonic), `wait` sleeps a little; injected so that tests run
  // calibration without a clock.
  OmniDevice(std::unique_ptr<OmniIo> io, const OmniParams& params, std::function<double()> now,
             std::function<void()> wait);
  std::string name() const override
  {
    return "omni";
  }
  // Opens, calibrates (by itself, or waiting for the inkwell), starts the servo loop. Throws
  // DeviceError saying what to do.
  void start() override;
  DeviceReading update(double time, const Eigen::Vector3d& force) override;
  // The HD API's servo frame reads and writes with room between: the servo loop decides the
  // force for a reading inside the frame that read it (OmniIo::exchangeFrame).
  DeviceExchange exchangeForm() const override
  {
    return DeviceExchange::kFrame;
  }
  // As update(), the force the one `responder` gives for this frame's reading, set in the same
  // frame. A failed frame: the responder answers what it read, or the last good frame's reading
  // where it read nothing (that force waits for the next frame); DeviceError after
  // io_failures_allowed in a row, as update().
  DeviceReading exchangeFrame(double time, FrameResponder& responder) override;

  static Eigen::Vector3d omniToDevice(const std::array<double, 3>& omni_mm, const std::array<double, 3>& center_mm);
  // The finger frame in the device frame for a stylus rotation (OmniFrame::rotation; see above).
  // Not normalised: a non-finite or non-rotation input gives what the servo loop rejects.
  static Eigen::Quaterniond stylusToDevice(const std::array<double, 9>& rotation);
  // The force limit in use after start(): min(max_force, nominal maximum if the device reports one).
  double forceLimit() const
  {
    return force_limit_;
  }

 private:
  class FrameAnswer;  // exchangeFrame()'s OmniFrameResponder (omni_device.cpp)
  void calibrate();
  // The reading of frame `frame` at `time` (velocity estimated; last_frame_ on a failed frame).
  DeviceReading readingOf(double time, const OmniFrame& frame);
  void recordFrame(bool ok, const OmniFrame& frame);  // DeviceError after too many failures

  std::unique_ptr<OmniIo> io_;
  OmniParams params_;
  std::function<double()> now_;
  std::function<void()> wait_;
  double force_limit_;
  IoFailureCounter io_failures_;
  VelocityEstimator velocity_;
  OmniFrame last_frame_;
};
}  // namespace god_finger
