// Random cpfg L-systems for differential tests of the GPU derivation against the CPU reference engine.
//
// A seed gives one `.l` text: a random alphabet with a fixed parameter count per symbol, parametric
// productions with left and right contexts (branches included), `ignore:`, conditions and statement blocks,
// stochastic factors, deletions, cuts, `ran()` and a decomposition section. Strings stay small (a few
// thousand modules) and parameter values bounded, so that float and double evaluation agree within rounding.
// Everything the generator writes is order-independent: no global is written and no local is read before
// it is assigned.
#pragma once

#include <cstdint>
#include <string>

namespace simeco::test {

// The text of a random cpfg `.l` file; the same seed gives the same text on every platform.
std::string randomGrammarText(std::uint64_t seed);

} // namespace simeco::test
