/* Test stand-in, written for god_finger from 3D Systems' (SensAble's) OpenHaptics HD API as
   published (the API reference, chapter 3, and the Linux SDK's include/HD headers); not the
   vendor's file. Mirrors: include/HD/hdScheduler.h: the servo-loop scheduler, its callback
   type and codes. Reproduces: the HD_SCHEDULER_H_DEFINE guard; it includes hdExport.h,
   hdCompilerConfig.h and hdDefines.h itself; HDSchedulerCallback carries HDCALLBACK and every
   prototype HDAPI/HDAPIENTRY, so it needs `linux` (or WIN32 / __APPLE__) defined like
   hdDevice.h; extern "C" under __cplusplus. HD_DEFAULT_SCHEDULER_PRIORITY is in hdDefines.h,
   as in the vendor's headers. */

#ifndef HD_SCHEDULER_H_DEFINE
#define HD_SCHEDULER_H_DEFINE

#include <HD/hdCompilerConfig.h>
#include <HD/hdDefines.h>
#include <HD/hdExport.h>

#ifdef __cplusplus
extern "C"
{
#endif

  /* What a callback returns: done (unscheduled) or run again next tick. */
  typedef unsigned int HDCallbackCode;
#define HD_CALLBACK_DONE 0
#define HD_CALLBACK_CONTINUE 1

  typedef unsigned long HDSchedulerHandle;

  typedef HDCallbackCode(HDCALLBACK* HDSchedulerCallback)(void* pUserData);

  /* hdWaitForCompletion modes. */
  typedef unsigned int HDWaitCode;
#define HD_WAIT_CHECK_STATUS 0
#define HD_WAIT_INFINITE 1

  HDAPI void HDAPIENTRY hdStartScheduler();
  HDAPI void HDAPIENTRY hdStopScheduler();
  HDAPI void HDAPIENTRY hdSetSchedulerRate(HDulong nRate);

  /* Runs pCallback in the servo thread and waits for it to return HD_CALLBACK_DONE; called from
     the servo thread itself, it runs at once. Higher nPriority runs first within a tick. */
  HDAPI void HDAPIENTRY hdScheduleSynchronous(HDSchedulerCallback pCallback, void* pUserData, HDushort nPriority);
  HDAPI HDSchedulerHandle HDAPIENTRY hdScheduleAsynchronous(HDSchedulerCallback pCallback, void* pUserData,
                                                            HDushort nPriority);
  HDAPI void HDAPIENTRY hdUnschedule(HDSchedulerHandle hHandle);
  HDAPI HDboolean HDAPIENTRY hdWaitForCompletion(HDSchedulerHandle hHandle, HDWaitCode param);

  /* Seconds since the start of the current servo tick. */
  HDAPI HDdouble HDAPIENTRY hdGetSchedulerTimeStamp();

#ifdef __cplusplus
}
#endif

#endif /* HD_SCHEDULER_H_DEFINE */
