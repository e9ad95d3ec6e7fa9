#pragma once
// The masked sum of squared errors of every candidate of a block, summed
// while each chunk of the block's output is still in registers, and summed
// in exactly the order in which Eigen's sum() reduces the same expression
// over one candidate's output vector. So a lane's value equals
// ModelProblem::sse_of() of that lane's output bit for bit, without first
// copying the lane out (which took about a third of a block's time).
//
// Eigen (3.4, Redux.h, a dynamic vector expression, linear vectorised
// traversal, P = doubles per packet) sums:
//   - the samples below the last multiple of 2P in 2P running sums, sample k
//     in sum k mod 2P;
//   - then the two packets of sums lane by lane, then one more packet of
//     samples if the record holds one, then reduces that packet with its
//     own predux();
//   - then adds the remaining samples one at a time.
// Records shorter than one packet, and builds without vectorisation, are
// summed one sample at a time from the first.
#include "framework/core/eigen.hpp"
#include <array>
#include <span>
#include <utility>

#include "framework/model/effect_lanes.hpp"

namespace hystbench {

class LaneSquaredError {
 public:
  // Σ_k mask_k (y_k − ŷ_k)² over the samples of y; mask_k is 0 or 1.
  LaneSquaredError(const Eigen::VectorXd& y, const Eigen::VectorXd& mask);
  // Adds samples [begin, begin + yhat.size()) of the block's output; chunks
  // come in order.
  void add(Eigen::Index begin, std::span<const LaneVector> yhat);
  // Each lane's sum, once every sample has been added.
  std::array<double, kEffectLanes> sums() const;

 private:
  using Expression = decltype((std::declval<const Eigen::VectorXd&>() - std::declval<const Eigen::VectorXd&>())
                                  .array()
                                  .square() *
                              std::declval<const Eigen::VectorXd&>().array());
  using Traits = Eigen::internal::redux_traits<Eigen::internal::scalar_sum_op<double, double>,
                                               Eigen::internal::redux_evaluator<Expression>>;
  static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4,
                "the order copied here is Eigen 3.4's: check Redux.h before building with another Eigen");
  static constexpr bool kVectorised = int(Traits::Traversal) == int(Eigen::LinearVectorizedTraversal);
  using Packet = typename Traits::PacketType;
  static constexpr int kPacket = kVectorised ? Eigen::internal::unpacket_traits<Packet>::size : 1;

  LaneVector term(Eigen::Index k, LaneVector yhat) const {
    const LaneVector e = y_[k] - yhat;
    return e * e * mask_[k];
  }
  void add_one(Eigen::Index k, LaneVector t);
  double lane_sum(int lane) const;

  const double* y_;
  const double* mask_;
  Eigen::Index size_;
  // Samples below end_of_pairs_ go to the running sums, then up to
  // end_of_packets_ to the last packet, the rest one by one. A sequential
  // sum keeps the whole record in running_[0].
  Eigen::Index end_of_pairs_ = 0, end_of_packets_ = 0;
  bool sequential_;
  // Eigen starts each running sum from its first term, these from +0:
  // the same, as no term is −0 (e·e ≥ +0, the mask 0 or 1).
  std::array<LaneVector, 2 * kPacket> running_{};
  std::array<LaneVector, kPacket> last_packet_{}, rest_{};
};

}  // namespace hystbench
