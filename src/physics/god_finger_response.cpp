// god_finger: the paper's method, the proxy's point plus the sub-god-objects of its contact
// area, as points (sub_god_object_injection.h) or as one pad constraint (pad_constraints.h).
#include "contact_response.h"

namespace god_finger::internal
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
  void respond(const WorldParams& params, const AreaSolverInput& contact, Proxy* proxy, long step,
               const SolverAdditions& to) const override
  {
    if (params.pad_solver == PadSolver::kConstraint)
    {
      to.pads->add(contact, proxy, step);
    }
    else
    {
      to.sub_god_objects->inject(contact, *proxy, step);
    }
  }
};
}  // namespace

std::unique_ptr<ContactResponse> makeGodFingerResponse()
{
  return std::make_unique<GodFingerResponse>();
}
}  // namespace god_finger::internal
