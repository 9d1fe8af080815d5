// Test control of the stand-in libHD (hd_stand_in.cpp): not part of OpenHaptics. It sets what the
// simulated Touch reports and reads what the code under test did with it. Plain C types, so it
// needs no HD header (and none of its `linux` guard). Thread-safe; callable from any thread.
#pragma once

#ifdef __cplusplus
extern "C"
{
#endif

  // Stops the scheduler, disables the device, empties the error stack, zeroes the counters and
  // restores the defaults: stylus at (0, 0, 0) mm, identity rotation, no button, calibration
  // HD_CALIBRATION_OK, styles HD_CALIBRATION_INKWELL, forces off.
  void hdStandInReset(void);

  // The simulated device, read by hdBeginFrame (and so by hdGet* inside the next frame).
  void hdStandInSetPositionMm(double x, double y, double z);
  void hdStandInSetRotation(const double column_major_3x3[9]);
  void hdStandInSetButtons(int buttons);                // HD_DEVICE_BUTTON_* bits
  void hdStandInSetCalibrationStatus(unsigned status);  // HD_CALIBRATION_OK / _NEEDS_UPDATE / ...
  void hdStandInSetCalibrationStyles(int styles);       // what hdGetIntegerv(HD_CALIBRATION_STYLE) gives
  unsigned hdStandInCalibrationStatus(void);

  // Pushes an error onto the HD error stack, as a device fault in the servo loop would.
  void hdStandInPushError(unsigned error_code, int internal_error_code);
  int hdStandInErrorCount(void);  // errors on the stack, not yet popped by hdGetError

  // Forces: the last hdSetDoublev(HD_CURRENT_FORCE) values, and what the motors got at the last
  // hdEndFrame (zero unless HD_FORCE_OUTPUT is enabled and the scheduler runs).
  void hdStandInLastForce(double force[3]);
  void hdStandInDeviceForce(double force[3]);
  int hdStandInForceOutputEnabled(void);

  int hdStandInDeviceInitialized(void);
  int hdStandInSchedulerRunning(void);
  long hdStandInServoTicks(void);       // servo ticks (1 kHz) since the scheduler first started
  long hdStandInFramesCompleted(void);  // hdBeginFrame/hdEndFrame pairs closed

  // hdUpdateCalibration calls made inside a scheduler callback on the servo thread (nonzero
  // argument) or from any other thread (zero), and the style of the last call.
  int hdStandInUpdateCalibrationCalls(int on_servo_thread);
  unsigned hdStandInLastCalibrationStyle(void);

  // Device-state calls (frames, hdGet*/hdSet*, hdEnable/hdDisable, calibration) made from
  // another thread than the servo thread while the scheduler runs: the programmer's guide says
  // such calls are not thread safe. hdMakeCurrentDevice and hdGetError are not counted.
  int hdStandInOffServoThreadCalls(void);

#ifdef __cplusplus
}
#endif
