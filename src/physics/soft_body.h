// A soft body in the rigid world (BodyDescription::soft, issue 28): a static Bullet body whose
// triangle mesh is the elastic volume's surface, moved after every elastic step. Internal to
// physics.
//
// Each world step: the fingers' contact forces on it (the reaction of what the solver did to each
// proxy) load its surface: god_finger and soft_finger as a uniform pressure over the pad's disk
// (soft/surface_load.h addPadPressure), god_object as a point force; the volume steps
// (soft/elastic_body.h, implicit Euler at the world's time step, glued by its lowest nodes:
// soft/soft_surface.h); the walk mesh, its locator and the Bullet mesh follow the surface, so the
// next step's proxies collide with and walk on the deformed surface.
//
// A resting body (<support value="resting">) is free: no node is glued; it stands on the plane
// under its lowest point at load (world z up), where a static box of the scene is under it
// (setSoftSupportExtent), with its <friction> (ElasticBody::setSupport), and
// starts settled on it (stepped until it sleeps). Its Bullet body follows the volume's mean
// displacement (`shift`), and the walk and Bullet meshes are its nodes less that shift: so the
// fingers' friction anchors, material points of that body, go where the body goes, and a pinch
// can lift it. A glued body's shift stays 0.
//
// Frames: the body is static, its geometry frame is its link frame at BodyDescription::pose; the
// volume's nodes are in that frame, the walk mesh and the Bullet mesh in that frame moved by
// `shift`. Units SI.
// Invariants: the walk mesh's vertex v is the volume's node node_of_vertex[v], displaced; the
// start (and a reset) is the volume at rest under gravity (staticDisplacement), so a scene
// starts still and its soft bodies sleep until touched. A body asleep moves nothing.
// Real-time safety: makeSoftVolume is not (factorises); the rest allocates nothing.
#pragma once

#include "god_finger/physics/world_state.h"
#include "god_finger/scene/scene_description.h"
#include "god_finger/soft/elastic_body.h"

#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <vector>

class btCollisionObject;
class btCollisionWorld;

namespace god_finger::internal
{
// A finger's load on a soft body moves this fraction of the way from the last step's to what
// the solver measured (the proxy's change of momentum less its applied forces): an
// under-relaxed staggered coupling. The surface moves after the proxy was stopped on it, so a
// load taken whole is answered a step later by a surface that sank under it, the proxy stopped
// again, and so on: on a 6 cm block of nodal-averaged elements the proxy chattered at half the
// step rate (0.1 m/s, 0.1 mm) with the whole load. Half kills that mode (its gain 1/3) and
// leaves a held press's load unchanged (soft_body_world_test).
constexpr double kSoftLoadRelaxation = 0.5;

struct SceneBody;

struct SoftVolume
{
  std::unique_ptr<ElasticBody> elastic;
  std::vector<int> node_of_vertex;                 // by walk-mesh vertex: the volume's node
  Eigen::VectorXd settled;                         // m, 3 per node: at rest under gravity, the start
  Eigen::VectorXd loads;                           // N, 3 per node, body frame: this step's finger loads
  std::vector<Eigen::Vector3d> nodes;              // m, body frame: where the nodes are now
  std::vector<Eigen::Vector3d> vertices;           // m, body frame: the walk mesh's, now
  std::vector<Eigen::Vector3d> previous_vertices;  // m: the walk mesh's before the last step (made, reset: now's)
  Eigen::VectorXd sink;                            // m, 3 per node: scratch, the displacement since settling
  Eigen::Isometry3d body_in_world = Eigen::Isometry3d::Identity();
  // A resting body's mean displacement (m, body frame; 0 for a glued body), and its Bullet
  // body's transform at shift 0.
  bool resting = false;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  // A resting body's deformation (ElasticBody::deformation) at the settled start and now (m, 3
  // per node): what its sink is measured from, its rigid motion taken out.
  Eigen::VectorXd settled_deformation;
  Eigen::VectorXd deformation;
  Eigen::Isometry3d rigid_at_rest = Eigen::Isometry3d::Identity();
  // The surface's triangles in walk-mesh vertices, for observers (WorldSnapshot::soft_surfaces).
  std::shared_ptr<const std::vector<Eigen::Vector3i>> triangles;
};

// The walk mesh of a soft body (its volume's surface at rest, body frame) and the map of its
// vertices to the volume's nodes.
std::unique_ptr<TriangleMesh> makeSoftWalkMesh(const BodyDescription& description, std::vector<int>* node_of_vertex);

// The volume of `body` (made by makeSceneBody from `description`), glued where it rests (or
// resting there), settled under `gravity` (m/s^2, world), stepping at `time_step` (s); its
// surface moved to the settled shape. InputError naming the body when its glued nodes do not
// hold it. A resting body that does not come to rest within kSoftSettleTime keeps where it got.
constexpr double kSoftSettleTime = 5.0;  // s
void makeSoftVolume(const BodyDescription& description, double time_step, const Eigen::Vector3d& gravity,
                    SceneBody* body);

// The extent of a resting body's support (ElasticBody::SupportPlane::extent): the tops of the
// `static_boxes` (world bounding boxes of the scene's static rigid bodies: a table) lying within
// kSupportTopTolerance of its support plane, each the rectangle its box covers. Pushed past their
// edges, its nodes are no longer held and it falls (then the world's bounds catch it). None
// found: the whole plane, as a body resting on something that is not a box of the scene. A glued
// body: nothing.
constexpr double kSupportTopTolerance = 0.005;  // m
void setSoftSupportExtent(const std::vector<Eigen::AlignedBox3d>& static_boxes, SceneBody* body);

// A finger's contact force on the body (N, world) at `area`: spread as a pressure over its pad
// (as_pad), or at its point.
void addSoftContactLoad(const WorldContactArea& area, const Eigen::Vector3d& force_on_body, bool as_pad,
                        SoftVolume* volume);

// One elastic step under the loads added since the last (then cleared); the surface follows
// (walk mesh, locator, Bullet mesh and its box in `world`). Returns whether it moved.
bool stepSoftVolume(btCollisionWorld* world, SceneBody* body);

// The stiffness (N/m) the body shows a finger pressing with `force_on_body` (N, world) at `area`:
// the force's normal part over the surface's sink there since it settled (its displacement
// along -normal; a resting body's deformation since, its rigid motion taken out). Infinity when either is too small to
// measure (under kMinStiffnessForce or kMinStiffnessSink).
constexpr double kMinStiffnessForce = 0.05;  // N
constexpr double kMinStiffnessSink = 1e-5;   // m
double softContactStiffness(const WorldContactArea& area, const Eigen::Vector3d& force_on_body, SoftVolume* volume);

// How far the material point at `point` (m, the body's centre-of-mass frame, on or near its
// surface) moved in the last elastic step, in that frame: the walk mesh's face nearest to it, its
// vertices' motion by the point's barycentric weights (a resting body's rigid motion excluded:
// its frame moves with it). The fingers' friction anchors on a soft body are such points: carried
// with it, they see the surface move under them, as the solver's rows would see a moving body.
Eigen::Vector3d materialMotion(const SceneBody& body, const Eigen::Vector3d& point);

// Back to the settled start, the surface with it.
void resetSoftVolume(btCollisionWorld* world, SceneBody* body);

// The surface now, in world, into `out` (allocates only when out's vectors are smaller).
void snapshotSoftSurface(const SceneBody& body, int index, SoftSurfaceState* out);
}  // namespace god_finger::internal
