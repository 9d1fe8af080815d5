#include "god_finger/devices/vendor_io.h"

#include <dlfcn.h>

namespace god_finger
{
VendorModule openHapticsModule()
{
#ifdef GOD_FINGER_OMNI_IO_MODULE
  return {GOD_FINGER_OMNI_IO_MODULE_NAME, GOD_FINGER_OMNI_IO_MODULE};
#else
  return {};
#endif
}

std::unique_ptr<OmniIo> loadOpenHapticsIo(const std::string& module)
{
  dlerror();
  void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle)
  {
    const std::string why = dlerror();
    std::string what = "install 3D Systems' OpenHaptics, then rebuild god_finger";
    if (why.find("PHANToMIO") != std::string::npos)
    {
      what =
          "libHD needs the Touch device driver's libPHANToMIO: install 3D Systems' Touch device driver for "
          "Linux (and check the device with Touch_Setup)";
    }
    else if (why.find("libHD") != std::string::npos)
    {
      what = "install 3D Systems' OpenHaptics (its libHD) where the loader finds it (ldconfig, or LD_LIBRARY_PATH)";
    }
    throw DeviceError("backend 'omni': cannot load the OpenHaptics backend " + module + " (" + why + "): " + what +
                      " (docs/devices.md)");
  }
  using Factory = OmniIo* (*)();
  auto factory = reinterpret_cast<Factory>(dlsym(handle, "god_finger_make_openhaptics_io"));
  if (!factory)
  {
    throw DeviceError("backend 'omni': " + module + " is not god_finger's OpenHaptics backend (no entry point)");
  }
  return std::unique_ptr<OmniIo>(factory());
}
}  // namespace god_finger
