#include "core/solve/SparseCholesky.hpp"

#include <Eigen/CholmodSupport>
#include <cmath>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {

namespace {
/// Eigen keeps the CHOLMOD factor protected; the condition estimate needs it.
class SupernodalLLT : public Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
 public:
  double rcond() { return cholmod_rcond(m_cholmodFactor, &cholmod()); }
  long factor_nonzeros() const {
    return m_cholmodFactor ? static_cast<long>(m_cholmodFactor->xsize) : 0;
  }
};
}  // namespace

struct SparseCholesky::Impl {
  SupernodalLLT llt;
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {
  impl_->llt.cholmod().print = 0;  // failures are reported by us, in one line, not on stdout
}
SparseCholesky::~SparseCholesky() = default;

FactorizationReport SparseCholesky::factorize(const Eigen::SparseMatrix<double>& lower,
                                              double min_rcond) {
  FactorizationReport report;
  Stopwatch clock;
  impl_->llt.analyzePattern(lower);
  report.seconds_analyze = clock.seconds();
  clock.restart();
  impl_->llt.factorize(lower);
  report.seconds_factorize = clock.seconds();
  if (impl_->llt.info() != Eigen::Success)
    throw NumericalError(
        "the stiffness matrix is not positive definite: the system is singular or indefinite "
        "(rigid-body motions left free, or a material so close to incompressible that the "
        "volumetric stiffness swamps the rest in double precision)");
  report.rcond = impl_->llt.rcond();
  report.factor_nonzeros = impl_->llt.factor_nonzeros();
  if (!(report.rcond >= min_rcond))
    throw NumericalError("the stiffness matrix is numerically singular (CHOLMOD reciprocal "
                         "condition estimate " + fmt(report.rcond) + ", below " + fmt(min_rcond) + ")");
  return report;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& rhs) const {
  Eigen::VectorXd x = impl_->llt.solve(rhs);
  if (!x.allFinite()) throw NumericalError("the sparse solve produced non-finite values");
  return x;
}

}  // namespace vorodg
