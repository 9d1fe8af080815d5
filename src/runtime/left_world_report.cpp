#include "god_finger/runtime/left_world_report.h"

#include <cstdio>

namespace god_finger
{
void LeftWorldReport::update(const SceneDescription& scene, const WorldSnapshot& snapshot, double stamp,
                             const std::function<void(const std::string&)>& warn)
{
  if (start_ < 0.0)
  {
    start_ = stamp;
  }
  bool same_bodies = seen_.size() == snapshot.bodies.size();  // objects spawned or deleted change them
  for (std::size_t i = 0; same_bodies && i < names_.size() && i < scene.bodies.size(); ++i)
  {
    same_bodies = names_[i] == scene.bodies[i].name;
  }
  if (!same_bodies)
  {
    // A body that stays keeps what was reported of it (its count goes on in the world).
    std::vector<int> seen(snapshot.bodies.size(), 0);
    std::vector<double> at(snapshot.bodies.size(), -1.0);
    std::vector<std::string> names(snapshot.bodies.size());
    for (std::size_t i = 0; i < snapshot.bodies.size() && i < scene.bodies.size(); ++i)
    {
      names[i] = scene.bodies[i].name;
      for (std::size_t old = 0; old < names_.size(); ++old)
      {
        if (names_[old] == names[i])
        {
          seen[i] = seen_[old];
          at[i] = at_[old];
        }
      }
    }
    seen_.swap(seen);
    at_.swap(at);
    names_.swap(names);
  }
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i)
  {
    const int count = snapshot.bodies[i].left_world;
    if (count <= seen_[i])
    {
      seen_[i] = count;  // a body spawned again under a name that had left: nothing new
      continue;
    }
    seen_[i] = count;
    at_[i] = stamp - start_;
    char line[256];
    std::snprintf(line, sizeof(line), "left the world at t = %.3f s: put back at its start (world_margin)", at_[i]);
    warn("body '" + names_[i] + "' " + line);
  }
}

std::string LeftWorldReport::diagnosticValue() const
{
  std::string value;
  for (std::size_t i = 0; i < seen_.size(); ++i)
  {
    if (seen_[i] > 0)
    {
      char entry[64];
      std::snprintf(entry, sizeof(entry), " (%d) at %.3f s", seen_[i], at_[i]);
      value += (value.empty() ? "" : "; ") + names_[i] + entry;
    }
  }
  return value.empty() ? "none" : value;
}
}  // namespace god_finger
