// Subnormal numbers (|x| < 2.2e-308) out of the real-time threads. On x86 an operation on a
// subnormal takes many times longer than on a normal number, and a decay that is never reset
// (a damped velocity, a proxy settling on its target) walks into that range after a long idle.
// flushDenormalsInThisThread() sets the calling thread's SSE control word to flush subnormal
// results to zero (FTZ) and read subnormal inputs as zero (DAZ); each real-time thread (the
// servo loop's haptic and physics threads, the device driver's and the physics node's loops)
// calls it once at its start. A safety net: the paths that decay are also cut at their source
// (flushTiny). No-op on a CPU without SSE. Real-time safe.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace god_finger
{
void flushDenormalsInThisThread();

// True when the calling thread flushes subnormals (FTZ and DAZ set).
bool denormalsFlushedInThisThread();

// Components of |v| below 1e-200 (far below any physical length, speed or force, far above the
// subnormal range) set to exactly 0: a decay toward zero ends there instead of in subnormals.
inline void flushTiny(Eigen::Vector3d* v)
{
  for (int i = 0; i < 3; ++i)
  {
    if (std::abs((*v)[i]) < 1e-200)
    {
      (*v)[i] = 0.0;
    }
  }
}
}  // namespace god_finger
