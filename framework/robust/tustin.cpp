#include "framework/robust/tustin.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/robust/slicot_error.hpp"

extern "C" void ab04md_(const char* type, const int* n, const int* m, const int* p, const double* alpha,
                        const double* beta, double* a, const int* lda, double* b, const int* ldb, double* c,
                        const int* ldc, double* d, const int* ldd, int* iwork, double* dwork, const int* ldwork,
                        int* info, std::size_t);

namespace hystbench::robust {
namespace {

StateSpace bilinear(const StateSpace& system, double sample_time, char type) {
  const char* who = type == 'C' ? "tustin" : "inverse_tustin";
  if (!system.consistent()) throw InputError(std::string(who) + ": the system's matrices have inconsistent sizes");
  if (!(sample_time > 0.0)) throw InputError(std::string(who) + ": the sample time must be positive");
  StateSpace s = system;
  const int n = int(s.states()), m = int(s.inputs()), p = int(s.outputs());
  const int ld_n = std::max(1, n), ld_p = std::max(1, p), ldwork = std::max(1, 64 * n);
  const double alpha = 1.0, beta = 2.0 / sample_time;
  std::vector<int> iwork(std::max(1, n));
  std::vector<double> dwork(ldwork);
  int info = 0;
  ab04md_(&type, &n, &m, &p, &alpha, &beta, s.A.data(), &ld_n, s.B.data(), &ld_n, s.C.data(), &ld_p, s.D.data(),
          &ld_p, iwork.data(), dwork.data(), &ldwork, &info, 1);
  if (info < 0) throw InputError(std::string(who) + ": " + take_argument_error("AB04MD", info));
  if (info > 0)
    throw InputError(std::string(who) + ": A has an eigenvalue at " + (type == 'C' ? "2/Ts" : "-1") +
                     ", where the bilinear map is singular");
  return s;
}

}  // namespace

StateSpace tustin(const StateSpace& continuous, double sample_time) { return bilinear(continuous, sample_time, 'C'); }

StateSpace inverse_tustin(const StateSpace& discrete, double sample_time) {
  return bilinear(discrete, sample_time, 'D');
}

}  // namespace hystbench::robust
