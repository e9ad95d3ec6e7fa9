#pragma once
// proposals.md: the ranked terms a researcher can test, each with where it
// enters, its coefficient and how much of the residual it explains; what
// stopped the choice; and how to try the first one as an effect.
#include <string>

#include "framework/discovery/proposal.hpp"

namespace hystbench {

// The generated effect, when one was written: its name and the model to
// fit with it (the fitted model with the effect added, or in place of msd).
struct GeneratedEffect {
  std::string name, model;  // empty when none was written
  std::string not_written;  // why not, when there was a term to write
};

std::string proposal_markdown(const Proposal& p, const std::string& data_name, const std::string& y_unit,
                              const GeneratedEffect& effect);

}  // namespace hystbench
