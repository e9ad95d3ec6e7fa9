#include "framework/cluster/run_fingerprint.hpp"

#include "framework/core/eigen.hpp"
#include <string>

namespace hystbench::cluster {
namespace {

// FNV-1a: fixed across machines and compilers, unlike std::hash.
class Fnv1a {
 public:
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash_ = (hash_ ^ p[i]) * 1099511628211ULL;
  }
  void add(const std::string& s) { add(s.data(), s.size()); }
  void add(const Eigen::VectorXd& v) { add(v.data(), sizeof(double) * std::size_t(v.size())); }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ULL;
};

}  // namespace

std::uint64_t run_fingerprint(const Experiment& experiment, const Problem& problem) {
  Fnv1a h;
  h.add(experiment.to_json().dump());
  h.add(problem.name());
  h.add(problem.bounds().lower);
  h.add(problem.bounds().upper);
  Eigen::MatrixXd centre = 0.5 * (problem.bounds().lower + problem.bounds().upper);
  Eigen::VectorXd f(1);
  problem.evaluate(centre, f);
  h.add(f);
  return h.value();
}

}  // namespace hystbench::cluster
