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

// The term as the generated effect computes it: the factors of its block's
// own signal a and of a's rate, and for a product of two signals those of
// the second signal b (power 0: no such factor).
struct WrittenTerm {
  CandidateTerm term;        // as written (written_term() may put w for v)
  double coefficient = 0.0;  // normalised units, of the written term
  TermFactor a, a_rate, b, b_rate;
  std::string note;          // why the written term differs from the proposed one ("" when it does not)

  bool product() const { return b.power > 0 || b_rate.power > 0; }
};

StageForm stage_form(const WrittenTerm& w) {
  const CandidateTerm& t = w.term;
  // A product reads its second signal from the stage input: v in the static
  // block, w in the dynamics.
  const char* other_drive = w.product() ? "StageInput" : "None";
  switch (t.stage) {
    case TermStage::Input:
      return {"Input", "the input (the stage input)", 1, 0, "StageInput", "drive", "the input u", "u"};
    case TermStage::Static:
      // A term of w is built from the signal the effect is handed (the block's
      // output so far), not from the stage input v; the residual view has no w.
      if (w.a.signal == TermSignal::StaticOutput)
        return {"Nonlinearity", "the static block's output before this effect (the signal it is handed)", 0, 1,
                other_drive, "signal", "the input u (the residual view has no w; u stands for it)", "u"};
      return {"Nonlinearity", "the drive (the stage input)", 0, 1, "StageInput", "drive", "the input u", "u"};
    case TermStage::Dynamics:
      return {"Dynamics", "the resonance's own output (the force depends on the output it drives)", 0, 1,
              other_drive, "signal", "the model output", "y_model"};
    case TermStage::Output:
      return {"Output", "the dynamics' output (the stage input)", 0, 1, "StageInput", "drive", "the model output",
              "y_model"};
  }
  return {"Output", "?", 0, 1, "StageInput", "drive", "the model output", "y_model"};
}

// The physical unit of c: the powers of y and u, and seconds per rate. A
// root gives c a half power, which EffectParam cannot state: c is then
// reported in normalised units.
void unit_powers(const WrittenTerm& w, int& u_power, int& y_power, std::string& unit) {
  if (w.term.has_root()) {
    u_power = y_power = 0;
    unit = "normalised units";
    return;
  }
  const StageForm f = stage_form(w);
  u_power = f.u_power;
  y_power = f.y_power;
  int seconds = 0;
  for (const TermFactor& factor : w.term.factors) {
    const bool of_u = factor.signal == TermSignal::Input || factor.signal == TermSignal::Drive;  // w, x, y: of y
    (of_u ? u_power : y_power) -= factor.power;
    if (factor.rate) seconds += factor.power;
  }
  unit = seconds == 0 ? "" : seconds == 1 ? "s" : "s^" + std::to_string(seconds);
}

constexpr const char* kCommon = R"src(// Proposed from data by `hystbench propose`: the term @PROPOSED@ at the @STAGE_NAME@ stage,
// from the residual of the model @MODEL@ fitted to @DATA@. It explained @SHARE@ %
// of what that fit left; proposed coefficient @COEF@ ± @SE@ (normalised units).
//
//   signal[k] += c·@TERM@,   @SYMBOL@' = (@SYMBOL@[k] − @SYMBOL@[k−1]) / Ts,   @SYMBOL@'[0] = 0
//
// with @SYMBOL@ @SIGNAL@@OTHER_LINE@.
// c = 0 leaves the signal unchanged.@NOTE@
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

// The term of the block's own signal a and of b@B_ROLE@.
template <class V>
V term(V a, V a_rate, [[maybe_unused]] V b, [[maybe_unused]] V b_rate) {
  return factor(a, @P@, @P_ODD@@P_ROOT@) * factor(a_rate, @Q@, @Q_ODD@)@B_FACTORS@;
}

// Residual signature: the residual follows the term, built from @VIEW_SIGNAL@.
hystbench::SignatureValue term_correlation(const hystbench::ResidualView& r) {
  const Eigen::VectorXd &a = r.@VIEW_MEMBER@, &b = r.u;
  Eigen::VectorXd phi(a.size());
  double previous = a.size() ? a[0] : 0.0, b_previous = b.size() ? b[0] : 0.0;  // no rate before the record
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    phi[k] = term(a[k], (a[k] - previous) / r.sample_time, b[k], (b[k] - b_previous) / r.sample_time);
    previous = a[k], b_previous = b[k];
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
    V previous{}, b_previous{};
    V finite{};  // 0 while every output is finite
    bool started = false;  // no rate before the record
  };

  template <class V, class Drive>
  static V sample(const std::array<V, 1>& c, const Aux& aux, State<V>& s, V signal, [[maybe_unused]] Drive drive) {
    const V a = @A_EXPR@, b = @B_EXPR@;
    const V rate = s.started ? (a - s.previous) / aux.ts : V{};
    const V b_rate = s.started ? (b - s.b_previous) / aux.ts : V{};
    s.previous = a, s.b_previous = b;
    s.started = true;
    const V out = signal + c[0] * term(a, rate, b, b_rate);
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
    V b1{};      // b one sample earlier
    V finite{};  // 0 while every output is finite and every force was solved
    bool started = false;  // no rate of b before the record
  };

  template <class V, class Drive>
  static V sample(const std::array<V, 6>& c, const Aux& aux, State<V>& s, V w, [[maybe_unused]] Drive drive) {
    const std::array<V, 5> g = {c[0], c[1], c[2], c[3], c[4]};
    const V coefficient = c[5], one = V{} + 1.0;
    const V b = @B_EXPR@, b_rate = s.started ? (b - s.b1) / aux.ts : V{};
    s.b1 = b, s.started = true;
    // The output for a given input of the resonance at this sample, its state left as it is.
    const auto output = [&](V input) {
      const V gw = ((g[0] * input + g[1] * s.resonance.w1) + (g[2] * s.resonance.w2 - g[4] * s.resonance.y2)) -
                   g[3] * s.resonance.y1;
      return input - gw;
    };
    // The force depends on the output it drives: x = output(w + c·term(x, (x − x1)/Ts, b, b')),
    // solved by Newton's method from the previous output, every lane on its own
    // (a lane stops when it has converged, or fails when it cannot).
    const auto residual = [&](V x) { return x - output(w + coefficient * term(x, (x - s.x1) / aux.ts, b, b_rate)); };
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
    const V force = coefficient == V{} ? V{} : coefficient * term(x, (x - s.x1) / aux.ts, b, b_rate);
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

std::string params_text(const WrittenTerm& t) {
  int u_power = 0, y_power = 0;
  std::string unit;
  unit_powers(t, u_power, y_power, unit);
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

std::string by_hand() { return "; write its effect by hand (docs/plugins.md#adding-a-physical-effect)"; }

// Two factors of two signals, each a power of the signal or of its rate.
bool of_two_signals(const CandidateTerm& t) {
  return t.factors.size() == 2 && t.factors[0].signal != t.factors[1].signal && !t.has_root() &&
         t.factors[0].signal != TermSignal::Play && t.factors[1].signal != TermSignal::Play;
}

bool has_static_effects(const Model& model) {
  return std::any_of(model.chain().begin(), model.chain().end(),
                     [](const Model::ChainEntry& e) { return e.info->stage == EffectStage::Nonlinearity; });
}

// A product of two signals as the block of its latest signal sees them: the
// static block its input v and the output w it hands on; a force inside the
// dynamics its own output x and its input w. A force's factor of v is
// written with w when the static block is the gain alone (w = gain·v, so
// the coefficient is divided by the gain); an output effect sees only y.
WrittenTerm written_product(WrittenTerm w, const Model& model, double gain) {
  const CandidateTerm& t = w.term;
  if (t.stage != TermStage::Static && t.stage != TermStage::Dynamics)
    throw InputError("the term " + t.text() + " pairs the " + term_stage_name(t.stage) +
                     " block's signal with a signal of an earlier block, which an effect of that block does not "
                     "see" + by_hand());
  const TermSignal own = t.stage == TermStage::Static ? TermSignal::StaticOutput : TermSignal::Resonance;
  TermFactor mine = t.factors[0], other = t.factors[1];
  if (other.signal == own) std::swap(mine, other);
  if (other.signal == TermSignal::Drive && t.stage == TermStage::Dynamics) {
    if (has_static_effects(model))
      throw InputError("the term " + t.text() + " pairs the drive v with the resonance's output; a force inside "
                       "the dynamics sees its input w, which is gain·v only when the static block is the gain "
                       "alone, and the model " + model.text() + " has static effects" + by_hand());
    if (!std::isfinite(gain) || gain == 0.0)
      throw InputError("the term " + t.text() + " is written with w = gain·v, and the fitted gain is " +
                       format_number("%g", gain) + by_hand());
    other.signal = TermSignal::StaticOutput;
    w.coefficient /= other.odd ? gain : std::abs(gain);
    w.note = "Written with w for v: the static block is the gain alone, so w = gain·v\n// and c is the proposed "
             "coefficient divided by the fitted gain (" + format_number("%.6g", gain) + ").";
  }
  w.term.factors = {mine, other};
  w.a = {own, false, 0, false}, w.a_rate = {own, true, 0, false};
  w.b = {other.signal, false, 0, false}, w.b_rate = {other.signal, true, 0, false};
  (mine.rate ? w.a_rate : w.a) = mine;
  (other.rate ? w.b_rate : w.b) = other;
  return w;
}

// The forms a generated effect has: a power of one signal of the term's
// block and of its rate, or a product of two signals its block sees; a
// force needs msd to extend. Throws InputError saying why otherwise.
WrittenTerm written_term(const ProposedTerm& p, const EffectSourceContext& context) {
  const CandidateTerm& t = p.term;
  const Model model = Model::parse(context.model);
  if (t.stage == TermStage::Dynamics && !model.has("msd"))
    throw InputError("the term " + t.text() +
                     " is a force inside the dynamics, and the generated effect adds it to msd, which the model " +
                     context.model + " does not have; fit a model with msd, or write the effect by hand (docs/plugins.md)");
  WrittenTerm w{t, p.coefficient, t.own_factor(false), t.own_factor(true), {}, {}, ""};
  if (t.of_one_signal()) return w;
  if (!of_two_signals(t))
    throw InputError("the term " + t.text() + " is neither a power of one signal of the " + term_stage_name(t.stage) +
                     " block and of its rate nor a product of two signals that block sees, the forms a generated "
                     "effect has" + by_hand());
  return written_product(w, model, context.gain);
}

// " * factor(b, 1, true)": the factors of the second signal, none for a term of one signal.
std::string second_factors(const WrittenTerm& w) {
  std::string out;
  if (w.b.power > 0) out += " * factor(b, " + std::to_string(w.b.power) + ", " + (w.b.odd ? "true" : "false") + ")";
  if (w.b_rate.power > 0)
    out += " * factor(b_rate, " + std::to_string(w.b_rate.power) + ", " + (w.b_rate.odd ? "true" : "false") + ")";
  return out;
}

// How the header names the second signal.
std::string second_signal_line(const WrittenTerm& w) {
  if (!w.product()) return "";
  const bool input = w.term.stage == TermStage::Dynamics;
  return ",\n// and " + w.b.symbol() + (input ? " the dynamics' input" : " the drive") + " (the stage input; b in the code)";
}

}  // namespace

std::string proposed_effect_source(const ProposedTerm& t, const EffectSourceContext& context) {
  check_effect_name(context.name);
  const WrittenTerm w = written_term(t, context);
  const bool force = t.term.stage == TermStage::Dynamics;
  const StageForm f = stage_form(w);
  std::string s = std::string(kCommon) + (force ? kForce : kAdditive);
  const std::vector<std::pair<std::string, std::string>> keys = {
      {"@PROPOSED@", t.term.text()},
      {"@TERM@", w.term.text()},
      {"@STAGE_NAME@", term_stage_name(t.term.stage)},
      {"@STAGE@", f.stage},
      {"@SYMBOL@", w.a.symbol()},
      {"@SIGNAL@", f.signal},
      {"@OTHER_LINE@", second_signal_line(w)},
      {"@NOTE@", w.note.empty() ? "" : "\n// " + w.note},
      {"@MODEL@", literal(context.model)},
      {"@DATA@", literal(context.data_name)},
      {"@SHARE@", format_number("%.3g", 100.0 * t.err)},
      {"@COEF@", format_number("%.6g", t.coefficient)},
      {"@SE@", format_number("%.2g", t.standard_error)},
      {"@P@", std::to_string(w.a.power)},
      {"@P_ODD@", w.a.odd ? "true" : "false"},
      {"@P_ROOT@", w.a.root ? ", true" : ""},
      {"@Q@", std::to_string(w.a_rate.power)},
      {"@Q_ODD@", w.a_rate.odd ? "true" : "false"},
      {"@B_FACTORS@", second_factors(w)},
      {"@B_ROLE@", w.product() ? ", the stage input" : " (unused: the term is of one signal)"},
      {"@B_EXPR@", w.product() ? "V{} + drive" : "V{}"},
      {"@A_EXPR@", f.a_expr},
      {"@DRIVE@", f.drive},
      {"@K@", force ? "6" : "1"},
      {"@VIEW_SIGNAL@", std::string(f.view_signal) + (w.product() ? ", and b from the input u, which stands for it" : "")},
      {"@VIEW_MEMBER@", f.view_member},
      {"@INCLUDES@", force ? "#include <numbers>\n\n#include \"problems/hammerstein/effects/biquad.hpp\""
                           : ""},
      {"@EXTENDS@", force ? "    i.extends = \"msd\";\n" : ""},
      {"@PARAMS@", params_text(w)},
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
