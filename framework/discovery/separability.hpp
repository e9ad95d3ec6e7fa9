#pragma once
// Which effects of a model the record cannot tell apart. Some effects can
// carry each other's role (EffectInfo::rivals): at one frequency a
// rate-independent loop and a linear lag draw the same ellipse, and at one
// amplitude a saturation and an asymmetry bend the same loop. When the
// record does not excite what separates a pair, a fit that prefers one of
// them says nothing about the physics, so discovery prunes no start effect
// on that evidence, marks an addition's evidence with it, and says what to
// record instead (docs/discovery.md, "What the record can tell apart").
#include <string>
#include <vector>

#include "framework/discovery/excitation_content.hpp"

namespace hystbench {

struct Inseparable {
  std::string effect, rival;
  ExcitationNeed need = ExcitationNeed::SeveralFrequencies;
  // "The record cannot tell hysteresis from msd: either can carry the
  // other's role unless the record holds several frequencies, and this one
  // holds one frequency (1 Hz). To tell them apart, record …"
  std::string sentence(const ExcitationContent& e) const;
};

// The rivals of `effect` among `others` that `e` cannot separate from it,
// from either side's declaration. `effect` itself is skipped in `others`.
std::vector<Inseparable> inseparable_from(const std::string& effect, const std::vector<std::string>& others,
                                          const ExcitationContent& e);

// The effects among `others` that can carry `effect`'s role (either side's
// declaration), whatever the record.
std::vector<std::string> rivals_among(const std::string& effect, const std::vector<std::string>& others);

// Every such pair within `effects`, each once.
std::vector<Inseparable> inseparable_pairs(const std::vector<std::string>& effects, const ExcitationContent& e);

}  // namespace hystbench
