// Factories of the vendor seams. Each is defined in one source file under
// src/devices/vendor/ that CMake builds only when it finds the vendor's library; the
// GOD_FINGER_HAVE_NIFALCON / GOD_FINGER_HAVE_OPENHAPTICS definitions say which were built.
#pragma once

#include "god_finger/devices/falcon_device.h"
#include "god_finger/devices/omni_device.h"

#include <memory>

namespace god_finger
{
std::unique_ptr<FalconIo> makeNifalconIo();   // libnifalcon (libusb-1.0 comm)
std::unique_ptr<OmniIo> makeOpenHapticsIo();  // OpenHaptics HD API
}  // namespace god_finger
