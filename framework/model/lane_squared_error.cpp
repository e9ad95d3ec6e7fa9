#include "framework/model/lane_squared_error.hpp"

namespace hystbench {

LaneSquaredError::LaneSquaredError(const Eigen::VectorXd& y, const Eigen::VectorXd& mask)
    : y_(y.data()), mask_(mask.data()), size_(y.size()), sequential_(!kVectorised || y.size() < kPacket) {
  eigen_assert(mask.size() == y.size());
  if (sequential_) return;
  end_of_pairs_ = y.size() / (2 * kPacket) * (2 * kPacket);
  end_of_packets_ = y.size() / kPacket * kPacket;
}

void LaneSquaredError::add_one(Eigen::Index k, LaneVector t) {
  if (sequential_)
    running_[0] += t;
  else if (k < end_of_pairs_)
    running_[std::size_t(k % (2 * kPacket))] += t;
  else if (k < end_of_packets_)
    last_packet_[std::size_t(k - end_of_pairs_)] = t;
  else
    rest_[std::size_t(k - end_of_packets_)] = t;
}

void LaneSquaredError::add(Eigen::Index begin, std::span<const LaneVector> yhat) {
  const auto n = Eigen::Index(yhat.size());
  eigen_assert(begin >= 0 && begin + n <= size_);
  Eigen::Index i = 0;
  if (!sequential_ && begin % (2 * kPacket) == 0) {
    // Whole rounds of the running sums, kept in registers (chunks start on
    // a round; any other start goes sample by sample below).
    std::array<LaneVector, 2 * kPacket> sums = running_;
    for (; i + 2 * kPacket <= n && begin + i + 2 * kPacket <= end_of_pairs_; i += 2 * kPacket)
      for (int j = 0; j < 2 * kPacket; ++j)
        sums[std::size_t(j)] += term(begin + i + j, yhat[std::size_t(i + j)]);
    running_ = sums;
  }
  for (; i < n; ++i) add_one(begin + i, term(begin + i, yhat[std::size_t(i)]));
}

double LaneSquaredError::lane_sum(int lane) const {
  if (sequential_) return running_[0][lane];
  const auto packet_of = [lane](const LaneVector* sums) {
    std::array<double, kPacket> a;
    for (int j = 0; j < kPacket; ++j) a[std::size_t(j)] = sums[j][lane];
    return Eigen::internal::ploadu<Packet>(a.data());
  };
  Packet packet = packet_of(end_of_pairs_ > 0 ? running_.data() : last_packet_.data());
  if (end_of_pairs_ > 0) {
    packet = Eigen::internal::padd(packet, packet_of(running_.data() + kPacket));
    if (end_of_packets_ > end_of_pairs_) packet = Eigen::internal::padd(packet, packet_of(last_packet_.data()));
  }
  double sum = Eigen::internal::predux(packet);
  for (Eigen::Index k = end_of_packets_; k < size_; ++k) sum += rest_[std::size_t(k - end_of_packets_)][lane];
  return sum;
}

std::array<double, kEffectLanes> LaneSquaredError::sums() const {
  std::array<double, kEffectLanes> out;
  for (int l = 0; l < kEffectLanes; ++l) out[std::size_t(l)] = lane_sum(l);
  return out;
}

}  // namespace hystbench
