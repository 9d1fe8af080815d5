// Factories of the vendor seams.
//  - libnifalcon: src/devices/vendor/falcon_io_nifalcon.cpp, linked into the registry when CMake
//    finds a libnifalcon with the std::array API (GOD_FINGER_HAVE_NIFALCON); it needs libusb only.
//  - OpenHaptics: src/devices/vendor/omni_io_openhaptics.cpp, built as a module of its own
//    (libgod_finger_omni_io.so) when CMake finds OpenHaptics, and loaded (dlopen) only by the
//    process that asks for backend omni: libHD needs the Touch device driver's libPHANToMIO.so.4,
//    which no other backend, and no program that never uses the Omni, may need.
#pragma once

#include "god_finger/devices/falcon_device.h"
#include "god_finger/devices/omni_device.h"

#include <memory>
#include <string>

namespace god_finger
{
std::unique_ptr<FalconIo> makeNifalconIo();  // libnifalcon (libusb-1.0 comm)

// The OpenHaptics module this build made: its file name (found on the library path, as after
// sourcing the workspace's setup.bash) and its path in the build; both empty when CMake did not
// find OpenHaptics.
struct VendorModule
{
  std::string file_name;
  std::string build_path;
};
VendorModule openHapticsModule();

// Loads the OmniIo of the module at `module` (a file name, searched on the library path, or a
// path), and with it libHD. DeviceError saying what to install when the module, libHD or the
// Touch driver's libraries cannot be loaded. The module stays loaded for the process' life (the
// HD scheduler's threads run in it).
std::unique_ptr<OmniIo> loadOpenHapticsIo(const std::string& module);
}  // namespace god_finger
