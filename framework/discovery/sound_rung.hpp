#pragma once
// The rung of a ladder that `propose` extends (docs/discovery.md, "Proposing
// from a sound model"). A ladder may take on a catalog effect the data do
// not support on its way to "beyond the catalog"; the residual of that
// model is bent by the doubtful effect, and a regression on it finds the
// term that undoes the bend rather than the missing physics. So propose
// starts from the last rung before the first doubtful addition.
//
// An added effect is doubtful when, at the rung that took it on,
//  - a parameter of it sits on a bound of its search range: it is stretched
//    to draw something its physics does not hold; or
//  - the record cannot tell it from a rival already in the model
//    (separability.hpp): which of the two carries the role is unknown.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/discovery/ladder.hpp"

namespace hystbench {

struct SoundRung {
  std::size_t step = 0;
  std::string model = {};
  std::string doubtful = {};  // the first doubtful addition; "" when every one is supported
  std::string why = {};       // why it is doubtful

  // "propose extends step 1 (hysteresis,msd): step 2 took on creep, which
  // the data do not support: creep.tau sits on a bound of its search range."
  std::string sentence() const;
  std::string fit_file() const { return "step_" + std::to_string(step) + "/fit.json"; }
  nlohmann::json to_json() const;
};

SoundRung sound_rung(const Ladder& ladder);

}  // namespace hystbench
