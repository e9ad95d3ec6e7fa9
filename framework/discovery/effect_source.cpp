#include "framework/discovery/effect_source.hpp"

#include <cmath>
#include <regex>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

std::string replace_all(std::string text, const std::string& key, const std::string& value) {
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
    text.replace(at, key.size(), value);
  return text;
}

std::string exact(double v) { return format_number("%.17g", v); }

// Text inside a C++ string literal of the generated source.
std::string literal(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch == '\n' ? ' ' : ch;
  }
  return out;
}

// What the effect is built from and adds to, as the comments of the source say it.
struct StageForm {
  const char* stage;   // EffectStage enumerator
  const char* signal;  // the signal the term is built from
  int u_power, y_power;  // of c's physical unit, before the term's own powers
  const char* a_decl;  // the declaration of that signal in apply()
  const char* view_signal;  // what the residual signature builds the term from
  const char* view_member;  // ... as a member of ResidualView
};

constexpr const char* kStageInput = "const Eigen::VectorXd& a = *ctx.stage_input;";

StageForm stage_form(const CandidateTerm& t) {
  switch (t.stage) {
    case TermStage::Input: return {"Input", "the input (the stage input)", 1, 0, kStageInput, "the input u", "u"};
    case TermStage::Static:
      // A term of w is built from the signal the effect is handed (the block's
      // output so far), not from the stage input v; the residual view has no w.
      if (t.own_factor(false).signal == TermSignal::StaticOutput)
        return {"Nonlinearity", "the static block's output before this effect (the signal it is handed)", 0, 1,
                "const Eigen::VectorXd a = signal;  // w before the term",
                "the input u (the residual view has no w; u stands for it)", "u"};
      return {"Nonlinearity", "the drive (the stage input)", 0, 1, kStageInput, "the input u", "u"};
    case TermStage::Dynamics:
      return {"Dynamics", "the resonance's own output (the force depends on the output it drives)", 0, 1,
              kStageInput, "the model output", "y_model"};
    case TermStage::Output:
      return {"Output", "the dynamics' output (the stage input)", 0, 1, kStageInput, "the model output", "y_model"};
  }
  return {"Output", "?", 0, 1, kStageInput, "the model output", "y_model"};
}

// The physical unit of c: the powers of y and u, and seconds per rate. A
// root gives c a half power, which EffectParam cannot state: c is then
// reported in normalised units.
void unit_powers(const CandidateTerm& t, int& u_power, int& y_power, std::string& unit) {
  if (t.has_root()) {
    u_power = y_power = 0;
    unit = "normalised units";
    return;
  }
  const StageForm f = stage_form(t);
  const int degree = t.degree();
  u_power = f.u_power;
  y_power = f.y_power;
  const TermSignal a = t.own_factor(false).signal;
  if (a == TermSignal::Input || a == TermSignal::Drive)  // in units of u; w, x and y are in units of y
    u_power -= degree;
  else
    y_power -= degree;
  const int q = t.own_factor(true).power;
  unit = q == 0 ? "" : q == 1 ? "s" : "s^" + std::to_string(q);
}

constexpr const char* kCommon = R"src(// Proposed from data by `hystbench propose`: the term @TERM@ at the @STAGE_NAME@ stage,
// from the residual of the model @MODEL@ fitted to @DATA@. It explained @SHARE@ %
// of what that fit left; proposed coefficient @COEF@ ± @SE@ (normalised units).
//
//   signal[k] += c·@TERM@,   @SYMBOL@' = (@SYMBOL@[k] − @SYMBOL@[k−1]) / Ts,   @SYMBOL@'[0] = 0
//
// with @SYMBOL@ @SIGNAL@. c = 0 leaves the signal unchanged.
// Build: see docs/plugins.md (out of the tree: a shared library).
#include <cmath>
@INCLUDES@
#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace {

// |a|^power (√|a| when root), times sign(a) when odd.
double factor(double a, int power, bool odd, bool root = false) {
  double m = 1.0;
  if (root && power > 0) m = std::sqrt(std::abs(a));
  else
    for (int i = 0; i < power; ++i) m *= std::abs(a);
  if (odd && power > 0) m = a < 0 ? -m : (a > 0 ? m : 0.0);
  return m;
}

double term(double a, double a_rate) {
  return factor(a, @P@, @P_ODD@@P_ROOT@) * factor(a_rate, @Q@, @Q_ODD@);
}

// Residual signature: the residual follows the term, built from @VIEW_SIGNAL@.
hystbench::SignatureValue term_correlation(const hystbench::ResidualView& r) {
  const Eigen::VectorXd& a = r.@VIEW_MEMBER@;
  Eigen::VectorXd phi(a.size());
  double previous = a.size() ? a[0] : 0.0;  // no rate before the record
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    phi[k] = term(a[k], (a[k] - previous) / r.sample_time);
    previous = a[k];
  }
  return {hystbench::correlation(r.e, phi)};
}

class @CLASS@ : public hystbench::Effect {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "@NAME@";
    i.summary = "proposed from data: c·@TERM@ at the @STAGE_NAME@ stage";
    i.citation = "proposed from data by hystbench propose (@DATA@, residual of @MODEL@)";
    i.stage = hystbench::EffectStage::@STAGE@;
@EXTENDS@    i.params = {@PARAMS@};
    i.signature = "the residual follows @TERM@";
    i.statistic = {"corr(e, @TERM@)", term_correlation, "the residual follows @TERM@ (r = {value})"};
    return i;
  }
)src";

constexpr const char* kAdditive = R"src(
  bool apply(std::span<const double> p, const hystbench::SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double c = p[0];
    if (!std::isfinite(c)) return false;
    if (c == 0.0) return true;  // neutral: the signal is left exactly as it was
    if (!(ctx.sample_time > 0.0) || !ctx.stage_input || ctx.stage_input->size() != signal.size()) return false;
    @A_DECL@
    double previous = a.size() ? a[0] : 0.0;  // no rate before the record
    for (Eigen::Index k = 0; k < signal.size(); ++k) {
      signal[k] += c * term(a[k], (a[k] - previous) / ctx.sample_time);
      previous = a[k];
    }
    return signal.allFinite();
  }
};
}  // namespace

HYSTBENCH_EFFECT(@CLASS@)
)src";

// msd's resonance (problems/hammerstein/effects/msd.cpp) computed the same
// way, so that c = 0 is msd bit for bit, with the force added to its input.
constexpr const char* kForce = R"src(
  bool apply(std::span<const double> p, const hystbench::SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double period = p[0], zeta = p[1], c = p[2], Ts = ctx.sample_time;
    if (!std::isfinite(period) || !std::isfinite(zeta) || !std::isfinite(c) || period < 0.0) return false;
    if (!(Ts > 0.0) || !std::isfinite(Ts)) return false;
    std::array<double, 5> g{};  // G = 1 − H, as msd
    const bool resonant = period > 0.0;
    if (resonant) {
      if (!(zeta > 0.0)) return false;
      const auto [k2, q, a0] = hystbench::tustin_resonance(period / (std::numbers::pi * Ts), zeta);
      g = {(k2 + q) / a0, -2.0 * k2 / a0, (k2 - q) / a0, (2.0 - 2.0 * k2) / a0, (k2 - q + 1.0) / a0};
      if (!std::isfinite(g[3]) || !std::isfinite(g[4]) || !std::isfinite(g[0])) return false;
    }
    hystbench::BiquadState<double> state{};
    double x1 = 0.0;  // the output one sample earlier
    for (Eigen::Index k = 0; k < signal.size(); ++k) {
      const double w = signal[k];
      // The output for a given input of the resonance at this sample, its state left as it is.
      const auto output = [&](double input) {
        if (!resonant) return input;
        const double gw = ((g[0] * input + g[1] * state.w1) + (g[2] * state.w2 - g[4] * state.y2)) - g[3] * state.y1;
        return input - gw;
      };
      double force = 0.0;
      if (c != 0.0) {
        // The force depends on the output it drives: x = output(w + c·term(x, (x − x1)/Ts)),
        // solved by Newton's method from the previous output.
        const auto residual = [&](double x) { return x - output(w + c * term(x, (x - x1) / Ts)); };
        double x = x1;
        bool converged = false;
        for (int i = 0; i < 12 && !converged; ++i) {
          const double f = residual(x), h = 1e-7 * std::max(1.0, std::abs(x));
          const double slope = (residual(x + h) - f) / h;
          if (!std::isfinite(f) || !std::isfinite(slope) || slope == 0.0) return false;
          const double step = f / slope;
          x -= step;
          converged = std::abs(step) <= 1e-12 * std::max(1.0, std::abs(x));
        }
        if (!converged) return false;  // no output consistent with its force: diverging
        force = c * term(x, (x - x1) / Ts);
      }
      const double input = w + force;
      const double x = resonant ? input - hystbench::biquad_step(g, state, input) : input;
      signal[k] = x;
      x1 = x;
    }
    return signal.allFinite();
  }
};
}  // namespace

HYSTBENCH_EFFECT(@CLASS@)
)src";

std::string param_text(const std::string& name, double lower, double upper, double neutral, int y_power,
                       int u_power, const std::string& unit, const std::string& doc) {
  return "{\"" + name + "\", " + exact(lower) + ", " + exact(upper) + ", " + exact(neutral) + ", " +
         std::to_string(y_power) + ", " + std::to_string(u_power) + ", \"" + literal(unit) + "\", \"" + literal(doc) +
         "\"}";
}

std::string params_text(const ProposedTerm& t) {
  int u_power = 0, y_power = 0;
  std::string unit;
  unit_powers(t.term, u_power, y_power, unit);
  const double bound = std::abs(t.coefficient) > 0.0 ? 10.0 * std::abs(t.coefficient) : 1.0;
  std::string c = param_text("c", -bound, bound, 0.0, y_power, u_power, unit, "coefficient of the proposed term");
  if (t.term.stage != TermStage::Dynamics) return c;
  const auto& params = EffectRegistry::instance().find("msd", "effect").params;
  std::string out;
  for (const auto& p : params)
    out += param_text(p.name, p.lower, p.upper, p.neutral, p.y_power, p.u_power, p.unit, p.doc) + ",\n                ";
  return out + c;
}

std::string class_name(const std::string& name) {
  std::string out;
  bool upper = true;
  for (char ch : name) {
    if (ch == '_') {
      upper = true;
      continue;
    }
    out += upper ? char(std::toupper(static_cast<unsigned char>(ch))) : ch;
    upper = false;
  }
  return out;
}

}  // namespace

void check_effect_name(const std::string& name) {
  if (!std::regex_match(name, std::regex("[a-z][a-z0-9_]*")))
    throw InputError("--name '" + name + "': an effect name is lower-case letters, digits and '_', starting with a letter");
  if (EffectRegistry::instance().contains(name))
    throw InputError("--name '" + name + "': the catalog already has an effect of that name; choose another");
}

namespace {

// The forms a generated effect has: a power of one signal of the term's
// block and of its rate; a force needs msd to extend.
void check_form(const CandidateTerm& t, const std::string& model) {
  if (!t.of_one_signal())
    throw InputError("the term " + t.text() + " is not a power of one signal of the " + term_stage_name(t.stage) +
                     " block and of its rate, the one form a generated effect has; write its effect by hand "
                     "(docs/plugins.md#adding-a-physical-effect)");
  if (t.stage == TermStage::Dynamics && !Model::parse(model).has("msd"))
    throw InputError("the term " + t.text() +
                     " is a force inside the dynamics, and the generated effect adds it to msd, which the model " +
                     model + " does not have; fit a model with msd, or write the effect by hand (docs/plugins.md)");
}

}  // namespace

std::string proposed_effect_source(const ProposedTerm& t, const EffectSourceContext& context) {
  check_effect_name(context.name);
  check_form(t.term, context.model);
  const bool force = t.term.stage == TermStage::Dynamics;
  const StageForm f = stage_form(t.term);
  const TermFactor a = t.term.own_factor(false), rate = t.term.own_factor(true);
  std::string s = std::string(kCommon) + (force ? kForce : kAdditive);
  const std::vector<std::pair<std::string, std::string>> keys = {
      {"@TERM@", t.term.text()},
      {"@STAGE_NAME@", term_stage_name(t.term.stage)},
      {"@STAGE@", f.stage},
      {"@SYMBOL@", a.symbol()},
      {"@SIGNAL@", f.signal},
      {"@MODEL@", literal(context.model)},
      {"@DATA@", literal(context.data_name)},
      {"@SHARE@", format_number("%.3g", 100.0 * t.err)},
      {"@COEF@", format_number("%.6g", t.coefficient)},
      {"@SE@", format_number("%.2g", t.standard_error)},
      {"@P@", std::to_string(a.power)},
      {"@P_ODD@", a.odd ? "true" : "false"},
      {"@P_ROOT@", a.root ? ", true" : ""},
      {"@Q@", std::to_string(rate.power)},
      {"@Q_ODD@", rate.odd ? "true" : "false"},
      {"@A_DECL@", f.a_decl},
      {"@VIEW_SIGNAL@", f.view_signal},
      {"@VIEW_MEMBER@", f.view_member},
      {"@INCLUDES@", force ? "#include <algorithm>\n#include <array>\n#include <numbers>\n\n#include \"problems/hammerstein/effects/biquad.hpp\""
                           : ""},
      {"@EXTENDS@", force ? "    i.extends = \"msd\";\n" : ""},
      {"@PARAMS@", params_text(t)},
      {"@NAME@", context.name},
      {"@CLASS@", class_name(context.name)}};
  for (const auto& [key, value] : keys) s = replace_all(s, key, value);
  return s;
}

std::string proposed_effect_cmake(const std::string& name) {
  return "# The proposed effect as a plugin (docs/plugins.md#out-of-the-tree-a-shared-library):\n"
         "#        cmake -S . -B build -DCMAKE_PREFIX_PATH=<hystbench prefix>\n"
         "#    or  cmake -S . -B build -Dhystbench_DIR=<hystbench build tree>\n"
         "#        cmake --build build\n"
         "cmake_minimum_required(VERSION 3.20)\n"
         "project(" + name + "_effect LANGUAGES CXX)\n\n"
         "find_package(hystbench REQUIRED)\n"
         "hystbench_add_plugin(" + name + " " + name + ".cpp)\n";
}

}  // namespace hystbench
