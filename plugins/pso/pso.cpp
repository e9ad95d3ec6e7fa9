// Particle swarm optimisation (docs/algorithms.md#pso): inertia-weight PSO
// (Shi & Eberhart) or constriction-factor PSO (Clerc & Kennedy).
//
// The swarm flies in normalised coordinates z in [0,1]^D
// (docs/algorithms.md#normalised-coordinates), so Vmax is a fraction of each
// parameter's range. Synchronous update (docs/algorithms.md#pso): every
// particle moves using the personal and neighbourhood bests of the previous
// iteration, the whole swarm is evaluated in one batch, then the bests are
// refreshed with the "<=" rule.
#include <algorithm>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/core/text.hpp"
#include "framework/evolution/greedy_selection.hpp"
#include "framework/evolution/normalised_space.hpp"
#include "framework/evolution/population.hpp"
#include "framework/evolution/pso_coefficients.hpp"

namespace hystbench {
namespace {

enum class Variant { Inertia, Constriction };
enum class Topology { Global, Ring };
enum class Walls { Absorbing, Reflect };

// v <- scale (inertia v + c1 r1 (p - z) + c2 r2 (g - z)): scale = 1 and a
// scheduled inertia for Shi-Eberhart, scale = chi and inertia 1 for
// Clerc-Kennedy.
struct VelocityRule {
  double scale, inertia;
};

struct Swarm {
  Eigen::MatrixXd Z, V, P;  // positions, velocities, personal bests
  Eigen::VectorXd fp;       // fitness of the personal bests
};

class ParticleSwarm : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"pso",
            "Particle swarm, inertia weight 0.9 -> 0.4 or constriction, gbest or ring, "
            "normalised coordinates",
            "Inertia: Y. Shi, R. Eberhart, A modified particle swarm optimizer, Proc. IEEE ICEC, "
            "pp. 69-73, 1998; Y. Shi, R. C. Eberhart, Empirical study of particle swarm "
            "optimization, CEC 1999, vol. 3, pp. 1945-1950. Constriction: M. Clerc, J. Kennedy, "
            "The particle swarm - explosion, stability, and convergence in a multidimensional "
            "complex space, IEEE TEC 6(1):58-73, 2002, doi:10.1109/4235.985692; Vmax = Xmax with "
            "constriction after R. C. Eberhart, Y. Shi, CEC 2000, pp. 84-88. RESOLUTION: swarm "
            "size, Vmax 0.2 of the range (inertia), absorbing walls, synchronous update and "
            "normalised coordinates are this project's choices (docs/algorithms.md#pso).",
            {ParamSpec::integer("swarm", 40, 2, 100000, "number of particles"),
             ParamSpec::choice("variant", "inertia", {"inertia", "constriction"},
                               "velocity rule: linearly decreasing inertia weight, or "
                               "Clerc-Kennedy constriction chi(c1 + c2)"),
             ParamSpec::real("w_max", 0.9, 0.0, 2.0, "inertia weight at the start (inertia)"),
             ParamSpec::real("w_min", 0.4, 0.0, 2.0, "inertia weight at the end (inertia)"),
             ParamSpec::real("c1", nullptr, 0.0, 10.0,
                             "cognitive coefficient; auto = 2 (inertia) or 2.05 (constriction)"),
             ParamSpec::real("c2", nullptr, 0.0, 10.0,
                             "social coefficient; auto = 2 (inertia) or 2.05 (constriction)"),
             ParamSpec::real("vmax", nullptr, 0.001, 1.0,
                             "velocity limit as a fraction of each range; auto = 0.2 (inertia) "
                             "or 0.5 = Xmax (constriction)"),
             ParamSpec::choice("topology", "gbest", {"gbest", "ring"},
                               "attractor: best of the swarm, or best of the particle and its "
                               "two ring neighbours"),
             ParamSpec::choice("bounds", "absorbing", {"absorbing", "reflect"},
                               "wall: clip and stop (v = 0), or mirror and reverse (v = -v)")}};
  }

  explicit ParticleSwarm(const Params& p)
      : swarm_(p.integer("swarm")),
        variant_(p.text("variant") == "inertia" ? Variant::Inertia : Variant::Constriction),
        topology_(p.text("topology") == "gbest" ? Topology::Global : Topology::Ring),
        walls_(p.text("bounds") == "absorbing" ? Walls::Absorbing : Walls::Reflect),
        w_max_(p.real("w_max")),
        w_min_(p.real("w_min")),
        c1_(p.is_auto("c1") ? default_c() : p.real("c1")),
        c2_(p.is_auto("c2") ? default_c() : p.real("c2")),
        vmax_(p.is_auto("vmax") ? (variant_ == Variant::Inertia ? 0.2 : 0.5) : p.real("vmax")) {
    if (variant_ == Variant::Constriction && !(c1_ + c2_ > 4.0))
      throw InputError("pso: the constriction variant needs c1 + c2 > 4; got c1 = " +
                       number_text(c1_) + ", c2 = " + number_text(c2_));
  }

  void run(EvaluationContext& ctx) override {
    const NormalisedSpace space(ctx.bounds());
    Swarm s;
    s.Z = uniform_population(space.unit(), swarm_, ctx.rng());
    s.V = Eigen::MatrixXd(s.Z.rows(), s.Z.cols());
    for (Eigen::Index k = 0; k < s.V.size(); ++k) s.V.data()[k] = ctx.rng().uniform(-vmax_, vmax_);
    if (space.evaluate(ctx, s.Z, s.fp) < swarm_) return;
    s.P = s.Z;

    Eigen::VectorXd fz;
    while (ctx.next_iteration()) {
      move(s, rule(ctx.progress()), ctx.rng());
      const Eigen::Index evaluated = space.evaluate(ctx, s.Z, fz);
      replace_if_not_worse(s.P, s.fp, s.Z, fz, evaluated);  // personal bests
      if (evaluated < swarm_) return;
    }
  }

 private:
  double default_c() const { return variant_ == Variant::Inertia ? 2.0 : 2.05; }

  VelocityRule rule(double tau) const {
    if (variant_ == Variant::Inertia) return {1.0, inertia_weight(w_max_, w_min_, tau)};
    return {constriction_factor(c1_ + c2_), 1.0};
  }

  // Best personal best among particle i and its ring neighbours i - 1, i + 1.
  int ring_best(const Eigen::VectorXd& fp, int i) const {
    int best = i;
    for (int n : {(i + swarm_ - 1) % swarm_, (i + 1) % swarm_})
      if (fp[n] < fp[best]) best = n;
    return best;
  }

  void move(Swarm& s, VelocityRule r, Rng& rng) const {
    const int gbest = rank_order(s.fp).front();
    // Attractors come from the bests before this move (synchronous update).
    std::vector<int> attractor(swarm_, gbest);
    if (topology_ == Topology::Ring)
      for (int i = 0; i < swarm_; ++i) attractor[i] = ring_best(s.fp, i);
    for (int i = 0; i < swarm_; ++i) {
      for (Eigen::Index j = 0; j < s.Z.rows(); ++j) {
        const double z = s.Z(j, i);
        const double r1 = rng.uniform(), r2 = rng.uniform();
        const double v = r.scale * (r.inertia * s.V(j, i) + c1_ * r1 * (s.P(j, i) - z) +
                                    c2_ * r2 * (s.P(j, attractor[i]) - z));
        s.V(j, i) = std::clamp(v, -vmax_, vmax_);
        s.Z(j, i) = z + s.V(j, i);
        hit_walls(s.Z(j, i), s.V(j, i));
      }
    }
  }

  // Wall handling in the unit cube (docs/algorithms.md#pso).
  void hit_walls(double& z, double& v) const {
    if (z >= 0.0 && z <= 1.0) return;
    if (walls_ == Walls::Absorbing) {
      v = 0.0;
    } else {
      z = z < 0.0 ? -z : 2.0 - z;
      v = -v;
    }
    z = std::clamp(z, 0.0, 1.0);  // also catches a mirror image still outside
  }

  int swarm_;
  Variant variant_;
  Topology topology_;
  Walls walls_;
  double w_max_, w_min_, c1_, c2_, vmax_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::ParticleSwarm)
