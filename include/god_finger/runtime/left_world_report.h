// Bodies that left the world (WorldParams::world_margin: put back at their start, counted in
// BodyState::left_world): one warning per catch naming the body and the session time, and the
// diagnostics value `left_world` that scripts/summarize_session reads. Session time: seconds
// since the first snapshot the report saw (simulated time: the clock). No ROS inside (the nodes
// pass their log call). Not real-time (formats and allocates): the nodes' publishing side, one
// report per world.
#pragma once

#include "god_finger/physics/god_finger_world.h"

#include <functional>
#include <string>
#include <vector>

namespace god_finger
{
class LeftWorldReport
{
 public:
  // `stamp` (s): the snapshot's, as published. Calls `warn` once per new catch since the last
  // call ("body 'ball' left the world at t = 52.013 s: put back at its start (world_margin)").
  void update(const SceneDescription& scene, const WorldSnapshot& snapshot, double stamp,
              const std::function<void(const std::string&)>& warn);
  // "NAME (COUNT) at T s" for each body caught so far, "; " between them, at its last catch;
  // "none" when no body has left.
  std::string diagnosticValue() const;

 private:
  double start_ = -1.0;  // s, the first snapshot's stamp
  std::vector<int> seen_;
  std::vector<double> at_;  // s, session time of each body's last catch
  std::vector<std::string> names_;
};
}  // namespace god_finger
