#include "god_finger/soft/elastic_body.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"
#include "sparse_factor.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace god_finger
{
namespace
{
// Below this reciprocal condition number the static stiffness is singular but for rounding.
constexpr double kMinStaticCondition = 1e-9;

// One linear tetrahedron's volume (m^3) and its shape functions' gradients g_a (1/m).
double tetGradients(const std::vector<Eigen::Vector3d>& nodes, const std::array<int, 4>& tet,
                    std::array<Eigen::Vector3d, 4>* gradients)
{
  Eigen::Matrix3d edges;
  edges << nodes[tet[1]] - nodes[tet[0]], nodes[tet[2]] - nodes[tet[0]], nodes[tet[3]] - nodes[tet[0]];
  const Eigen::Matrix3d inverse = edges.inverse();
  for (int k = 1; k < 4; ++k)
  {
    (*gradients)[k] = inverse.row(k - 1).transpose();
  }
  (*gradients)[0] = -((*gradients)[1] + (*gradients)[2] + (*gradients)[3]);
  return edges.determinant() / 6.0;
}

void addBlock(int a, int b, const Eigen::Matrix3d& block, std::vector<Eigen::Triplet<double>>* triplets)
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      triplets->emplace_back(3 * a + i, 3 * b + j, block(i, j));
    }
  }
}

// The deviatoric stiffness of one tetrahedron, 3x3 block (a, b):
// V (-2 mu / 3 g_a g_b^T + mu g_b g_a^T + mu (g_a . g_b) I), the energy V mu |dev(eps)|^2
// (lambda's part, the volume change, is the nodes').
void addDeviatoricStiffness(const std::array<int, 4>& tet, const std::array<Eigen::Vector3d, 4>& g, double volume,
                            double mu, std::vector<Eigen::Triplet<double>>* triplets)
{
  for (int a = 0; a < 4; ++a)
  {
    for (int b = 0; b < 4; ++b)
    {
      addBlock(tet[a], tet[b],
               volume * (-2.0 * mu / 3.0 * g[a] * g[b].transpose() + mu * g[b] * g[a].transpose() +
                         mu * g[a].dot(g[b]) * Eigen::Matrix3d::Identity()),
               triplets);
    }
  }
}

// A node's share of the volume change: V_n = sum over its tetrahedra of V_e / 4, and the
// vector s_n that gives V_n times its averaged volumetric strain, s_n . u = sum V_e / 4 div u_e,
// as (node, 3-vector) pairs.
struct NodalDilatation
{
  double volume = 0.0;
  std::vector<std::pair<int, Eigen::Vector3d>> terms;

  void add(int node, const Eigen::Vector3d& term)
  {
    for (auto& [known, sum] : terms)
    {
      if (known == node)
      {
        sum += term;
        return;
      }
    }
    terms.emplace_back(node, term);
  }
};

// The rows and columns of `matrix` that `free_index` keeps (-1: dropped).
Eigen::SparseMatrix<double> freeBlock(const Eigen::SparseMatrix<double>& matrix, const std::vector<int>& free_index,
                                      int free_count)
{
  std::vector<Eigen::Triplet<double>> kept;
  kept.reserve(static_cast<std::size_t>(matrix.nonZeros()));
  for (int column = 0; column < matrix.outerSize(); ++column)
  {
    if (free_index[column] < 0)
    {
      continue;
    }
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, column); it; ++it)
    {
      if (free_index[it.row()] >= 0)
      {
        kept.emplace_back(free_index[it.row()], free_index[column], it.value());
      }
    }
  }
  Eigen::SparseMatrix<double> block(free_count, free_count);
  block.setFromTriplets(kept.begin(), kept.end());
  return block;
}
}  // namespace

ElasticBody::ElasticBody(TetMesh mesh, const SoftMaterial& material, const std::vector<int>& fixed_nodes,
                         double time_step, const Eigen::Vector3d& gravity, const std::vector<int>& fixed_dofs)
    : mesh_(std::move(mesh)), material_(material), time_step_(time_step), gravity_(gravity)
{
  surface_ = surfaceTriangles(mesh_);
  const int dofs = 3 * nodeCount();
  free_index_.assign(static_cast<std::size_t>(dofs), 0);
  for (int node : fixed_nodes)
  {
    if (node < 0 || node >= nodeCount())
    {
      throw InputError("soft body: fixed node " + std::to_string(node) + " is not one of its " +
                       std::to_string(nodeCount()) + " nodes");
    }
    for (int i = 0; i < 3; ++i)
    {
      free_index_[static_cast<std::size_t>(3 * node + i)] = -1;
    }
  }
  for (int dof : fixed_dofs)
  {
    if (dof < 0 || dof >= dofs)
    {
      throw InputError("soft body: fixed degree of freedom " + std::to_string(dof) + " is not one of its " +
                       std::to_string(dofs));
    }
    free_index_[static_cast<std::size_t>(dof)] = -1;
  }
  for (int dof = 0; dof < dofs; ++dof)
  {
    if (free_index_[dof] >= 0)
    {
      free_index_[dof] = static_cast<int>(free_dofs_.size());
      free_dofs_.push_back(dof);
    }
  }
  if (free_dofs_.empty())
  {
    throw InputError("soft body: every node is fixed: nothing can move");
  }

  const double mu = material_.shearModulus();
  const double bulk = material_.lameLambda() + 2.0 * mu / 3.0;  // kappa (Pa)
  std::vector<Eigen::Triplet<double>> triplets;                 // the shear's, then the nodes' volume change
  triplets.reserve(mesh_.tets.size() * 144);
  std::vector<Eigen::Triplet<double>> element_volume;  // the tetrahedra's own volume change
  element_volume.reserve(mesh_.tets.size() * 144);
  lumped_mass_ = Eigen::VectorXd::Zero(dofs);
  std::vector<NodalDilatation> dilatation(mesh_.nodes.size());
  for (const std::array<int, 4>& tet : mesh_.tets)
  {
    std::array<Eigen::Vector3d, 4> gradients;
    const double tet_volume = tetGradients(mesh_.nodes, tet, &gradients);
    addDeviatoricStiffness(tet, gradients, tet_volume, mu, &triplets);
    Eigen::Matrix<double, 3, 4> columns;
    for (int a = 0; a < 4; ++a)
    {
      columns.col(a) = gradients[a];
    }
    tet_gradients_.push_back(columns);
    tet_volumes_.push_back(tet_volume);
    for (int a = 0; a < 4; ++a)
    {
      for (int b = 0; b < 4; ++b)
      {
        addBlock(tet[a], tet[b], bulk * tet_volume * gradients[a] * gradients[b].transpose(), &element_volume);
      }
    }
    for (int node : tet)
    {
      lumped_mass_.segment<3>(3 * node).array() += material_.density * tet_volume / 4.0;
      dilatation[node].volume += tet_volume / 4.0;
      for (int a = 0; a < 4; ++a)
      {
        dilatation[node].add(tet[a], tet_volume / 4.0 * gradients[a]);
      }
    }
  }
  // The step's matrix: the shear and each tetrahedron's own volume change (the 1-ring sparsity).
  element_volume.insert(element_volume.end(), triplets.begin(), triplets.end());
  Eigen::SparseMatrix<double> step_stiffness(dofs, dofs);
  step_stiffness.setFromTriplets(element_volume.begin(), element_volume.end());
  element_volume = {};
  // The volume change's energy, per node: kappa / 2 V_n (s_n . u / V_n)^2.
  for (const NodalDilatation& node : dilatation)
  {
    for (const auto& [a, term_a] : node.terms)
    {
      for (const auto& [b, term_b] : node.terms)
      {
        addBlock(a, b, bulk / node.volume * term_a * term_b.transpose(), &triplets);
      }
    }
  }
  stiffness_.resize(dofs, dofs);
  stiffness_.setFromTriplets(triplets.begin(), triplets.end());
  shear_modulus_ = mu;
  bulk_modulus_ = bulk;
  nodal_volume_.resize(nodeCount());
  for (int node = 0; node < nodeCount(); ++node)
  {
    nodal_volume_(node) = dilatation[node].volume;
  }
  nodal_pressure_ = Eigen::VectorXd::Zero(nodeCount());
  ku_ = Eigen::VectorXd::Zero(dofs);
  gravity_load_.resize(dofs);
  for (int node = 0; node < nodeCount(); ++node)
  {
    gravity_load_.segment<3>(3 * node) = lumped_mass_(3 * node) * gravity_;
  }

  const int free_count = static_cast<int>(free_dofs_.size());
  free_stiffness_ = freeBlock(stiffness_, free_index_, free_count);
  // A = (1 + dt alpha) M + (dt beta + dt^2) K_A over the free degrees of freedom.
  Eigen::SparseMatrix<double> step_matrix = (time_step_ * material_.stiffness_damping + time_step_ * time_step_) *
                                            freeBlock(step_stiffness, free_index_, free_count);
  for (int i = 0; i < free_count; ++i)
  {
    step_matrix.coeffRef(i, i) += (1.0 + time_step_ * material_.mass_damping) * lumped_mass_(free_dofs_[i]);
  }
  step_factor_ = std::make_unique<SparseFactor>(step_matrix);
  if (!step_factor_->ok())
  {
    throw InputError("soft body: its step matrix cannot be factored (a node is not part of any volume?)");
  }
  displacement_ = Eigen::VectorXd::Zero(dofs);
  velocity_ = Eigen::VectorXd::Zero(dofs);
  // A free body (nothing fixed) takes its elastic forces in its best-fit rotation.
  corotated_ = static_cast<int>(free_dofs_.size()) == dofs;
  rest_centre_.setZero();
  for (int node = 0; node < nodeCount(); ++node)
  {
    rest_centre_ += lumped_mass_(3 * node) * mesh_.nodes[node];
  }
  rest_centre_ /= lumped_mass_.sum() / 3.0;
  local_displacement_ = Eigen::VectorXd::Zero(dofs);
  free_v_ = Eigen::VectorXd::Zero(free_count);
  free_rhs_ = Eigen::VectorXd::Zero(free_count);
  last_forces_ = Eigen::VectorXd::Zero(dofs);
}

ElasticBody::~ElasticBody() = default;

double ElasticBody::mass() const
{
  return lumped_mass_.sum() / 3.0;
}

double ElasticBody::volume() const
{
  double total = 0.0;
  for (const std::array<int, 4>& tet : mesh_.tets)
  {
    total += signedTetVolume(mesh_.nodes, tet);
  }
  return total;
}

void ElasticBody::step(const Eigen::VectorXd& external_forces)
{
  const bool same_forces = (external_forces.array() == last_forces_.array()).all();
  if (sleeping_ && same_forces)
  {
    return;
  }
  sleeping_ = false;
  if (!same_forces)
  {
    last_forces_ = external_forces;
    quiet_steps_ = 0;
  }
  ++solved_steps_;
  const int free_count = static_cast<int>(free_dofs_.size());
  if (corotated_)
  {
    const Eigen::Matrix3d rotation = localDisplacement(&local_displacement_);
    applyStiffness(local_displacement_, &ku_);
    for (int node = 0; node < nodeCount(); ++node)
    {
      ku_.segment<3>(3 * node) = rotation * ku_.segment<3>(3 * node).eval();
    }
  }
  else
  {
    applyStiffness(displacement_, &ku_);
  }
  for (int i = 0; i < free_count; ++i)
  {
    const int dof = free_dofs_[i];
    free_rhs_(i) =
        lumped_mass_(dof) * velocity_(dof) + time_step_ * (external_forces(dof) + gravity_load_(dof) - ku_(dof));
  }
  step_factor_->solve(free_rhs_, &free_v_);
  for (int i = 0; i < free_count; ++i)
  {
    velocity_(free_dofs_[i]) = free_v_(i);
  }
  support_force_ = 0.0;
  if (has_support_)
  {
    holdOnSupport();
  }
  for (const int dof : free_dofs_)
  {
    displacement_(dof) += time_step_ * velocity_(dof);
  }
  quiet_steps_ = velocity_.lpNorm<Eigen::Infinity>() < kSoftSleepSpeed ? quiet_steps_ + 1 : 0;
  if (quiet_steps_ >= kSoftSleepSteps)
  {
    sleeping_ = true;
    velocity_.setZero();
  }
}

void ElasticBody::setSupport(const SupportPlane& plane)
{
  if (!(std::abs(plane.normal.norm() - 1.0) < 1e-9) || !std::isfinite(plane.offset) ||
      !(plane.friction >= 0.0 && std::isfinite(plane.friction)))
  {
    throw InputError("soft body: a support plane needs a unit normal, a finite offset and a friction >= 0");
  }
  checkExtent(plane);
  support_ = plane;
  has_support_ = true;
  // The plane's directions: its normal and two along it.
  const Eigen::Vector3d& n = plane.normal;
  const Eigen::Vector3d t1 = n.unitOrthogonal();
  support_directions_ << n, t1, n.cross(t1);
  // The nodes that can touch it: free surface nodes (within a reach of the body's extent along the
  // normal from its lowest node, at rest).
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  for (const Eigen::Vector3d& node : mesh_.nodes)
  {
    lowest = std::min(lowest, n.dot(node));
    highest = std::max(highest, n.dot(node));
  }
  std::vector<char> on_surface(mesh_.nodes.size(), 0);
  for (const std::array<int, 3>& face : surface_)
  {
    for (int node : face)
    {
      on_surface[node] = 1;
    }
  }
  const auto candidates = [&](double reach)
  {
    support_nodes_.clear();
    for (int node = 0; node < nodeCount(); ++node)
    {
      if (on_surface[node] && !isFixed(node) && free_index_[3 * node] >= 0 && free_index_[3 * node + 1] >= 0 &&
          free_index_[3 * node + 2] >= 0 && n.dot(mesh_.nodes[node]) <= lowest + reach * (highest - lowest))
      {
        support_nodes_.push_back(node);
      }
    }
  };
  // Every surface node, so that the body can roll over on it, when their responses fit
  // kSupportResponseBudget; else the lowest ones.
  candidates(1.0);
  const double bytes = 3.0 * static_cast<double>(support_nodes_.size()) * static_cast<double>(free_dofs_.size()) *
                       static_cast<double>(sizeof(double));
  if (bytes > kSupportResponseBudget)
  {
    candidates(kSupportReach);
  }
  // Each candidate row's response: A^-1 of a unit impulse on that node along that direction.
  const int rows = 3 * static_cast<int>(support_nodes_.size());
  const int free_count = static_cast<int>(free_dofs_.size());
  support_response_.resize(free_count, rows);
  Eigen::VectorXd impulse = Eigen::VectorXd::Zero(free_count);
  Eigen::VectorXd response(free_count);
  for (int row = 0; row < rows; ++row)
  {
    const int node = support_nodes_[row / 3];
    for (int k = 0; k < 3; ++k)
    {
      impulse(free_index_[3 * node + k]) = support_directions_(k, row % 3);
    }
    step_factor_->solve(impulse, &response);
    support_response_.col(row) = response;
    for (int k = 0; k < 3; ++k)
    {
      impulse(free_index_[3 * node + k]) = 0.0;
    }
  }
  active_nodes_.reserve(support_nodes_.size());
  active_velocity_.resize(rows);
  support_impulse_.resize(rows);
  support_gap_.resize(support_nodes_.size());
  support_coupling_.resize(rows, rows);
}

void ElasticBody::checkExtent(const SupportPlane& plane)
{
  for (const SupportRectangle& rectangle : plane.extent)
  {
    const auto unit_along = [&](const Eigen::Vector3d& axis)
    { return std::abs(axis.norm() - 1.0) < 1e-9 && std::abs(axis.dot(plane.normal)) < 1e-9; };
    if (!rectangle.centre.allFinite() || !unit_along(rectangle.u) || !unit_along(rectangle.v) ||
        !(std::abs(rectangle.u.dot(rectangle.v)) < 1e-9) ||
        !(rectangle.half_u >= 0.0 && std::isfinite(rectangle.half_u)) ||
        !(rectangle.half_v >= 0.0 && std::isfinite(rectangle.half_v)))
    {
      throw InputError(
          "soft body: a support rectangle needs a finite centre, unit orthogonal axes along the plane and half sizes "
          ">= 0");
    }
  }
}

void ElasticBody::setSupportExtent(const std::vector<SupportRectangle>& extent)
{
  if (!has_support_)
  {
    throw InputError("soft body: an extent for a support it does not have");
  }
  SupportPlane plane = support_;
  plane.extent = extent;
  checkExtent(plane);
  support_.extent = extent;
}

bool ElasticBody::overSupport(int node) const
{
  if (support_.extent.empty())
  {
    return true;
  }
  const Eigen::Vector3d at = position(node);
  for (const SupportRectangle& rectangle : support_.extent)
  {
    if (rectangle.covers(at))
    {
      return true;
    }
  }
  return false;
}

void ElasticBody::holdOnSupport()
{
  // The candidates that touch the plane or would pass it in this step.
  active_nodes_.clear();
  for (std::size_t j = 0; j < support_nodes_.size(); ++j)
  {
    const int node = support_nodes_[j];
    const double gap = support_.normal.dot(position(node)) - support_.offset;
    const double moving = support_.normal.dot(velocity_.segment<3>(3 * node));
    if ((gap <= kSupportContactGap || gap + time_step_ * moving < 0.0) && gap >= -kSupportEdgeDepth &&
        overSupport(node))
    {
      active_nodes_.push_back(static_cast<int>(j));
      support_gap_(active_nodes_.size() - 1) = gap;  // < 0 (rounding, the solver's tolerance): lifted back
    }
  }
  const int count = static_cast<int>(active_nodes_.size());
  if (count == 0)
  {
    return;
  }
  // The active rows' coupling: row (a, d)'s velocity per unit impulse on row (b, e).
  for (int a = 0; a < count; ++a)
  {
    const int node_a = support_nodes_[active_nodes_[a]];
    for (int b = 0; b < count; ++b)
    {
      for (int e = 0; e < 3; ++e)
      {
        const int column = 3 * active_nodes_[b] + e;
        Eigen::Vector3d moved;
        for (int k = 0; k < 3; ++k)
        {
          moved(k) = support_response_(free_index_[3 * node_a + k], column);
        }
        support_coupling_.block<3, 1>(3 * a, 3 * b + e) = support_directions_.transpose() * moved;
      }
    }
    active_velocity_.segment<3>(3 * a) = support_directions_.transpose() * velocity_.segment<3>(3 * node_a);
  }
  // Projected Gauss-Seidel on the impulses: normal ones >= 0 keeping each node on or above the
  // plane at the step's end, friction ones within friction x normal, holding the node still.
  support_impulse_.head(3 * count).setZero();
  for (int iteration = 0; iteration < kSupportIterations; ++iteration)
  {
    double largest_change = 0.0;
    for (int a = 0; a < count; ++a)
    {
      const int row = 3 * a;
      const double wanted = -support_gap_(a) / time_step_;
      const double normal =
          std::max(0.0, support_impulse_(row) + (wanted - active_velocity_(row)) / support_coupling_(row, row));
      Eigen::Vector3d change(normal - support_impulse_(row), 0.0, 0.0);
      active_velocity_.head(3 * count).noalias() += support_coupling_.block(0, row, 3 * count, 1) * change(0);
      support_impulse_(row) = normal;
      Eigen::Vector2d along = support_impulse_.segment<2>(row + 1);
      along(0) -= active_velocity_(row + 1) / support_coupling_(row + 1, row + 1);
      along(1) -= active_velocity_(row + 2) / support_coupling_(row + 2, row + 2);
      const double bound = support_.friction * normal;
      if (along.norm() > bound)
      {
        along *= bound / along.norm();
      }
      change.tail<2>() = along - support_impulse_.segment<2>(row + 1);
      active_velocity_.head(3 * count).noalias() +=
          support_coupling_.block(0, row + 1, 3 * count, 2) * change.tail<2>();
      support_impulse_.segment<2>(row + 1) = along;
      largest_change = std::max(largest_change, change.cwiseAbs().maxCoeff());
    }
    if (largest_change <= kSupportImpulseTolerance)
    {
      break;
    }
  }
  // The impulses on every free degree of freedom.
  for (int a = 0; a < count; ++a)
  {
    for (int e = 0; e < 3; ++e)
    {
      const double impulse = support_impulse_(3 * a + e);
      if (impulse != 0.0)
      {
        free_v_.noalias() += impulse * support_response_.col(3 * active_nodes_[a] + e);
      }
    }
    support_force_ += support_impulse_(3 * a) / time_step_;
  }
  for (int i = 0; i < static_cast<int>(free_dofs_.size()); ++i)
  {
    velocity_(free_dofs_[i]) = free_v_(i);
  }
}

void ElasticBody::reset()
{
  displacement_.setZero();
  velocity_.setZero();
  last_forces_.setZero();
  quiet_steps_ = 0;
  sleeping_ = false;
}

void ElasticBody::restAt(const Eigen::VectorXd& displacement)
{
  reset();
  for (const int dof : free_dofs_)
  {
    displacement_(dof) = displacement(dof);
  }
}

Eigen::VectorXd ElasticBody::staticDisplacement(const Eigen::VectorXd& external_forces)
{
  if (!static_factor_)
  {
    static_factor_ = std::make_unique<SparseFactor>(free_stiffness_);
    // A body held against no or too few of its rigid motions has no equilibrium: its factor's
    // smallest pivot is rounding (1e-15-1e-13 of the largest, measured on PyBullet's ball, torus,
    // bread and banana held by one or two nodes) where a held body's is 1e-3-1e-1 of it.
    const double condition = static_factor_->ok() ? static_factor_->reciprocalCondition() : 0.0;
    if (!(condition >= kMinStaticCondition))
    {
      static_factor_.reset();
      throw InputError("soft body: its fixed nodes do not hold it (it can still turn or slide: reciprocal condition " +
                       roundedNumber(condition) + "); fix at least three nodes not on one line");
    }
  }
  const int free_count = static_cast<int>(free_dofs_.size());
  Eigen::VectorXd load(free_count);
  for (int i = 0; i < free_count; ++i)
  {
    load(i) = external_forces(free_dofs_[i]) + gravity_load_(free_dofs_[i]);
  }
  Eigen::VectorXd free_solution(free_count);
  static_factor_->solve(load, &free_solution);
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(3 * nodeCount());
  for (int i = 0; i < free_count; ++i)
  {
    solution(free_dofs_[i]) = free_solution(i);
  }
  return solution;
}

void ElasticBody::applyStiffness(const Eigen::VectorXd& u, Eigen::VectorXd* ku)
{
  // The nodes' pressure: kappa times each node's averaged volume change.
  nodal_pressure_.setZero();
  for (std::size_t e = 0; e < mesh_.tets.size(); ++e)
  {
    const std::array<int, 4>& tet = mesh_.tets[e];
    double divergence = 0.0;
    for (int a = 0; a < 4; ++a)
    {
      divergence += tet_gradients_[e].col(a).dot(u.segment<3>(3 * tet[a]));
    }
    for (int a = 0; a < 4; ++a)
    {
      nodal_pressure_(tet[a]) += 0.25 * tet_volumes_[e] * divergence;
    }
  }
  nodal_pressure_ = bulk_modulus_ * nodal_pressure_.cwiseQuotient(nodal_volume_);
  // Per tetrahedron: its deviatoric stress and its nodes' mean pressure, on its nodes.
  ku->resize(3 * nodeCount());  // no allocation when presized (as step()'s scratch is)
  ku->setZero();
  for (std::size_t e = 0; e < mesh_.tets.size(); ++e)
  {
    const std::array<int, 4>& tet = mesh_.tets[e];
    const Eigen::Matrix<double, 3, 4>& g = tet_gradients_[e];
    Eigen::Matrix3d displacement_gradient = Eigen::Matrix3d::Zero();
    double pressure = 0.0;
    for (int a = 0; a < 4; ++a)
    {
      displacement_gradient.noalias() += u.segment<3>(3 * tet[a]) * g.col(a).transpose();
      pressure += 0.25 * nodal_pressure_(tet[a]);
    }
    const Eigen::Matrix3d strain = 0.5 * (displacement_gradient + displacement_gradient.transpose());
    Eigen::Matrix3d stress = 2.0 * shear_modulus_ * strain;
    stress.diagonal().array() += pressure - 2.0 * shear_modulus_ * strain.trace() / 3.0;
    for (int a = 0; a < 4; ++a)
    {
      ku->segment<3>(3 * tet[a]).noalias() += tet_volumes_[e] * stress * g.col(a);
    }
  }
}

void ElasticBody::positions(std::vector<Eigen::Vector3d>* out) const
{
  out->resize(mesh_.nodes.size());
  for (int node = 0; node < nodeCount(); ++node)
  {
    (*out)[node] = position(node);
  }
}

void ElasticBody::deformation(Eigen::VectorXd* out) const
{
  if (corotated_)
  {
    localDisplacement(out);
  }
  else
  {
    *out = displacement_;
  }
}

Eigen::Matrix3d ElasticBody::localDisplacement(Eigen::VectorXd* local) const
{
  // The best-fit rotation of the nodes about their centre of mass (shape matching: the polar
  // factor of sum m (x - c)(X - C)^T).
  const double total = lumped_mass_.sum() / 3.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int node = 0; node < nodeCount(); ++node)
  {
    centre += lumped_mass_(3 * node) * position(node);
  }
  centre /= total;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (int node = 0; node < nodeCount(); ++node)
  {
    covariance.noalias() +=
        lumped_mass_(3 * node) * (position(node) - centre) * (mesh_.nodes[node] - rest_centre_).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0.0)
  {
    u.col(2) *= -1.0;
  }
  const Eigen::Matrix3d rotation = u * svd.matrixV().transpose();
  local->resize(3 * nodeCount());
  for (int node = 0; node < nodeCount(); ++node)
  {
    local->segment<3>(3 * node) = rotation.transpose() * (position(node) - centre) + rest_centre_ - mesh_.nodes[node];
  }
  return rotation;
}

double ElasticBody::elasticEnergy() const
{
  if (corotated_)
  {
    Eigen::VectorXd local;
    localDisplacement(&local);
    return 0.5 * local.dot(stiffness_ * local);
  }
  return 0.5 * displacement_.dot(stiffness_ * displacement_);
}

double ElasticBody::kineticEnergy() const
{
  return 0.5 * velocity_.dot(lumped_mass_.cwiseProduct(velocity_));
}

long ElasticBody::factorNonZeros() const
{
  return step_factor_->factorNonZeros();
}
}  // namespace god_finger
