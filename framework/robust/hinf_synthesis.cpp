#include "framework/robust/hinf_synthesis.hpp"

#include "framework/core/eigen.hpp"
#include <complex>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/robust/slicot_error.hpp"

extern "C" void sb10ad_(const int* job, const int* n, const int* m, const int* np, const int* ncon,
                        const int* nmeas, double* gamma, const double* a, const int* lda, const double* b,
                        const int* ldb, const double* c, const int* ldc, const double* d, const int* ldd,
                        double* ak, const int* ldak, double* bk, const int* ldbk, double* ck, const int* ldck,
                        double* dk, const int* lddk, double* ac, const int* ldac, double* bc, const int* ldbc,
                        double* cc, const int* ldcc, double* dc, const int* lddc, double* rcond,
                        const double* gtol, const double* actol, int* iwork, const int* liwork, double* dwork,
                        const int* ldwork, int* bwork, const int* lbwork, int* info);

namespace hystbench::robust {
namespace {

struct Sizes {
  int n, m, np, ncon, nmeas;
  int m1() const { return m - ncon; }
  int np1() const { return np - nmeas; }
};

// SB10AD's minimum real workspace, as its documentation states it.
int real_workspace(const Sizes& s) {
  const int n = s.n, m = s.m, np = s.np, m2 = s.ncon, np2 = s.nmeas, m1 = s.m1(), np1 = s.np1();
  const int nd1 = np1 - m2, nd2 = m1 - np2;
  const int lw1 = n * m + np * n + np * m + m2 * m2 + np2 * np2;
  const int lw2 = std::max({(n + np1 + 1) * (n + m2) + std::max(3 * (n + m2) + n + np1, 5 * (n + m2)),
                            (n + np2) * (n + m1 + 1) + std::max(3 * (n + np2) + n + m1, 5 * (n + np2)),
                            m2 + np1 * np1 + std::max({np1 * std::max(n, m1), 3 * m2 + np1, 5 * m2}),
                            np2 + m1 * m1 + std::max({std::max(n, np1) * m1, 3 * np2 + m1, 5 * np2})});
  const int lw3 = std::max(nd1 * m1 + std::max(4 * std::min(nd1, m1) + std::max(nd1, m1), 6 * std::min(nd1, m1)),
                           np1 * nd2 + std::max(4 * std::min(np1, nd2) + std::max(np1, nd2), 6 * std::min(np1, nd2)));
  const int lw4 = 2 * m * m + np * np + 2 * m * n + m * np + 2 * n * np;
  const int lw5 = 2 * n * n + m * n + n * np;
  const int lw6 = std::max(m * m + std::max(2 * m1, 3 * n * n + std::max(n * m, 10 * n * n + 12 * n + 5)),
                           np * np + std::max(2 * np1, 3 * n * n + std::max(n * np, 10 * n * n + 12 * n + 5)));
  const int lw7 = m2 * np2 + np2 * np2 + m2 * m2 +
                  std::max({nd1 * nd1 + std::max(2 * nd1, (nd1 + nd2) * np2), nd2 * nd2 + std::max(2 * nd2, nd2 * m2),
                            3 * n,
                            n * (2 * np2 + m2) +
                                std::max(2 * n * m2, m2 * np2 + std::max(m2 * m2 + 3 * m2, np2 * (2 * np2 + m2 + std::max(np2, n))))});
  return lw1 + std::max({1, lw2, lw3, lw4, lw5 + std::max(lw6, lw7)});
}

std::string reason(int info) {
  switch (info) {
    case 1: return "[A - jwI, B2; C1, D12] loses column rank on the imaginary axis (a weight with a pole or zero at s = 0?)";
    case 2: return "[A - jwI, B1; C2, D21] loses row rank on the imaginary axis (a weight with a pole or zero at s = 0?)";
    case 3: return "D12 does not have full column rank: every control input must reach the performance outputs directly (add a small control-effort output)";
    case 4: return "D21 does not have full row rank: every measurement needs a direct disturbance (add small sensor noise)";
    case 5: return "a singular value decomposition did not converge";
    case 6: return "no admissible controller at this gamma (gamma too small)";
    case 7: return "the X Riccati equation could not be solved: is (A, B2) stabilizable?";
    case 8: return "the Y Riccati equation could not be solved: is (C2, A) detectable?";
    case 9: return "det(I + Tu D11 Ty D22) = 0";
    case 10: return "the singular values of the D11 blocks could not be estimated";
    case 11: return "I - D22 DK is singular: the loop is not well posed";
    case 12: return "no stabilizing controller was found";
    default: return "INFO = " + std::to_string(info);
  }
}

// `where`: the γ the call was made at, for the messages that depend on it.
[[noreturn]] void fail(int info, const std::string& where = "") {
  throw InputError("hinf_synthesis: SB10AD: " + reason(info) + where);
}

// The unstable modes (Re λ >= 0) that [A − λI, B] (or [A − λI; C]
// transposed) cannot reach: the PBH test of stabilizability (detectability).
std::string unreachable_mode(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  const Eigen::VectorXcd poles = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  const Eigen::Index n = A.rows();
  for (const std::complex<double>& pole : poles) {
    if (pole.real() < 0.0) continue;
    Eigen::MatrixXcd pbh(n, n + B.cols());
    pbh << A.cast<std::complex<double>>() - pole * Eigen::MatrixXcd::Identity(n, n), B.cast<std::complex<double>>();
    Eigen::JacobiSVD<Eigen::MatrixXcd> svd(pbh);
    svd.setThreshold(1e3 * std::numeric_limits<double>::epsilon());
    if (svd.rank() < n)
      return std::to_string(pole.real()) + (pole.imag() != 0.0 ? " ± " + std::to_string(std::abs(pole.imag())) + "i" : "");
  }
  return "";
}

// Numerical rank at SB10AD's tolerance, sqrt(eps) relative to the largest singular value.
Eigen::Index full_rank(const Eigen::MatrixXd& m) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(m);
  svd.setThreshold(std::sqrt(std::numeric_limits<double>::epsilon()));
  return svd.rank();
}

void check(const StateSpace& p, const Sizes& s) {
  if (!p.consistent()) throw InputError("hinf_synthesis: the plant's matrices have inconsistent sizes");
  if (s.n < 1) throw InputError("hinf_synthesis: the plant has no states");
  if (s.ncon < 1 || s.nmeas < 1 || s.m1() < 1 || s.np1() < 1)
    throw InputError("hinf_synthesis: the plant needs at least one disturbance, control input, performance "
                     "output and measurement (got " + std::to_string(s.m1()) + ", " + std::to_string(s.ncon) +
                     ", " + std::to_string(s.np1()) + ", " + std::to_string(s.nmeas) + ")");
  if (s.ncon > s.np1() || s.nmeas > s.m1())
    throw InputError("hinf_synthesis: SB10AD needs ncon <= performance outputs and nmeas <= disturbances");
  // A zero D12 came back from SB10AD's search as "no stabilizing
  // controller" (INFO 12), not as its rank failure: the ranks are checked
  // first, with its tolerance.
  const Eigen::MatrixXd d12 = p.D.topRightCorner(s.np1(), s.ncon), d21 = p.D.bottomLeftCorner(s.nmeas, s.m1());
  if (full_rank(d12) < s.ncon) fail(3);
  if (full_rank(d21) < s.nmeas) fail(4);
  // SB10AD's Riccati failures end its γ loop as "no stabilizing controller":
  // the assumption (A1) is checked here, so that the message names it.
  const Eigen::MatrixXd B2 = p.B.rightCols(s.ncon), C2 = p.C.bottomRows(s.nmeas);
  if (const std::string mode = unreachable_mode(p.A, B2); !mode.empty())
    throw InputError("hinf_synthesis: (A, B2) is not stabilizable: the control inputs cannot reach the unstable "
                     "mode at " + mode);
  if (const std::string mode = unreachable_mode(p.A.transpose(), C2.transpose()); !mode.empty())
    throw InputError("hinf_synthesis: (C2, A) is not detectable: the measurements do not see the unstable "
                     "mode at " + mode);
}

// One SB10AD call; returns its INFO (argument errors throw).
int run(const StateSpace& p, const Sizes& s, int job, double gamma, const HinfOptions& o, HinfController& r) {
  const int n = s.n, two_n = 2 * n, m1 = s.m1(), np1 = s.np1();
  r.controller = {Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, s.nmeas), Eigen::MatrixXd(s.ncon, n),
                  Eigen::MatrixXd(s.ncon, s.nmeas)};
  r.closed_loop = {Eigen::MatrixXd(two_n, two_n), Eigen::MatrixXd(two_n, m1), Eigen::MatrixXd(np1, two_n),
                   Eigen::MatrixXd(np1, m1)};
  const int liwork = std::max(2 * std::max({n, m1, np1, s.ncon, s.nmeas}), n * n);
  const int ldwork = 2 * real_workspace(s), lbwork = two_n;  // twice the minimum, for speed
  std::vector<int> iwork(liwork), bwork(lbwork);
  std::vector<double> dwork(ldwork);
  const double actol = 0.0;
  int info = 0;
  sb10ad_(&job, &s.n, &s.m, &s.np, &s.ncon, &s.nmeas, &gamma, p.A.data(), &n, p.B.data(), &n, p.C.data(), &s.np,
          p.D.data(), &s.np, r.controller.A.data(), &n, r.controller.B.data(), &n, r.controller.C.data(), &s.ncon,
          r.controller.D.data(), &s.ncon, r.closed_loop.A.data(), &two_n, r.closed_loop.B.data(), &two_n,
          r.closed_loop.C.data(), &np1, r.closed_loop.D.data(), &np1, r.rcond, &o.gamma_tol, &actol, iwork.data(),
          &liwork, dwork.data(), &ldwork, bwork.data(), &lbwork, &info);
  if (info < 0) throw InputError("hinf_synthesis: " + take_argument_error("SB10AD", info));
  r.gamma = r.gamma_min = gamma;
  return info;
}

}  // namespace

HinfController hinf_synthesis(const StateSpace& plant, int nmeas, int ncon, const HinfOptions& o) {
  const Sizes s{int(plant.states()), int(plant.inputs()), int(plant.outputs()), ncon, nmeas};
  check(plant, s);
  HinfController r;
  const auto at = [](double gamma) { return " at gamma = " + number_text(gamma); };
  if (o.fixed_gamma > 0.0) {
    if (const int info = run(plant, s, 4, o.fixed_gamma, o, r)) fail(info, at(o.fixed_gamma));
    return r;
  }
  if (const int info = run(plant, s, 1, o.gamma_max, o, r))
    fail(info, " below gamma_max = " + number_text(o.gamma_max) + " (raise gamma_max, or check the weights)");
  const double gamma_min = r.gamma_min;
  if (const int info = run(plant, s, 4, (1.0 + o.backoff) * gamma_min, o, r))
    fail(info, at((1.0 + o.backoff) * gamma_min) + ", (1 + backoff) times the least gamma found");
  r.gamma_min = gamma_min;
  return r;
}

}  // namespace hystbench::robust
