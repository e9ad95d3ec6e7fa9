#pragma once
// From a proposed term to an effect plugin (docs/discovery.md#proposing-a-missing-term):
// the source of one .cpp with the registration macro that builds out of the
// tree like any user effect (docs/plugins.md#out-of-the-tree-a-shared-library),
// so that `discover --plugin` can add the term and refit it with the rest.
//
// The effect adds c·f(a)·g(a') where the proposal says the term enters:
//   input, static, output   a = the stage input (u, v, or the dynamics'
//                           output), added to the signal of that stage
//   static, of w            a = the signal the effect is handed: the static
//                           block's output so far (the effect is appended
//                           to the block; a static effect added after it
//                           acts on w + c·f(w)·g(w'))
//   dynamics                a force inside the mass-spring-damper: the effect
//                           extends msd (same period and zeta) and adds
//                           c·f(x)·g(x') to its input, x its own output at
//                           the same sample (an implicit step)
//
// or a product of two signals its block sees, each to the first power or
// its rate: v and w in the static block (c·a(w)·b(v) added to w), w and x in
// the dynamics (the force c·a(x)·b(w)). A force's factor of the drive v is
// written with w when the static block is the gain alone (w = gain·v, c
// divided by the gain); other products (an output effect sees only y) are
// written by hand.
// c = 0 leaves the signal exactly as it was (for the dynamics form: exactly
// as msd leaves it). The bounds of c are ten times the proposed value
// either way; its citation says it was proposed from data.
#include <string>

#include "framework/discovery/proposal.hpp"

namespace hystbench {

struct EffectSourceContext {
  std::string name;       // the effect's catalog name: [a-z][a-z0-9_]*
  std::string data_name;  // the measurement it was proposed from
  std::string model;      // the fitted model's effects
  double gain = 1.0;      // its fitted gain (normalised), for a product written with w for v
};

// Throws InputError for a bad name, for a term of neither form above (a play
// operator, a product the block cannot see: those effects are written by
// hand), and for a dynamics term when the model has no msd to extend.
std::string proposed_effect_source(const ProposedTerm& term, const EffectSourceContext& context);

// The CMakeLists.txt that builds it as NAME.so with find_package(hystbench).
std::string proposed_effect_cmake(const std::string& name);

// The name, when it is a valid catalog name not already registered; throws
// InputError otherwise.
void check_effect_name(const std::string& name);

}  // namespace hystbench
