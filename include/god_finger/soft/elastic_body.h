// A soft body as linear finite elements: linear tetrahedra, isotropic linear elasticity, lumped
// mass, Rayleigh damping, integrated by implicit (backward) Euler with a fixed step.
// Each tetrahedron carries the shear (deviatoric) energy of its constant strain; the volume
// change is averaged over each node's tetrahedra (nodal-averaged dilatation, Bonet and Burton
// 1998): per node n, V_n = sum V_e / 4 and theta_n = sum (V_e / 4) div u_e / V_n, with energy
// kappa V_n theta_n^2 / 2 (kappa = lambda + 2 mu / 3). Constant-strain tetrahedra alone lock as
// nu nears 0.5 (one volume constraint per tetrahedron, about two per degree of freedom): a
// 1,000-node block at nu = 0.45 sank 0.76 of Boussinesq's w0 under a pad, against 0.90 with the
// nodes' average (one constraint per node); bench/REPORT.md section 12. A uniform strain is
// still exact.
// The step: A v' = M v + dt (f - K u), u' = u + dt v', with K the stiffness above and
// A = (1 + dt alpha) M + (dt beta + dt^2) K_A, where K_A takes each tetrahedron's own volume
// change (the locking stiffness, K_A >= K: an average's square is at most the average of the
// squares). K_A couples only nodes that share a tetrahedron, so A's factor keeps the 1-ring's
// fill (K itself couples nodes two edges apart: its factor held 2.5 times the nonzeros and
// stepped 2-3 times slower). This is implicit Euler with stiffness K and the damping
// alpha M + beta K_A + dt (K_A - K), positive semi-definite: unconditionally stable, and its
// rest is K u = f exactly (the modes that lock settle a little slower). A never changes, so it
// is factored once (sparse LDL^T, CHOLMOD's fill-reducing ordering) at construction and each
// step is one K u (applyStiffness: per element, without the matrix) and one pair of triangular
// solves: no iteration.
//
// Units: SI; vectors are 3 per node (node i's x y z at 3i..3i+2), in the body's rest frame.
// A free body (no node or axis fixed: a resting one) takes its elastic forces in its best-fit
// rotation (global corotation, shape matching: R the polar factor of sum m (x - c)(X - C)^T,
// the forces R K (R^T (x - c) + C - X)), so that it can turn as a whole, swinging in a pinch,
// without the growth linear elements give a turned body; the step's matrix stays the rest one.
// A held body's forces stay K u.
// Invariants: fixed nodes (glued to the world) never move: their displacement and velocity stay
// 0 and forces on them are taken by the support. The state (displacement u, velocity v) changes
// only in step() and reset(). Linear elasticity is exact for small strains and rotations; a body
// turned far from rest grows (the known artefact that corotated elements remove).
// A support plane (setSupport: a resting body's floor, issue 28's pinch_soft): no node over its
// extent passes below it. The nodes that can touch it (its surface nodes, kSupportResponseBudget) get,
// each step, contact impulses solved with the step (through A^-1 of a unit impulse on each,
// made once in setSupport): a normal one >= 0 that ends the step on or above the plane, never
// pushing out beyond, and a friction one within friction x normal that holds the node still
// (Coulomb), by projected Gauss-Seidel. Taken after the solve but through A, they move the whole
// body as the step would have: at rest the support carries the weight and nothing creeps (a
// velocity projected node by node instead ate the neighbours' elastic response, and a 5 cm block
// sank 1.7 mm into a compressed, still state).
// Sleep: a body whose every node moved slower than kSoftSleepSpeed for kSoftSleepSteps steps in a
// row under the same forces stops (its velocity set to 0) and costs nothing per step until the
// forces it is given change, which wake it on that step. Bodies at rest under a held press, or
// under gravity alone, sleep as rigid ones do.
// Real-time safety: step() allocates nothing after construction; construction and
// staticDisplacement() do (factorisation).
#pragma once

#include "god_finger/soft/soft_material.h"
#include "god_finger/soft/tet_mesh.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cmath>
#include <memory>
#include <vector>

namespace god_finger
{
class SparseFactor;

// A node slower than this (m/s) is at rest; kSoftSleepSteps steps at rest in a row put a body to
// sleep (0.1 s at 1 kHz): 0.01 mm/s, far below what a hand can feel of a 1 mm dimple.
constexpr double kSoftSleepSpeed = 1e-5;
constexpr int kSoftSleepSteps = 100;
// A node within this (m) of its support plane lies on it (it lands there exactly: rounding).
constexpr double kSupportContactGap = 1e-9;
// A node further than this (m) below the plane is beside its extent, not on it (it went past the
// table's edge; held nodes end each step on the plane): it is not lifted back onto the plane
// when it swings back over the extent, which would throw the body up.
constexpr double kSupportEdgeDepth = 1e-3;
// Every surface node can touch the support (a ball rolls over on it) when the responses to their
// impulses (3 columns of free degrees of freedom each, doubles) fit this budget (bytes: 64 MB, a
// 729-node ball takes 20 MB); else only those within kSupportReach of the body's extent along the
// plane's normal from its lowest node (at rest): such a body turned over further sinks through.
// The contact's Gauss-Seidel sweeps at most kSupportIterations.
constexpr double kSupportResponseBudget = 64.0 * 1024 * 1024;
constexpr double kSupportReach = 0.25;
constexpr int kSupportIterations = 60;
constexpr double kSupportImpulseTolerance = 1e-12;  // N s

// A rectangle of a support plane (body frame, m): the points whose offsets from `centre` along
// `u` and `v` (unit, along the plane, orthogonal) lie within half_u and half_v (>= 0).
struct SupportRectangle
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();
  Eigen::Vector3d v = Eigen::Vector3d::UnitY();
  double half_u = 0.0;
  double half_v = 0.0;
  bool covers(const Eigen::Vector3d& point) const
  {
    const Eigen::Vector3d from = point - centre;
    return std::abs(from.dot(u)) <= half_u && std::abs(from.dot(v)) <= half_v;
  }
};

// A plane the body's nodes stay on or above: normal . x >= offset (body frame, unit normal, m),
// with Coulomb friction `friction` against sliding on it. `extent`: where the plane is (a table's
// top): a node over none of its rectangles is not held (it falls past the edge); empty: the whole
// plane.
struct SupportPlane
{
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;
  double friction = 0.0;
  std::vector<SupportRectangle> extent;
};

class ElasticBody
{
 public:
  // `mesh` checked (checkedTetMesh), `material` checked (checkSoftMaterial), `time_step` > 0
  // (s), `fixed_nodes` indices into mesh.nodes, `fixed_dofs` single degrees of freedom held as
  // well (3 node + axis: rollers), `gravity` (m/s^2) in the body's frame. Throws InputError when
  // nothing can move (every node fixed) or a fixed node or axis is not the body's.
  ElasticBody(TetMesh mesh, const SoftMaterial& material, const std::vector<int>& fixed_nodes, double time_step,
              const Eigen::Vector3d& gravity, const std::vector<int>& fixed_dofs = {});
  ~ElasticBody();

  const TetMesh& restMesh() const
  {
    return mesh_;
  }
  const std::vector<std::array<int, 3>>& surface() const
  {
    return surface_;
  }
  int nodeCount() const
  {
    return static_cast<int>(mesh_.nodes.size());
  }
  double timeStep() const
  {
    return time_step_;
  }
  double mass() const;    // kg
  double volume() const;  // m^3, at rest
  bool isFixed(int node) const
  {
    return free_index_[3 * node] < 0 && free_index_[3 * node + 1] < 0 && free_index_[3 * node + 2] < 0;
  }

  // One step under `external_forces` (N, 3 per node; gravity is added here). RT-safe.
  void step(const Eigen::VectorXd& external_forces);
  // Holds every free node on or above `plane` from the next step on (see the header). InputError
  // when its normal is not a unit vector, its friction is negative or not finite, or a rectangle
  // of its extent does not lie along it (non-unit or non-orthogonal axes, a negative or
  // non-finite half size).
  void setSupport(const SupportPlane& plane);
  // The support's extent from the next step on (its plane and friction kept: no new responses
  // to compute, so cheap). InputError as setSupport(); a body without a support: InputError.
  void setSupportExtent(const std::vector<SupportRectangle>& extent);
  // The support as set (body frame), or null for a body without one.
  const SupportPlane* support() const
  {
    return has_support_ ? &support_ : nullptr;
  }
  // The force (N, along the plane's normal) the support gave in the last step: the weight of a
  // body at rest on it, 0 when it is lifted off (or has no support).
  double supportForce() const
  {
    return support_force_;
  }
  // Back to rest: u = v = 0, awake.
  void reset();
  // At displacement u, velocity 0, awake, as if its last forces were zero (a body settled under
  // gravity by staticDisplacement, the start a world resets it to). `u` has 3 per node; fixed
  // degrees of freedom keep 0. RT-safe (copies).
  void restAt(const Eigen::VectorXd& displacement);
  bool sleeping() const
  {
    return sleeping_;
  }
  // The steps that solved (not slept) since construction.
  long solvedSteps() const
  {
    return solved_steps_;
  }

  // The equilibrium displacement K u = f + gravity's load (factors K on first use; not RT-safe).
  // Throws InputError when the fixed nodes do not hold the body against every rigid motion.
  Eigen::VectorXd staticDisplacement(const Eigen::VectorXd& external_forces);

  const Eigen::VectorXd& displacement() const
  {
    return displacement_;
  }
  const Eigen::VectorXd& velocity() const
  {
    return velocity_;
  }
  Eigen::Vector3d position(int node) const
  {
    return mesh_.nodes[node] + displacement_.segment<3>(3 * node);
  }
  // Every node's current position (for the surface, the markers and the contact).
  void positions(std::vector<Eigen::Vector3d>* out) const;
  // Its deformation (m, 3 per node, rest frame): a free body's displacement in its best-fit
  // rotation about its centre of mass (its rigid motion taken out), a held body's displacement.
  // RT-safe when `out` has 3 per node already.
  void deformation(Eigen::VectorXd* out) const;

  double elasticEnergy() const;  // 1/2 u^T K u (J), u in the best-fit rotation for a free body
  double kineticEnergy() const;  // 1/2 v^T M v (J)
  // The stiffness matrix over every degree of freedom (fixed ones included), for tests.
  const Eigen::SparseMatrix<double>& stiffness() const
  {
    return stiffness_;
  }
  // K u (N, 3 per node) without the matrix: per tetrahedron its deviatoric stress, per node its
  // averaged pressure (equal to stiffness() * u up to rounding; about a tenth of the matrix's
  // memory traffic). RT-safe when `ku` has 3 per node already (else it is resized); its scratch
  // is the body's: not concurrently with step().
  void applyStiffness(const Eigen::VectorXd& u, Eigen::VectorXd* ku);
  // Nonzeros of the step's factor (what a step's solve costs).
  long factorNonZeros() const;

 private:
  // The support's contact impulses on this step's velocities (before they move the nodes).
  void holdOnSupport();
  // Whether candidate `node` lies over the support's extent now.
  bool overSupport(int node) const;
  // InputError unless every rectangle of `plane`'s extent lies along it (setSupport's words).
  static void checkExtent(const SupportPlane& plane);
  // A free body's displacement in its best-fit rotation, and that rotation (body frame).
  Eigen::Matrix3d localDisplacement(Eigen::VectorXd* local) const;

  TetMesh mesh_;
  std::vector<std::array<int, 3>> surface_;
  SoftMaterial material_;
  double time_step_;
  Eigen::Vector3d gravity_;
  std::vector<int> free_index_;                 // per degree of freedom: its index among the free ones, or -1
  std::vector<int> free_dofs_;                  // the free ones' degrees of freedom
  Eigen::SparseMatrix<double> stiffness_;       // K, every degree of freedom
  Eigen::SparseMatrix<double> free_stiffness_;  // K over the free ones
  Eigen::VectorXd lumped_mass_;                 // per degree of freedom (kg)
  Eigen::VectorXd gravity_load_;                // per degree of freedom (N)
  std::unique_ptr<SparseFactor> step_factor_;
  std::unique_ptr<SparseFactor> static_factor_;
  Eigen::VectorXd displacement_;
  Eigen::VectorXd velocity_;
  // K u without the matrix: per tetrahedron its shape functions' gradients (columns) and
  // volume, per node its share of the volume; the moduli.
  std::vector<Eigen::Matrix<double, 3, 4>> tet_gradients_;
  std::vector<double> tet_volumes_;
  Eigen::VectorXd nodal_volume_;
  double shear_modulus_ = 0.0;
  double bulk_modulus_ = 0.0;
  // Step scratch: the nodes' pressure, K u (every degree of freedom), and over the free ones.
  Eigen::VectorXd nodal_pressure_;
  Eigen::VectorXd ku_;
  Eigen::VectorXd free_v_;
  Eigen::VectorXd free_rhs_;
  // The support (has_support_ false: none) and its force in the last step.
  bool corotated_ = false;
  Eigen::Vector3d rest_centre_ = Eigen::Vector3d::Zero();  // m, the nodes' centre of mass at rest
  Eigen::VectorXd local_displacement_;
  bool has_support_ = false;
  SupportPlane support_;
  double support_force_ = 0.0;
  Eigen::Matrix3d support_directions_;  // columns: the normal, two along the plane
  std::vector<int> support_nodes_;      // the nodes that can touch it
  Eigen::MatrixXd support_response_;    // free dofs x 3 per candidate: A^-1 of a unit impulse
  std::vector<int> active_nodes_;       // this step's, into support_nodes_
  Eigen::VectorXd active_velocity_;     // 3 per active node, in support_directions_
  Eigen::VectorXd support_impulse_;     // N s, 3 per active node, in support_directions_
  Eigen::VectorXd support_gap_;         // m, per active node
  Eigen::MatrixXd support_coupling_;    // active rows x active rows
  // Sleep: the forces of the last step, the steps at rest under them in a row.
  Eigen::VectorXd last_forces_;
  int quiet_steps_ = 0;
  bool sleeping_ = false;
  long solved_steps_ = 0;
};
}  // namespace god_finger
