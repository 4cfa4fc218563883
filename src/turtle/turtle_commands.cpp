#include "turtle/turtle_commands.h"

#include <string_view>
#include <unordered_map>

#include "compute/shared/turtle_layout.h"

namespace simeco::turtle {

using namespace shared;

namespace {

uint32_t plainCommand(std::string_view name) {
    static const std::unordered_map<std::string_view, uint32_t> kCommands = {
        {"[", kTurtleBranchOpen},     {"]", kTurtleBranchClose},   {"F", kTurtleDraw},
        {"G", kTurtleDrawNoVertex},   {"f", kTurtleMove},          {"g", kTurtleMoveNoVertex},
        {"+", kTurtleTurnLeft},       {"-", kTurtleTurnRight},     {"&", kTurtlePitchDown},
        {"^", kTurtlePitchUp},        {"\\", kTurtleRollLeft},     {"/", kTurtleRollRight},
        {"|", kTurtleTurnAround},     {"$", kTurtleRollLevel},     {"#", kTurtleWidthUp},
        {"!", kTurtleWidthDown},      {";", kTurtleColorUp},       {",", kTurtleColorDown},
        {"{", kTurtlePolygonBegin},   {"}", kTurtlePolygonEnd},    {".", kTurtlePolygonVertex},
        {"rotx", kTurtleRotateWorldX}, {"roty", kTurtleRotateWorldY}, {"rotz", kTurtleRotateWorldZ},
        {"rotr", kTurtlePitchRadians}, {"rotu", kTurtleRollRadians}, {"_", kTurtleElasticityStep},
        {"tropism", kTurtleTropism}, {"alive", kTurtleAlive}, {"phototropism", kTurtlePhototropism},
        {"tilt", kTurtleTilt}, {"?", kTurtleSubLsystemCall},
    };
    auto it = kCommands.find(name);
    return it == kCommands.end() ? kTurtleNone : it->second;
}

uint32_t atCommand(std::string_view name) {
    static const std::unordered_map<std::string_view, uint32_t> kCommands = {
        {"O", kTurtleSphere},       {"c", kTurtleDisc},          {"o", kTurtleDiscFacing},
        {"M", kTurtleSetPosition},  {"R", kTurtleSetHeading},    {"v", kTurtleRollUpright},
        {"D", kTurtleScaleSet},     {"T", kTurtleElasticityUp},  {"!", kTurtleIgnored},
        {"#", kTurtleContour},      {";", kTurtleIgnored},       {",", kTurtleIgnored},
        {"L", kTurtleIgnored},      {"I", kTurtleIgnored},
    };
    auto it = kCommands.find(name);
    return it == kCommands.end() ? kTurtleNone : it->second;
}

uint32_t pairPrefixOf(std::string_view name) {
    if (name == "G") return kPairG;
    if (name == "T") return kPairT;
    if (name == "D") return kPairD;
    if (name == "b") return kPairB;
    if (name == "P") return kPairP;
    return kPairNone;
}

uint32_t pairCommand(uint32_t prefix, std::string_view name) {
    switch (prefix) {
    case kPairG:
        if (name == "s") return kTurtleCylinderStart;
        if (name == "c" || name == "e") return kTurtleCylinderPoint;
        if (name == "t") return kTurtleCylinderTangents;
        if (name == "r") return kTurtleRadiusTangents;
        break;
    case kPairT:
        if (name == "s") return kTurtleElasticitySet;
        if (name == "i") return kTurtleElasticityUp;
        if (name == "d") return kTurtleElasticityDown;
        if (name == "p" || name == "f" || name == "x") return kTurtleIgnored;
        break;
    case kPairD:
        if (name == "i") return kTurtleScaleUp;
        if (name == "d") return kTurtleScaleDown;
        break;
    case kPairB:
        if (name == "o") return kTurtleDiscFacing;
        if (name == "c") return kTurtleDisc;
        break;
    case kPairP:
        if (name == "S" || name == "C" || name == "D") return kTurtleIgnored;
        break;
    default: break;
    }
    return kTurtleNone;
}

uint32_t queryCommand(std::string_view name) {
    if (name == "P") return kTurtleQueryPosition;
    if (name == "H") return kTurtleQueryHeading;
    if (name == "L") return kTurtleQueryLeft;
    if (name == "U") return kTurtleQueryUp;
    if (name == "E") return kTurtleQueryEnvironment;
    return kTurtleIgnored; // other environment queries
}

} // namespace

TurtleCommands turtleCommands(const ir::Alphabet& alphabet) {
    TurtleCommands t;
    t.symbols = uint32_t(alphabet.size());
    t.plain.resize(t.symbols);
    t.afterAt.resize(t.symbols);
    t.afterQuery.resize(t.symbols);
    t.pairPrefix.resize(t.symbols);
    t.pairs.assign(size_t(kPairPrefixes) * t.symbols, kTurtleNone);
    for (uint32_t s = 0; s < t.symbols; ++s) {
        const std::string& name = alphabet.name(s);
        t.plain[s] = plainCommand(name);
        t.afterAt[s] = atCommand(name);
        t.afterQuery[s] = queryCommand(name);
        t.pairPrefix[s] = pairPrefixOf(name);
        for (uint32_t p = 0; p < kPairPrefixes; ++p) t.pairs[p * t.symbols + s] = pairCommand(p, name);
        if (name == "@") t.at = s;
        if (name == "~") t.tilde = s;
        if (name == "?") t.query = s;
    }
    return t;
}

uint32_t TurtleCommands::commandAt(const stream::ModuleString& s, size_t begin, size_t end, size_t i) const {
    uint32_t sym = s.sym[i];
    if (sym >= symbols) return kTurtleNone;
    if (i == begin) return plain[sym];
    uint32_t previous = s.sym[i - 1];
    if (previous == at) {
        uint32_t prefix = pairPrefix[sym];
        if (prefix != kPairNone && s.paramCount[i] == 0 && i + 1 < end && s.sym[i + 1] < symbols &&
            pairs[prefix * symbols + s.sym[i + 1]] != kTurtleNone)
            return kTurtleNone; // the first letter of a two-letter command
        return afterAt[sym];
    }
    if (i >= begin + 2 && s.sym[i - 2] == at && previous < symbols && pairPrefix[previous] != kPairNone &&
        s.paramCount[i - 1] == 0) {
        uint32_t pair = pairs[pairPrefix[previous] * symbols + sym];
        if (pair != kTurtleNone) return pair;
    }
    if (previous == tilde) return shared::kTurtleSurface;
    if (previous == query && s.paramCount[i - 1] == 0) return afterQuery[sym]; // `?(label, s)` is a call
    return plain[sym];
}

} // namespace simeco::turtle
