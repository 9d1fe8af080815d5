#include "roll_metrics.h"

#include <algorithm>

namespace god_finger
{
RollMetrics::RollMetrics(int body, double roll_start) : body_(body), roll_start_(roll_start) {}

void RollMetrics::add(double time, const InterfaceState& finger)
{
  // Steps end at multiples of dt: half a microsecond absorbs their rounding.
  const bool rolling = time > roll_start_ + 5e-7;
  const WorldContactArea* area = nullptr;
  for (int c = 0; c < finger.contact_count; ++c)
  {
    area = finger.contacts[c].body == body_ ? &finger.contacts[c] : area;
  }
  if (!rolling)
  {
    have_start_ = area != nullptr;
    start_centre_ = area ? area->point : start_centre_;
    start_orientation_ = finger.proxy_orientation;
  }
  else
  {
    if (have_last_force_)
    {
      max_force_step_ = std::max(max_force_step_, (finger.user_force - last_force_).norm());
    }
    lost_ += area ? 0 : 1;
  }
  if (area)
  {
    last_centre_ = area->point;
  }
  last_force_ = finger.user_force;
  have_last_force_ = true;
  last_orientation_ = finger.proxy_orientation;
}

void RollMetrics::addTo(std::map<std::string, double>* metrics) const
{
  (*metrics)["area_centre_travel_m"] = have_start_ ? (last_centre_ - start_centre_).norm() : NAN;
  (*metrics)["max_force_step_N"] = max_force_step_;
  (*metrics)["rolled_rad"] = Eigen::AngleAxisd(last_orientation_ * start_orientation_.conjugate()).angle();
  (*metrics)["contact_lost_steps"] = static_cast<double>(lost_);
}
}  // namespace god_finger
