#include "framework/discovery/beyond_catalog.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/diagnosis.hpp"
#include "framework/io/json_number.hpp"

namespace hystbench {
namespace {

std::string g4(double v) { return format_number("%.4g", v); }
std::string pct(double share) { return format_number("%.3g", 100.0 * share) + " %"; }

std::string amplitude_sentence(const Comparison& c) {
  const AmplitudeErrors* worst = nullptr;
  for (const auto& b : c.by_amplitude)
    if (b.metrics.n > 0 && (!worst || b.metrics.rmse > worst->metrics.rmse)) worst = &b;
  if (!worst) return "";
  return "by amplitude: largest at |u − mean| in [" + g4(worst->u_low) + ", " + g4(worst->u_high) + "] (RMSE " +
         g4(worst->metrics.rmse) + " against " + g4(c.parts.all.rmse) + " overall)";
}

std::string direction_sentence(const Comparison& c) {
  const double up = c.by_branch.loading.rmse, down = c.by_branch.unloading.rmse;
  if (!(up > 0.0) || !(down > 0.0)) return "";
  const std::string which = up > 1.2 * down   ? "larger while the drive rises"
                            : down > 1.2 * up ? "larger while the drive falls"
                                              : "alike in both directions";
  return "by direction: " + which + " (RMSE " + g4(up) + " loading, " + g4(down) + " unloading)";
}

std::string segment_sentence(const Comparison& c) {
  const SegmentErrors* worst = nullptr;
  for (const auto& s : c.by_segment)
    if (s.metrics.n > 0 && (!worst || s.metrics.rmse > worst->metrics.rmse)) worst = &s;
  if (!worst || c.by_segment.size() < 2) return "";
  return "by segment: largest in " + worst->segment + " (RMSE " + g4(worst->metrics.rmse) + ")";
}

// RMSE where the drive moves fastest (top quarter of |Δu|) against where it
// moves slowest (bottom quarter).
std::string rate_sentence(const Diagnosis& d, const ModelData& data) {
  Eigen::VectorXd y;
  const Eigen::Index n = data.size();
  if (n < 8 || !d.model.simulate(d.x, data, y)) return "";
  std::vector<std::pair<double, double>> by_rate;  // |Δu|, e²
  for (Eigen::Index k = 1; k < n; ++k) {
    const double e = (data.y[k] - y[k]) * data.scales.y;
    by_rate.push_back({std::abs(data.u[k] - data.u[k - 1]), e * e});
  }
  std::sort(by_rate.begin(), by_rate.end());
  const std::size_t q = by_rate.size() / 4;
  const auto rmse = [&](std::size_t from, std::size_t to) {
    double sum = 0.0;
    for (std::size_t i = from; i < to; ++i) sum += by_rate[i].second;
    return std::sqrt(sum / double(to - from));
  };
  const double slow = rmse(0, q), fast = rmse(by_rate.size() - q, by_rate.size());
  const std::string which = fast > 1.2 * slow ? "larger where the drive moves fast"
                            : slow > 1.2 * fast ? "larger where the drive moves slowly"
                                                : "alike at every drive rate";
  return "by rate: " + which + " (RMSE " + g4(fast) + " in the fastest quarter of samples, " + g4(slow) +
         " in the slowest)";
}

std::string stage_sentence(const std::vector<StageLead>& leads) {
  std::vector<StageLead> sorted = leads;
  std::stable_sort(sorted.begin(), sorted.end(), [](const StageLead& a, const StageLead& b) { return a.share > b.share; });
  std::string out = "by stage, the best single term explains";
  for (std::size_t i = 0; i < sorted.size(); ++i)
    out += std::string(i ? ";" : "") + " " + term_stage_name(sorted[i].stage) + " " +
           (sorted[i].term.empty() ? "nothing" : sorted[i].term + " " + pct(sorted[i].share));
  return out;
}

}  // namespace

double excess_share(double before, double after, double sigma) {
  const double excess = before * before - sigma * sigma;
  if (!(excess > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return (before * before - after * after) / excess;
}

double candidate_share(const Diagnosis& d, const std::string& effect) {
  const Candidate* c = d.find(effect);
  if (!c) return std::numeric_limits<double>::quiet_NaN();
  const bool held = d.errors.n_heldout > 0;
  return excess_share(held ? d.errors.rmse_heldout : d.errors.rmse_estimation,
                      held ? c->after.rmse_heldout : c->after.rmse_estimation, d.completeness.sigma);
}

bool refit_could_pass(const Diagnosis& d) {
  if (d.completeness.kind != "systematic") return true;
  for (const Candidate& c : d.candidates)
    if (candidate_share(d, c.effect) >= 0.25 * kPartialShare) return true;
  return false;
}

void describe_beyond_catalog(Diagnosis& d, const ModelData& data) {
  if (d.verdict != "none" || d.completeness.complete || d.completeness.kind != "systematic") return;
  BeyondCatalog& b = d.beyond;
  b.applies = true;
  b.judged_on = d.errors.n_heldout > 0 ? "held-out" : "estimation";
  for (const Candidate& c : d.candidates) b.tried.push_back({c.effect, candidate_share(d, c.effect)});
  for (const std::string& s : {amplitude_sentence(d.where), rate_sentence(d, data), direction_sentence(d.where),
                               segment_sentence(d.where)})
    if (!s.empty()) b.where.push_back(s);
  ProposeOptions probe;
  probe.regression.max_terms = 1;
  b.stages = propose_terms(d.model, d.x, data, probe).stage_leads;
  b.where.push_back(stage_sentence(b.stages));
  b.advice = "run hystbench propose on this fit to look for the missing term";
  std::string best;
  double best_share = -std::numeric_limits<double>::infinity();
  for (const auto& [effect, share] : b.tried)
    if (share > best_share) best = effect, best_share = share;
  const std::string prefix = "Something systematic is left: ";
  std::string numbers = d.completeness.reason;
  if (numbers.rfind(prefix, 0) == 0) numbers = numbers.substr(prefix.size());
  d.completeness.kind = "beyond_catalog";
  d.completeness.reason =
      "Something systematic is left and no catalog effect captures it: " + numbers +
      (best.empty() ? std::string(" No catalog effect was tried.")
                    : " The most any catalog effect removed of what is left above the noise on the " + b.judged_on +
                          " data is " +
                          pct(std::max(best_share, 0.0)) + " (" + best + ")" +
                          (b.refused.empty() ? "" : "; " + b.refused + " was significant but removed too little to add") +
                          ".") +
      " The missing physics may not be in the catalog: " + b.advice + ".";
}

std::string beyond_catalog_markdown(const BeyondCatalog& b, const std::string& data_name, const std::string& fit) {
  if (!b.applies) return "";
  std::string out = "## Beyond the catalog\n\nSomething systematic is left and no catalog effect captures it.\n\n"
                    "Where the error concentrates:\n\n";
  for (const std::string& w : b.where) out += "- " + w + "\n";
  out += "\nWhat each catalog effect removed of the error left above the noise (" + b.judged_on +
         " data; an effect must remove " + pct(kPartialShare) + " to be added):";
  for (std::size_t i = 0; i < b.tried.size(); ++i)
    out += std::string(i ? "," : "") + " " + b.tried[i].first + " " +
           (std::isfinite(b.tried[i].second) ? pct(b.tried[i].second) : "–");
  out += ".\n\nThe missing physics may not be in the catalog. `hystbench propose` regresses the residual on "
         "powers, play operators and products of the model's own signals and writes the best as an effect plugin "
         "(docs/discovery.md, \"Proposing a missing term\"):\n\n"
         "```sh\nhystbench propose --data DATA --fit " + fit + " --out DIR/proposals\n```\n\n"
         "with DATA the measurement (" + data_name + ") and DIR this folder.\n\n";
  return out;
}

nlohmann::json BeyondCatalog::to_json() const {
  nlohmann::json tried_json = nlohmann::json::array();
  for (const auto& [effect, share] : tried) tried_json.push_back({{"effect", effect}, {"excess_share", number_or_null(share)}});
  return {{"applies", applies},
          {"refused", refused.empty() ? nlohmann::json(nullptr) : nlohmann::json(refused)},
          {"refused_share", number_or_null(refused_share)},
          {"partial_share_rule", kPartialShare},
          {"tried", tried_json},
          {"where", where},
          {"stages", hystbench::to_json(stages)},
          {"advice", advice},
          {"judged_on", judged_on}};
}

namespace {

double number_of(const nlohmann::json& j) {
  return j.is_null() ? std::numeric_limits<double>::quiet_NaN() : j.get<double>();
}

TermStage stage_named(const std::string& name) {
  for (TermStage s : {TermStage::Input, TermStage::Static, TermStage::Dynamics, TermStage::Output})
    if (term_stage_name(s) == name) return s;
  throw InputError("unknown term stage \"" + name + "\"");
}

}  // namespace

BeyondCatalog BeyondCatalog::from_json(const nlohmann::json& j) {
  BeyondCatalog b;
  b.applies = j.at("applies").get<bool>();
  b.refused = j.at("refused").is_null() ? std::string() : j.at("refused").get<std::string>();
  b.refused_share = number_of(j.at("refused_share"));
  for (const auto& t : j.at("tried")) b.tried.emplace_back(t.at("effect").get<std::string>(), number_of(t.at("excess_share")));
  b.where = j.at("where").get<std::vector<std::string>>();
  for (const auto& l : j.at("stages"))
    b.stages.push_back({stage_named(l.at("stage").get<std::string>()),
                        l.at("term").is_null() ? std::string() : l.at("term").get<std::string>(),
                        number_of(l.at("share_of_residual"))});
  b.advice = j.at("advice").get<std::string>();
  b.judged_on = j.at("judged_on").get<std::string>();
  return b;
}

}  // namespace hystbench
