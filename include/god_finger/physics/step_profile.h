// What one world step spent, stage by stage (Box2D's b2Profile, MuJoCo's mjTIMER_*), and what its
// solver and sleep counted (WorldCounters). GodFingerWorld::step() runs the stages in this order
// (src/physics/god_finger_world.cpp); each is a piece of its own under src/physics/stages or
// src/physics/sleep:
//   coupling       the virtual couplings' forces on the proxies, the overlap pushes, joint friction
//   wake           sleeping bodies near a proxy or a moving body rejoin the world
//   collide        Bullet's motion prediction, broadphase and narrowphase (and the velocities
//                  recorded before the solve)
//   contact_areas  Algorithm 1 for every (finger, body) contact: the pads and sub-god-objects
//   solve          Bullet's islands, constraint solver and integration
//   record         the solver's impulses kept for the next warm start, the bodies' net forces
//   soft_bodies    the fingers' loads on the soft bodies, and their step
//   sleep          bodies at rest leave the world
//   escapees       bodies past the world's bounds go back to their start
//   overlap        the push apart of fingers whose areas overlap, for the next step
//
// One step in WorldParams::profile_every is timed (a step's eleven clock reads cost about 0.26 us,
// 5 % of a 4 us step; one in 16 costs 0.4 %); the others cost one branch per stage.
// Units: nanoseconds of the steady clock (std::chrono::steady_clock, the TSC on x86 Linux). Plain
// data; reading and copying it is real-time safe.
#pragma once

#include <array>
#include <cstdint>

namespace god_finger
{
enum class StepStage : int
{
  kCoupling,
  kWake,
  kCollide,
  kContactAreas,
  kSolve,
  kRecord,
  kSoftBodies,
  kSleep,
  kEscapees,
  kOverlap,
};
constexpr int kStepStageCount = 10;

// The stage's name, as /diagnostics and the bench report print it ("contact_areas").
const char* stepStageName(StepStage stage);

struct StepProfile
{
  long step = -1;  // the world's step count after the step timed (GodFingerWorld::steps()); -1: none yet
  std::array<std::int64_t, kStepStageCount> stage_ns{};  // by StepStage
  std::int64_t total_ns = 0;                             // the whole step (the sum of the stages)

  std::int64_t operator[](StepStage stage) const
  {
    return stage_ns[static_cast<int>(stage)];
  }
};

// What the world's last step counted, in one place (before: one getter each).
struct WorldCounters
{
  int awake_bodies = 0;              // dynamic bodies simulated in the step (static ones never count)
  int solver_contact_rows = 0;       // normal, friction and torsional rows, all pairs
  int solver_iterations = 0;         // sequential-impulse iterations run (solver_tolerance may stop early)
  int solver_proxy_points = 0;       // proxy-object contact points the solver received
  double deepest_penetration = 0.0;  // m, >= 0: among all contacts, before the solve
  long rejected_targets = 0;         // non-finite interface targets ignored since the world was made
  // Contacts a finger lost because it touched more than InterfaceState::kMaxContacts bodies at
  // once: in the last step, and since the world was made.
  int dropped_contacts = 0;
  long dropped_contacts_total = 0;
};
}  // namespace god_finger
