#include "framework/local/nlopt_search.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <limits>

namespace hystbench {
namespace {

struct Objective {
  EvaluationContext& ctx;
  long allowed;
  long used = 0;
};

// NLopt's model-based methods break on infinite values; a huge finite
// value steers them away from a diverging region just as well. The context
// has already recorded the true (+inf) fitness.
constexpr double kFiniteStandIn = 1e300;

double objective(const std::vector<double>& x, std::vector<double>& /*gradient*/, void* data) {
  auto& o = *static_cast<Objective*>(data);
  if (o.used >= o.allowed || o.ctx.stopped()) throw nlopt::forced_stop();
  ++o.used;
  // Some methods step onto the bound with rounding past it.
  const double f = o.ctx.evaluate(
      o.ctx.bounds().clamp(Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(x.size()))));
  return std::min(f, kFiniteStandIn);
}

nlopt::opt make_optimizer(const NloptSearch& s, const Bounds& b, long maxeval) {
  const unsigned n = static_cast<unsigned>(b.dimension());
  nlopt::opt opt(s.algorithm.c_str(), n);
  opt.set_lower_bounds(std::vector<double>(b.lower.begin(), b.lower.end()));
  opt.set_upper_bounds(std::vector<double>(b.upper.begin(), b.upper.end()));
  opt.set_maxeval(static_cast<int>(std::min<long>(maxeval, std::numeric_limits<int>::max())));
  if (s.population > 0) opt.set_population(static_cast<unsigned>(s.population));
  const bool local = s.algorithm.rfind("LN_", 0) == 0;
  if (local) {
    opt.set_xtol_rel(s.xtol_rel);
    opt.set_ftol_rel(s.ftol_rel);
  }
  if (!s.local.empty()) {
    // MLSL otherwise forces its own tight tolerances on the local searches.
    nlopt::opt inner(s.local.c_str(), n);
    inner.set_xtol_rel(s.xtol_rel);
    inner.set_ftol_rel(s.ftol_rel);
    opt.set_local_optimizer(inner);
  }
  return opt;
}

}  // namespace

const std::vector<std::string>& nlopt_local_algorithms() {
  static const std::vector<std::string> names{"LN_BOBYQA", "LN_COBYLA", "LN_NEWUOA_BOUND",
                                              "LN_NELDERMEAD", "LN_SBPLX", "LN_PRAXIS"};
  return names;
}

const std::vector<std::string>& nlopt_box_algorithms() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n{"GN_DIRECT",       "GN_DIRECT_L",       "GN_DIRECT_L_RAND",
                               "GN_DIRECT_NOSCAL", "GN_DIRECT_L_NOSCAL", "GN_DIRECT_L_RAND_NOSCAL",
                               "GN_ORIG_DIRECT",  "GN_ORIG_DIRECT_L",  "GN_CRS2_LM",
                               "GN_MLSL",         "GN_MLSL_LDS",       "G_MLSL",
                               "G_MLSL_LDS",      "GN_ISRES",          "GN_ESCH"};
    n.insert(n.end(), nlopt_local_algorithms().begin(), nlopt_local_algorithms().end());
    return n;
  }();
  return names;
}

std::string run_nlopt(EvaluationContext& ctx, const NloptSearch& search, Eigen::VectorXd x0,
                      long max_evaluations) {
  const long allowed = std::min(max_evaluations, ctx.remaining_evaluations());
  if (allowed <= 0 || ctx.stopped()) return "FORCED_STOP";
  x0 = ctx.bounds().clamp(x0);
  std::vector<double> x(x0.begin(), x0.end());
  Objective data{ctx, allowed};
  nlopt::opt opt = make_optimizer(search, ctx.bounds(), allowed);
  opt.set_min_objective(objective, &data);
  const Eigen::VectorXd range = ctx.bounds().upper - ctx.bounds().lower;
  if (search.initial_step > 0 && range.minCoeff() > 0) {
    const Eigen::VectorXd dx = search.initial_step * range;
    opt.set_initial_step(std::vector<double>(dx.begin(), dx.end()));
  }
  // NLopt's generator is per thread: seed it here, in the trial's thread.
  nlopt::srand(static_cast<unsigned long>(ctx.rng().next()));
  double f = 0.0;
  try {
    return nlopt_result_to_string(static_cast<nlopt_result>(opt.optimize(x, f)));
  } catch (const nlopt::forced_stop&) {
    return "FORCED_STOP";
  } catch (const nlopt::roundoff_limited&) {
    return "ROUNDOFF_LIMITED";  // a normal end for a converged local method
  }
}

}  // namespace hystbench
