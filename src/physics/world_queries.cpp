#include "world_queries.h"

#include "bullet_helpers.h"
#include "near_callback.h"

#include "god_finger/physics/joint_measure.h"

namespace god_finger::internal
{
BodyState bodyState(const WorldCore& core, int body)
{
  const SceneBody& b = core.bodies.at(body);
  BodyState state;
  const Eigen::Isometry3d com = toEigen(b.rigid->getWorldTransform());
  state.pose = com * b.com_in_link.inverse();
  state.center_of_mass = com.translation();
  state.linear_velocity = toEigen(b.rigid->getLinearVelocity());
  state.angular_velocity = toEigen(b.rigid->getAngularVelocity());
  state.net_force = b.net_force;
  state.asleep = bodyAsleep(core, body);
  state.left_world = b.left_world;
  state.left_world_at = b.left_world_at;
  return state;
}

JointState jointState(const WorldCore& core, int index)
{
  const JointDescription& joint = core.scene.joints.at(index);
  if (joint.parent < 0)
  {
    return measureJoint(joint, nullptr, bodyState(core, joint.child));
  }
  const BodyState parent = bodyState(core, joint.parent);
  return measureJoint(joint, &parent, bodyState(core, joint.child));
}

Eigen::Isometry3d geometryToWorld(const SceneBody& body)
{
  return toEigen(body.rigid->getWorldTransform()) * body.geometry_in_com;
}

std::pair<int, double> deepestOverlap(const WorldCore& core, const Eigen::Vector3d& position)
{
  btSphereShape sphere(static_cast<btScalar>(core.params.coupling.proxy_radius));
  btCollisionObject probe;
  probe.setCollisionShape(&sphere);
  probe.setWorldTransform(btTransform(btQuaternion::getIdentity(), toBullet(position)));
  probe.setUserIndex(kKindProxy);
  std::pair<int, double> deepest(-1, 0.0);
  for (std::size_t i = 0; i < core.bodies.size(); ++i)
  {
    const double depth = deepestPenetrationAsCollided(core.world.get(), &probe, core.bodies[i].rigid.get());
    if (depth > deepest.second)
    {
      deepest = {static_cast<int>(i), depth};
    }
  }
  return deepest;
}
}  // namespace god_finger::internal
