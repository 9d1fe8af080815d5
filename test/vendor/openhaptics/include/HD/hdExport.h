/* Test stand-in, written for god_finger from 3D Systems' (SensAble's) OpenHaptics HD API as
   published (the API reference and the Linux SDK's include/HD headers); not the vendor's file.
   Mirrors: include/HD/hdExport.h of OpenHaptics 3.0 for Linux (3.4's copy was not available).
   Reproduces its guards: HDAPI, HDAPIENTRY and HDCALLBACK are defined only under
   defined(WIN32) (dllexport/dllimport + __stdcall), defined(linux) (HDAPI empty, HDAPIENTRY and
   HDCALLBACK __attribute__((stdcall)), which x86-64 GCC ignores with -Wattributes) and
   defined(__APPLE__) (all empty). GCC defines `linux` only in its GNU modes: with -std=c++17
   (CMAKE_CXX_EXTENSIONS OFF) nothing is defined and every HD declaration fails with
   "'HDAPI' does not name a type", as with the vendor's header; the vendor's example Makefiles
   pass -Dlinux. */

#ifndef HD_EXPORT_H_DEFINE
#define HD_EXPORT_H_DEFINE

#if defined(WIN32)
#ifdef HD_EXPORTS
#define HDAPI __declspec(dllexport)
#else
#define HDAPI __declspec(dllimport)
#endif
#define HDAPIENTRY __stdcall
#define HDCALLBACK __stdcall
#endif /* WIN32 */

#if defined(linux)
#define HDAPI
#define HDAPIENTRY __attribute__((stdcall))
#define HDCALLBACK __attribute__((stdcall))
#endif /* linux */

#if defined(__APPLE__)
#define HDAPI
#define HDAPIENTRY
#define HDCALLBACK
#endif /* __APPLE__ */

#endif /* HD_EXPORT_H_DEFINE */
