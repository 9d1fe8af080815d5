// How Bullet combines the rolling friction of a finger (a proxy) with an object's: the
// finger's own pad decides it, not the object's Coulomb coefficient.
//
// Bullet's rule multiplies one body's rolling friction by the other's Coulomb friction
// (btManifoldResult::calculateCombinedRollingFriction). For a finger pad that is not physics: a
// pad of radius a under a normal force N resists a torque about a tangent (a tilt, or an object
// rolling under it) up to N a while its centre of pressure stays inside the pad, whatever mu
// is. With this rule, a contact of a proxy gets the proxy's rolling friction as its lever (m);
// contacts between objects keep Bullet's rule. Spinning friction keeps Bullet's product, which
// is physics for a pad: (3 pi / 16) mu N a.
//
// The rule is Bullet's process-wide callback: installing it is idempotent and affects every
// world of the process (contacts of objects only see Bullet's own rule). Not real-time safe
// to call concurrently with a step; GodFingerWorld's constructor installs it.
#pragma once

namespace god_finger::internal
{
void useFingerRollingFriction();
}  // namespace god_finger::internal
