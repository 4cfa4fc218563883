// The CPU turtle against cpfg's own interpretation: corpus models whose strings hold query modules (?P, ?H,
// ?L, ?U) carry the turtle's position and vectors as cpfg computed them. Each expected string is read back
// into modules with the model's alphabet, its queries are refilled by simeco's turtle, and the values must
// agree with cpfg's.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "corpus.h"
#include "lang/load_grammar.h"
#include "stream/module_string.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"

namespace {

namespace fs = std::filesystem;

using simeco::test::kCorpus;

// Splits a cpfg string into the alphabet's modules, taking the longest name that matches at each place.
simeco::stream::ModuleString readString(const std::string& text, const simeco::ir::Alphabet& alphabet) {
    simeco::stream::ModuleString s;
    s.stride = 8;
    s.plantStart = {0};
    size_t longest = 0;
    for (const std::string& n : alphabet.names()) longest = std::max(longest, n.size());
    for (size_t i = 0; i < text.size();) {
        if (text[i] == '\n' || text[i] == '\r' || text[i] == ' ') {
            ++i;
            continue;
        }
        std::optional<simeco::ir::SymbolId> sym;
        size_t length = std::min(longest, text.size() - i);
        for (; length > 0 && !sym; --length) sym = alphabet.find(text.substr(i, length));
        if (!sym) throw std::runtime_error("no symbol of the alphabet at offset " + std::to_string(i));
        i += alphabet.name(*sym).size();
        std::vector<float> params;
        if (i < text.size() && text[i] == '(') {
            size_t close = text.find(')', i);
            std::stringstream list(text.substr(i + 1, close - i - 1));
            for (std::string value; std::getline(list, value, ',');) params.push_back(std::stof(value));
            i = close + 1;
        }
        s.push(*sym, params.data(), params.size());
    }
    s.plantStart.push_back(s.size());
    return s;
}

struct QueryModel {
    const char* folder;
    const char* file;
    const char* expected;
};

class TurtleQueries : public ::testing::TestWithParam<QueryModel> {};

TEST_P(TurtleQueries, MatchCpfg) {
    const QueryModel& m = GetParam();
    simeco::ir::Grammar g = simeco::lang::loadGrammarFile((kCorpus / "models" / m.folder / m.file).string());
    std::ifstream in(kCorpus / "expected" / m.expected);
    std::stringstream text;
    text << in.rdbuf();
    simeco::stream::ModuleString want = readString(text.str(), g.alphabet);
    simeco::stream::ModuleString got = want;
    simeco::turtle::TurtleCommands commands = simeco::turtle::turtleCommands(g.alphabet);
    // cpfg derived these strings without the models' view files: the positions show its default 45-degree
    // angle where the view files ask for others. So the turtle runs with the default view here.
    simeco::ir::Grammar defaults = g;
    defaults.view = {};
    std::vector<simeco::turtle::TurtleSettings> settings{simeco::turtle::turtleSettings(defaults, g.alphabet)};
    for (float& p : got.params) p = std::nanf(""); // only the queries get values back
    auto isQuery = [&](size_t i) { return i > 0 && g.alphabet.name(want.sym[i - 1]) == "?"; };
    for (size_t i = 0; i < got.size(); ++i)
        if (!isQuery(i)) std::copy(want.paramsOf(i), want.paramsOf(i) + want.stride, got.params.begin() + i * got.stride);
    simeco::turtle::fillQueries(got, commands, settings);

    size_t queries = 0, differences = 0;
    for (size_t i = 0; i < want.size(); ++i) {
        if (!isQuery(i)) continue;
        ++queries;
        for (size_t k = 0; k < want.paramCount[i]; ++k) {
            float a = want.paramsOf(i)[k], b = got.paramsOf(i)[k];
            if (std::abs(a - b) <= 1e-3f * std::max(1.0f, std::abs(a))) continue;
            if (++differences <= 5)
                ADD_FAILURE() << m.expected << ": module " << i << " ?" << g.alphabet.name(want.sym[i])
                              << " parameter " << k << ": cpfg " << a << ", simeco " << b;
        }
    }
    EXPECT_GT(queries, 0u) << "the string holds no query module";
    EXPECT_EQ(differences, 0u) << "of " << queries << " query modules";
}

// Models whose queried modules do not move once queried: cpfg fills queries by interpreting the string
// between steps, so a string's query values describe the previous step's geometry, and only where that geometry
// stays put do they equal the final string's. (query-position, topiary and patterns grow past their queries.)
INSTANTIATE_TEST_SUITE_P(Corpus, TurtleQueries,
                         ::testing::Values(QueryModel{"06-Enviro-sensitive/ellipse", "plant.l",
                                                      "06-Enviro-sensitive_ellipse.str"}),
                         [](const ::testing::TestParamInfo<QueryModel>& param) {
                             return fs::path(param.param.folder).filename().string();
                         });

} // namespace
