#include "framework/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "framework/core/error.hpp"
#include "framework/core/scratch_pool.hpp"
#include "framework/core/text.hpp"
#include "framework/model/held_start.hpp"

namespace hystbench {
namespace {

EffectParam gain_parameter() {
  return {"gain", -20.0, 20.0, 1.0, 1, -1, "",
          "static gain from input to output (the chain's effects have unit static gain)"};
}

std::string unit_power(const std::string& name, int power) {
  if (power == 0) return "";
  if (power == 1) return name;
  return name + "^" + std::to_string(power);
}

std::string unit_text(const EffectParam& p, const std::string& u, const std::string& y) {
  // A unit "1/s" is a denominator: with y_power 1 it reads "µm/s", not "1/s·µm".
  const bool inverse = p.unit.rfind("1/", 0) == 0;
  std::string num = inverse ? "" : p.unit;
  std::string den = inverse ? p.unit.substr(2) : "";
  auto put = [](std::string& into, const std::string& part) {
    if (part.empty()) return;
    into += (into.empty() ? "" : "·") + part;
  };
  put(p.y_power > 0 ? num : den, unit_power(y, std::abs(p.y_power)));
  put(p.u_power > 0 ? num : den, unit_power(u, std::abs(p.u_power)));
  if (den.empty()) return num;
  return (num.empty() ? "1" : num) + "/" + den;
}

}  // namespace

double physical_factor(const EffectParam& p, const SignalScales& s) {
  return std::pow(s.y, p.y_power) * std::pow(s.u, p.u_power);
}

Model::Model(const std::vector<std::string>& effects, const std::string& where) {
  build(effects, where);
}

Model Model::parse(const std::string& list, const std::string& where) {
  std::vector<std::string> names;
  std::string item;
  for (std::size_t i = 0; i <= list.size(); ++i) {
    if (i == list.size() || list[i] == ',') {
      const auto b = item.find_first_not_of(" \t");
      const auto e = item.find_last_not_of(" \t");
      if (b != std::string::npos) names.push_back(item.substr(b, e - b + 1));
      item.clear();
    } else {
      item += list[i];
    }
  }
  // An empty list is more often a shell variable that came out empty than a
  // wish for the gain alone, so the gain alone has to be asked for by name.
  if (names.empty())
    throw InputError(where + ": the effect list is empty; write none for the gain alone, or "
                             "effects such as hysteresis,msd (`hystbench list effects` lists them)");
  if (names.size() == 1 && names[0] == "none") names.clear();
  return Model(names, where);
}

void Model::build(std::vector<std::string> names, const std::string& where) {
  const auto& registry = EffectRegistry::instance();
  std::vector<const EffectInfo*> infos;
  for (const auto& n : names) {
    if (std::count(names.begin(), names.end(), n) > 1)
      throw InputError(where + ": effect '" + n + "' is listed twice");
    infos.push_back(&registry.find(n, where));
  }
  std::vector<int> order(names.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return infos[a]->stage < infos[b]->stage; });
  names_.clear();
  entries_.clear();
  params_ = {gain_parameter()};
  owner_ = {""};
  for (int i : order) {
    names_.push_back(names[i]);
    entries_.push_back({infos[i], infos[i]->create(), dimension()});
    for (const auto& p : infos[i]->params) {
      params_.push_back(p);
      owner_.push_back(names[i]);
    }
  }
}

bool Model::has(const std::string& effect) const {
  return std::find(names_.begin(), names_.end(), effect) != names_.end();
}

std::string Model::text() const { return names_.empty() ? "none" : join(names_, ","); }

std::vector<std::string> Model::parameter_names() const {
  std::vector<std::string> out;
  for (int i = 0; i < dimension(); ++i)
    out.push_back(owner_[i].empty() ? params_[i].name : owner_[i] + "." + params_[i].name);
  return out;
}

Bounds Model::bounds() const {
  Bounds b;
  b.lower.resize(dimension());
  b.upper.resize(dimension());
  for (int i = 0; i < dimension(); ++i) {
    b.lower[i] = params_[i].lower;
    b.upper[i] = params_[i].upper;
  }
  b.names = parameter_names();
  return b;
}

Eigen::VectorXd Model::neutral() const {
  Eigen::VectorXd x(dimension());
  for (int i = 0; i < dimension(); ++i) x[i] = params_[i].neutral;
  return x;
}

std::vector<int> Model::parameters_of(const std::string& effect) const {
  std::vector<int> out;
  for (int i = 0; i < dimension(); ++i)
    if (owner_[i] == effect) out.push_back(i);
  return out;
}

Model Model::with(const std::string& effect) const {
  if (has(effect)) throw InputError("model already has effect '" + effect + "'");
  const EffectInfo& info = EffectRegistry::instance().find(effect, "effect");
  std::vector<std::string> names = names_;
  auto replaced = std::find(names.begin(), names.end(), info.extends);
  if (!info.extends.empty() && replaced != names.end())
    *replaced = effect;
  else
    names.push_back(effect);
  Model m(names);
  m.substeps_ = substeps_;
  m.input_hold_ = input_hold_;
  return m;
}

Model Model::without(const std::string& effect) const {
  std::vector<std::string> names = names_;
  names.erase(std::remove(names.begin(), names.end(), effect), names.end());
  Model m(names);
  m.substeps_ = substeps_;
  m.input_hold_ = input_hold_;
  return m;
}

Eigen::VectorXd Model::carry_over(const Model& from,
                                  const Eigen::Ref<const Eigen::VectorXd>& x_from) const {
  Eigen::VectorXd x = neutral();
  const auto from_names = from.parameter_names();
  for (int i = 0; i < dimension(); ++i) {
    std::vector<std::string> sources = {owner_[i]};
    if (!owner_[i].empty()) {
      const auto& ext = EffectRegistry::instance().find(owner_[i], "effect").extends;
      if (!ext.empty()) sources.push_back(ext);
    }
    for (const auto& src : sources) {
      const std::string key = src.empty() ? params_[i].name : src + "." + params_[i].name;
      const auto j = std::find(from_names.begin(), from_names.end(), key);
      if (j != from_names.end()) {
        x[i] = x_from[j - from_names.begin()];
        break;
      }
    }
  }
  return x;
}

bool Model::simulate(const Eigen::Ref<const Eigen::VectorXd>& x, const ModelData& data,
                     Eigen::VectorXd& y) const {
  return simulate_probed(x, data, y, Entry::Output, nullptr, nullptr);
}

bool Model::simulate_probed(const Eigen::Ref<const Eigen::VectorXd>& x, const ModelData& data,
                            Eigen::VectorXd& y, Entry entry, const Eigen::VectorXd* added,
                            ChainSignals* signals) const {
  if (data.held_start && data.warmup > 0) return simulate_held(x, data, y, entry, added, signals);
  const auto add_at = [&](Entry here) {
    if (added && entry == here) y += *added;
  };
  // The signal of each stage starts as the previous stage's output, which
  // parallel branches (SignalContext::stage_input) also see.
  Eigen::VectorXd stage_input = data.u;
  y = data.u;
  SignalContext ctx{data.sample_time, &data.t, &stage_input, substeps_, input_hold_};
  auto run_stage = [&](EffectStage stage) {
    bool first = true;
    for (const auto& e : entries_) {
      if (e.info->stage != stage) continue;
      std::span<const double> p(x.data() + e.offset, e.info->params.size());
      if (!e.effect->apply(p, ctx, y)) return false;
      if (signals && stage == EffectStage::Dynamics && first) signals->resonance = y;
      first = false;
    }
    return true;
  };
  if (!run_stage(EffectStage::Input)) return false;
  add_at(Entry::Drive);
  stage_input = y;
  if (signals) signals->v = y;
  y *= x[0];
  if (!run_stage(EffectStage::Nonlinearity)) return false;
  add_at(Entry::Dynamics);
  if (signals) signals->w = signals->resonance = y;
  stage_input = y;
  if (!run_stage(EffectStage::Dynamics)) return false;
  if (signals) signals->x = y;
  stage_input = y;
  if (!run_stage(EffectStage::Output)) return false;
  add_at(Entry::Output);
  return y.allFinite();
}

// simulate_probed() after the input held at the level that matches the
// warm-up, every signal cut back to the record.
bool Model::simulate_held(const Eigen::Ref<const Eigen::VectorXd>& x, const ModelData& data,
                          Eigen::VectorXd& y, Entry entry, const Eigen::VectorXd* added,
                          ChainSignals* signals) const {
  double level = 0.0;
  if (!held_level(*this, x, data, level)) return false;
  const ModelData held = with_held_input(data, level, kHeldStartSamples);
  Eigen::VectorXd added_held;
  if (added) {
    added_held.setZero(held.size());
    added_held.tail(data.size()) = *added;
  }
  const bool ok = simulate_probed(x, held, y, entry, added ? &added_held : nullptr, signals);
  const Eigen::Index n = data.size();
  y = y.tail(n).eval();
  if (signals)
    for (Eigen::VectorXd* s : {&signals->v, &signals->w, &signals->resonance, &signals->x})
      if (s->size() == held.size()) *s = s->tail(n).eval();
  return ok;
}

bool Model::has_lanes() const {
  return std::all_of(entries_.begin(), entries_.end(),
                     [](const ChainEntry& e) { return e.effect->has_lanes(); });
}

namespace {

// Samples per chunk of simulate_lanes(): a block's signals of one chunk (the
// signal, the stage input, an effect's copy of idle lanes) take 16 kB each
// with 8 lanes, so that the effects pass them on in L1 (1 024 samples, in
// L2, measured 8 % slower).
constexpr Eigen::Index kLaneChunk = 256;

using LaneRuns = std::vector<std::unique_ptr<LaneRun>>;

struct LaneBuffers {
  std::vector<LaneVector> signal, stage_input;
};

// One chunk of a block through the chain, as simulate() runs a record: each
// stage sees what entered it as its stage input (copied only for a stage
// with an effect that reads it), the gain between input and nonlinearity.
void run_chunk(const std::vector<Model::ChainEntry>& chain, LaneRuns& runs, const LaneVector& gain,
               const double* u, std::span<LaneVector> y, std::span<LaneVector> stage_input,
               const LaneChunk& chunk) {
  const auto reads = [&](EffectStage stage) {
    for (std::size_t i = 0; i < chain.size(); ++i)
      if (chain[i].info->stage == stage && runs[i]->reads_stage_input()) return true;
    return false;
  };
  const auto enter = [&](EffectStage stage) {
    if (reads(stage)) std::copy(y.begin(), y.end(), stage_input.begin());
  };
  const auto run_stage = [&](EffectStage stage) {
    for (std::size_t i = 0; i < chain.size(); ++i)
      if (chain[i].info->stage == stage) runs[i]->run(y, chunk);
  };
  const bool input_effects = std::any_of(chain.begin(), chain.end(), [](const Model::ChainEntry& e) {
    return e.info->stage == EffectStage::Input;
  });
  if (input_effects) {
    for (std::size_t k = 0; k < y.size(); ++k) y[k] = LaneVector{} + u[k];
    enter(EffectStage::Input);
    run_stage(EffectStage::Input);
    enter(EffectStage::Nonlinearity);
    for (auto& v : y) v *= gain;
  } else {
    // Nothing acts before the gain: the input, the nonlinearity's stage
    // input and the gained signal are written in one pass.
    const bool read = reads(EffectStage::Nonlinearity);
    for (std::size_t k = 0; k < y.size(); ++k) {
      const LaneVector v = LaneVector{} + u[k];
      if (read) stage_input[k] = v;
      y[k] = v * gain;
    }
  }
  run_stage(EffectStage::Nonlinearity);
  for (EffectStage stage : {EffectStage::Dynamics, EffectStage::Output}) {
    enter(stage);
    run_stage(stage);
  }
}

// Clears ok[l] where a sample of lane l is not finite (|v| < inf is false
// for infinities and NaN alike).
void check_finite(std::span<const LaneVector> y, LaneMask& ok) {
  LaneBits finite = LaneBits{} - 1;
  for (const auto& v : y) finite &= lane_abs(v) < std::numeric_limits<double>::infinity();
  for (int l = 0; l < kEffectLanes; ++l) ok[l] = ok[l] && finite[l] != 0;
}

}  // namespace

void Model::simulate_lanes(const Eigen::Ref<const Eigen::MatrixXd>& X, const ModelData& data, LaneMask& ok,
                           const LaneSink& sink) const {
  ok.fill(true);
  LaneRuns runs;
  for (const auto& e : entries_) {
    LaneParams p;
    for (int l = 0; l < kEffectLanes; ++l) p[l] = {X.col(l).data() + e.offset, e.info->params.size()};
    runs.push_back(e.effect->lane_run(p, {data.sample_time, substeps_, input_hold_}, ok));
  }
  const bool whole = std::any_of(runs.begin(), runs.end(), [](const auto& r) { return r->whole_record(); });
  LaneVector gain{};
  for (int l = 0; l < kEffectLanes; ++l) gain[l] = X(0, l);
  const Eigen::Index n = data.size();
  const bool timed = data.t.size() == n;
  const Eigen::Index chunk = whole ? std::max<Eigen::Index>(n, 1) : kLaneChunk;
  // Reused: with an effect that takes the whole record these are megabytes,
  // and fresh ones for every block cost page faults (the chain writes each
  // sample before it reads it).
  static ScratchPool<LaneBuffers> pool;
  const auto buffers = pool.lend();
  std::vector<LaneVector>& buffer = buffers->signal;
  std::vector<LaneVector>& stage_buffer = buffers->stage_input;
  buffer.resize(std::size_t(std::min(n, chunk)));
  stage_buffer.resize(buffer.size());
  for (Eigen::Index begin = 0; begin < n; begin += chunk) {
    const auto m = std::size_t(std::min(chunk, n - begin));
    const std::span<LaneVector> y(buffer.data(), m), stage_input(stage_buffer.data(), m);
    run_chunk(entries_, runs, gain, data.u.data() + begin, y, stage_input,
              {begin, timed ? data.t.data() + begin : nullptr, stage_input});
    check_finite(y, ok);
    sink(begin, y);
  }
  for (const auto& r : runs) r->finish(ok);
}

nlohmann::json Model::physical_values(const Eigen::Ref<const Eigen::VectorXd>& x,
                                      const SignalScales& scales) const {
  nlohmann::json out = nlohmann::json::object();
  const auto names = parameter_names();
  for (int i = 0; i < dimension(); ++i) out[names[i]] = x[i] * physical_factor(params_[i], scales);
  return out;
}

nlohmann::json Model::physical_units(const std::string& u_unit, const std::string& y_unit) const {
  nlohmann::json out = nlohmann::json::object();
  const auto names = parameter_names();
  const std::string u = u_unit.empty() ? "u" : u_unit;
  const std::string y = y_unit.empty() ? "y" : y_unit;
  for (int i = 0; i < dimension(); ++i) out[names[i]] = unit_text(params_[i], u, y);
  return out;
}

Eigen::VectorXd Model::from_physical(const nlohmann::json& values, const SignalScales& scales,
                                     const std::string& where) const {
  if (!values.is_object()) throw InputError(where + ": expected an object of parameter values");
  const auto names = parameter_names();
  require_known_keys(values, names, where);
  Eigen::VectorXd x(dimension());
  for (int i = 0; i < dimension(); ++i) {
    if (!values.contains(names[i]) || !values[names[i]].is_number())
      throw InputError(where + ": missing number for parameter '" + names[i] +
                       "' (model: " + text() + ")");
    x[i] = values[names[i]].get<double>() / physical_factor(params_[i], scales);
  }
  return x;
}

std::string stage_name(EffectStage stage) {
  switch (stage) {
    case EffectStage::Input: return "input";
    case EffectStage::Nonlinearity: return "nonlinearity";
    case EffectStage::Dynamics: return "dynamics";
    case EffectStage::Output: return "output";
  }
  return "?";
}

}  // namespace hystbench
