// A sparse symmetric positive definite matrix factored once (CHOLMOD's simplicial LDL^T with its
// fill-reducing ordering) and solved many times into preallocated memory: the soft body's step
// solve. CHOLMOD's simplicial solve measured 1.9x faster than Eigen's SimplicialLDLT on a
// 1,000-node body (370 us against 717 us a solve; /tmp-free numbers: bench/soft_body_bench's).
// Private to the soft library. Not copyable. solve() is RT-safe: cholmod_solve2 reuses the
// workspace the first solve allocated (done in the constructor).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace god_finger
{
class SparseFactor
{
 public:
  // Factors `matrix` (symmetric; only its lower triangle is read). ok() is false when it is not
  // positive definite.
  explicit SparseFactor(const Eigen::SparseMatrix<double>& matrix);
  ~SparseFactor();
  SparseFactor(const SparseFactor&) = delete;
  SparseFactor& operator=(const SparseFactor&) = delete;

  bool ok() const
  {
    return ok_;
  }
  // x = matrix^-1 b; x and b of the matrix's size, distinct. Allocates nothing.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd* x);
  // Nonzeros of the factor L.
  long factorNonZeros() const;
  // CHOLMOD's estimate of the reciprocal condition number (the smallest pivot over the largest):
  // near rounding (below 1e-12) when the matrix is singular in all but rounding, as the stiffness
  // of a body free to turn about its one held node is.
  double reciprocalCondition();

 private:
  struct Cholmod;
  Cholmod* cholmod_;
  bool ok_ = false;
};
}  // namespace god_finger
