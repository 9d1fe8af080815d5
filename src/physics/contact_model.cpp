#include "god_finger/physics/contact_model.h"

#include "contact_response.h"

namespace god_finger
{
using namespace internal;  // the physics' private pieces (src/physics)
namespace
{
// The one list of contact models: name (messages, the cfg's enum, the tools, the device's model
// button, which cycles through them in this order) and response (how its contacts reach the
// solver). A new model: its enum value, its response's file and one row here.
struct ContactModelEntry
{
  ContactModel model;
  const char* name;
  std::unique_ptr<ContactResponse> (*make_response)();
};
const ContactModelEntry kContactModelList[] = {
    {ContactModel::kGodObject, "god_object", &makeGodObjectResponse},
    {ContactModel::kGodFinger, "god_finger", &makeGodFingerResponse},
    {ContactModel::kSoftFinger, "soft_finger", &makeSoftFingerResponse},
};

const ContactModelEntry* entryOf(ContactModel model)
{
  for (const ContactModelEntry& entry : kContactModelList)
  {
    if (entry.model == model)
    {
      return &entry;
    }
  }
  return nullptr;
}
}  // namespace

const std::vector<ContactModel>& contactModels()
{
  static const std::vector<ContactModel> models = []
  {
    std::vector<ContactModel> list;
    for (const ContactModelEntry& entry : kContactModelList)
    {
      list.push_back(entry.model);
    }
    return list;
  }();
  return models;
}

const char* contactModelName(ContactModel model)
{
  const ContactModelEntry* entry = entryOf(model);
  return entry != nullptr ? entry->name : "unknown";
}

bool isContactModel(ContactModel model)
{
  return entryOf(model) != nullptr;
}

std::unique_ptr<ContactResponse> internal::makeContactResponse(ContactModel model)
{
  const ContactModelEntry* entry = entryOf(model);
  return entry != nullptr ? entry->make_response() : nullptr;
}

ContactModel nextContactModel(ContactModel model)
{
  const std::vector<ContactModel>& models = contactModels();
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    if (models[i] == model)
    {
      return models[(i + 1) % models.size()];
    }
  }
  return models.front();
}

std::string contactModelNames()
{
  std::string names;
  for (const ContactModelEntry& entry : kContactModelList)
  {
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  }
  return names;
}

bool parseContactModel(const std::string& text, ContactModel* model)
{
  for (const ContactModelEntry& entry : kContactModelList)
  {
    if (text == entry.name)
    {
      *model = entry.model;
      return true;
    }
  }
  return false;
}
}  // namespace god_finger
