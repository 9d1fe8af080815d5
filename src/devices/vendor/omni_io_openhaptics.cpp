// OmniIo on the OpenHaptics HD API. The only file that includes an HD header; built when
// CMake finds OpenHaptics, as a module of its own (god_finger_omni_io) that the device registry
// loads only when backend omni is chosen (devices/vendor_io.h): libHD needs the Touch driver's
// libPHANToMIO.so.4, which no other backend may need. Compiled with `linux` defined, as the
// vendor's Makefiles do: HD/hdExport.h defines HDAPI, HDAPIENTRY and HDCALLBACK only under it.
// Every device access runs inside the HD scheduler's servo thread (hdScheduleSynchronous), as
// the HD API requires for hdBeginFrame/hdEndFrame and the vendor's examples do for calibration,
// force enabling and queries once the scheduler runs.
#include "god_finger/devices/omni_device.h"

#include <HD/hd.h>

namespace god_finger
{
namespace
{
struct ServoExchange
{
  HHD device;
  HDdouble force[3];
  HDdouble position[3];
  HDint buttons;
  HDErrorInfo error;
  HDdouble transform[16];         // HD_CURRENT_TRANSFORM, column-major (zero-initialised)
  OmniFrameResponder* responder;  // non-null: the force is its answer to this frame's reading
};

void toOmniFrame(const ServoExchange& exchange, OmniFrame* frame)
{
  frame->position_mm = {exchange.position[0], exchange.position[1], exchange.position[2]};
  frame->buttons = static_cast<unsigned>(exchange.buttons);
  frame->has_rotation = true;
  for (int column = 0; column < 3; ++column)
  {
    for (int row = 0; row < 3; ++row)
    {
      frame->rotation[3 * column + row] = exchange.transform[4 * column + row];
    }
  }
}

HDCallbackCode HDCALLBACK servoFrame(void* data)
{
  auto* exchange = static_cast<ServoExchange*>(data);
  hdBeginFrame(exchange->device);
  hdGetDoublev(HD_CURRENT_POSITION, exchange->position);
  hdGetDoublev(HD_CURRENT_TRANSFORM, exchange->transform);  // column-major 4x4
  hdGetIntegerv(HD_CURRENT_BUTTONS, &exchange->buttons);
  if (exchange->responder != nullptr)
  {
    OmniFrame frame;
    toOmniFrame(*exchange, &frame);
    const std::array<double, 3> force = exchange->responder->forceFor(frame);
    for (int axis = 0; axis < 3; ++axis)
    {
      exchange->force[axis] = force[axis];
    }
  }
  hdSetDoublev(HD_CURRENT_FORCE, exchange->force);
  hdEndFrame(exchange->device);
  exchange->error = hdGetError();
  return HD_CALLBACK_DONE;
}

// Runs `work` in the servo thread while this one waits.
template <class Work>
HDCallbackCode HDCALLBACK runWork(void* data)
{
  (*static_cast<Work*>(data))();
  return HD_CALLBACK_DONE;
}

template <class Work>
void inServoThread(Work work)
{
  hdScheduleSynchronous(runWork<Work>, &work, HD_DEFAULT_SCHEDULER_PRIORITY);
}

struct CalibrationCheck
{
  HHD device;
  HDenum status;
};

HDCallbackCode HDCALLBACK checkCalibration(void* data)
{
  auto* check = static_cast<CalibrationCheck*>(data);
  hdBeginFrame(check->device);
  check->status = hdCheckCalibration();
  hdEndFrame(check->device);
  return HD_CALLBACK_DONE;
}

class OpenHapticsIo : public OmniIo
{
 public:
  ~OpenHapticsIo() override
  {
    if (scheduler_running_)
    {
      hdStopScheduler();
    }
    if (device_ != HD_INVALID_HANDLE)
    {
      hdDisableDevice(device_);
    }
  }
  bool open(const std::string& device_name) override
  {
    device_ = hdInitDevice(device_name.empty() ? HD_DEFAULT_DEVICE : device_name.c_str());
    if (failed(hdGetError()))
    {
      device_ = HD_INVALID_HANDLE;
      return false;
    }
    // Calibration checks need the scheduler; forces stay off until startServo().
    hdStartScheduler();
    scheduler_running_ = !failed(hdGetError());
    return scheduler_running_;
  }
  OmniCalibration calibration() override
  {
    CalibrationCheck check{device_, HD_CALIBRATION_OK};
    hdScheduleSynchronous(checkCalibration, &check, HD_DEFAULT_SCHEDULER_PRIORITY);
    if (check.status == HD_CALIBRATION_OK)
    {
      return OmniCalibration::ok;
    }
    return check.status == HD_CALIBRATION_NEEDS_UPDATE ? OmniCalibration::needs_update
                                                       : OmniCalibration::needs_manual_input;
  }
  // In a scheduled callback, as the vendor's Calibration example does: the style the device
  // supports (auto, then inkwell, then encoder reset), then hdUpdateCalibration with it.
  bool updateCalibration() override
  {
    const HHD device = device_;
    inServoThread(
        [device]()
        {
          hdMakeCurrentDevice(device);
          HDint styles = 0;
          hdGetIntegerv(HD_CALIBRATION_STYLE, &styles);
          const HDenum style = (styles & HD_CALIBRATION_AUTO)      ? HD_CALIBRATION_AUTO
                               : (styles & HD_CALIBRATION_INKWELL) ? HD_CALIBRATION_INKWELL
                                                                   : HD_CALIBRATION_ENCODER_RESET;
          hdUpdateCalibration(style);
        });
    return !failed(hdGetError());
  }
  bool startServo() override
  {
    const HHD device = device_;
    inServoThread(
        [device]()
        {
          hdMakeCurrentDevice(device);
          hdEnable(HD_FORCE_OUTPUT);
        });
    return !failed(hdGetError());
  }
  bool exchange(const std::array<double, 3>& force, OmniFrame* frame) override
  {
    return runFrame({force[0], force[1], force[2]}, nullptr, frame);
  }
  bool exchangeFrame(OmniFrameResponder& responder, OmniFrame* frame) override
  {
    return runFrame({0.0, 0.0, 0.0}, &responder, frame);
  }
  // One servo frame in the HD scheduler's thread, this one waiting (hdScheduleSynchronous).
  bool runFrame(const std::array<double, 3>& force, OmniFrameResponder* responder, OmniFrame* frame)
  {
    ServoExchange exchange{device_, {force[0], force[1], force[2]}, {0.0, 0.0, 0.0}, 0, HDErrorInfo(), {}, responder};
    hdScheduleSynchronous(servoFrame, &exchange, HD_DEFAULT_SCHEDULER_PRIORITY);
    if (failed(exchange.error))
    {
      return false;
    }
    toOmniFrame(exchange, frame);
    return true;
  }
  double nominalMaxForce() override
  {
    const HHD device = device_;
    HDdouble force = 0.0;
    inServoThread(
        [device, &force]()
        {
          hdMakeCurrentDevice(device);
          hdGetDoublev(HD_NOMINAL_MAX_FORCE, &force);
        });
    return force;
  }
  std::string lastError() override
  {
    return std::string(hdGetErrorString(last_error_.errorCode)) + ", HD error " +
           std::to_string(last_error_.errorCode) + ", internal " + std::to_string(last_error_.internalErrorCode);
  }

 private:
  bool failed(const HDErrorInfo& error)
  {
    if (HD_DEVICE_ERROR(error))
    {
      last_error_ = error;
      return true;
    }
    return false;
  }

  HHD device_ = HD_INVALID_HANDLE;
  bool scheduler_running_ = false;
  HDErrorInfo last_error_{};
};
}  // namespace

}  // namespace god_finger

// The module's one entry point (devices/vendor_io.h, loadOpenHapticsIo): a new OmniIo the caller owns.
extern "C" __attribute__((visibility("default"))) god_finger::OmniIo* god_finger_make_openhaptics_io()
{
  return new god_finger::OpenHapticsIo();
}
