#include "god_finger/physics/step_profile.h"

namespace god_finger
{
const char* stepStageName(StepStage stage)
{
  switch (stage)
  {
    case StepStage::kCoupling:
      return "coupling";
    case StepStage::kWake:
      return "wake";
    case StepStage::kCollide:
      return "collide";
    case StepStage::kContactAreas:
      return "contact_areas";
    case StepStage::kSolve:
      return "solve";
    case StepStage::kRecord:
      return "record";
    case StepStage::kSoftBodies:
      return "soft_bodies";
    case StepStage::kSleep:
      return "sleep";
    case StepStage::kEscapees:
      return "escapees";
    case StepStage::kOverlap:
      return "overlap";
  }
  return "unknown";
}
}  // namespace god_finger
