#include "framework/discovery/sound_rung.hpp"

#include "framework/core/text.hpp"
#include "framework/discovery/separability.hpp"

namespace hystbench {
namespace {

// Why the effect added at rung k is doubtful, "" when the data support it
// (or it was dropped again, so the rung took nothing on).
std::string why_doubtful(const Ladder& ladder, std::size_t k) {
  const LadderStep& s = ladder.steps[k];
  if (s.added.empty() || !s.model.has(s.added)) return "";
  const Diagnosis& d = ladder.diagnoses[k];
  for (const auto& e : d.check.effects)
    if (e.effect == s.added && !e.at_bound.empty())
      return join(e.at_bound, ", ") + (e.at_bound.size() == 1 ? " sits" : " sit") +
             " on a bound of the search range";
  const auto pairs = inseparable_from(s.added, ladder.steps[k - 1].model.effects(), d.where.excitation);
  if (!pairs.empty()) return "the record cannot tell it from " + pairs.front().rival;
  return "";
}

}  // namespace

SoundRung sound_rung(const Ladder& ladder) {
  const std::size_t rungs = std::min(ladder.steps.size(), ladder.diagnoses.size());
  for (std::size_t k = 1; k < rungs; ++k) {
    const std::string why = why_doubtful(ladder, k);
    if (!why.empty()) return {k - 1, ladder.steps[k - 1].model.text(), ladder.steps[k].added, why};
  }
  return {rungs - 1, ladder.steps[rungs - 1].model.text()};
}

std::string SoundRung::sentence() const {
  const std::string from = "propose extends step " + std::to_string(step) + " (" + model + ")";
  if (doubtful.empty() && step == 0) return from + ", the start model: the ladder added nothing.";
  if (doubtful.empty()) return from + ", the last rung: the data support every effect it added.";
  return from + ": step " + std::to_string(step + 1) + " took on " + doubtful +
         ", which the data do not support (" + why + "), and a residual bent by it would point at the term "
         "that undoes the bend rather than at the missing physics.";
}

nlohmann::json SoundRung::to_json() const {
  return {{"step", step},
          {"model", model},
          {"fit", fit_file()},
          {"doubtful", doubtful.empty() ? nlohmann::json(nullptr) : nlohmann::json(doubtful)},
          {"why", why},
          {"sentence", sentence()}};
}

}  // namespace hystbench
