/* Test stand-in, written for god_finger from 3D Systems' (SensAble's) OpenHaptics HD API as
   published (the Linux SDK's include/HD headers); not the vendor's file.
   Mirrors: include/HD/hdCompilerConfig.h of OpenHaptics 3.0 for Linux, which on Linux defines
   nothing: its only branch is defined(__APPLE__) (includes <TargetConditionals.h>). Note: its
   closing comment names HD_COMPILER_CONFIG_H_DEFINE while the guard is
   HD_COMPILERCONFIG_H_DEFINE; the guard below is the one the vendor tests. (Another published
   copy, of unknown version, also defines TRUE, FALSE, max, min, MB_OK and Sleep under
   defined(linux) || defined(__APPLE__); not reproduced here.) */

#ifndef HD_COMPILERCONFIG_H_DEFINE
#define HD_COMPILERCONFIG_H_DEFINE

#if defined(__APPLE__)
#include <TargetConditionals.h>
#endif /* __APPLE__ */

#endif /* HD_COMPILERCONFIG_H_DEFINE */
