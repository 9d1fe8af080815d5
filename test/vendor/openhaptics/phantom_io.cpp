// Test stand-in for libPHANToMIO.so.4, the device I/O library of the Touch device driver
// (installed as libPHANToMIO.so.4.3, linked as libPHANToMIO.so.4). The real libHD.so.3.0.0 has
// it as DT_NEEDED and its hdInitDevice calls the driver's init_phantom(name) (name "" for
// HD_DEFAULT_DEVICE), which returns a device id >= 0, used as the HHD, or a negative PHANToM
// error that libHD maps to an HD_ code. This stand-in has that one function, so that the
// stand-in libHD has the same dependency; its signature is the one of SensAble's PHANToM I/O
// header as published, with const added.
#include <cstring>

extern "C" __attribute__((visibility("default"))) int init_phantom(const char* config_name)
{
  const char* const known[] = {"", "Default Device", "Default PHANToM"};  // Touch driver, OpenHaptics 3.0
  for (const char* name : known)
  {
    if (config_name != nullptr && std::strcmp(config_name, name) == 0)
    {
      return 0;  // the first (and only) device
    }
  }
  return -4;  // PHTM_DEV_FAULT: no such configuration (libHD reports HD_DEVICE_FAULT)
}
