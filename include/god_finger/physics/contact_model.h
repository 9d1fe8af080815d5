// The ways a finger's contact reaches the solver, switchable while running. The one list of
// them (names, order, responses) is in contact_model.cpp; everything else (the cfg's enum,
// the tools, the device's model button, messages) follows it.
#pragma once

#include <string>
#include <vector>

namespace god_finger
{
enum class ContactModel
{
  kGodObject = 0,   // the single contact point of the god-object (the paper's baseline)
  kGodFinger = 1,   // plus the sub-god-objects of the contact area (the paper's method)
  kSoftFinger = 2,  // the single point with Bullet's spinning and rolling friction
};
// The models in the list's order.
const std::vector<ContactModel>& contactModels();
const char* contactModelName(ContactModel model);
// False for a value that is no model of the list.
bool isContactModel(ContactModel model);
// "god_object", "god_finger", "soft_finger"; false on anything else.
bool parseContactModel(const std::string& text, ContactModel* model);
// The next in the list (the device's model button cycles through them).
ContactModel nextContactModel(ContactModel model);
// "god_object, god_finger, soft_finger".
std::string contactModelNames();
}  // namespace god_finger
