// What each module of a string does to the turtle (compute/shared/turtle_layout.h): cpfg's predefined modules, `~`
// surfaces, queries and SimEco's rotations. A module's command depends on its symbol and on the one or two
// modules before it (`@` `O(d)` is a sphere, a lone `O` nothing), so the tables below are looked up per
// symbol and per prefix; the turtle kernels read the same tables.
#pragma once

#include <cstdint>
#include <vector>

#include "ir/grammar.h"
#include "stream/module_string.h"

namespace simeco::turtle {

inline constexpr uint32_t kNoSymbol = 0xFFFFFFFFu;

struct TurtleCommands {
    uint32_t symbols = 0;
    std::vector<uint32_t> plain;      // per symbol: its command on its own
    std::vector<uint32_t> afterAt;    // per symbol: its command right after `@`
    std::vector<uint32_t> afterQuery; // per symbol: its command right after `?`
    std::vector<uint32_t> pairPrefix; // per symbol: kPair* when `@` and it may begin a two-letter command
    std::vector<uint32_t> pairs;      // kPairPrefixes rows of symbols: the command of `@`, prefix, symbol
    uint32_t at = kNoSymbol, tilde = kNoSymbol, query = kNoSymbol;

    // The command of module i of a plant's modules [begin, end).
    uint32_t commandAt(const stream::ModuleString& s, size_t begin, size_t end, size_t i) const;
};

TurtleCommands turtleCommands(const ir::Alphabet& alphabet);

} // namespace simeco::turtle
