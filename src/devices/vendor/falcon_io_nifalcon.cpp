// FalconIo on libnifalcon (git master, 1.0.2+: std::array positions and forces, firmware compiled in;
// checked by compiling and linking against it).
// The only file that includes a libnifalcon header; built when CMake finds libnifalcon.
#include "god_finger/devices/vendor_io.h"

#include <falcon/core/FalconDevice.h>
#include <falcon/firmware/FalconFirmwareNovintSDK.h>
#include <falcon/grip/FalconGripFourButton.h>
#include <falcon/kinematic/FalconKinematicStamper.h>
#include <falcon/util/FalconFirmwareBinaryNvent.h>

namespace god_finger
{
namespace
{
class NifalconIo : public FalconIo
{
 public:
  NifalconIo()
  {
    falcon_.setFalconFirmware<libnifalcon::FalconFirmwareNovintSDK>();
    falcon_.setFalconGrip<libnifalcon::FalconGripFourButton>();
    falcon_.setFalconKinematic<libnifalcon::FalconKinematicStamper>();
  }
  ~NifalconIo() override
  {
    falcon_.close();
  }
  int deviceCount() override
  {
    unsigned int count = 0;
    return falcon_.getDeviceCount(count) ? static_cast<int>(count) : 0;
  }
  bool open(int index) override
  {
    return falcon_.open(static_cast<unsigned int>(index));
  }
  bool isFirmwareLoaded() override
  {
    return falcon_.isFirmwareLoaded();
  }
  bool loadFirmware() override
  {
    // The Novint firmware ships inside libnifalcon; skip_checksum as its own tools do on Linux.
    return falcon_.getFalconFirmware()->loadFirmware(true, libnifalcon::NOVINT_FALCON_NVENT_FIRMWARE_SIZE,
                                                     const_cast<uint8_t*>(libnifalcon::NOVINT_FALCON_NVENT_FIRMWARE));
  }
  void setHomingMode(bool on) override
  {
    falcon_.getFalconFirmware()->setHomingMode(on);
  }
  bool isHomed() override
  {
    return falcon_.getFalconFirmware()->isHomed();
  }
  bool runIoLoop() override
  {
    return falcon_.runIOLoop();
  }
  std::array<double, 3> position() override
  {
    return falcon_.getPosition();
  }
  void setForce(const std::array<double, 3>& force) override
  {
    falcon_.setForce(force);
  }
  unsigned buttons() override
  {
    return falcon_.getFalconGrip()->getDigitalInputs();
  }
  std::string lastError() override
  {
    return nifalconErrorText(falcon_.getErrorCode());
  }

 private:
  libnifalcon::FalconDevice falcon_;
};
}  // namespace

std::unique_ptr<FalconIo> makeNifalconIo()
{
  return std::make_unique<NifalconIo>();
}
}  // namespace god_finger
