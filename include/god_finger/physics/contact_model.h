// The three ways a finger's contact reaches the solver, switchable while running.
#pragma once

#include <string>

namespace god_finger
{
enum class ContactModel
{
  kGodObject = 0,   // the single contact point of the god-object (the paper's baseline)
  kGodFinger = 1,   // plus the sub-god-objects of the contact area (the paper's method)
  kSoftFinger = 2,  // the single point with Bullet's spinning and rolling friction
};
const char* contactModelName(ContactModel model);
// "god_object", "god_finger", "soft_finger"; false on anything else.
bool parseContactModel(const std::string& text, ContactModel* model);
// The models in order, for lists and the device's model button (which cycles through them).
constexpr ContactModel kContactModels[] = {ContactModel::kGodObject, ContactModel::kGodFinger,
                                           ContactModel::kSoftFinger};
ContactModel nextContactModel(ContactModel model);
// "god_object, god_finger, soft_finger".
std::string contactModelNames();
}  // namespace god_finger
