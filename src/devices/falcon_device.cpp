#include "god_finger/devices/falcon_device.h"

#include "god_finger/devices/vendor_frames.h"

#include <algorithm>

namespace god_finger
{
const ParameterTable<FalconParams>& falconParameterTable()
{
  using P = FalconParams;
  static const ParameterTable<P> table = {
      integerRow<P>("index", closed(0, 15), "which Falcon (libnifalcon's device index)",
                    [](P& p) -> int& { return p.index; }),
      integerRow<P>("firmware_attempts", closed(1, 100), "firmware loads tried (loading fails now and then over USB)",
                    [](P& p) -> int& { return p.firmware_attempts; }),
      realRow<P>("homing_timeout", "s", openClosed(0.0, 600.0), "time the user has to home the Falcon",
                 [](P& p) -> double& { return p.homing_timeout; }),
      realRow<P>("center_z", "m", closed(0.0, 0.3), "Falcon z of the workspace centre",
                 [](P& p) -> double& { return p.center_z; }),
  };
  return table;
}

FalconParams readFalconParams(const ParameterSource& source, double max_force)
{
  FalconParams params;
  readRows(source, falconParameterTable(), &params);
  params.max_force = std::min(max_force, params.max_force);
  return params;
}

FalconDevice::FalconDevice(std::unique_ptr<FalconIo> io, const FalconParams& params, std::function<double()> now,
                           std::function<void()> wait)
    : io_(std::move(io)),
      params_(params),
      now_(std::move(now)),
      wait_(std::move(wait)),
      io_failures_(params.io_failures_allowed)
{
}

Eigen::Vector3d FalconDevice::falconToDevice(const std::array<double, 3>& falcon, double center_z)
{
  return hdFrame().toDevice(Eigen::Vector3d(falcon[0], falcon[1], falcon[2] - center_z));
}

void FalconDevice::start()
{
  const int count = io_->deviceCount();
  if (count <= params_.index)
  {
    throw DeviceError("falcon: " + std::to_string(count) + " Falcon(s) found, asked for number " +
                      std::to_string(params_.index) +
                      ": check the USB cable and the power supply, and the udev rule (docs/devices.md)");
  }
  if (!io_->open(params_.index))
  {
    throw DeviceError("falcon: cannot open Falcon " + std::to_string(params_.index) + " (" + io_->lastError() +
                      "): is another program using it? does the udev rule give you access?");
  }
  firmware_attempts_ = 0;
  while (!io_->isFirmwareLoaded())
  {
    if (firmware_attempts_ >= params_.firmware_attempts)
    {
      throw DeviceError("falcon: firmware not loaded after " + std::to_string(firmware_attempts_) + " attempts (" +
                        io_->lastError() + "): unplug the USB cable and the power, plug them back, try again");
    }
    ++firmware_attempts_;
    io_->loadFirmware();
  }
  io_->setHomingMode(true);
  const double deadline = now_() + params_.homing_timeout;
  while (true)
  {
    io_->runIoLoop();
    if (io_->isHomed())
    {
      break;
    }
    if (now_() > deadline)
    {
      throw DeviceError("falcon: not homed within " + std::to_string(static_cast<int>(params_.homing_timeout)) +
                        " s: pull the grip all the way out, then push it all the way in (the LED turns green)");
    }
    wait_();
  }
  io_->setHomingMode(false);
}

DeviceReading FalconDevice::update(double time, const Eigen::Vector3d& force)
{
  io_->setForce(deviceForceToVendorAxes(motorCommand(force, params_.max_force)));
  if (io_failures_.record(io_->runIoLoop()))
  {
    throw DeviceError("falcon: USB communication lost (" + std::to_string(io_failures_.consecutive()) +
                      " failed cycles in a row; " + io_->lastError() + ")");
  }
  DeviceReading reading;
  reading.position = falconToDevice(io_->position(), params_.center_z);
  reading.velocity = velocity_.update(time, reading.position);
  reading.buttons = io_->buttons();
  return reading;
}
}  // namespace god_finger

namespace god_finger
{
std::string nifalconErrorText(int code)
{
  struct NamedError
  {
    int code;
    const char* name;
    const char* meaning;
  };
  // libnifalcon's anonymous enums (FalconDevice.h, FalconComm.h, FalconFirmware.h, FalconGrip.h,
  // FalconKinematic.h), their documented meanings.
  static const NamedError errors[] = {
      {1000, "FALCON_DEVICE_NO_COMM_SET", "no communications policy set"},
      {1001, "FALCON_DEVICE_NO_FIRMWARE_SET", "no firmware policy set"},
      {1002, "FALCON_DEVICE_NO_KINEMATIC_SET", "no kinematics policy set"},
      {1003, "FALCON_DEVICE_NO_GRIP_SET", "no grip policy set"},
      {1004, "FALCON_DEVICE_NO_FIRMWARE_LOADED", "no firmware loaded"},
      {1005, "FALCON_DEVICE_FIRMWARE_NOT_VALID", "firmware file missing"},
      {1006, "FALCON_DEVICE_FIRMWARE_CHECKSUM_MISMATCH", "checksum mismatch while loading the firmware"},
      {2000, "FALCON_COMM_DEVICE_ERROR", "USB driver error"},
      {2001, "FALCON_COMM_NOT_INITIALIZED", "USB driver not initialized"},
      {2002, "FALCON_COMM_DEVICE_NOT_FOUND_ERROR", "no Falcon found on the system"},
      {2003, "FALCON_COMM_DEVICE_NOT_VALID_ERROR", "device not opened"},
      {2004, "FALCON_COMM_DEVICE_INDEX_OUT_OF_RANGE_ERROR", "device index out of range of the Falcons found"},
      {2005, "FALCON_COMM_FIRMWARE_NOT_FOUND_ERROR", "firmware file not found"},
      {2006, "FALCON_COMM_WRITE_ERROR", "USB write failed (time-out or underflow)"},
      {2007, "FALCON_COMM_READ_ERROR", "USB read failed (time-out or underflow)"},
      {3000, "FALCON_FIRMWARE_NO_COMM_SET", "no communications policy set"},
      {3001, "FALCON_FIRMWARE_NO_FIRMWARE_SET", "no firmware policy set"},
      {3002, "FALCON_FIRMWARE_NO_FIRMWARE_LOADED", "no firmware loaded"},
      {3003, "FALCON_FIRMWARE_FILE_NOT_VALID", "firmware file missing"},
      {3004, "FALCON_FIRMWARE_CHECKSUM_MISMATCH", "checksum mismatch while loading the firmware"},
      {4000, "FALCON_GRIP_INDEX_OUT_OF_RANGE", "button index out of range for the grip"},
      {5000, "FALCON_KINEMATIC_OUT_OF_RANGE", "position out of the workspace"},
  };
  for (const NamedError& error : errors)
  {
    if (error.code == code)
    {
      return "libnifalcon error " + std::to_string(code) + ": " + error.meaning + " (" + error.name + ")";
    }
  }
  return "libnifalcon error " + std::to_string(code);
}
}  // namespace god_finger
