#include "god_finger/devices/omni_device.h"

#include "god_finger/devices/vendor_frames.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
const ParameterTable<OmniParams>& omniParameterTable()
{
  using P = OmniParams;
  static const ParameterTable<P> table = {
      realRow<P>("calibration_timeout", "s", openClosed(0.0, 600.0), "time to put the stylus in the inkwell",
                 [](P& p) -> double& { return p.calibration_timeout; }),
  };
  return table;
}

OmniParams readOmniParams(const ParameterSource& source, double max_force)
{
  OmniParams params;
  params.device_name = readString(source, "device_name", params.device_name);
  readRows(source, omniParameterTable(), &params);
  params.max_force = max_force;
  const Eigen::VectorXd center = readVector(source, "center_mm", Eigen::Vector3d::Zero());
  params.center_mm = {center[0], center[1], center[2]};
  return params;
}

OmniDevice::OmniDevice(std::unique_ptr<OmniIo> io, const OmniParams& params, std::function<double()> now,
                       std::function<void()> wait)
    : io_(std::move(io)),
      params_(params),
      now_(std::move(now)),
      wait_(std::move(wait)),
      force_limit_(params.max_force),
      io_failures_(params.io_failures_allowed)
{
}

Eigen::Vector3d OmniDevice::omniToDevice(const std::array<double, 3>& omni_mm, const std::array<double, 3>& center_mm)
{
  const Eigen::Vector3d relative(omni_mm[0] - center_mm[0], omni_mm[1] - center_mm[1], omni_mm[2] - center_mm[2]);
  return hdFrame().toDevice(relative) * 1e-3;
}

Eigen::Quaterniond OmniDevice::stylusToDevice(const std::array<double, 9>& rotation)
{
  // Omni axes to device axes (device = (-z, -x, y)), and the finger's axes in the stylus frame
  // (columns: x = -z_s, y = x_s, z = -y_s).
  const Eigen::Matrix3d& omni_to_device = hdFrame().to_device;
  Eigen::Matrix3d finger_in_stylus;
  finger_in_stylus << 0, 1, 0, 0, 0, -1, -1, 0, 0;
  const Eigen::Map<const Eigen::Matrix3d> stylus(rotation.data());  // column-major, as the HD API's
  const Eigen::Matrix3d finger = omni_to_device * stylus * finger_in_stylus;
  if (!finger.allFinite())
  {
    return Eigen::Quaterniond(NAN, NAN, NAN, NAN);
  }
  return Eigen::Quaterniond(finger);
}

void OmniDevice::start()
{
  const std::string shown_name = params_.device_name.empty() ? "the default device" : "'" + params_.device_name + "'";
  if (!io_->open(params_.device_name))
  {
    throw DeviceError("omni: cannot open " + shown_name + " (" + io_->lastError() +
                      "): is the Touch / Phantom driver installed, the device configured with Touch_Setup, "
                      "and no other program using it?");
  }
  calibrate();
  const double nominal = io_->nominalMaxForce();
  force_limit_ = std::isfinite(nominal) && nominal > 0.0 ? std::min(params_.max_force, nominal) : params_.max_force;
  if (!io_->startServo())
  {
    throw DeviceError("omni: cannot start the servo loop (" + io_->lastError() +
                      "): check that the device's motors are powered");
  }
}

void OmniDevice::calibrate()
{
  const double deadline = now_() + params_.calibration_timeout;
  while (true)
  {
    const OmniCalibration state = io_->calibration();
    if (state == OmniCalibration::ok)
    {
      return;
    }
    if (state == OmniCalibration::needs_update)
    {
      if (!io_->updateCalibration())
      {
        throw DeviceError("omni: calibration update failed (" + io_->lastError() +
                          "): run Touch_Diagnostic to calibrate it by hand");
      }
      continue;
    }
    if (now_() > deadline)
    {
      throw DeviceError("omni: not calibrated within " + std::to_string(static_cast<int>(params_.calibration_timeout)) +
                        " s: put the stylus in the inkwell (or, on an old Omni, push the arm to its reset "
                        "position) and start again");
    }
    wait_();
  }
}

void OmniDevice::recordFrame(bool ok, const OmniFrame& frame)
{
  if (io_failures_.record(ok))
  {
    throw DeviceError("omni: device fault (" + std::to_string(io_failures_.consecutive()) +
                      " failed servo frames in a row; " + io_->lastError() + ")");
  }
  if (io_failures_.consecutive() == 0)
  {
    last_frame_ = frame;
  }
}

DeviceReading OmniDevice::readingOf(double time, const OmniFrame& frame)
{
  DeviceReading reading;
  reading.position = omniToDevice(frame.position_mm, params_.center_mm);
  reading.velocity = velocity_.update(time, reading.position);
  reading.buttons = frame.buttons;
  reading.has_orientation = frame.has_rotation;
  if (reading.has_orientation)
  {
    reading.orientation = stylusToDevice(frame.rotation);
  }
  return reading;
}

DeviceReading OmniDevice::update(double time, const Eigen::Vector3d& force)
{
  OmniFrame frame;
  recordFrame(io_->exchange(deviceForceToVendorAxes(motorCommand(force, force_limit_)), &frame), frame);
  return readingOf(time, last_frame_);
}

// The servo loop's responder inside the HD frame: the frame's reading in device terms, its force
// back in the Omni's, clamped to the device.
class OmniDevice::FrameAnswer : public OmniFrameResponder
{
 public:
  FrameAnswer(OmniDevice& device, FrameResponder& responder, double time)
      : device_(device), responder_(responder), time_(time)
  {
  }
  std::array<double, 3> forceFor(const OmniFrame& frame) override
  {
    reading = device_.readingOf(time_, frame);
    Eigen::Vector3d torque;  // the Omni renders none
    responder_.respond(reading, &force, &torque);
    answered = true;
    return deviceForceToVendorAxes(motorCommand(force, device_.force_limit_));
  }
  DeviceReading reading;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  bool answered = false;

 private:
  OmniDevice& device_;
  FrameResponder& responder_;
  double time_;
};

DeviceReading OmniDevice::exchangeFrame(double time, FrameResponder& responder)
{
  OmniFrame frame;
  FrameAnswer answer(*this, responder, time);
  const bool ok = io_->exchangeFrame(answer, &frame);
  recordFrame(ok, frame);
  if (answer.answered)
  {
    return answer.reading;  // a failed frame that read: what it read (the loop refuses a non-finite one)
  }
  // A frame that failed before reading: the loop still decides for this tick, on the last good
  // frame, and its force goes with the next frame.
  const DeviceReading reading = readingOf(time, last_frame_);
  Eigen::Vector3d force;
  Eigen::Vector3d torque;
  responder.respond(reading, &force, &torque);
  return reading;
}
}  // namespace god_finger
