#include "problems/hammerstein/batched_sse.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "problems/hammerstein/recurrence_coefficients.hpp"

namespace hystbench {
namespace {

// GCC vector extensions rather than Eigen: the block's state must live in
// named registers across the time loop, and a vector wider than the
// hardware's registers runs 2-3x slower, so the width follows the target.
#if defined(__AVX512F__)
constexpr int kLanes = 8;
#elif defined(__AVX__)
constexpr int kLanes = 4;
#else
constexpr int kLanes = 2;
#endif
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
using LaneBits = std::int64_t __attribute__((vector_size(kLanes * sizeof(double))));

constexpr double kInf = std::numeric_limits<double>::infinity();

// |x| by clearing the sign bit, exactly as std::abs does for a double.
inline Lanes abs(Lanes x) {
  return std::bit_cast<Lanes>(std::bit_cast<LaneBits>(x) & std::numeric_limits<std::int64_t>::max());
}

// RecurrenceCoefficients of kLanes candidates, lane l holding candidate l.
struct BlockCoefficients {
  Lanes beta, aL, gamma, d1, d2, k_h0, k_h1, k_h2, k_r1, k_r2, a, b, c, d;

  void set_lane(int l, const RecurrenceCoefficients& q) {
    beta[l] = q.beta, aL[l] = q.aL, gamma[l] = q.gamma, d1[l] = q.d1, d2[l] = q.d2;
    k_h0[l] = q.k_h0, k_h1[l] = q.k_h1, k_h2[l] = q.k_h2, k_r1[l] = q.k_r1, k_r2[l] = q.k_r2;
    a[l] = q.a, b[l] = q.b, c[l] = q.c, d[l] = q.d;
  }
};

// The model's memory for one block; every signal is 0 before k = 0.
struct BlockState {
  Lanes h{}, h1_1{}, h1_2{}, r_1{}, r_2{}, r1_1{}, r1_2{}, sse{};
};

// What every candidate shares at sample k.
struct Sample {
  double drive, abs_drive, u, y;
};

// One time step of one block: run_model() in hammerstein_model.cpp, the
// same operations in the same order, on every lane.
[[gnu::always_inline]] inline void advance(BlockState& s, const BlockCoefficients& q, const Sample& x) {
  const Lanes h = (s.h * (1.0 - q.beta * x.abs_drive) + q.aL * x.drive) - q.gamma * x.drive * abs(s.h);
  const Lanes h1 = q.d1 * x.u + q.d2 * x.u * x.u - h;
  const Lanes r = (q.k_h0 * h1 + q.k_h1 * s.h1_1 + q.k_h2 * s.h1_2 + q.k_r2 * s.r_2) + q.k_r1 * s.r_1;
  const Lanes r1 = (q.a * s.r_1 + q.b * s.r_2 - q.d * s.r1_2) - q.c * s.r1_1;
  const Lanes e = x.y - r1;
  s.sse += e * e;
  s.h = h;
  s.h1_2 = s.h1_1;
  s.h1_1 = h1;
  s.r_2 = s.r_1;
  s.r_1 = r;
  s.r1_2 = s.r1_1;
  s.r1_1 = r1;
}

template <BoucWenForm form>
[[gnu::always_inline]] inline Sample sample(const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                                            Eigen::Index k, double u_prev) {
  const double drive = form == BoucWenForm::Increment ? u[k] - u_prev : u[k];
  return {drive, std::abs(drive), u[k], y[k]};
}

// The states are locals (never stored to memory in the loop) so that they
// stay in registers; the coefficients are read from memory, which costs
// loads but no latency.
template <BoucWenForm form>
Lanes block_sse(const BlockCoefficients& q0, const Eigen::VectorXd& u, const Eigen::VectorXd& y) {
  BlockState s0;
  double u_prev = 0.0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const Sample x = sample<form>(u, y, k, u_prev);
    advance(s0, q0, x);
    u_prev = x.u;
  }
  return s0.sse;
}

template <BoucWenForm form>
void block_pair_sse(const BlockCoefficients& q0, const BlockCoefficients& q1, const Eigen::VectorXd& u,
                    const Eigen::VectorXd& y, Lanes& sse0, Lanes& sse1) {
  BlockState s0, s1;
  double u_prev = 0.0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const Sample x = sample<form>(u, y, k, u_prev);
    advance(s0, q0, x);
    advance(s1, q1, x);
    u_prev = x.u;
  }
  sse0 = s0.sse;
  sse1 = s1.sse;
}

// The candidates that need simulating: unstable linear blocks have fitness
// +inf without a simulation, exactly as in hammerstein_sse().
struct Packing {
  std::vector<Eigen::Index> columns;  // live candidates, in column order
  std::vector<BlockCoefficients> blocks;
};

Packing pack(const Eigen::Ref<const Eigen::MatrixXd>& X, double Ts, Eigen::Ref<Eigen::VectorXd> f) {
  Packing pk;
  std::vector<RecurrenceCoefficients> live;
  for (Eigen::Index i = 0; i < X.cols(); ++i) {
    const HammersteinParams p = HammersteinParams::from_vector(X.col(i));
    if (!linear_blocks_stable(p, Ts)) {
      f[i] = kInf;
      continue;
    }
    pk.columns.push_back(i);
    live.emplace_back(p, Ts);
  }
  const std::size_t n = live.size();
  pk.blocks.resize((n + kLanes - 1) / kLanes);
  // A partial last block is padded with copies of its last candidate: valid
  // numbers (no spurious overflow) whose results are discarded.
  for (std::size_t b = 0; b < pk.blocks.size(); ++b)
    for (int l = 0; l < kLanes; ++l) pk.blocks[b].set_lane(l, live[std::min(b * kLanes + l, n - 1)]);
  return pk;
}

void store(const Packing& pk, std::size_t block, const Lanes& sse, Eigen::Ref<Eigen::VectorXd> f) {
  for (int l = 0; l < kLanes; ++l) {
    const std::size_t j = block * kLanes + l;
    if (j >= pk.columns.size()) return;
    f[pk.columns[j]] = std::isfinite(sse[l]) ? sse[l] : kInf;
  }
}

template <BoucWenForm form>
void simulate_blocks(const Packing& pk, const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                     Eigen::Ref<Eigen::VectorXd> f, int threads) {
  const long blocks = static_cast<long>(pk.blocks.size());
  const long pairs = (blocks + 1) / 2;
  // Each pair of blocks writes its own entries of f, so threads never share
  // a write, and a lane's value does not depend on who computed it.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) if (threads > 1 && pairs > 1)
  for (long g = 0; g < pairs; ++g) {
    const std::size_t b = 2 * g;
    if (b + 1 < pk.blocks.size()) {
      Lanes sse0, sse1;
      block_pair_sse<form>(pk.blocks[b], pk.blocks[b + 1], u, y, sse0, sse1);
      store(pk, b, sse0, f);
      store(pk, b + 1, sse1, f);
    } else {
      store(pk, b, block_sse<form>(pk.blocks[b], u, y), f);
    }
  }
}

}  // namespace

int batched_sse_lanes() { return kLanes; }

void hammerstein_sse_batched(const Eigen::Ref<const Eigen::MatrixXd>& X, const Eigen::VectorXd& u,
                             const Eigen::VectorXd& y, double Ts, BoucWenForm form,
                             Eigen::Ref<Eigen::VectorXd> f, int threads) {
  const Packing pk = pack(X, Ts, f);
  if (pk.columns.empty()) return;
  if (form == BoucWenForm::Increment)
    simulate_blocks<BoucWenForm::Increment>(pk, u, y, f, threads);
  else
    simulate_blocks<BoucWenForm::Paper>(pk, u, y, f, threads);
}

}  // namespace hystbench
