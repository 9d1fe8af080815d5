#include "start_overlaps.h"

#include "near_callback.h"

#include <algorithm>
#include <cstdio>

namespace god_finger::internal
{

std::vector<StartOverlap> startOverlaps(btCollisionWorld* world, const std::vector<SceneBody>& bodies,
                                        const SceneDescription& scene)
{
  std::vector<StartOverlap> overlaps;
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    btVector3 min_i;
    btVector3 max_i;
    bodies[i].rigid->getAabb(min_i, max_i);
    for (std::size_t j = i + 1; j < bodies.size(); ++j)
    {
      if (scene.bodies[i].is_static && scene.bodies[j].is_static)
      {
        continue;  // a fixed scene's own parts may interlock
      }
      const auto joined = [i, j](const JointDescription& joint)
      {
        const int parent = joint.parent;
        const int child = joint.child;
        return (parent == int(i) && child == int(j)) || (parent == int(j) && child == int(i));
      };
      if (std::any_of(scene.joints.begin(), scene.joints.end(), joined))
      {
        continue;  // a drawer in its cabinet: a joint's two bodies do not collide
      }
      btVector3 min_j;
      btVector3 max_j;
      bodies[j].rigid->getAabb(min_j, max_j);
      if (!TestAabbAgainstAabb2(min_i, max_i, min_j, max_j))
      {
        continue;
      }
      const double depth = deepestPenetrationAsCollided(world, bodies[i].rigid.get(), bodies[j].rigid.get());
      if (depth > kStartOverlapDepth)
      {
        overlaps.push_back({static_cast<int>(i), static_cast<int>(j), depth});
      }
    }
  }
  return overlaps;
}

std::string describe(const StartOverlap& overlap, const SceneDescription& scene)
{
  char depth[32];
  std::snprintf(depth, sizeof(depth), "%.1f mm", 1e3 * overlap.depth);
  return "bodies '" + scene.bodies[overlap.body].name + "' and '" + scene.bodies[overlap.other].name + "' start " +
         depth + " inside each other (more than " + std::to_string(int(1e3 * kStartOverlapDepth)) +
         " mm): the first step pushes them apart; move one of them";
}
}  // namespace god_finger::internal
