// god_object: the paper's baseline, the proxy's single contact point as Bullet finds it.
#include "contact_response.h"

namespace god_finger::internal
{
namespace
{
class GodObjectResponse : public ContactResponse
{
 public:
  void configureProxy(const WorldParams&, btRigidBody* proxy) const override
  {
    proxy->setRollingFriction(0.0);
    proxy->setSpinningFriction(0.0);
  }
  void respond(const WorldParams&, const AreaSolverInput&, Proxy*, long, const SolverAdditions&) const override {}
};
}  // namespace

std::unique_ptr<ContactResponse> makeGodObjectResponse()
{
  return std::make_unique<GodObjectResponse>();
}
}  // namespace god_finger::internal
