#include "soft_body.h"

#include "bullet_helpers.h"
#include "scene_body.h"

#include "god_finger/scene/deformable_object.h"
#include "god_finger/soft/soft_surface.h"
#include "god_finger/soft/surface_load.h"
#include "god_finger/support/input_error.h"

#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <limits>

namespace god_finger::internal
{
namespace
{
// The Bullet tree's quantisation box reaches this far beyond the surface (m), so a refit after a
// small motion keeps its precision.
constexpr double kTreeBoxReach = 0.005;

// The surface at the volume's nodes now: walk mesh, locator, Bullet's mesh and box.
void moveSurface(btCollisionWorld* world, SceneBody* body)
{
  SoftVolume& volume = *body->soft;
  volume.elastic->positions(&volume.nodes);
  if (volume.resting)
  {
    const Eigen::VectorXd& u = volume.elastic->displacement();
    volume.shift = u.reshaped(3, u.size() / 3).rowwise().mean();
    if (body->rigid)  // none between a reset's teardown and its rebuild (makeSoftVolume places it)
    {
      Eigen::Isometry3d at = volume.rigid_at_rest;
      at.pretranslate(volume.body_in_world.linear() * volume.shift);
      body->rigid->setWorldTransform(toBullet(at));
    }
    volume.elastic->deformation(&volume.deformation);
  }
  volume.previous_vertices = volume.vertices;
  for (std::size_t v = 0; v < volume.vertices.size(); ++v)
  {
    volume.vertices[v] = volume.nodes[volume.node_of_vertex[v]] - volume.shift;
  }
  body->walk->moveVertices(volume.vertices);
  body->locator->refit();
  btScalar* coordinates = body->collision->vertices.data();
  Eigen::Vector3d lower = volume.vertices.front();
  Eigen::Vector3d upper = lower;
  for (std::size_t v = 0; v < volume.vertices.size(); ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      coordinates[3 * v + k] = volume.vertices[v][k];
    }
    lower = lower.cwiseMin(volume.vertices[v]);
    upper = upper.cwiseMax(volume.vertices[v]);
  }
  auto* mesh = static_cast<btBvhTriangleMeshShape*>(body->collision->shape);
  mesh->refitTree(toBullet(lower) - btVector3(kTreeBoxReach, kTreeBoxReach, kTreeBoxReach),
                  toBullet(upper) + btVector3(kTreeBoxReach, kTreeBoxReach, kTreeBoxReach));
  if (body->placed)
  {
    body->placed->updateChildTransform(0, body->placed->getChildTransform(0), true);
  }
  if (world != nullptr && body->rigid)
  {
    world->updateSingleAabb(body->rigid.get());
  }
}
// The surface placed where the volume is, outside a step (made, reset, rebuilt): it has not
// moved, so its previous vertices are its current ones (materialMotion() reads no motion).
void placeSurface(btCollisionWorld* world, SceneBody* body)
{
  moveSurface(world, body);
  body->soft->previous_vertices = body->soft->vertices;
}
// A resting body's Bullet body is kinematic: Bullet takes its velocity from its transform's
// change each step (the volume's mean motion), so the fingers' contacts see the surface move
// with it.
void makeKinematic(btRigidBody* rigid)
{
  rigid->setCollisionFlags(rigid->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  rigid->setActivationState(DISABLE_DEACTIVATION);
}
}  // namespace

std::unique_ptr<TriangleMesh> makeSoftWalkMesh(const BodyDescription& description, std::vector<int>* node_of_vertex)
{
  SoftSurfaceMesh surface = makeSoftSurfaceMesh(description.soft->mesh, description.soft->volume_file);
  *node_of_vertex = std::move(surface.node_of_vertex);
  return std::make_unique<TriangleMesh>(std::move(surface.mesh));
}

void makeSoftVolume(const BodyDescription& description, double time_step, const Eigen::Vector3d& gravity,
                    SceneBody* body)
{
  SoftVolume& volume = *body->soft;
  if (volume.elastic && volume.elastic->timeStep() == time_step)
  {
    // Made already: a reset or a scene change rebuilt its Bullet body at the scene's pose. A
    // resting body's follows the volume again (kinematic, where its mean motion took it).
    if (volume.resting)
    {
      makeKinematic(body->rigid.get());
      placeSurface(nullptr, body);
    }
    return;
  }
  const DeformableDescription& soft = *description.soft;
  volume.body_in_world = description.pose * description.collision_origin;
  const Eigen::Vector3d gravity_in_body = volume.body_in_world.linear().transpose() * gravity;
  volume.resting = soft.resting;
  volume.shift.setZero();
  volume.rigid_at_rest = toEigen(body->rigid->getWorldTransform());
  if (soft.resting)
  {
    makeKinematic(body->rigid.get());
  }
  try
  {
    if (soft.resting)
    {
      volume.elastic =
          std::make_unique<ElasticBody>(soft.mesh, soft.material, std::vector<int>(), time_step, gravity_in_body);
      SupportPlane plane;
      plane.normal = volume.body_in_world.linear().transpose() * Eigen::Vector3d::UnitZ();
      plane.offset = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& node : soft.mesh.nodes)
      {
        plane.offset = std::min(plane.offset, plane.normal.dot(node));
      }
      plane.friction = soft.friction;
      volume.elastic->setSupport(plane);
      const Eigen::VectorXd no_load = Eigen::VectorXd::Zero(3 * volume.elastic->nodeCount());
      for (int k = 0; k * time_step < kSoftSettleTime && !volume.elastic->sleeping(); ++k)
      {
        volume.elastic->step(no_load);
      }
      volume.settled = volume.elastic->displacement();
      volume.elastic->deformation(&volume.settled_deformation);
      volume.deformation = volume.settled_deformation;
    }
    else
    {
      volume.elastic = std::make_unique<ElasticBody>(
          soft.mesh, soft.material, nodesGluedToSupport(soft.mesh, volume.body_in_world), time_step, gravity_in_body);
      volume.settled = volume.elastic->staticDisplacement(Eigen::VectorXd::Zero(3 * volume.elastic->nodeCount()));
    }
  }
  catch (const InputError& error)
  {
    throw InputError("soft body '" + description.name + "': " + error.what());
  }
  volume.elastic->restAt(volume.settled);
  volume.loads = Eigen::VectorXd::Zero(3 * volume.elastic->nodeCount());
  volume.sink = Eigen::VectorXd::Zero(3 * volume.elastic->nodeCount());
  volume.nodes.resize(volume.elastic->nodeCount());
  volume.vertices.resize(volume.node_of_vertex.size());
  auto triangles = std::make_shared<std::vector<Eigen::Vector3i>>(body->walk->triangles());
  volume.triangles = std::move(triangles);
  placeSurface(nullptr, body);
}

void setSoftSupportExtent(const std::vector<Eigen::AlignedBox3d>& static_boxes, SceneBody* body)
{
  SoftVolume& volume = *body->soft;
  if (!volume.resting)
  {
    return;
  }
  // The support plane in the world: z = its height (makeSoftVolume: its normal the world's z in
  // the body's frame, n = R^T z, so a body point x on it, n . x = offset, lies at world height
  // offset + t_z).
  const Eigen::Isometry3d& to_world = volume.body_in_world;
  const Eigen::Isometry3d to_body = to_world.inverse();
  const double height = volume.elastic->support()->offset + to_world.translation().z();
  std::vector<SupportRectangle> extent;
  for (const Eigen::AlignedBox3d& box : static_boxes)
  {
    if (std::abs(box.max().z() - height) > kSupportTopTolerance)
    {
      continue;
    }
    SupportRectangle rectangle;
    const Eigen::Vector3d centre = box.center();
    rectangle.centre = to_body * Eigen::Vector3d(centre.x(), centre.y(), height);
    rectangle.u = to_body.linear() * Eigen::Vector3d::UnitX();
    rectangle.v = to_body.linear() * Eigen::Vector3d::UnitY();
    rectangle.half_u = 0.5 * box.sizes().x();
    rectangle.half_v = 0.5 * box.sizes().y();
    extent.push_back(rectangle);
  }
  volume.elastic->setSupportExtent(extent);
}

void addSoftContactLoad(const WorldContactArea& area, const Eigen::Vector3d& force_on_body, bool as_pad,
                        SoftVolume* volume)
{
  const Eigen::Isometry3d to_body = volume->body_in_world.inverse();
  const Eigen::Vector3d force = to_body.linear() * force_on_body;
  const Eigen::Vector3d point = to_body * area.point;
  if (as_pad && area.radius > 0.0)
  {
    PadDisk pad;
    pad.centre = point;
    pad.normal = to_body.linear() * area.normal;
    pad.radius = area.radius;
    if (addPadPressure(volume->nodes, volume->elastic->surface(), pad, force, &volume->loads) > 0.0)
    {
      return;
    }
  }
  addPointForce(volume->nodes, volume->elastic->surface(), point, force, &volume->loads);
}

double softContactStiffness(const WorldContactArea& area, const Eigen::Vector3d& force_on_body, SoftVolume* volume)
{
  const double pressing = -force_on_body.dot(area.normal);
  if (!(pressing >= kMinStiffnessForce))
  {
    return std::numeric_limits<double>::infinity();
  }
  const Eigen::Isometry3d to_body = volume->body_in_world.inverse();
  if (volume->resting)
  {
    volume->elastic->deformation(&volume->deformation);
    volume->sink = volume->deformation - volume->settled_deformation;
  }
  else
  {
    volume->sink = volume->elastic->displacement() - volume->settled;
  }
  // The rest surface's point under the contact: the dimple is along the normal, so the closest
  // point of the rest surface to the dimpled one is where it was.
  const Eigen::Vector3d moved = surfaceDisplacementAt(volume->elastic->restMesh().nodes, volume->elastic->surface(),
                                                      volume->sink, to_body * area.point);
  const double sink = -moved.dot(to_body.linear() * area.normal);
  return sink >= kMinStiffnessSink ? pressing / sink : std::numeric_limits<double>::infinity();
}

bool stepSoftVolume(btCollisionWorld* world, SceneBody* body)
{
  SoftVolume& volume = *body->soft;
  const long solved = volume.elastic->solvedSteps();
  volume.elastic->step(volume.loads);
  volume.loads.setZero();
  if (volume.elastic->solvedSteps() == solved)
  {
    return false;  // asleep under the same (no) loads: nothing moved
  }
  moveSurface(world, body);
  return true;
}

Eigen::Vector3d materialMotion(const SceneBody& body, const Eigen::Vector3d& point)
{
  const SoftVolume& volume = *body.soft;
  const SurfaceLocation on = body.locator->closest(body.geometry_in_com.inverse() * point);
  Eigen::Vector3d moved = Eigen::Vector3d::Zero();
  if (on.face < 0 || volume.previous_vertices.size() != volume.vertices.size())
  {
    return moved;
  }
  const Eigen::Vector3i& face = body.walk->triangles()[on.face];
  for (int k = 0; k < 3; ++k)
  {
    moved += on.barycentric[k] * (volume.vertices[face[k]] - volume.previous_vertices[face[k]]);
  }
  return body.geometry_in_com.linear() * moved;
}

void resetSoftVolume(btCollisionWorld* world, SceneBody* body)
{
  body->soft->elastic->restAt(body->soft->settled);
  body->soft->loads.setZero();
  placeSurface(world, body);
}

void snapshotSoftSurface(const SceneBody& body, int index, SoftSurfaceState* out)
{
  const SoftVolume& volume = *body.soft;
  out->body = index;
  out->triangles = volume.triangles;
  out->vertices.resize(volume.vertices.size());
  out->sink.resize(volume.vertices.size());
  const Eigen::VectorXd& displacement = volume.elastic->displacement();
  for (std::size_t v = 0; v < volume.vertices.size(); ++v)
  {
    out->vertices[v] = volume.body_in_world * (volume.vertices[v] + volume.shift);
    const int node = volume.node_of_vertex[v];
    out->sink[v] = static_cast<float>(
        volume.resting
            ? (volume.deformation.segment<3>(3 * node) - volume.settled_deformation.segment<3>(3 * node)).norm()
            : (displacement.segment<3>(3 * node) - volume.settled.segment<3>(3 * node)).norm());
  }
}
}  // namespace god_finger::internal
