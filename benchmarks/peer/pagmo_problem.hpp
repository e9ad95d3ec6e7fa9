#pragma once
// pagmo user-defined problems. Included only by the pagmo library's
// translation units (see pagmo_peer.hpp).
#include <memory>
#include <pagmo/types.hpp>
#include <string>
#include <utility>

#include "benchmarks/peer/box_fitness.hpp"

namespace hystbench::peer {

// Our problem as pagmo sees it. pagmo calls fitness() with one candidate at a
// time; batch_fitness() serves the few algorithms that take a batch
// evaluator. The box is shared, not copied: pagmo copies problems freely.
class PagmoProblem {
 public:
  PagmoProblem() = default;  // pagmo requires it
  explicit PagmoProblem(std::shared_ptr<const BoxFitness> box) : box_(std::move(box)) {}

  pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    pagmo::vector_double f(1);
    box_->evaluate(x.data(), 1, f.data());
    return f;
  }
  pagmo::vector_double batch_fitness(const pagmo::vector_double& xs) const {
    pagmo::vector_double f(xs.size() / box_->dimension());
    box_->evaluate(xs.data(), f.size(), f.data());
    return f;
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {box_->lower, box_->upper};
  }
  std::string get_name() const { return "hystbench problem"; }

 private:
  std::shared_ptr<const BoxFitness> box_;
};

// A fitness that costs almost nothing, so that a run's time is pagmo's own.
class SumOfSquares {
 public:
  SumOfSquares() = default;
  explicit SumOfSquares(unsigned dimension) : dimension_(dimension) {}

  pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    double s = 0.0;
    for (double v : x) s += v * v;
    return {s};
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(dimension_, -5.0), pagmo::vector_double(dimension_, 5.0)};
  }

 private:
  unsigned dimension_ = 1;
};

}  // namespace hystbench::peer
