// Building and tearing down what a WorldCore's scene compiles to (world_core.h): the bodies'
// shapes and walk meshes, Bullet's world with the bodies, joints and proxies in it, the bounds,
// sleep's and the stages' per-body and per-proxy vectors. Internal to physics.
//
// Not real-time safe (all of it allocates). buildWorld after teardownWorld gives a world that
// steps bit for bit as a new one (a reset); the bodies' shapes are made once (buildBodies) and
// kept across rebuilds.
#pragma once

#include "scene_body.h"

#include "god_finger/physics/world_params.h"

namespace god_finger::internal
{
struct WorldCore;

// The scene's bodies' shapes and walk meshes (the costly part), one per scene body.
void buildBodies(WorldCore* core);
// Bullet's world around core->bodies (shapes made), with every proxy at its `initial` position
// and its per-body state restarted (proxy.h buildProxyBody).
void buildWorld(WorldCore* core);
// Takes everything out of Bullet's world and destroys it (rigid bodies too; shapes stay).
void teardownWorld(WorldCore* core);
// Which bodies core->scene's joints hold (core->jointed; they never sleep).
void markJointed(WorldCore* core);
// `body` (made for `description`, scene index `index`) built at its description's pose: its rigid
// body, its soft volume made and settled. InputError (a soft body its glue does not hold).
void buildBody(const WorldParams& params, const BodyDescription& description, int index, SceneBody* body);
// Body `index` (built, core->jointed marked): its sleep prepared, into Bullet's world (not into
// sleep.awake).
void addBodyToWorld(WorldCore* core, int index);
// Joint `index` of core->scene (its bodies in the world) appended to core->joints and the world.
void addJointToWorld(WorldCore* core, int index);
// Proxy `index` (in core->proxies, `initial` set) into the world.
void addProxyToWorld(WorldCore* core, int index);
// The per-proxy and per-island scratch, sized for the proxies and bodies there are now.
void sizeProxyScratch(WorldCore* core);
// The current model's response (contact_response.h), made once per model.
void chooseResponse(WorldCore* core);
// The walk edge the world's bodies are made with (m): walk_edge_per_max_radius x r_max.
double walkEdge(const WorldCore& core);
}  // namespace god_finger::internal
