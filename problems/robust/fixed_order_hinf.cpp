#include "problems/robust/fixed_order_hinf.hpp"

#include <cmath>

#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/io/data_path.hpp"
#include "framework/robust/hinf_norm.hpp"
#include "framework/robust/linear_system.hpp"
#include "framework/tracking/hinf_design.hpp"
#include "framework/tracking/tracking_run.hpp"

namespace hystbench {
namespace {

// (s² + 2ζω s + ω²) or (s + ω) times `poly`, highest power first.
std::vector<double> times_factor(const std::vector<double>& poly, const std::vector<double>& factor) {
  std::vector<double> out(poly.size() + factor.size() - 1, 0.0);
  for (std::size_t i = 0; i < poly.size(); ++i)
    for (std::size_t j = 0; j < factor.size(); ++j) out[i + j] += poly[i] * factor[j];
  return out;
}

// The polynomial of `roots` roots from the variables at x[at..]: pairs first, a last real one.
std::vector<double> polynomial(const Eigen::Ref<const Eigen::VectorXd>& x, int& at, int roots) {
  std::vector<double> p{1.0};
  for (int r = 0; r + 1 < roots; r += 2, at += 2) {
    const double w = std::pow(10.0, x[at]), zeta = x[at + 1];
    p = times_factor(p, {1.0, 2.0 * zeta * w, w * w});
  }
  if (roots % 2 == 1) p = times_factor(p, {1.0, std::pow(10.0, x[at++])});
  return p;
}

void add(Bounds& b, const std::string& name, std::pair<double, double> r) {
  const Eigen::Index n = b.lower.size();
  b.lower.conservativeResize(n + 1);
  b.upper.conservativeResize(n + 1);
  b.lower[n] = r.first, b.upper[n] = r.second;
  b.names.push_back(name);
}

void add_roots(Bounds& b, const std::string& what, int roots, std::pair<double, double> omega,
               std::pair<double, double> zeta) {
  for (int r = 0, pair = 1; r + 1 < roots; r += 2, ++pair) {
    add(b, what + "_pair" + std::to_string(pair) + ".log10_omega", omega);
    add(b, what + "_pair" + std::to_string(pair) + ".zeta", zeta);
  }
  if (roots % 2 == 1) add(b, what + "_real.log10_omega", omega);
}

}  // namespace

ProblemInfo FixedOrderHinfProblem::info() {
  return {"fixed_order_hinf",
          "H-infinity tuning of a fixed-order controller: fitness = closed-loop H-infinity norm (SLICOT AB13DD) of a "
          "tracking design's generalized plant, unstable loops penalised",
          {ParamSpec::integer("order", 3, 1, 12, "order of the controller"),
           ParamSpec::text("experiment", nullptr,
                           "tracking experiment file whose design gives the plant; none = the "
                           "reference design"),
           ParamSpec::range("log10_gain", 0.0, 6.0, "search interval of log10 of the gain"),
           ParamSpec::range("log10_omega", -3.0, 5.0, "search interval of log10 of each pole and zero frequency"),
           ParamSpec::range("zeta", 0.05, 2.0, "search interval of each complex pair's damping")},
          [](const Params& p, const std::filesystem::path& base_dir) {
            return std::unique_ptr<Problem>(new FixedOrderHinfProblem(p, base_dir));
          }};
}

FixedOrderHinfProblem::FixedOrderHinfProblem(const Params& p, const std::filesystem::path& base_dir) {
  order_ = p.integer("order");
  ControllerDesign design;
  DesignOptions options;
  options.reduced_order = order_;
  if (!p.is_auto("experiment")) {
    const auto path = resolve_data_path(p.text("experiment"), base_dir, "problem.experiment");
    TrackingExperiment x = TrackingExperiment::load(path);
    x.design.reduced_order = order_;
    design = design_tracking(x).design;
    source_ = path.filename().string();
  } else {
    design = reference_design(options);
    source_ = "reference";
  }
  plant_ = design.plant;
  reference_norm_ = design.reduced_check.norm;
  reference_method_ = design.reduction;
  const auto omega = p.range("log10_omega"), zeta = p.range("zeta");
  add(bounds_, "log10_gain", p.range("log10_gain"));
  add_roots(bounds_, "pole", order_, omega, zeta);
  add_roots(bounds_, "zero", order_ - 1, omega, zeta);
}

std::string FixedOrderHinfProblem::name() const {
  return "fixed_order_hinf(" + source_ + ", order " + std::to_string(order_) + ")";
}

robust::StateSpace FixedOrderHinfProblem::controller(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  int at = 1;
  const std::vector<double> poles = polynomial(x, at, order_);
  std::vector<double> zeros = polynomial(x, at, order_ - 1);
  for (double& c : zeros) c *= std::pow(10.0, x[0]);
  return robust::transfer_function(zeros, poles);
}

double FixedOrderHinfProblem::fitness(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const robust::StateSpace closed = robust::lower_lft(plant_, controller(x), 1, 1);
  const double margin = robust::stability_margin(closed, robust::TimeDomain::Continuous);
  // Far above the norms of the stable loops the search meets (|Wp(0)| = 1/A = 1e4
  // for a loop that does nothing), so that stabilising comes first.
  if (!(margin < 0.0)) return 1e6 + (std::isfinite(margin) ? margin : 1e9);
  const double norm = robust::hinf_norm(closed, robust::TimeDomain::Continuous).norm;
  return std::isfinite(norm) ? norm : 1e9;
}

void link_fixed_order_hinf() {}

void FixedOrderHinfProblem::evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                                     Eigen::Ref<Eigen::VectorXd> f) const {
  for (Eigen::Index i = 0; i < X.cols(); ++i) {
    try {
      f[i] = fitness(X.col(i));
    } catch (const InputError&) {
      f[i] = 1e9;  // SLICOT could not compute the norm (a loop at the edge of stability)
    }
  }
}

nlohmann::json FixedOrderHinfProblem::describe() const {
  return {{"name", name()},
          {"order", order_},
          {"plant", source_},
          {"reference_norm", reference_norm_},
          {"reference", "synthesis (SB10AD) then reduction to the same order, " + reference_method_}};
}

}  // namespace hystbench

HYSTBENCH_PROBLEM(hystbench::FixedOrderHinfProblem)
