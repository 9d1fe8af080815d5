/* Test stand-in, written for god_finger from 3D Systems' (SensAble's) OpenHaptics HD API as
   published (the Linux SDK's include/HD headers); not the vendor's file.
   Mirrors: include/HD/hd.h, the umbrella header. Like the vendor's, it has no include guard of
   its own (each sub-header has one) and includes hdCompilerConfig.h, hdDefines.h, hdDevice.h
   and hdScheduler.h in that order; hdExport.h comes in through hdDevice.h, so the
   defined(linux) guard of hdExport.h decides whether anything declared here compiles. */

#include <HD/hdCompilerConfig.h>
#include <HD/hdDefines.h>
#include <HD/hdDevice.h>
#include <HD/hdScheduler.h>
