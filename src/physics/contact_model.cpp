#include "god_finger/physics/contact_model.h"

namespace god_finger
{
const char* contactModelName(ContactModel model)
{
  switch (model)
  {
    case ContactModel::kGodObject:
      return "god_object";
    case ContactModel::kGodFinger:
      return "god_finger";
    case ContactModel::kSoftFinger:
      return "soft_finger";
  }
  return "unknown";
}

bool parseContactModel(const std::string& text, ContactModel* model)
{
  for (ContactModel candidate : {ContactModel::kGodObject, ContactModel::kGodFinger, ContactModel::kSoftFinger})
  {
    if (text == contactModelName(candidate))
    {
      *model = candidate;
      return true;
    }
  }
  return false;
}
}  // namespace god_finger
