#include "framework/robust/model_reduction.hpp"

#include "framework/core/eigen.hpp"
#include <algorithm>
#include <cstddef>

#include "framework/core/error.hpp"
#include "framework/robust/slicot_error.hpp"

extern "C" {
void ab09ad_(const char* dico, const char* job, const char* equil, const char* ordsel, const int* n, const int* m,
             const int* p, int* nr, double* a, const int* lda, double* b, const int* ldb, double* c, const int* ldc,
             double* hsv, const double* tol, int* iwork, double* dwork, const int* ldwork, int* iwarn, int* info,
             std::size_t, std::size_t, std::size_t, std::size_t);
void ab09hd_(const char* dico, const char* job, const char* equil, const char* ordsel, const int* n, const int* m,
             const int* p, int* nr, const double* alpha, const double* beta, double* a, const int* lda, double* b,
             const int* ldb, double* c, const int* ldc, double* d, const int* ldd, int* ns, double* hsv,
             const double* tol1, const double* tol2, int* iwork, double* dwork, const int* ldwork, int* bwork,
             int* iwarn, int* info, std::size_t, std::size_t, std::size_t, std::size_t);
}

namespace hystbench::robust {
namespace {

std::string bt_reason(int info) {
  switch (info) {
    case 1: return "the reduction of A to real Schur form failed";
    case 2: return "the system is not stable; balanced truncation needs a stable system (use stochastic_truncation)";
    case 3: return "the Hankel singular values could not be computed";
    default: return "INFO = " + std::to_string(info);
  }
}

std::string bst_reason(int info) {
  switch (info) {
    case 1: return "the ordered real Schur form of A could not be computed";
    case 2: case 3: return "the Hamiltonian's Schur form could not be computed or reordered";
    case 4: return "the Hamiltonian has fewer stable eigenvalues than states";
    case 5: return "the Riccati solution is singular";
    case 6: return "beta = 0 needs D of full row rank; give beta > 0 for a strictly proper system";
    case 7: return "the Hankel singular values could not be computed";
    case 8: return "stable and unstable eigenvalues are too close to separate";
    case 9: return "the order asked for is below the number of unstable zeros of the stable part";
    default: return "INFO = " + std::to_string(info);
  }
}

void check(const StateSpace& s, int order, const char* who) {
  if (!s.consistent()) throw InputError(std::string(who) + ": the system's matrices have inconsistent sizes");
  // At order 0 SLICOT returns before computing the Hankel values, so no bound would be known.
  if (order < 1 || order > s.states())
    throw InputError(std::string(who) + ": order " + std::to_string(order) + " is outside 1.." +
                     std::to_string(s.states()));
}

StateSpace leading(const StateSpace& s, int nr) {
  return {s.A.topLeftCorner(nr, nr), s.B.topRows(nr), s.C.leftCols(nr), s.D};
}

}  // namespace

Reduction balanced_truncation(const StateSpace& system, TimeDomain domain, int order) {
  check(system, order, "balanced_truncation");
  StateSpace s = system;
  const int n = int(s.states()), m = int(s.inputs()), p = int(s.outputs());
  const int ld_n = std::max(1, n), ld_p = std::max(1, p);
  int nr = order, iwarn = 0, info = 0;
  std::vector<double> hsv(std::max(1, n));
  const double tol = 0.0;
  std::vector<int> iwork(std::max(1, n));
  const int ldwork = std::max(1, n * (2 * n + std::max({n, m, p}) + 5) + n * (n + 1) / 2);
  std::vector<double> dwork(ldwork);
  const char dico = domain == TimeDomain::Continuous ? 'C' : 'D';
  ab09ad_(&dico, "N", "N", "F", &n, &m, &p, &nr, s.A.data(), &ld_n, s.B.data(), &ld_n, s.C.data(), &ld_p,
          hsv.data(), &tol, iwork.data(), dwork.data(), &ldwork, &iwarn, &info, 1, 1, 1, 1);
  if (info < 0) throw InputError("balanced_truncation: " + take_argument_error("AB09AD", info));
  if (info > 0) throw InputError("balanced_truncation: AB09AD: " + bt_reason(info));
  Reduction r{leading(s, nr), std::vector<double>(hsv.begin(), hsv.begin() + n), 0, 0.0};
  for (int i = nr; i < n; ++i) r.error_bound += 2.0 * r.hankel[i];
  return r;
}

Reduction stochastic_truncation(const StateSpace& system, TimeDomain domain, int order, double beta) {
  check(system, order, "stochastic_truncation");
  if (!(beta >= 0.0)) throw InputError("stochastic_truncation: beta must be 0 or more");
  if (beta == 0.0 && (system.outputs() > system.inputs() || system.D.fullPivLu().rank() < system.outputs()))
    throw InputError("stochastic_truncation: " + bst_reason(6));
  StateSpace s = system;
  const int n = int(s.states()), m = int(s.inputs()), p = int(s.outputs());
  const int ld_n = std::max(1, n), ld_p = std::max(1, p), mb = beta == 0.0 ? m : m + p;
  int nr = order, ns = 0, iwarn = 0, info = 0;
  std::vector<double> hsv(std::max(1, n));
  const double alpha = 0.0, tol1 = 0.0, tol2 = 0.0;
  std::vector<int> iwork(std::max(1, 2 * n)), bwork(std::max(1, 2 * n));
  const int ldwork = 2 * n * n + mb * (n + p) +
                     std::max({2, n * (std::max({n, mb, p}) + 5), 2 * n * p + std::max(p * (mb + 2), 10 * n * (n + 1))});
  std::vector<double> dwork(ldwork);
  const char dico = domain == TimeDomain::Continuous ? 'C' : 'D';
  const double boundary = domain == TimeDomain::Continuous ? alpha : 1.0;  // stability boundary
  ab09hd_(&dico, "B", "S", "F", &n, &m, &p, &nr, &boundary, &beta, s.A.data(), &ld_n, s.B.data(), &ld_n,
          s.C.data(), &ld_p, s.D.data(), &ld_p, &ns, hsv.data(), &tol1, &tol2, iwork.data(), dwork.data(), &ldwork,
          bwork.data(), &iwarn, &info, 1, 1, 1, 1);
  if (info < 0) throw InputError("stochastic_truncation: " + take_argument_error("AB09HD", info));
  if (info > 0) throw InputError("stochastic_truncation: AB09HD: " + bst_reason(info));
  Reduction r{leading(s, nr), std::vector<double>(hsv.begin(), hsv.begin() + ns), n - ns, 0.0};
  double product = 1.0;
  for (int i = nr - r.unstable_kept; i < ns; ++i) product *= (1.0 + r.hankel[i]) / (1.0 - r.hankel[i]);
  r.error_bound = product - 1.0;
  return r;
}

}  // namespace hystbench::robust
