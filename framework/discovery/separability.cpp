#include "framework/discovery/separability.hpp"

#include <algorithm>
#include <optional>

namespace hystbench {
namespace {

// What separates `a` from `b`, if either declares the other a rival.
std::optional<ExcitationNeed> declared_rivalry(const std::string& a, const std::string& b) {
  const auto& registry = EffectRegistry::instance();
  for (const auto& [x, y] : {std::pair{a, b}, std::pair{b, a}})
    for (const auto& r : registry.find(x, "effect").rivals)
      if (r.effect == y) return r.need;
  return std::nullopt;
}

// The same, where an effect also inherits the rivals of the effect it
// generalises (EffectInfo::extends: a Bouc-Wen oscillator can carry
// whatever the msd it replaces can).
std::optional<ExcitationNeed> rivalry(const std::string& a, const std::string& b) {
  const auto& registry = EffectRegistry::instance();
  const std::string& a_base = registry.find(a, "effect").extends;
  const std::string& b_base = registry.find(b, "effect").extends;
  for (const auto& x : {a, a_base})
    for (const auto& y : {b, b_base})
      if (!x.empty() && !y.empty() && x != y)
        if (const auto need = declared_rivalry(x, y)) return need;
  return std::nullopt;
}

}  // namespace

std::string Inseparable::sentence(const ExcitationContent& e) const {
  return "The record cannot tell " + effect + " from " + rival +
         ": either can carry the other's role unless the record holds " + need_text(need) + ", and this one holds " +
         e.holds(need) + ". To tell them apart, " + excitation_advice(need) + ".";
}

std::vector<Inseparable> inseparable_from(const std::string& effect, const std::vector<std::string>& others,
                                          const ExcitationContent& e) {
  std::vector<Inseparable> out;
  for (const auto& other : others) {
    if (other == effect) continue;
    const auto need = rivalry(effect, other);
    if (need && !e.meets(*need)) out.push_back({effect, other, *need});
  }
  return out;
}

std::vector<std::string> rivals_among(const std::string& effect, const std::vector<std::string>& others) {
  std::vector<std::string> out;
  for (const auto& other : others)
    if (other != effect && rivalry(effect, other)) out.push_back(other);
  return out;
}

std::vector<Inseparable> inseparable_pairs(const std::vector<std::string>& effects, const ExcitationContent& e) {
  std::vector<Inseparable> out;
  for (std::size_t i = 0; i < effects.size(); ++i) {
    const std::vector<std::string> later(effects.begin() + std::ptrdiff_t(i) + 1, effects.end());
    for (auto& p : inseparable_from(effects[i], later, e)) out.push_back(std::move(p));
  }
  return out;
}

}  // namespace hystbench
