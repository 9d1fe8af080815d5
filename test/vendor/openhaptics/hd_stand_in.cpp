// Test stand-in for OpenHaptics' libHD.so.3.0.0 (soname libHD.so.3.0): the HD API routines
// god_finger's Omni backend uses, on a simulated Touch, plus the test control API of
// include/hd_stand_in_control.h. Written from the API reference and programmer's guide; it
// keeps the vendor's observable rules:
// - hdInitDevice(name) asks the device driver (libPHANToMIO.so.4, here phantom_io.cpp) for the
//   device: init_phantom("" for HD_DEFAULT_DEVICE) gives the id used as the HHD, or a negative
//   driver error, pushed as HD_DEVICE_FAULT (the reference's error for a name that is not a
//   configured device) with the driver's code as internalErrorCode; HD_INVALID_HANDLE returned.
// - one error stack for all threads; hdGetError pops the most recent, HD_SUCCESS when empty.
// - the scheduler's servo thread ticks at 1 kHz, runs the scheduled callbacks by decreasing
//   priority, again each tick while they return HD_CALLBACK_CONTINUE; hdScheduleSynchronous
//   waits for its callback to run there (called from the servo thread, it runs it at once).
// - frames: hdBeginFrame snapshots the device, hdEndFrame sends the force set inside the frame
//   (to the motors only when HD_FORCE_OUTPUT is enabled and the scheduler runs); one frame per
//   device per tick (HD_ILLEGAL_BEGIN), hdEndFrame without a begin is HD_ILLEGAL_END, setting
//   state outside a frame is HD_FRAME_ERROR; getting state outside one gives the last frame's.
// - hdUpdateCalibration: the real 3.0 library hands HD_CALIBRATION_ENCODER_RESET to the
//   driver's reset and INKWELL/AUTO to its calibration update, and ignores any other value. The
//   vendor's Calibration example calls it for INKWELL/AUTO only inside a scheduler callback
//   (and for ENCODER_RESET before the scheduler starts). The stand-in makes that contract
//   checkable: INKWELL/AUTO off the servo thread pushes HD_INVALID_OPERATION ("the operation
//   could not be performed"), because the API documents no error code for a call outside the
//   scheduler (HD_FRAME_ERROR is for calls that need a frame, which this one does not).
// Stand-in choices where the vendor documents nothing: hdScheduleSynchronous with the scheduler
// stopped pushes HD_INVALID_OPERATION and returns (instead of waiting); forces are not clamped.
#ifndef linux
#define linux 1  // as the vendor's own Makefiles pass -Dlinux
#endif
#pragma GCC diagnostic ignored "-Wattributes"  // HDAPIENTRY's stdcall, ignored on x86-64

#include <cstddef>  // NULL, which HD_DEFAULT_DEVICE names and hdDefines.h does not bring

#include <HD/hd.h>

#include "hd_stand_in_control.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

extern "C" int init_phantom(const char* config_name);  // libPHANToMIO.so.4 (phantom_io.cpp)

namespace
{
using Clock = std::chrono::steady_clock;

constexpr double kNominalMaxForce = 3.3;  // N, a Touch's HD_NOMINAL_MAX_FORCE

struct Operation
{
  HDSchedulerCallback callback;
  void* data;
  HDushort priority;
  HDSchedulerHandle handle;
  bool done;
};

struct Snapshot  // what a frame sees: read at hdBeginFrame, force written at hdEndFrame
{
  double position[3];
  double rotation[9];
  int buttons;
  double force[3];
};

struct Model  // all that hdStandInReset restores
{
  Snapshot device{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}, 0, {0.0, 0.0, 0.0}};
  HDenum calibration = HD_CALIBRATION_OK;
  int styles = HD_CALIBRATION_INKWELL;
  bool initialized = false;
  HHD handle = HD_INVALID_HANDLE;
  HHD current = HD_INVALID_HANDLE;
  std::map<HDenum, bool> capabilities;
  std::vector<HDErrorInfo> errors;
  // The scheduler.
  HDulong rate = 1000;
  std::list<std::shared_ptr<Operation>> operations;
  HDSchedulerHandle next_handle = 1;
  long ticks = 0;
  Clock::time_point tick_start = Clock::now();
  // Frames, and what the tests read.
  Snapshot frame = device;
  int frame_depth = 0;
  bool frame_done_this_tick = false;
  long frames_completed = 0;
  double last_force[3] = {0.0, 0.0, 0.0};
  double device_force[3] = {0.0, 0.0, 0.0};
  int calibrations_on_servo = 0;
  int calibrations_off_servo = 0;
  HDenum last_style = 0;
  int off_servo_calls = 0;
};

struct State : Model
{
  std::mutex mutex;
  std::condition_variable changed;
  std::thread servo;
  bool running = false;

  ~State()
  {
    stop();
  }
  // Stops the servo thread and joins it, unless called from it (then a later stop joins it).
  void stop();
};

thread_local bool t_servo_thread = false;

State& state()
{
  static State s;
  return s;
}

template <typename F>
auto locked(F&& f)
{
  State& s = state();
  std::lock_guard<std::mutex> lock(s.mutex);
  return f(s);
}

void pushError(State& s, HDerror code, int internal_code = 0)
{
  s.errors.push_back(HDErrorInfo{code, internal_code, s.current});
}

// Device-state calls off the servo thread while it runs are counted; a call with no device
// current is HD_BAD_HANDLE.
bool deviceCall(State& s)
{
  if (s.running && !t_servo_thread)
  {
    ++s.off_servo_calls;
  }
  if (!s.initialized || s.current != s.handle)
  {
    pushError(s, HD_BAD_HANDLE);
    return false;
  }
  return true;
}

void finish(State& s, const std::shared_ptr<Operation>& operation)
{
  operation->done = true;
  s.operations.remove(operation);
  s.changed.notify_all();
}

void servoLoop()
{
  t_servo_thread = true;
  State& s = state();
  std::unique_lock<std::mutex> lock(s.mutex);
  Clock::time_point next = Clock::now();
  while (s.running)
  {
    ++s.ticks;
    s.tick_start = Clock::now();
    s.frame_done_this_tick = false;
    std::vector<std::shared_ptr<Operation>> batch(s.operations.begin(), s.operations.end());
    std::stable_sort(batch.begin(), batch.end(),
                     [](const auto& a, const auto& b) { return a->priority > b->priority; });
    for (const auto& operation : batch)
    {
      if (operation->done || !s.running)
      {
        continue;
      }
      lock.unlock();
      const HDCallbackCode code = operation->callback(operation->data);
      lock.lock();
      if (code != HD_CALLBACK_CONTINUE && !operation->done)
      {
        finish(s, operation);
      }
    }
    next += std::chrono::microseconds(1000000 / s.rate);
    const Clock::time_point now = Clock::now();
    if (next < now)
    {
      next = now;  // overrun: no catching up
    }
    s.changed.wait_until(lock, next, [&s] { return !s.running; });
  }
}

void State::stop()
{
  std::unique_lock<std::mutex> lock(mutex);
  running = false;
  changed.notify_all();
  if (t_servo_thread || !servo.joinable())
  {
    return;
  }
  std::thread thread = std::move(servo);
  lock.unlock();
  thread.join();
}

std::shared_ptr<Operation> schedule(State& s, HDSchedulerCallback callback, void* data, HDushort priority)
{
  auto operation = std::make_shared<Operation>(Operation{callback, data, priority, s.next_handle++, false});
  s.operations.push_back(operation);
  return operation;
}

bool isCapability(HDenum cap)
{
  switch (cap)
  {
    case HD_FORCE_OUTPUT:
    case HD_MAX_FORCE_CLAMPING:
    case HD_FORCE_RAMPING:
    case HD_SOFTWARE_FORCE_LIMIT:
    case HD_ONE_FRAME_LIMIT:
    case HD_SOFTWARE_VELOCITY_LIMIT:
    case HD_SOFTWARE_FORCE_IMPULSE_LIMIT:
    case HD_USER_STATUS_LIGHT:
      return true;
    default:
      return false;
  }
}

bool enabled(State& s, HDenum cap)
{
  const auto found = s.capabilities.find(cap);
  return found != s.capabilities.end() ? found->second : cap != HD_FORCE_OUTPUT;  // forces start off
}

const struct
{
  HDerror code;
  const char* text;
} kErrorStrings[] = {
    {HD_SUCCESS, "No error"},
    {HD_INVALID_ENUM, "Parameter or capability not supported by this function"},
    {HD_INVALID_VALUE, "Value not accepted"},
    {HD_INVALID_OPERATION, "Operation not possible now"},
    {HD_INVALID_INPUT_TYPE, "Parameter does not take this type"},
    {HD_BAD_HANDLE, "Not the handle of an initialized device"},
    {HD_WARM_MOTORS, "Motors warm: wait before commanding forces"},
    {HD_EXCEEDED_MAX_FORCE, "Force above the device's maximum"},
    {HD_EXCEEDED_MAX_FORCE_IMPULSE, "Force change above the maximum impulse"},
    {HD_EXCEEDED_MAX_VELOCITY, "Velocity above the device's maximum"},
    {HD_FORCE_ERROR, "Incompatible kinds of force commanded together"},
    {HD_DEVICE_FAULT, "Device fault: not found, not connected or not set up"},
    {HD_DEVICE_ALREADY_INITIATED, "Device already initialized"},
    {HD_COMM_ERROR, "Communication error with the device"},
    {HD_COMM_CONFIG_ERROR, "Device communication configuration error"},
    {HD_TIMER_ERROR, "Servo loop timer could not start or keep running"},
    {HD_ILLEGAL_BEGIN, "hdBeginFrame inside a frame, or a second frame in one tick"},
    {HD_ILLEGAL_END, "hdEndFrame without hdBeginFrame"},
    {HD_FRAME_ERROR, "Call that needs a frame made outside one"},
    {HD_INVALID_PRIORITY, "Scheduler priority out of range"},
    {HD_SCHEDULER_FULL, "Scheduler full"},
    {HD_INVALID_LICENSE, "License invalid or missing"},
};

void setCapability(State& s, HDenum cap, bool on)
{
  if (deviceCall(s))
  {
    if (isCapability(cap))
    {
      s.capabilities[cap] = on;
    }
    else
    {
      pushError(s, HD_INVALID_ENUM);
    }
  }
}
}  // namespace

// The HD API (C linkage from the declarations in HD/hd.h).

HDAPI HHD HDAPIENTRY hdInitDevice(HDstring pConfigName)
{
  const int id = init_phantom(pConfigName == NULL ? "" : pConfigName);
  return locked(
      [id](State& s)
      {
        if (id < 0)
        {
          pushError(s, HD_DEVICE_FAULT, id);
          return static_cast<HHD>(HD_INVALID_HANDLE);
        }
        if (s.initialized)
        {
          pushError(s, HD_DEVICE_ALREADY_INITIATED);
          return static_cast<HHD>(HD_INVALID_HANDLE);
        }
        s.initialized = true;
        s.handle = s.current = static_cast<HHD>(id);
        s.capabilities.clear();
        s.frame = s.device;
        return s.handle;
      });
}

HDAPI void HDAPIENTRY hdMakeCurrentDevice(HHD hHD)
{
  locked(
      [hHD](State& s)
      {
        if (s.initialized && hHD == s.handle)
        {
          s.current = hHD;
        }
        else
        {
          pushError(s, HD_BAD_HANDLE);
        }
      });
}

HDAPI void HDAPIENTRY hdDisableDevice(HHD hHD)
{
  locked(
      [hHD](State& s)
      {
        if (s.initialized && hHD == s.handle)
        {
          s.initialized = false;
          s.current = HD_INVALID_HANDLE;
          s.frame_depth = 0;
        }
      });
}

HDAPI HHD HDAPIENTRY hdGetCurrentDevice()
{
  return locked([](State& s) { return s.current; });
}

HDAPI void HDAPIENTRY hdBeginFrame(HHD hHD)
{
  locked(
      [hHD](State& s)
      {
        if (s.initialized && hHD == s.handle)
        {
          s.current = hHD;  // hdBeginFrame makes its device current
        }
        if (!deviceCall(s))
        {
          return;
        }
        if (s.frame_depth == 0)
        {
          if (t_servo_thread && s.frame_done_this_tick && enabled(s, HD_ONE_FRAME_LIMIT))
          {
            pushError(s, HD_ILLEGAL_BEGIN);
            return;
          }
          s.frame = s.device;
          std::fill(s.frame.force, s.frame.force + 3, 0.0);
        }
        ++s.frame_depth;
      });
}

HDAPI void HDAPIENTRY hdEndFrame(HHD hHD)
{
  locked(
      [hHD](State& s)
      {
        if (!deviceCall(s))
        {
          return;
        }
        if (hHD != s.handle || s.frame_depth == 0)
        {
          pushError(s, HD_ILLEGAL_END);
          return;
        }
        if (--s.frame_depth > 0)
        {
          return;
        }
        s.frame_done_this_tick = t_servo_thread;
        ++s.frames_completed;
        const bool output = enabled(s, HD_FORCE_OUTPUT) && s.running;
        for (int axis = 0; axis < 3; ++axis)
        {
          s.device_force[axis] = output ? s.frame.force[axis] : 0.0;
        }
      });
}

HDAPI HDErrorInfo HDAPIENTRY hdGetError()
{
  return locked(
      [](State& s)
      {
        if (s.errors.empty())
        {
          return HDErrorInfo{HD_SUCCESS, 0, s.current};
        }
        const HDErrorInfo error = s.errors.back();  // most recent first
        s.errors.pop_back();
        return error;
      });
}

HDAPI HDstring HDAPIENTRY hdGetErrorString(HDerror errorCode)
{
  for (const auto& entry : kErrorStrings)
  {
    if (entry.code == errorCode)
    {
      return entry.text;
    }
  }
  return "Unknown error";
}

HDAPI void HDAPIENTRY hdEnable(HDenum cap)
{
  locked([cap](State& s) { setCapability(s, cap, true); });
}

HDAPI void HDAPIENTRY hdDisable(HDenum cap)
{
  locked([cap](State& s) { setCapability(s, cap, false); });
}

HDAPI HDboolean HDAPIENTRY hdIsEnabled(HDenum cap)
{
  return locked(
      [cap](State& s)
      {
        if (deviceCall(s) && !isCapability(cap))
        {
          pushError(s, HD_INVALID_ENUM);
        }
        return static_cast<HDboolean>(s.initialized && isCapability(cap) && enabled(s, cap) ? HD_TRUE : HD_FALSE);
      });
}

HDAPI void HDAPIENTRY hdGetDoublev(HDenum pname, HDdouble* params)
{
  locked(
      [pname, params](State& s)
      {
        if (!deviceCall(s))
        {
          return;
        }
        switch (pname)
        {
          case HD_CURRENT_POSITION:
            std::copy(s.frame.position, s.frame.position + 3, params);
            return;
          case HD_CURRENT_TRANSFORM:  // column-major 4x4: rotation columns, then the position in mm
            for (int column = 0; column < 3; ++column)
            {
              std::copy(s.frame.rotation + 3 * column, s.frame.rotation + 3 * column + 3, params + 4 * column);
              params[4 * column + 3] = 0.0;
            }
            std::copy(s.frame.position, s.frame.position + 3, params + 12);
            params[15] = 1.0;
            return;
          case HD_CURRENT_FORCE:
            std::copy(s.frame.force, s.frame.force + 3, params);
            return;
          case HD_NOMINAL_MAX_FORCE:
            params[0] = kNominalMaxForce;
            return;
          case HD_CURRENT_BUTTONS:
          case HD_CALIBRATION_STYLE:
            pushError(s, HD_INVALID_INPUT_TYPE);
            return;
          default:
            pushError(s, HD_INVALID_ENUM);
        }
      });
}

HDAPI void HDAPIENTRY hdGetIntegerv(HDenum pname, HDint* params)
{
  locked(
      [pname, params](State& s)
      {
        if (!deviceCall(s))
        {
          return;
        }
        switch (pname)
        {
          case HD_CURRENT_BUTTONS:
            params[0] = s.frame.buttons;
            return;
          case HD_CALIBRATION_STYLE:
            params[0] = s.styles;
            return;
          case HD_CURRENT_POSITION:
          case HD_CURRENT_TRANSFORM:
          case HD_CURRENT_FORCE:
          case HD_NOMINAL_MAX_FORCE:
            pushError(s, HD_INVALID_INPUT_TYPE);
            return;
          default:
            pushError(s, HD_INVALID_ENUM);
        }
      });
}

HDAPI HDstring HDAPIENTRY hdGetString(HDenum pname)
{
  return locked(
      [pname](State& s)
      {
        if (!deviceCall(s))
        {
          return "";
        }
        if (pname != HD_DEVICE_MODEL_TYPE)
        {
          pushError(s, HD_INVALID_ENUM);
          return "";
        }
        return "Touch (god_finger stand-in)";
      });
}

HDAPI void HDAPIENTRY hdSetDoublev(HDenum pname, const HDdouble* params)
{
  locked(
      [pname, params](State& s)
      {
        if (!deviceCall(s))
        {
          return;
        }
        if (pname != HD_CURRENT_FORCE)
        {
          pushError(s, HD_INVALID_ENUM);
        }
        else if (s.frame_depth == 0)
        {
          pushError(s, HD_FRAME_ERROR);  // setting state outside a frame
        }
        else
        {
          std::copy(params, params + 3, s.frame.force);
          std::copy(params, params + 3, s.last_force);
        }
      });
}

HDAPI HDenum HDAPIENTRY hdCheckCalibration()
{
  return locked([](State& s)
                { return deviceCall(s) ? s.calibration : static_cast<HDenum>(HD_CALIBRATION_NEEDS_MANUAL_INPUT); });
}

HDAPI void HDAPIENTRY hdUpdateCalibration(HDenum style)
{
  locked(
      [style](State& s)
      {
        ++(t_servo_thread ? s.calibrations_on_servo : s.calibrations_off_servo);
        s.last_style = style;
        if (!deviceCall(s))
        {
          return;
        }
        if (style != HD_CALIBRATION_ENCODER_RESET && style != HD_CALIBRATION_AUTO && style != HD_CALIBRATION_INKWELL)
        {
          return;  // as the real one: any other value (e.g. a mask of several styles) does nothing
        }
        if ((s.styles & static_cast<int>(style)) == 0)
        {
          pushError(s, HD_DEVICE_FAULT);  // the device cannot calibrate this way
        }
        else if (style != HD_CALIBRATION_ENCODER_RESET && !t_servo_thread)
        {
          pushError(s, HD_INVALID_OPERATION);  // stand-in rule, see the top of this file
        }
        else if (style == HD_CALIBRATION_ENCODER_RESET || s.calibration == HD_CALIBRATION_NEEDS_UPDATE)
        {
          s.calibration = HD_CALIBRATION_OK;  // NEEDS_MANUAL_INPUT stays: the stylus is not in the inkwell
        }
      });
}

HDAPI void HDAPIENTRY hdStartScheduler()
{
  State& s = state();
  std::unique_lock<std::mutex> lock(s.mutex);
  if (s.running)
  {
    return;
  }
  std::thread previous = std::move(s.servo);  // left by a stop from the servo thread itself
  if (previous.joinable())
  {
    lock.unlock();
    previous.join();
    lock.lock();
  }
  s.running = true;
  s.servo = std::thread(servoLoop);
}

HDAPI void HDAPIENTRY hdStopScheduler()
{
  state().stop();
}

HDAPI void HDAPIENTRY hdSetSchedulerRate(HDulong nRate)
{
  locked(
      [nRate](State& s)
      {
        if (nRate == 500 || nRate == 1000 || nRate == 2000)
        {
          s.rate = nRate;
        }
        else
        {
          pushError(s, HD_INVALID_VALUE);
        }
      });
}

HDAPI void HDAPIENTRY hdScheduleSynchronous(HDSchedulerCallback pCallback, void* pUserData, HDushort nPriority)
{
  if (t_servo_thread)
  {
    pCallback(pUserData);  // from the servo thread: at once, whatever the priority
    return;
  }
  State& s = state();
  std::unique_lock<std::mutex> lock(s.mutex);
  if (!s.running)
  {
    pushError(s, HD_INVALID_OPERATION);  // stand-in choice: no waiting for a scheduler never started
    return;
  }
  const auto operation = schedule(s, pCallback, pUserData, nPriority);
  s.changed.wait(lock, [&] { return operation->done || !s.running; });
  s.operations.remove(operation);  // if the scheduler stopped first
}

HDAPI HDSchedulerHandle HDAPIENTRY hdScheduleAsynchronous(HDSchedulerCallback pCallback, void* pUserData,
                                                          HDushort nPriority)
{
  return locked([&](State& s) { return schedule(s, pCallback, pUserData, nPriority)->handle; });
}

HDAPI void HDAPIENTRY hdUnschedule(HDSchedulerHandle hHandle)
{
  locked(
      [hHandle](State& s)
      {
        for (const auto& operation : s.operations)
        {
          if (operation->handle == hHandle)
          {
            finish(s, operation);
            return;
          }
        }
        pushError(s, HD_INVALID_OPERATION);  // already terminated
      });
}

HDAPI HDboolean HDAPIENTRY hdWaitForCompletion(HDSchedulerHandle hHandle, HDWaitCode param)
{
  State& s = state();
  std::unique_lock<std::mutex> lock(s.mutex);
  const auto scheduled = [&s, hHandle]
  {
    return std::any_of(s.operations.begin(), s.operations.end(),
                       [hHandle](const auto& operation) { return operation->handle == hHandle; });
  };
  if (param == HD_WAIT_INFINITE)
  {
    s.changed.wait(lock, [&] { return !scheduled() || !s.running; });
    return scheduled() ? HD_FALSE : HD_TRUE;  // true: the wait succeeded
  }
  return scheduled() ? HD_TRUE : HD_FALSE;  // HD_WAIT_CHECK_STATUS: true while still scheduled
}

HDAPI HDdouble HDAPIENTRY hdGetSchedulerTimeStamp()
{
  return locked([](State& s) { return std::chrono::duration<double>(Clock::now() - s.tick_start).count(); });
}

// The test control API (C linkage from hd_stand_in_control.h).

void hdStandInReset(void)
{
  state().stop();
  locked([](State& s) { static_cast<Model&>(s) = Model(); });
}

void hdStandInSetPositionMm(double x, double y, double z)
{
  locked(
      [=](State& s)
      {
        s.device.position[0] = x;
        s.device.position[1] = y;
        s.device.position[2] = z;
      });
}

void hdStandInSetRotation(const double column_major_3x3[9])
{
  locked([=](State& s) { std::copy(column_major_3x3, column_major_3x3 + 9, s.device.rotation); });
}

void hdStandInSetButtons(int buttons)
{
  locked([=](State& s) { s.device.buttons = buttons; });
}

void hdStandInSetCalibrationStatus(unsigned status)
{
  locked([=](State& s) { s.calibration = status; });
}

void hdStandInSetCalibrationStyles(int styles)
{
  locked([=](State& s) { s.styles = styles; });
}

unsigned hdStandInCalibrationStatus(void)
{
  return locked([](State& s) { return s.calibration; });
}

void hdStandInPushError(unsigned error_code, int internal_error_code)
{
  locked([=](State& s) { pushError(s, error_code, internal_error_code); });
}

int hdStandInErrorCount(void)
{
  return locked([](State& s) { return static_cast<int>(s.errors.size()); });
}

void hdStandInLastForce(double force[3])
{
  locked([=](State& s) { std::copy(s.last_force, s.last_force + 3, force); });
}

void hdStandInDeviceForce(double force[3])
{
  locked([=](State& s) { std::copy(s.device_force, s.device_force + 3, force); });
}

int hdStandInForceOutputEnabled(void)
{
  return locked([](State& s) { return s.initialized && enabled(s, HD_FORCE_OUTPUT) ? 1 : 0; });
}

int hdStandInDeviceInitialized(void)
{
  return locked([](State& s) { return s.initialized ? 1 : 0; });
}

int hdStandInSchedulerRunning(void)
{
  return locked([](State& s) { return s.running ? 1 : 0; });
}

long hdStandInServoTicks(void)
{
  return locked([](State& s) { return s.ticks; });
}

long hdStandInFramesCompleted(void)
{
  return locked([](State& s) { return s.frames_completed; });
}

int hdStandInUpdateCalibrationCalls(int on_servo_thread)
{
  return locked([=](State& s) { return on_servo_thread != 0 ? s.calibrations_on_servo : s.calibrations_off_servo; });
}

unsigned hdStandInLastCalibrationStyle(void)
{
  return locked([](State& s) { return s.last_style; });
}

int hdStandInOffServoThreadCalls(void)
{
  return locked([](State& s) { return s.off_servo_calls; });
}
