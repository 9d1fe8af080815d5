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

ContactModel nextContactModel(ContactModel model)
{
  const int count = static_cast<int>(sizeof(kContactModels) / sizeof(kContactModels[0]));
  for (int i = 0; i < count; ++i)
  {
    if (kContactModels[i] == model)
    {
      return kContactModels[(i + 1) % count];
    }
  }
  return kContactModels[0];
}

std::string contactModelNames()
{
  std::string names;
  for (ContactModel model : kContactModels)
  {
    names += (names.empty() ? "" : ", ") + std::string(contactModelName(model));
  }
  return names;
}

bool parseContactModel(const std::string& text, ContactModel* model)
{
  for (ContactModel candidate : kContactModels)
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
