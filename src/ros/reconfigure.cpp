#include "god_finger/ros/reconfigure.h"

namespace god_finger
{
god_finger::GodFingerConfig configOf(const WorldParams& params)
{
  god_finger::GodFingerConfig config;
  config.model = contactModelName(params.model);
  config.r_max = params.contact.max_radius;
  config.d0 = params.contact.distance_constant;
  config.alpha = params.contact.alpha;
  config.n_sgo = params.contact.sub_god_objects;
  config.tau_a = params.contact.max_angle;
  config.friction = params.contact.friction;
  config.walk = walkVariantName(params.contact.walk);
  return config;
}

bool contactFromConfig(const god_finger::GodFingerConfig& config, const ContactParams& base, ContactParams* contact,
                       ContactModel* model, std::string* error)
{
  *contact = base;
  contact->max_radius = config.r_max;
  contact->distance_constant = config.d0;
  contact->alpha = config.alpha;
  contact->sub_god_objects = config.n_sgo;
  contact->max_angle = config.tau_a;
  contact->friction = config.friction;
  if (!parseWalkVariant(config.walk, &contact->walk))
  {
    *error = "unknown walk '" + config.walk + "'";
    return false;
  }
  if (!parseContactModel(config.model, model))
  {
    *error = "unknown contact model '" + config.model + "'";
    return false;
  }
  *error = validate(*contact);
  return error->empty();
}
}  // namespace god_finger
