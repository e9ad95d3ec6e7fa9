// The hidden-effect cases of the discovery workflow
// (docs/discovery.md#discovery-workflow), read
// from benchmarks/experiments/hidden_effects.json: data are simulated from a
// known model that has one effect more than the start model (two in the
// two-effect case, none in the `none` case). Each case asserts that
//   - the hidden effect really changes the output (several noise sd), so the
//     case can only pass by finding it;
//   - the diagnosis of the fitted start model names it (the first rung of
//     discover is exactly `diagnose` of the start fit), or says "none";
//   - discover ends with every hidden effect in the model and no effect the
//     data do not have, without hitting its step limit, at a held-out RMSE
//     within 1.2 times the true noise sd.
// The records are the case file's short `test_excitation` (about 6 800
// samples); benchmarks/hidden_effects.sh runs the same cases at full size.
// Fits use the library's default budgets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "framework/core/text.hpp"
#include "framework/discovery/ladder.hpp"
#include "framework/discovery/separability.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/model/holdout.hpp"

namespace hystbench {
namespace {

const std::string kCaseFile =
    std::string(HYSTBENCH_SOURCE_DIR) + "/benchmarks/experiments/hidden_effects.json";

nlohmann::json read_case_file() {
  std::ifstream in(kCaseFile);
  if (!in) return nlohmann::json::object();
  return nlohmann::json::parse(in);
}

struct HiddenCase {
  std::string effect;
  nlohmann::json spec;
};

// gtest prints a parameter in failure messages and test listings.
void PrintTo(const HiddenCase& c, std::ostream* os) { *os << c.effect; }

// Cases marked "in_test_suite": false stay in the file (with their reason)
// but are not instantiated here.
std::vector<HiddenCase> suite_cases() {
  std::vector<HiddenCase> out;
  const nlohmann::json file = read_case_file();
  for (const auto& c : file.value("cases", nlohmann::json::array()))
    if (c.value("in_test_suite", true)) out.push_back({c.at("effect").get<std::string>(), c});
  return out;
}

std::string test_name(const testing::TestParamInfo<HiddenCase>& info) {
  std::string name = info.param.effect;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

// Physical values of `start` taken from the truth's values: the same name,
// or the same parameter of an effect that extends the start's effect
// (feedback_hysteresis.period for msd.period).
nlohmann::json start_values(const Model& start, const Model& truth, const nlohmann::json& values) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& name : start.parameter_names()) {
    if (values.contains(name)) {
      out[name] = values[name];
      continue;
    }
    const auto dot = name.find('.');
    const std::string effect = name.substr(0, dot), param = name.substr(dot + 1);
    for (const auto& e : truth.effects())
      if (EffectRegistry::instance().find(e, "effect").extends == effect &&
          values.contains(e + "." + param))
        out[name] = values[e + "." + param];
  }
  return out;
}

class HiddenEffectTest : public testing::TestWithParam<HiddenCase> {};

TEST(HiddenEffectFile, EveryCatalogEffectHasACase) {
  const nlohmann::json file = read_case_file();
  ASSERT_TRUE(file.contains("cases")) << "cannot read " << kCaseFile;
  std::vector<std::string> effects;
  for (const auto& c : file["cases"]) effects.push_back(c.at("effect").get<std::string>());
  for (const auto* info : EffectRegistry::instance().all())
    EXPECT_NE(std::find(effects.begin(), effects.end(), info->name), effects.end())
        << "no hidden-effect case for " << info->name;
  EXPECT_NE(std::find(effects.begin(), effects.end(), "none"), effects.end());
  // A case left out of the test suite must say why.
  for (const auto& c : file["cases"]) {
    if (!c.value("in_test_suite", true)) {
      EXPECT_FALSE(c.value("reason", std::string()).empty()) << c.dump();
    }
  }
}

// The nesting invariant (framework/discovery/pruning.hpp): every rung fits
// the estimation data at least as well as each model with one effect less
// tried while pruning it, and as the rung before when it contains that rung.
void expect_nested_models_fit_at_least_as_well(const Ladder& ladder) {
  const double margin = 1.0 + kNestingTolerance;
  for (std::size_t k = 0; k < ladder.steps.size(); ++k) {
    const LadderStep& s = ladder.steps[k];
    for (const auto& sub : s.sub_models) {
      EXPECT_LE(s.errors.sse, sub.sse * margin) << "step " << k << ": " << s.model.text() << " against " << sub.model;
    }
    if (k == 0) continue;
    const LadderStep& before = ladder.steps[k - 1];
    const auto effects = before.model.effects();
    if (std::all_of(effects.begin(), effects.end(), [&](const std::string& e) { return s.model.has(e); })) {
      EXPECT_LE(s.errors.sse, before.errors.sse * margin) << "step " << k << " against step " << k - 1;
    }
  }
}

TEST_P(HiddenEffectTest, DiagnosedAndDiscovered) {
  const auto started = std::chrono::steady_clock::now();
  const nlohmann::json file = read_case_file();
  const nlohmann::json& c = GetParam().spec;
  const auto hidden = c.at("hidden").get<std::vector<std::string>>();
  const Model truth = Model::parse(c.at("truth").get<std::string>(), "truth");
  const Model start = Model::parse(c.at("start").get<std::string>(), "start");
  const nlohmann::json& excitation = file.at("test_excitation");
  const auto seed = c.at("seed").get<std::uint64_t>();

  const SyntheticData s = make_model_synthetic_data(truth, c.at("values"), excitation,
                                                    c.at("noise").get<double>(), seed, "case");
  const double sd = s.truth["noise"]["sd"].get<double>();
  ASSERT_GT(sd, 0.0);

  // How much the hidden effect changes the noise-free output.
  const SyntheticData clean = make_model_synthetic_data(truth, c.at("values"), excitation, 0.0, seed, "case");
  const SyntheticData without = make_model_synthetic_data(
      start, start_values(start, truth, c.at("values")), excitation, 0.0, seed, "case");
  const double effect_rms =
      std::sqrt((clean.data.y - without.data.y).squaredNorm() / double(clean.data.y.size()));
  if (hidden.empty()) {
    EXPECT_EQ(effect_rms, 0.0);
  } else {
    EXPECT_GT(effect_rms, 2.0 * sd) << "the hidden effect barely shows in these data";
  }

  ModelData data(s.data, SignalScales::of(s.data));
  apply_holdout(data, HoldoutSpec{});
  ASSERT_GT(data.heldout_count(), 0);

  DiscoverOptions options;
  options.diagnose.fit.seed = seed;
  const Ladder ladder = discover(start, data, options);
  ASSERT_FALSE(ladder.diagnoses.empty());

  const std::string first_verdict = ladder.diagnoses.front().verdict;
  const auto final_effects = ladder.final_effects();
  const LadderStep& last = ladder.steps.back();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::string path;
  std::size_t nesting_refits = 0;
  for (const auto& step : ladder.steps) {
    path += step.added.empty() ? start.text() : " +" + step.added;
    nesting_refits += step.nesting.size();
  }
  std::printf("[ %-19s] %ld samples, effect RMS %.2f sd; first verdict %s; ladder %s; "
              "held-out RMSE %.4g = %.3f sd; nesting refits %zu; %.1f s\n",
              GetParam().effect.c_str(), long(data.size()), effect_rms / sd, first_verdict.c_str(),
              path.c_str(), last.errors.rmse_heldout, last.errors.rmse_heldout / sd, nesting_refits, seconds);
  expect_nested_models_fit_at_least_as_well(ladder);
  RecordProperty("seconds", std::to_string(seconds));

  if (hidden.empty()) {
    EXPECT_EQ(first_verdict, "none");
    EXPECT_EQ(final_effects, start.effects());
  } else {
    EXPECT_NE(std::find(hidden.begin(), hidden.end(), first_verdict), hidden.end())
        << "diagnosis of " << start.text() << " named " << first_verdict;
    for (const auto& effect : hidden)
      EXPECT_NE(std::find(final_effects.begin(), final_effects.end(), effect), final_effects.end())
          << "discover ended with " << last.model.text() << " without " << effect;
  }
  for (const auto& effect : final_effects)
    EXPECT_TRUE(truth.has(effect)) << "discover ended with " << last.model.text() << ": " << effect
                                   << " is not in the data (truth " << truth.text() << ")";
  EXPECT_FALSE(ladder.stopped_by_limit);
  EXPECT_EQ(ladder.diagnoses.back().verdict, "none");
  EXPECT_LE(last.errors.rmse_heldout, 1.2 * sd);
}

// One frequency at one amplitude after a rest with a sensor offset, as a
// lab's first recording often is: a linear lag draws the same ellipse as
// the hysteresis loop there, so discovery must not drop the start model's
// hysteresis on this record, must say why it cannot confirm it, and must
// find the offset at rest.
TEST(SingleFrequency, DiscoveryKeepsHysteresisAndSaysWhyTheRecordCannotConfirmIt) {
  const Model truth = Model::parse("hysteresis,msd,offset");
  const nlohmann::json values = {{"gain", 0.12},          {"hysteresis.A", 0.025}, {"hysteresis.beta", 0.006},
                                 {"hysteresis.gamma", 0.001}, {"msd.period", 0.022},   {"msd.zeta", 0.12},
                                 {"offset.c0", -1.7}};
  const nlohmann::json excitation = {
      {"sample_rate", 1000},
      {"segments", {{{"type", "sine"}, {"frequency", 1}, {"amplitude", 0}, {"duration", 1}, {"label", "rest"}},
                    {{"type", "sine"}, {"frequency", 1}, {"amplitude", 80}, {"duration", 5}, {"label", "sine"}}}}};
  const SyntheticData s = make_model_synthetic_data(truth, values, excitation, 0.01, 7, "single frequency");
  ModelData data(s.data, SignalScales::of(s.data));
  apply_holdout(data, HoldoutSpec{});
  DiscoverOptions options;
  options.diagnose.fit.seed = 7;
  const Ladder ladder = discover(Model::parse("hysteresis,asymmetry,msd"), data, options);
  const auto final_effects = ladder.final_effects();
  const auto has = [&](const std::string& e) {
    return std::find(final_effects.begin(), final_effects.end(), e) != final_effects.end();
  };
  std::string trace;
  for (const auto& step : ladder.steps)
    trace.append("\n").append(step.model.text()).append(" (+").append(step.added).append(", −")
        .append(join(step.removed, ",")).append("): ").append(step.attribution);
  std::printf("[ single frequency ] ladder:%s\n", trace.c_str());
  EXPECT_TRUE(has("hysteresis")) << trace;
  EXPECT_TRUE(has("offset")) << trace;
  const ExcitationContent& e = ladder.diagnoses.back().where.excitation;
  EXPECT_FALSE(e.meets(ExcitationNeed::SeveralFrequencies)) << e.summary();
  const auto pairs = inseparable_pairs(final_effects, e);
  ASSERT_FALSE(pairs.empty()) << "nothing said about what the record cannot tell apart";
  EXPECT_EQ(pairs.front().effect, "hysteresis");
  EXPECT_NE(pairs.front().sentence(e).find("three frequencies over a decade"), std::string::npos);
  expect_nested_models_fit_at_least_as_well(ladder);
}

INSTANTIATE_TEST_SUITE_P(HiddenEffect, HiddenEffectTest, testing::ValuesIn(suite_cases()), test_name);

}  // namespace
}  // namespace hystbench
