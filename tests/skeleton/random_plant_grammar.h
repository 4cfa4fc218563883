// Random bracketed L-systems that draw plants: an apex A (and a second kind B) that put out segments F(l),
// turns + - & ^ / \ by angles of their own, width changes !(w) and branches, derived a few steps.
#pragma once

#include <cstdint>
#include <string>

namespace simeco::test {

// The cpfg text of random plant grammar `seed` (the same seed, the same text).
std::string randomPlantGrammar(uint64_t seed);

} // namespace simeco::test
