// How a contact model's contacts reach the solver: one implementation per model
// (god_object_response.cpp, god_finger_response.cpp, soft_finger_response.cpp), chosen once
// per model change through the one list of models (contact_model.cpp). Internal to physics.
//
// A new contact model is a new file implementing this and one row in that list.
#pragma once

#include "area_solver_input.h"
#include "solver/pad_constraints.h"
#include "proxy.h"
#include "solver/sub_god_object_injection.h"

#include "god_finger/physics/contact_model.h"
#include "god_finger/physics/world_params.h"

#include <memory>

namespace god_finger::internal
{
// Where a response puts what it adds to this step's solve.
struct SolverAdditions
{
  SubGodObjectInjector* sub_god_objects = nullptr;  // pad_solver: points
  PadConstraints* pads = nullptr;                   // pad_solver: constraint
};

class ContactResponse
{
 public:
  virtual ~ContactResponse() = default;
  // The proxy's Bullet settings under this model (its rolling and spinning friction).
  // Not real-time (called on a model change and when a proxy is built).
  virtual void configureProxy(const WorldParams& params, btRigidBody* proxy) const = 0;
  // One contact area, between collision detection and the solver of step `step`: adds
  // whatever the model adds to the solver into `to`. Real-time safe once their lists have grown.
  virtual void respond(const WorldParams& params, const AreaSolverInput& contact, Proxy* proxy, long step,
                       const SolverAdditions& to) const = 0;
};

// The response of `model`, from the one list (contact_model.cpp).
std::unique_ptr<ContactResponse> makeContactResponse(ContactModel model);

std::unique_ptr<ContactResponse> makeGodObjectResponse();
std::unique_ptr<ContactResponse> makeGodFingerResponse();
std::unique_ptr<ContactResponse> makeSoftFingerResponse();
}  // namespace god_finger::internal
