#include "sparse_factor.h"

#include <cholmod.h>

#include <cstring>

namespace god_finger
{
struct SparseFactor::Cholmod
{
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  cholmod_dense* rhs = nullptr;
  cholmod_dense* solution = nullptr;
  cholmod_dense* work_y = nullptr;
  cholmod_dense* work_e = nullptr;
};

SparseFactor::SparseFactor(const Eigen::SparseMatrix<double>& matrix) : cholmod_(new Cholmod)
{
  cholmod_start(&cholmod_->common);
  cholmod_->common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_->common.final_ll = 0;  // keep LDL^T
  cholmod_->common.print = 0;
  const Eigen::SparseMatrix<double> lower = matrix.triangularView<Eigen::Lower>();
  cholmod_sparse view{};
  view.nrow = static_cast<std::size_t>(lower.rows());
  view.ncol = static_cast<std::size_t>(lower.cols());
  view.nzmax = static_cast<std::size_t>(lower.nonZeros());
  view.p = const_cast<int*>(lower.outerIndexPtr());
  view.i = const_cast<int*>(lower.innerIndexPtr());
  view.x = const_cast<double*>(lower.valuePtr());
  view.stype = -1;  // symmetric, lower triangle stored
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  cholmod_->factor = cholmod_analyze(&view, &cholmod_->common);
  ok_ = cholmod_->factor != nullptr && cholmod_factorize(&view, cholmod_->factor, &cholmod_->common) != 0 &&
        cholmod_->common.status == CHOLMOD_OK;
  if (ok_)
  {
    cholmod_->rhs = cholmod_zeros(view.nrow, 1, CHOLMOD_REAL, &cholmod_->common);
    // One solve allocates the solution and the workspace that every later solve reuses.
    ok_ = cholmod_solve2(CHOLMOD_A, cholmod_->factor, cholmod_->rhs, nullptr, &cholmod_->solution, nullptr,
                         &cholmod_->work_y, &cholmod_->work_e, &cholmod_->common) != 0;
  }
}

SparseFactor::~SparseFactor()
{
  cholmod_free_dense(&cholmod_->rhs, &cholmod_->common);
  cholmod_free_dense(&cholmod_->solution, &cholmod_->common);
  cholmod_free_dense(&cholmod_->work_y, &cholmod_->common);
  cholmod_free_dense(&cholmod_->work_e, &cholmod_->common);
  cholmod_free_factor(&cholmod_->factor, &cholmod_->common);
  cholmod_finish(&cholmod_->common);
  delete cholmod_;
}

void SparseFactor::solve(const Eigen::VectorXd& b, Eigen::VectorXd* x)
{
  std::memcpy(cholmod_->rhs->x, b.data(), sizeof(double) * static_cast<std::size_t>(b.size()));
  cholmod_solve2(CHOLMOD_A, cholmod_->factor, cholmod_->rhs, nullptr, &cholmod_->solution, nullptr, &cholmod_->work_y,
                 &cholmod_->work_e, &cholmod_->common);
  std::memcpy(x->data(), cholmod_->solution->x, sizeof(double) * static_cast<std::size_t>(x->size()));
}

double SparseFactor::reciprocalCondition()
{
  return cholmod_->factor != nullptr ? cholmod_rcond(cholmod_->factor, &cholmod_->common) : 0.0;
}

long SparseFactor::factorNonZeros() const
{
  if (cholmod_->factor == nullptr || cholmod_->factor->nz == nullptr)
  {
    return 0;
  }
  long total = 0;
  const int* counts = static_cast<const int*>(cholmod_->factor->nz);
  for (std::size_t column = 0; column < cholmod_->factor->n; ++column)
  {
    total += counts[column];
  }
  return total;
}
}  // namespace god_finger
