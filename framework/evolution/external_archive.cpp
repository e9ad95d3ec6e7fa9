#include "framework/evolution/external_archive.hpp"

#include <cmath>
#include <utility>

namespace hystbench {

void ExternalArchive::shrink_to(int capacity, Rng& rng) {
  while (size() > capacity) {
    // Members are drawn uniformly, so their order carries no meaning and
    // the deleted slot can be filled by the last member.
    const auto k = rng.integer(0, size() - 1);
    std::swap(members_[k], members_.back());
    members_.pop_back();
  }
}

int archive_capacity(double rate, int np) { return static_cast<int>(std::lround(rate * np)); }

}  // namespace hystbench
