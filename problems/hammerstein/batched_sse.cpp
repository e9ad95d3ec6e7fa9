#include "problems/hammerstein/batched_sse.hpp"

#include <cmath>
#include <algorithm>
#include <span>
#include <limits>
#include <vector>

#include "framework/model/effect_lanes.hpp"
#include "problems/hammerstein/recurrence_coefficients.hpp"
#include "problems/hammerstein/seed_step.hpp"

namespace hystbench {
namespace {

// The discovery models' lane vectors (GCC vector extensions, one register
// of the target): the block's state lives in named registers across the
// time loop, two blocks interleaved hide each other's latency.
constexpr int kLanes = kEffectLanes;
using Lanes = LaneVector;

constexpr double kInf = std::numeric_limits<double>::infinity();

// RecurrenceCoefficients of kLanes candidates, lane l holding candidate l.
struct BlockCoefficients {
  Lanes beta, aL, gamma, d1, d2, k_h0, k_h1, k_h2, k_r1, k_r2, a, b, c, d;

  void set_lane(int l, const RecurrenceCoefficients& q) {
    beta[l] = q.beta, aL[l] = q.aL, gamma[l] = q.gamma, d1[l] = q.d1, d2[l] = q.d2;
    k_h0[l] = q.k_h0, k_h1[l] = q.k_h1, k_h2[l] = q.k_h2, k_r1[l] = q.k_r1, k_r2[l] = q.k_r2;
    a[l] = q.a, b[l] = q.b, c[l] = q.c, d[l] = q.d;
  }
};

// One block's model memory and partial SSE.
struct BlockState {
  SeedState<Lanes> model;
  Lanes sse{};
};

// What every candidate shares at sample k.
struct Sample {
  double drive, abs_drive, u, y;
};

// One time step of one block: the seed model's step on every lane.
[[gnu::always_inline]] inline void advance(BlockState& s, const BlockCoefficients& q, const Sample& x) {
  const Lanes e = x.y - seed_step(s.model, q, x.drive, x.abs_drive, x.u);
  s.sse += e * e;
}

template <BoucWenForm form>
[[gnu::always_inline]] inline Sample sample(const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                                            Eigen::Index k, double u_prev) {
  const double drive = form == BoucWenForm::Increment ? u[k] - u_prev : u[k];
  return {drive, std::abs(drive), u[k], y[k]};
}

// Samples between checks for blocks whose every lane is settled: the check
// costs a compare, the run it may save is the rest of the record.
constexpr Eigen::Index kCheckEvery = 256;

// True when no lane's remaining samples can change what the caller learns:
// its partial SSE already exceeds its abandon_above limit, or is no longer
// finite (so the final value is +inf whatever follows).
inline bool settled(const Lanes& sse, const Lanes& limit) {
  const LaneBits open = (sse <= limit) & (sse < kInf);
  for (int l = 0; l < kLanes; ++l)
    if (open[l]) return false;
  return true;
}

// Advances one block from sample k until the end of the record or until it
// is settled. The state is copied into locals, never stored to memory in
// the loop, so that it stays in registers; the coefficients are read from
// memory, which costs loads but no latency.
template <BoucWenForm form>
void run_block(BlockState& state, const BlockCoefficients& q, const Lanes& limit, const Eigen::VectorXd& u,
               const Eigen::VectorXd& y, Eigen::Index k) {
  BlockState s = state;
  double u_prev = k > 0 ? u[k - 1] : 0.0;
  while (k < u.size() && !settled(s.sse, limit)) {
    for (const Eigen::Index end = std::min(k + kCheckEvery, u.size()); k < end; ++k) {
      const Sample x = sample<form>(u, y, k, u_prev);
      advance(s, q, x);
      u_prev = x.u;
    }
  }
  state = s;
}

// Two blocks together, until one of them is settled; returns the next sample.
template <BoucWenForm form>
Eigen::Index run_pair(BlockState& state0, const BlockCoefficients& q0, const Lanes& limit0, BlockState& state1,
                      const BlockCoefficients& q1, const Lanes& limit1, const Eigen::VectorXd& u,
                      const Eigen::VectorXd& y) {
  BlockState s0 = state0, s1 = state1;
  double u_prev = 0.0;
  Eigen::Index k = 0;
  while (k < u.size() && !settled(s0.sse, limit0) && !settled(s1.sse, limit1)) {
    for (const Eigen::Index end = std::min(k + kCheckEvery, u.size()); k < end; ++k) {
      const Sample x = sample<form>(u, y, k, u_prev);
      advance(s0, q0, x);
      advance(s1, q1, x);
      u_prev = x.u;
    }
  }
  state0 = s0;
  state1 = s1;
  return k;
}

// The candidates that need simulating: unstable linear blocks have fitness
// +inf without a simulation, exactly as in hammerstein_sse().
struct Packing {
  std::vector<Eigen::Index> columns;  // live candidates, in column order
  std::vector<BlockCoefficients> blocks;
  std::vector<Lanes> limits;  // abandon_above of each lane, +inf when not given
};

Packing pack(const Eigen::Ref<const Eigen::MatrixXd>& X, double Ts, std::span<const double> abandon_above,
             Eigen::Ref<Eigen::VectorXd> f) {
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
  pk.limits.resize(pk.blocks.size());
  // A partial last block is padded with copies of its last candidate: valid
  // numbers (no spurious overflow) whose results are discarded.
  for (std::size_t b = 0; b < pk.blocks.size(); ++b)
    for (int l = 0; l < kLanes; ++l) {
      const std::size_t j = std::min(b * kLanes + l, n - 1);
      pk.blocks[b].set_lane(l, live[j]);
      pk.limits[b][l] = abandon_above.empty() ? kInf : abandon_above[pk.columns[j]];
    }
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
    BlockState s0, s1;
    Eigen::Index k = 0;
    const bool paired = b + 1 < pk.blocks.size();
    if (paired) k = run_pair<form>(s0, pk.blocks[b], pk.limits[b], s1, pk.blocks[b + 1], pk.limits[b + 1], u, y);
    // Alone, or the one of the pair still running once the other settled.
    run_block<form>(s0, pk.blocks[b], pk.limits[b], u, y, k);
    store(pk, b, s0.sse, f);
    if (!paired) continue;
    run_block<form>(s1, pk.blocks[b + 1], pk.limits[b + 1], u, y, k);
    store(pk, b + 1, s1.sse, f);
  }
}

}  // namespace

int batched_sse_lanes() { return kLanes; }

void hammerstein_sse_batched(const Eigen::Ref<const Eigen::MatrixXd>& X, const Eigen::VectorXd& u,
                             const Eigen::VectorXd& y, double Ts, BoucWenForm form,
                             Eigen::Ref<Eigen::VectorXd> f, const EvaluationOptions& options) {
  const Packing pk = pack(X, Ts, options.abandon_above, f);
  if (pk.columns.empty()) return;
  if (form == BoucWenForm::Increment)
    simulate_blocks<BoucWenForm::Increment>(pk, u, y, f, options.threads);
  else
    simulate_blocks<BoucWenForm::Paper>(pk, u, y, f, options.threads);
}

}  // namespace hystbench
