/* Test stand-in, written for god_finger from 3D Systems' (SensAble's) OpenHaptics HD API as
   published (the API reference, chapters 1-2, and the Linux SDK's include/HD headers); not the
   vendor's file. Mirrors: include/HD/hdDevice.h: the device, frame, error, capability,
   parameter and calibration routines, with the same names, signatures and HD_DEVICE_ERROR.
   Reproduces: the HD_DEVICE_H_DEFINE guard; it includes hdExport.h, hdCompilerConfig.h and
   hdDefines.h itself; every prototype is `HDAPI <type> HDAPIENTRY name(...)`, so without
   `linux` (or WIN32 / __APPLE__) defined the first one fails with
   "'HDAPI' does not name a type"; extern "C" under __cplusplus. The stand-in libHD
   (hd_stand_in.cpp) defines the routines god_finger uses; the others are declared only. */

#ifndef HD_DEVICE_H_DEFINE
#define HD_DEVICE_H_DEFINE

#include <HD/hdCompilerConfig.h>
#include <HD/hdDefines.h>
#include <HD/hdExport.h>

#ifdef __cplusplus
extern "C"
{
#endif

  /* Devices: NULL (HD_DEFAULT_DEVICE) opens the first one; the handle becomes current. */
  HDAPI HHD HDAPIENTRY hdInitDevice(HDstring pConfigName);
  HDAPI void HDAPIENTRY hdMakeCurrentDevice(HHD hHD);
  HDAPI void HDAPIENTRY hdDisableDevice(HHD hHD);
  HDAPI HHD HDAPIENTRY hdGetCurrentDevice();

  /* A frame: begin reads the device state, end writes forces; state calls belong inside one. */
  HDAPI void HDAPIENTRY hdBeginFrame(HHD hHD);
  HDAPI void HDAPIENTRY hdEndFrame(HHD hHD);

  /* Pops the most recent error; HD_SUCCESS when none is left. */
  HDAPI HDErrorInfo HDAPIENTRY hdGetError();
#define HD_DEVICE_ERROR(X) (((X).errorCode) != HD_SUCCESS)
  HDAPI HDstring HDAPIENTRY hdGetErrorString(HDerror errorCode);

  HDAPI void HDAPIENTRY hdEnable(HDenum cap);
  HDAPI void HDAPIENTRY hdDisable(HDenum cap);
  HDAPI HDboolean HDAPIENTRY hdIsEnabled(HDenum cap);

  /* The caller sizes params for pname (e.g. 3 for HD_CURRENT_POSITION, 16 for a transform). */
  HDAPI void HDAPIENTRY hdGetBooleanv(HDenum pname, HDboolean* params);
  HDAPI void HDAPIENTRY hdGetIntegerv(HDenum pname, HDint* params);
  HDAPI void HDAPIENTRY hdGetFloatv(HDenum pname, HDfloat* params);
  HDAPI void HDAPIENTRY hdGetDoublev(HDenum pname, HDdouble* params);
  HDAPI void HDAPIENTRY hdGetLongv(HDenum pname, HDlong* params);
  HDAPI HDstring HDAPIENTRY hdGetString(HDenum pname);

  HDAPI void HDAPIENTRY hdSetBooleanv(HDenum pname, const HDboolean* params);
  HDAPI void HDAPIENTRY hdSetIntegerv(HDenum pname, const HDint* params);
  HDAPI void HDAPIENTRY hdSetFloatv(HDenum pname, const HDfloat* params);
  HDAPI void HDAPIENTRY hdSetDoublev(HDenum pname, const HDdouble* params);
  HDAPI void HDAPIENTRY hdSetLongv(HDenum pname, const HDlong* params);

  HDAPI HDenum HDAPIENTRY hdCheckCalibration();
  HDAPI HDenum HDAPIENTRY hdCheckCalibrationStyle();
  HDAPI void HDAPIENTRY hdUpdateCalibrationMessage(HDenum style);
  HDAPI void HDAPIENTRY hdUpdateCalibration(HDenum style);

  HDAPI void HDAPIENTRY hdScaleGimbalAngles(HDdouble scaleX, HDdouble scaleY, HDdouble scaleZ, HDdouble nT[16]);

  HDAPI HDboolean HDAPIENTRY hdDeploymentLicense(const char* vendorName, const char* applicationName,
                                                 const char* password);

#ifdef __cplusplus
}
#endif

#endif /* HD_DEVICE_H_DEFINE */
