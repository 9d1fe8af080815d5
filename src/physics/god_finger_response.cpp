// god_finger: the paper's method, the proxy's point plus the sub-god-objects of its contact
// area (sub_god_object_injection.h).
#include "contact_response.h"

namespace god_finger
{
namespace
{
class GodFingerResponse : public ContactResponse
{
 public:
  void configureProxy(const WorldParams&, btRigidBody* proxy) const override
  {
    proxy->setRollingFriction(0.0);
    proxy->setSpinningFriction(0.0);
  }
  void respond(const AreaContact& contact, const Proxy& proxy, long step, SubGodObjectInjector* injector) const override
  {
    injector->inject(contact, proxy, step);
  }
};
}  // namespace

std::unique_ptr<ContactResponse> makeGodFingerResponse()
{
  return std::make_unique<GodFingerResponse>();
}
}  // namespace god_finger
