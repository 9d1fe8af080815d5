// A device that carries several fingers (a hand tracker, a glove, mocap, the scripted fake
// hand): a HandSource reads every fingertip at once; splitHand() makes one HapticDevice per
// finger, which the servo loop runs as an interface each (all of them in one tick).
//
// Frames and units: positions in metres in the device frame (haptic_device.h), one per finger.
// A hand source is input only: it renders no force (the forces its fingers are given are
// dropped; the registry row says so, DeviceBackend::renders_force).
//
// Lost fingers: a finger the source does not see (no pose yet, a pose older than its timeout,
// a non-finite one) reads tracked = false; the loop then lets it go (its target follows its
// proxy: no force, the proxy released) and the servo node reports it in a diagnostic naming
// the finger. The others go on.
//
// Real-time safety: read() is called from the loop's thread once per tick (the first finger's
// update at a new time) and must not allocate (its output vector is sized by start()).
#pragma once

#include "god_finger/devices/haptic_device.h"

#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
class HandSource
{
 public:
  virtual ~HandSource() = default;
  virtual std::string name() const = 0;
  // The fingers' names, in order (e.g. thumb, index, middle); fixed at construction.
  virtual std::vector<std::string> fingers() const = 0;
  // Opens the source. Throws DeviceError.
  virtual void start() {}
  // Every finger at `time` (s, update()'s clock), into `readings` (fingers().size() entries).
  virtual void read(double time, std::vector<DeviceReading>* readings) = 0;
  // Scripted sources: the time of read()'s clock at which the script's time 0 is played.
  virtual void setScriptStart(double /*time*/) {}
};

// The hand as one HapticDevice whose fingers() are its fingers; it is itself never updated
// (update() throws: the loop runs its fingers).
std::unique_ptr<HapticDevice> makeHandDevice(std::shared_ptr<HandSource> source);
}  // namespace god_finger
