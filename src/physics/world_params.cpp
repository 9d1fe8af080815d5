#include "god_finger/physics/world_params.h"

#include "god_finger/support/input_error.h"

#include <sstream>

namespace god_finger
{
const char* padSolverName(PadSolver solver)
{
  return solver == PadSolver::kConstraint ? "constraint" : "points";
}

constexpr PadSolver kPadSolvers[] = {PadSolver::kPoints, PadSolver::kConstraint};

std::string padSolverNames()
{
  std::string names;
  for (const PadSolver solver : kPadSolvers)
  {
    names += (names.empty() ? "" : ", ") + std::string(padSolverName(solver));
  }
  return names;
}

bool parsePadSolver(const std::string& text, PadSolver* solver)
{
  for (const PadSolver candidate : kPadSolvers)
  {
    if (text == padSolverName(candidate))
    {
      *solver = candidate;
      return true;
    }
  }
  return false;
}

const ParameterTable<WorldParams>& worldParameterTable()
{
  using P = WorldParams;
  static const ParameterTable<P> table = []
  {
    ParameterTable<P> rows = {
        choiceRow<P>(
            "model", contactModelNames(), "contact model: how a proxy touches objects",
            [](const P& p) -> std::string { return contactModelName(p.model); },
            [](P* p, const std::string& text) { return parseContactModel(text, &p->model); }),
        choiceRow<P>(
            "pad_solver", padSolverNames(),
            "god_finger: a solver point per sub-god-object (the paper's), or one pad constraint per contact area",
            [](const P& p) -> std::string { return padSolverName(p.pad_solver); },
            [](P* p, const std::string& text) { return parsePadSolver(text, &p->pad_solver); }),
        integerRow<P>("solver_iterations", closed(1, 1000),
                      "sequential-impulse iterations per step (a pinch creeps with too few)",
                      [](P& p) -> int& { return p.solver_iterations; }),
        realRow<P>("solver_tolerance", "m/s", closed(0.0, 1.0),
                   "iterations stop once none corrects a velocity by more than this (0: all iterations)",
                   [](P& p) -> double& { return p.solver_tolerance; }),
        integerRow<P>("support_passes", closed(0, 100),
                      "passes after them that hold a pressed object on its static support (light objects sink without)",
                      [](P& p) -> int& { return p.support_passes; }),
    };
    const ParameterTable<P> contact =
        liftRows<P, ContactParams>(contactParameterTable(), [](P& p) -> ContactParams& { return p.contact; });
    rows.insert(rows.end(), contact.begin(), contact.end());
    const ParameterTable<P> more = {
        realRow<P>("proxy_mass", "kg", openClosed(0.0, 10.0), "mass of each god-object proxy",
                   [](P& p) -> double& { return p.coupling.proxy_mass; }),
        realRow<P>("proxy_radius", "m", openClosed(0.0, 0.1), "radius of each god-object proxy's sphere",
                   [](P& p) -> double& { return p.coupling.proxy_radius; }),
        realRow<P>("spinning_friction", "m", closed(0.0, 1.0), "soft_finger: Bullet's torsional friction at the point",
                   [](P& p) -> double& { return p.soft_finger.spinning_friction; }),
        realRow<P>(
            "rolling_friction", "m", openClosed(0.0, 1.0),
            "soft_finger: the pad's tilt lever, torque about a tangent up to this times N (> 0 for spinning to act)",
            [](P& p) -> double& { return p.soft_finger.rolling_friction; }),
        realRow<P>("pad_stiffness", "N/m", openClosed(0.0, 1e7), "the pad's stiffness at each contact point",
                   [](P& p) -> double& { return p.pad.stiffness; }),
        realRow<P>("pad_damping", "N s/m", closed(0.0, 1e5), "the pad's damping at each contact point",
                   [](P& p) -> double& { return p.pad.damping; }),
        realRow<P>("sleep_time", "s", closed(0.0, 100.0),
                   "a body slower than sleep_speed and sleep_angular_speed this long sleeps (0: never)",
                   [](P& p) -> double& { return p.sleep.time; }),
        realRow<P>("sleep_speed", "m/s", closed(0.0, 1.0), "speed of a body's centre of mass below which it may sleep",
                   [](P& p) -> double& { return p.sleep.speed; }),
        realRow<P>("sleep_angular_speed", "rad/s", closed(0.0, 10.0), "angular speed below which a body may sleep",
                   [](P& p) -> double& { return p.sleep.angular_speed; }),
        realRow<P>("fingertip_radius", "m", openClosed(0.0, 0.05),
                   "oriented finger: the fingertip's radius R_f; rolling by theta moves the contact area by R_f theta",
                   [](P& p) -> double& { return p.finger.fingertip_radius; }),
        realRow<P>("nail_angle", "rad", openClosed(0.0, 3.14159),
                   "oriented finger: tilt of the pulp from the surface at which the area shrinks to a point (the nail)",
                   [](P& p) -> double& { return p.finger.nail_angle; }),
        realRow<P>("orientation_stiffness", "N m/rad", closed(0.0, 100.0),
                   "oriented finger: the rotational spring between the device's orientation and the proxy's",
                   [](P& p) -> double& { return p.finger.orientation_stiffness; }),
        realRow<P>("orientation_damping", "N m s/rad", closed(0.0, 10.0),
                   "oriented finger: the rotational damper between the device's orientation and the proxy's",
                   [](P& p) -> double& { return p.finger.orientation_damping; }),
        realRow<P>("proxy_inertia", "kg m^2", openClosed(0.0, 1.0),
                   "oriented finger: the proxy's rotational inertia under the rotational coupling",
                   [](P& p) -> double& { return p.finger.proxy_inertia; }),
        realRow<P>(
            "overlap_stiffness", "N/m^2", closed(0.0, 1e7),
            "god_finger: push apart two fingers whose areas on one body overlap, per m^2 of overlap (0: no push)",
            [](P& p) -> double& { return p.overlap.stiffness; }),
        realRow<P>("overlap_force_rate", "N/s", openClosed(0.0, 1e5),
                   "god_finger: how fast the overlap push may change (bounds the hand's force step)",
                   [](P& p) -> double& { return p.overlap.force_rate; }),
        realRow<P>("walk_edge_per_max_radius", "dimensionless", openClosed(0.0, 10.0),
                   "largest edge of a sphere's or cylinder's walk mesh, as a fraction of r_max",
                   [](P& p) -> double& { return p.walk_edge_per_max_radius; }),
        realRow<P>("world_margin", "m", openClosed(0.0, 1e6),
                   "a body whose centre of mass leaves the scene's box grown by this is put back at its start",
                   [](P& p) -> double& { return p.world_margin; }),
        realRow<P>("let_go_time", "s", closed(0.0, 10.0),
                   "a finger pressing an object that is deleted lets go over this time (its force ramps to zero)",
                   [](P& p) -> double& { return p.let_go_time; }),
        integerRow<P>("profile_every", closed(0, 1000000),
                      "one step in this many is timed stage by stage (/diagnostics' step profile; 0: none, 1: all)",
                      [](P& p) -> int& { return p.profile_every; }),
    };
    rows.insert(rows.end(), more.begin(), more.end());
    return rows;
  }();
  return table;
}

ParameterRange timeStepRange()
{
  return closed(1e-5, 0.1);
}

std::string validate(const WorldParams& params)
{
  using P = WorldParams;
  static const ParameterTable<P> step = {
      realRow<P>("time_step", "s", timeStepRange(), "the world's fixed step (the servo loop's period, 1 / rate)",
                 [](P& p) -> double& { return p.time_step; }),
  };
  const std::string step_error = validateRows(step, params);
  if (!step_error.empty())
  {
    return step_error;
  }
  if (!params.gravity.allFinite())
  {
    return "parameter 'gravity' must be finite (m/s^2)";
  }
  const std::string contact_error = validate(params.contact);
  if (!contact_error.empty())
  {
    return contact_error;
  }
  const std::string row_error = validateRows(worldParameterTable(), params);
  if (!row_error.empty())
  {
    return row_error;
  }
  const CouplingParams& c = params.coupling;
  const std::string coupling_error = validate(static_cast<const CouplingProfile&>(c));
  if (!coupling_error.empty())
  {
    return coupling_error;
  }
  const std::string stability_error = couplingStabilityError(c, c.proxy_mass, params.time_step);
  if (!stability_error.empty())
  {
    return stability_error;
  }
  return orientationStabilityError(params.finger, params.time_step);
}

void validateOrThrow(const WorldParams& params)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
}

std::string couplingStabilityError(const CouplingProfile& c, double proxy_mass, double time_step)
{
  // The coupling force is explicit (from the proxy's state at the start of the step, then
  // symplectic Euler): in free space it is stable iff k dt^2 / m + 2 c dt / m < 4.
  const double stability = (c.stiffness * time_step + 2.0 * c.damping) * time_step / proxy_mass;
  if (stability < 4.0)
  {
    return "";
  }
  std::ostringstream message;
  message << "coupling unstable at this time step: (coupling_stiffness * dt + 2 coupling_damping) * dt / proxy_mass = "
          << stability << " must be < 4 (stiffness " << c.stiffness << " N/m, damping " << c.damping
          << " N s/m, proxy_mass " << proxy_mass << " kg, dt " << time_step
          << " s): lower the stiffness, damping or time step, or raise proxy_mass";
  return message.str();
}
}  // namespace god_finger
