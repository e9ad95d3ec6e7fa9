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
  const char* drive;   // the EffectDrive of the kernel: what it reads besides the signal
  const char* a_expr;  // that signal in sample(): the drive, or the signal handed in
  const char* view_signal;  // what the residual signature builds the term from
  const char* view_member;  // ... as a member of ResidualView
};

StageForm stage_form(const CandidateTerm& t) {
  switch (t.stage) {
    case TermStage::Input:
      return {"Input", "the input (the stage input)", 1, 0, "StageInput", "drive", "the input u", "u"};
    case TermStage::Static:
      // A term of w is built from the signal the effect is handed (the block's
      // output so far), not from the stage input v; the residual view has no w.
      if (t.own_factor(false).signal == TermSignal::StaticOutput)
        return {"Nonlinearity", "the static block's output before this effect (the signal it is handed)", 0, 1,
                "None", "signal", "the input u (the residual view has no w; u stands for it)", "u"};
      return {"Nonlinearity", "the drive (the stage input)", 0, 1, "StageInput", "drive", "the input u", "u"};
    case TermStage::Dynamics:
      return {"Dynamics", "the resonance's own output (the force depends on the output it drives)", 0, 1, "None",
              "signal", "the model output", "y_model"};
    case TermStage::Output:
      return {"Output", "the dynamics' output (the stage input)", 0, 1, "StageInput", "drive", "the model output",
              "y_model"};
  }
  return {"Output", "?", 0, 1, "StageInput", "drive", "the model output", "y_model"};
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
// Written as one per-sample kernel (framework/model/kernel_effect.hpp), which
// gives the effect its batched form: candidates are fitted a block at a time,
// as the catalog's effects are. Build: see docs/plugins.md (out of the tree: a
// shared library).
#include <array>
#include <cmath>
#include <span>
@INCLUDES@
#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"

namespace {

using hystbench::LaneBits;
using hystbench::LaneVector;
using hystbench::lane_abs;

// √x, and whether every lane of a mask is set: for one candidate (double,
// bool) or a block (LaneVector, LaneBits).
double lane_sqrt(double x) { return std::sqrt(x); }
LaneVector lane_sqrt(LaneVector x) {
  for (int l = 0; l < hystbench::kEffectLanes; ++l) x[l] = std::sqrt(x[l]);
  return x;
}
bool lane_all(bool m) { return m; }
bool lane_all(LaneBits m) {
  for (int l = 0; l < hystbench::kEffectLanes; ++l)
    if (!m[l]) return false;
  return true;
}

// |a|^power (√|a| when root), times sign(a) when odd.
template <class V>
V factor(V a, int power, bool odd, bool root = false) {
  V m = V{} + 1.0;
  if (root && power > 0)
    m = lane_sqrt(lane_abs(a));
  else
    for (int i = 0; i < power; ++i) m *= lane_abs(a);
  if (odd && power > 0) m = a < V{} ? -m : (a > V{} ? m : V{});
  return m;
}

template <class V>
V term(V a, V a_rate) {
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

class @CLASS@ : public hystbench::KernelEffect<@CLASS@, @K@, hystbench::EffectDrive::@DRIVE@> {
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

  struct Aux {
    double ts;
  };
  static Aux aux(double ts) { return {ts}; }
  static constexpr bool kEarlyExit = true;
)src";

constexpr const char* kAdditive = R"src(
  static hystbench::EffectSetup setup(std::span<const double> p, double ts, std::array<double, 1>& c) {
    if (!std::isfinite(p[0]) || !(ts > 0.0)) return hystbench::EffectSetup::Invalid;
    if (p[0] == 0.0) return hystbench::EffectSetup::PassThrough;  // neutral: the signal as it was
    c = {p[0]};
    return hystbench::EffectSetup::Run;
  }

  template <class V>
  struct State {
    V previous{};
    V finite{};  // 0 while every output is finite
    bool started = false;  // no rate before the record
  };

  template <class V, class Drive>
  static V sample(const std::array<V, 1>& c, const Aux& aux, State<V>& s, V signal, [[maybe_unused]] Drive drive) {
    const V a = @A_EXPR@;
    const V rate = s.started ? (a - s.previous) / aux.ts : V{};
    s.previous = a;
    s.started = true;
    const V out = signal + c[0] * term(a, rate);
    s.finite += out * 0.0;
    return out;
  }

  template <class V>
  static V health(const std::array<V, 1>&, const State<V>& s) {
    return s.finite;
  }
};
}  // namespace

HYSTBENCH_EFFECT(@CLASS@)
)src";

// msd's resonance (problems/hammerstein/effects/msd.cpp) computed the same
// way, so that c = 0 is msd bit for bit, with the force added to its input.
constexpr const char* kForce = R"src(
  // c = (g0, g1, g2, g3, g4, coefficient): G = 1 − H as msd, all 0 without a resonance.
  static hystbench::EffectSetup setup(std::span<const double> p, double ts, std::array<double, 6>& c) {
    const double period = p[0], zeta = p[1], coefficient = p[2];
    if (!std::isfinite(period) || !std::isfinite(zeta) || !std::isfinite(coefficient) || period < 0.0)
      return hystbench::EffectSetup::Invalid;
    if (!(ts > 0.0) || !std::isfinite(ts)) return hystbench::EffectSetup::Invalid;
    c = {0.0, 0.0, 0.0, 0.0, 0.0, coefficient};
    if (period == 0.0) return coefficient == 0.0 ? hystbench::EffectSetup::PassThrough : hystbench::EffectSetup::Run;
    if (!(zeta > 0.0)) return hystbench::EffectSetup::Invalid;
    const auto [k2, q, a0] = hystbench::tustin_resonance(period / (std::numbers::pi * ts), zeta);
    c = {(k2 + q) / a0, -2.0 * k2 / a0, (k2 - q) / a0, (2.0 - 2.0 * k2) / a0, (k2 - q + 1.0) / a0, coefficient};
    if (!std::isfinite(c[3]) || !std::isfinite(c[4]) || !std::isfinite(c[0])) return hystbench::EffectSetup::Invalid;
    return hystbench::EffectSetup::Run;
  }

  template <class V>
  struct State {
    hystbench::BiquadState<V> resonance{};
    V x1{};      // the output one sample earlier
    V finite{};  // 0 while every output is finite and every force was solved
  };

  template <class V, class Drive>
  static V sample(const std::array<V, 6>& c, const Aux& aux, State<V>& s, V w, Drive) {
    const std::array<V, 5> g = {c[0], c[1], c[2], c[3], c[4]};
    const V coefficient = c[5], one = V{} + 1.0;
    // The output for a given input of the resonance at this sample, its state left as it is.
    const auto output = [&](V input) {
      const V gw = ((g[0] * input + g[1] * s.resonance.w1) + (g[2] * s.resonance.w2 - g[4] * s.resonance.y2)) -
                   g[3] * s.resonance.y1;
      return input - gw;
    };
    // The force depends on the output it drives: x = output(w + c·term(x, (x − x1)/Ts)),
    // solved by Newton's method from the previous output, every lane on its own
    // (a lane stops when it has converged, or fails when it cannot).
    const auto residual = [&](V x) { return x - output(w + coefficient * term(x, (x - s.x1) / aux.ts)); };
    V x = s.x1;
    auto done = coefficient == V{};  // no force: nothing to solve
    auto failed = coefficient != coefficient;  // none yet
    for (int i = 0; i < 12 && !lane_all(done); ++i) {
      const V f = residual(x), h = 1e-7 * (one < lane_abs(x) ? lane_abs(x) : one);
      const V slope = (residual(x + h) - f) / h;
      const auto broken = (f - f != V{}) | (slope - slope != V{}) | (slope == V{});
      const V step = f / slope, next = x - step;
      failed = done ? failed : (failed | broken);
      const auto close = lane_abs(step) <= 1e-12 * (one < lane_abs(next) ? lane_abs(next) : one);
      x = done ? x : next;
      done = done ? done : (close | broken);
    }
    failed = failed | (done == decltype(done){});  // no output consistent with its force: diverging
    const V force = coefficient == V{} ? V{} : coefficient * term(x, (x - s.x1) / aux.ts);
    const V input = w + force;
    const V out = input - hystbench::biquad_step(g, s.resonance, input);
    s.x1 = out;
    s.finite = failed ? V{} + NAN : s.finite + out * 0.0;
    return out;
  }

  template <class V>
  static V health(const std::array<V, 6>&, const State<V>& s) {
    return s.finite;
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
      {"@A_EXPR@", f.a_expr},
      {"@DRIVE@", f.drive},
      {"@K@", force ? "6" : "1"},
      {"@VIEW_SIGNAL@", f.view_signal},
      {"@VIEW_MEMBER@", f.view_member},
      {"@INCLUDES@", force ? "#include <numbers>\n\n#include \"problems/hammerstein/effects/biquad.hpp\""
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
