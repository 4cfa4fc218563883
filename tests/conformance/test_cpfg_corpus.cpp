// Conformance with cpfg: every model of the shared corpus is derived by the CPU reference engine from its own
// folder. `exact` models must reproduce cpfg's string (names exactly, parameters within 1e-5 relative);
// `structure` models must derive without error into a plausible string.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "corpus.h"
#include "cpu/derive.h"
#include "lang/load_grammar.h"

namespace {

namespace fs = std::filesystem;

// A module of a cpfg string: one character (or a UTF-8 sequence) and its parameters.
struct ParsedModule {
    std::string name;
    std::vector<double> params;
};

std::vector<ParsedModule> parseCpfgString(const std::string& s) {
    std::vector<ParsedModule> out;
    for (size_t i = 0; i < s.size();) {
        if (s[i] == '\n' || s[i] == '\r') {
            ++i;
            continue;
        }
        ParsedModule m;
        m.name = s.substr(i, 1);
        ++i;
        if (i < s.size() && s[i] == '(') {
            size_t close = s.find(')', i);
            std::stringstream list(s.substr(i + 1, close - i - 1));
            for (std::string value; std::getline(list, value, ',');) m.params.push_back(std::stod(value));
            i = close + 1;
        }
        out.push_back(std::move(m));
    }
    return out;
}

using CorpusTest = simeco::test::ScratchFolderTest;
using simeco::test::CorpusModel;
using simeco::test::kCorpus;
using simeco::test::readManifest;

std::string describeDifference(const std::vector<ParsedModule>& want, const std::vector<ParsedModule>& got) {
    if (want.size() != got.size())
        return "module count " + std::to_string(got.size()) + ", expected " + std::to_string(want.size());
    for (size_t i = 0; i < want.size(); ++i) {
        const ParsedModule& a = want[i];
        const ParsedModule& b = got[i];
        bool same = a.name == b.name && a.params.size() == b.params.size();
        for (size_t k = 0; same && k < a.params.size(); ++k)
            same = std::fabs(a.params[k] - b.params[k]) <= 1e-5 * std::max(1.0, std::fabs(a.params[k]));
        if (!same) return "first difference at module " + std::to_string(i) + " (" + b.name + " vs " + a.name + ")";
    }
    return {};
}

TEST_F(CorpusTest, ExactModelsMatchCpfgAndStructureModelsDerive) {
    std::vector<CorpusModel> models = readManifest();
    ASSERT_GE(models.size(), 60u) << "the corpus manifest was not found or is incomplete at " << kCorpus;
    int exactTotal = 0, exactMatched = 0, structureDerived = 0;
    std::vector<std::string> mismatches;
    for (const CorpusModel& model : models) {
        fs::path file = kCorpus / "models" / model.folder / model.file;
        SCOPED_TRACE(model.folder);
        std::vector<ParsedModule> got;
        try {
            simeco::ir::Grammar g = simeco::lang::loadGrammarFile(file.string());
            simeco::stream::DeriveResult result = simeco::cpu::deriveCpu(g, {});
            got = parseCpfgString(simeco::stream::formatModules(result.string, g.alphabet, 0, result.string.size()));
        } catch (const simeco::ir::InputError& e) {
            ADD_FAILURE() << model.folder << ": " << e.formatted();
            continue;
        } catch (const std::exception& e) {
            ADD_FAILURE() << model.folder << ": " << e.what();
            continue;
        }
        if (model.compare == "exact") {
            ++exactTotal;
            std::string expectedName = model.folder;
            std::replace(expectedName.begin(), expectedName.end(), '/', '_');
            std::ifstream in(kCorpus / "expected" / (expectedName + ".str"));
            ASSERT_TRUE(in) << "missing expected string for " << model.folder;
            std::stringstream expected;
            expected << in.rdbuf();
            std::string difference = describeDifference(parseCpfgString(expected.str()), got);
            if (difference.empty()) ++exactMatched;
            else mismatches.push_back(model.folder + ": " + difference);
        } else {
            // Plausible structure: balanced brackets and more than the axiom's first module.
            int depth = 0;
            bool balanced = true;
            for (const ParsedModule& m : got) {
                depth += m.name == "[" ? 1 : m.name == "]" ? -1 : 0;
                balanced = balanced && depth >= 0;
            }
            EXPECT_TRUE(balanced && depth == 0) << model.folder << ": unbalanced brackets";
            EXPECT_FALSE(got.empty()) << model.folder << ": empty string";
            ++structureDerived;
        }
    }
    for (const std::string& m : mismatches) std::printf("not matching cpfg: %s\n", m.c_str());
    std::printf("exact models matching cpfg: %d of %d; structure models derived: %d\n", exactMatched, exactTotal,
                structureDerived);
    EXPECT_EQ(exactTotal, 44);
    EXPECT_GE(exactMatched, 40);
}

// A nested folder (a model inside another model's folder) must also be found through the manifest.
TEST(CorpusManifest, ListsModelsThatExist) {
    std::vector<CorpusModel> models = readManifest();
    ASSERT_FALSE(models.empty());
    for (const CorpusModel& model : models)
        EXPECT_TRUE(fs::exists(kCorpus / "models" / model.folder / model.file)) << model.folder;
}

} // namespace
