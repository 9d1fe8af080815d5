// soft_finger: one point with a pad's torques through Bullet's spinning and rolling friction (SoftFingerParams;
// Bullet's sequential impulse solver adds spinning friction only when rolling friction is set).
#include "contact_response.h"

namespace god_finger::internal
{
namespace
{
class SoftFingerResponse : public ContactResponse
{
 public:
  void configureProxy(const WorldParams& params, btRigidBody* proxy) const override
  {
    proxy->setRollingFriction(params.soft_finger.rolling_friction);
    proxy->setSpinningFriction(params.soft_finger.spinning_friction);
  }
  void respond(const WorldParams&, const AreaSolverInput&, Proxy*, long, const SolverAdditions&) const override {}
};
}  // namespace

std::unique_ptr<ContactResponse> makeSoftFingerResponse()
{
  return std::make_unique<SoftFingerResponse>();
}
}  // namespace god_finger::internal
