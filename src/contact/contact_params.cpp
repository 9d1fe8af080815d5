#include "god_finger/contact/contact_params.h"

#include "god_finger/support/input_error.h"

#include <cmath>
#include <sstream>

namespace god_finger
{
const char* walkVariantName(WalkVariant variant)
{
  switch (variant)
  {
    case WalkVariant::kProject:
      return "project";
    case WalkVariant::kUnfold:
      return "unfold";
  }
  return "unknown";  // not a variant: validate() refuses it by name
}

bool parseWalkVariant(const std::string& text, WalkVariant* variant)
{
  if (text == "project")
  {
    *variant = WalkVariant::kProject;
    return true;
  }
  if (text == "unfold")
  {
    *variant = WalkVariant::kUnfold;
    return true;
  }
  return false;
}

const ParameterTable<ContactParams>& contactParameterTable()
{
  using P = ContactParams;
  static const ParameterTable<P> table = {
      realRow<P>("r_max", "m", openClosed(0.0, 1e3),
                 "r_max (Eq. 1): radius of the contact area under an infinite force",
                 [](P& p) -> double& { return p.max_radius; }),
      realRow<P>("d0", "m", openClosed(0.0, 1e3),
                 "D0' (Eq. 1): coupling stretch at which the radius reaches 63 % of r_max",
                 [](P& p) -> double& { return p.distance_constant; }),
      realRow<P>("alpha", "dimensionless", closed(1.0, 100.0),
                 "alpha (Eq. 2): how far a tangential force pushes the area backwards; 1 keeps it round",
                 [](P& p) -> double& { return p.alpha; }),
      integerRow<P>("n_sgo", closed(3, P::kMaxSubGodObjects),
                    "n_SGO: sub-god-objects (radial vectors) per contact area",
                    [](P& p) -> int& { return p.sub_god_objects; }),
      realRow<P>("tau_a", "rad", openClosed(0.0, M_PI),
                 "tau_a: largest angle between the contact normal and a face the area spreads onto",
                 [](P& p) -> double& { return p.max_angle; }),
      realRow<P>(
          "friction", "dimensionless", closed(0.0, INFINITY),
          "theta: a walk stops where the face normal leaves the cone atan(theta) about the contact normal; inf: never",
          [](P& p) -> double& { return p.friction; }),
      choiceRow<P>(
          "walk", "project, unfold",
          "how a walk crosses an edge: unfold (the straight geodesic) or project (onto each face, as in the paper)",
          [](const P& p) -> std::string { return walkVariantName(p.walk); },
          [](P* p, const std::string& text) { return parseWalkVariant(text, &p->walk); }),
      integerRow<P>("max_crossings", closed(1, 1000000), "most edges one walk may cross",
                    [](P& p) -> int& { return p.max_crossings; }),
  };
  return table;
}

std::string validate(const ContactParams& params)
{
  return validateRows(contactParameterTable(), params);  // the walk row refuses a value that is no variant
}

void validateOrThrow(const ContactParams& params)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
}
}  // namespace god_finger
