// The state of a GodFingerWorld, declared in one place: what its scene compiled to, Bullet's
// objects, and what each step changes. The world's stages (stages/*.h, sleep/world_sleep.h) are
// functions of it; GodFingerWorld (god_finger_world.cpp) runs them in order. Internal to physics.
//
// Compiled (world_build.h: made when the world is built, and again by a scene edit, never by a
// step): params, scene, bodies' shapes and walk meshes, joints, bounds, the Bullet world.
// Stepped (changed by every step): the proxies, the bodies' Bullet motion and their net forces,
// sleep, the touches and pads of the step, time, profile and counters.
//
// Invariants: bodies, scene.bodies and sleep's per-body vectors have one entry per scene body, by
// scene index (a body's Bullet user index 2); proxies' per-body vectors (proxy.h) too; every
// rigid body is in `world` unless it is dormant (sleep.dormant). Units: SI, world frame.
#pragma once

#include "contact_response.h"
#include "overlap_push.h"
#include "proxy.h"
#include "proxy_touches.h"
#include "scene_body.h"
#include "sleep/hooked_world.h"
#include "sleep/world_sleep.h"
#include "solver/contact_solver.h"
#include "solver/pad_constraints.h"
#include "solver/sub_god_object_injection.h"
#include "stages/soft_coupling.h"
#include "stages/stage_clock.h"

#include "god_finger/contact/contact_area.h"
#include "god_finger/physics/step_profile.h"
#include "god_finger/physics/world_params.h"
#include "god_finger/scene/scene_description.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace god_finger::internal
{
struct WorldCore
{
  WorldCore() = default;
  // Tears Bullet's world down first (world_build.h teardownWorld): its bodies outlive it.
  ~WorldCore();
  WorldCore(const WorldCore&) = delete;
  WorldCore& operator=(const WorldCore&) = delete;

  // --- compiled: the scene and what it was made into ---
  WorldParams params;
  SceneDescription scene;
  std::shared_ptr<const SceneDescription> shared_scene;  // a copy of `scene` for snapshots
  std::vector<SceneBody> bodies;                         // by scene index
  std::vector<int> soft_bodies;                          // the soft ones' scene indices, in order
  Eigen::AlignedBox3d bounds;                            // world_bounds.h
  // The scene's joints' constraints (scene_joints.h), by joint index; jointed[body]: a joint's
  // parent or child, which never sleeps (a sleeping body leaves Bullet's world, its constraint
  // cannot).
  std::vector<std::unique_ptr<btTypedConstraint>> joints;
  std::vector<char> jointed;
  // The world's own fixed body, a joint's parent when it is the world (not Bullet's process-wide
  // btTypedConstraint::getFixedBody(), which every world's constraints would share).
  std::unique_ptr<btRigidBody> world_anchor =
      std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0.0, nullptr, nullptr));

  // --- Bullet's world and the solver's additions ---
  std::unique_ptr<btDefaultCollisionConfiguration> configuration;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<ContactSolver> solver;
  std::unique_ptr<HookedWorld> world;
  std::unique_ptr<SubGodObjectInjector> injector;
  PadConstraints pads;  // this step's pads (pad_solver: constraint); the solver reads them
  // Every model's response, made once; `response` is the current model's (a model change while
  // running allocates nothing).
  std::vector<std::pair<ContactModel, std::unique_ptr<ContactResponse>>> responses;
  const ContactResponse* response = nullptr;

  // --- stepped ---
  std::vector<Proxy> proxies;  // by interface index
  WorldSleep sleep;
  ProxyTouches touches;       // this step's proxy-body touches
  ContactAreaResult scratch;  // Algorithm 1's output, reused
  OverlapPush overlap;        // one push per proxy
  SoftCoupling soft;          // the fingers' loads on the soft bodies
  double time = 0.0;
  long steps = 0;
  StepProfile profile;     // the last step's
  WorldCounters counters;  // the last step's (and the totals it keeps)
  StageClock clock{&profile};
  std::vector<std::string> start_warnings;  // GodFingerWorld::startWarnings()
};
}  // namespace god_finger::internal
