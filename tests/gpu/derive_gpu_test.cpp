// The GPU derivation against the CPU reference engine: the example grammars, the cpfg corpus, random grammars
// and many plants at once must give the same modules, with parameters equal within float rounding.
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../unit/grammar_text.h"
#include "codegen/derive_codegen.h"
#include "compare_strings.h"
#include "compute/shared/derive_layout.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/source_loc.h"
#include "lang/load_grammar.h"
#include "random_grammar.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

const fs::path kGrammars = fs::path(SIMECO_SOURCE_DIR) / "grammars";
const fs::path kCorpus = fs::path(SIMECO_SHARED_DIR) / "corpus" / "cpfg-vlab";

// Random grammars keep below this; a grammar that outgrows it is skipped, not failed.
constexpr std::uint64_t kRandomModuleBudget = 20000;
constexpr int kRandomGrammars = 500;
constexpr double kMinSupportedShare = 0.9;

// Reruns a range of random grammars by hand: SIMECO_RANDOM_FIRST_SEED=1234 SIMECO_RANDOM_GRAMMARS=1.
std::uint64_t envOr(const char* name, std::uint64_t fallback) {
    const char* value = std::getenv(name);
    return value && *value ? std::strtoull(value, nullptr, 10) : fallback;
}

enum class Verdict { Match, Differ, Unsupported, OverBudget };

struct Outcome {
    Verdict verdict = Verdict::Match;
    std::string detail; // the difference, the reason it is unsupported, or the error
};

// Derives `g` with both engines. Errors other than the CPU outgrowing the module budget propagate.
Outcome compareEngines(const vk::Context& context, const ir::Grammar& g, const stream::DeriveOptions& options,
                       gpu::GpuStrategy strategy = gpu::GpuStrategy::Auto, gpu::GpuLoads loads = gpu::GpuLoads::Auto,
                       gpu::GpuContextMatch contexts = gpu::GpuContextMatch::Auto) {
    if (std::optional<std::string> reason = codegen::gpuUnsupportedReason(g)) return {Verdict::Unsupported, *reason};
    stream::DeriveResult want;
    try {
        want = cpu::deriveCpu(g, options);
    } catch (const ir::LimitError& e) {
        return {Verdict::OverBudget, e.what()};
    }
    gpu::GpuDeriver deriver(context, g, strategy, loads, contexts);
    stream::DeriveResult got = deriver.derive(options);
    std::string difference = firstDifference(want, got, g.alphabet);
    return {difference.empty() ? Verdict::Match : Verdict::Differ, difference};
}

std::string describeError(const std::exception& e) {
    if (const auto* input = dynamic_cast<const ir::InputError*>(&e)) return input->formatted();
    return e.what();
}

// Tallies of a loop over grammar files: unsupported ones are listed, differences and errors fail.
struct Tally {
    int total = 0, matched = 0;
    std::vector<std::string> unsupported;

    void expectSupportedShare(const char* what) const {
        for (const std::string& u : unsupported)
            std::printf("unsupported on the GPU: %s\n", u.c_str());
        std::printf("%s: %d of %d match the CPU, %zu unsupported\n", what, matched, total, unsupported.size());
        EXPECT_GE(static_cast<double>(total - static_cast<int>(unsupported.size())), kMinSupportedShare * total)
            << "too many " << what << " unsupported on the GPU";
    }
};

void compareFile(const vk::Context& context, const fs::path& file, const std::string& name, Tally& tally,
                 gpu::GpuStrategy strategy = gpu::GpuStrategy::Auto, gpu::GpuLoads loads = gpu::GpuLoads::Auto,
                 gpu::GpuContextMatch contexts = gpu::GpuContextMatch::Auto) {
    ++tally.total;
    try {
        ir::Grammar g = lang::loadGrammarFile(file.string());
        Outcome outcome = compareEngines(context, g, {}, strategy, loads, contexts);
        switch (outcome.verdict) {
        case Verdict::Match:
            ++tally.matched;
            break;
        case Verdict::Unsupported:
            tally.unsupported.push_back(name + ": " + outcome.detail);
            break;
        case Verdict::OverBudget:
            ADD_FAILURE() << name << ": over the module budget: " << outcome.detail;
            break;
        case Verdict::Differ:
            ADD_FAILURE() << name << ": GPU differs from CPU: " << outcome.detail;
            break;
        }
    } catch (const std::exception& e) {
        ADD_FAILURE() << name << ": " << describeError(e);
    }
}

class DeriveGpuTest : public GpuTest {
protected:
    // `plants` plants of g derived by the parallel strategy must match the CPU reference's.
    void expectParallelMatch(const ir::Grammar& g, std::uint32_t plants) {
        stream::DeriveOptions options;
        options.plants = plants;
        Outcome outcome = compareEngines(context(), g, options, gpu::GpuStrategy::Parallel);
        EXPECT_EQ(outcome.verdict, Verdict::Match) << outcome.detail;
    }
};

// Models may write files (fopen) relative to the working directory: they run in a scratch directory.
class ScratchDirGpuTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        if (HasFatalFailure()) return;
        char pattern[] = "/tmp/simeco-gpu-derive-XXXXXX";
        ASSERT_NE(mkdtemp(pattern), nullptr);
        scratch_ = pattern;
        previous_ = fs::current_path();
        fs::current_path(scratch_);
    }
    void TearDown() override {
        if (!scratch_.empty()) {
            fs::current_path(previous_);
            fs::remove_all(scratch_);
        }
        GpuTest::TearDown();
    }

private:
    fs::path scratch_, previous_;
};

std::vector<fs::path> exampleGrammarFiles() {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kGrammars)) {
        std::string extension = entry.path().extension().string();
        if (entry.is_regular_file() && (extension == ".l" || extension == ".lsys")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST_F(DeriveGpuTest, ExampleGrammarsMatchTheCpu) {
    std::vector<fs::path> files = exampleGrammarFiles();
    ASSERT_GE(files.size(), 15u) << "example grammars not found under " << kGrammars;
    Tally tally, sequential;
    for (const fs::path& file : files) {
        compareFile(context(), file, fs::relative(file, kGrammars).string(), tally);
        compareFile(context(), file, fs::relative(file, kGrammars).string(), sequential, gpu::GpuStrategy::Sequential);
    }
    tally.expectSupportedShare("example grammars");
    sequential.expectSupportedShare("example grammars, sequential strategy");
}

struct CorpusModel {
    std::string folder, file;
};

std::vector<CorpusModel> readManifest() {
    std::vector<CorpusModel> models;
    std::ifstream in(kCorpus / "MANIFEST.tsv");
    std::string line;
    std::getline(in, line); // header: folder, file, chars, features, compare
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream row(line);
        for (std::string cell; std::getline(row, cell, '\t');)
            cells.push_back(cell);
        if (cells.size() >= 2) models.push_back({cells[0], cells[1]});
    }
    return models;
}

TEST_F(ScratchDirGpuTest, CorpusModelsMatchTheCpu) {
    std::vector<CorpusModel> models = readManifest();
    ASSERT_GE(models.size(), 60u) << "the corpus manifest was not found or is incomplete at " << kCorpus;
    Tally tally;
    for (const CorpusModel& model : models)
        compareFile(context(), kCorpus / "models" / model.folder / model.file, model.folder, tally);
    tally.expectSupportedShare("corpus models");
}

// Every corpus model again with one invocation per plant: the strategy for grammars the parallel passes
// refuse, checked here on all of them.
TEST_F(ScratchDirGpuTest, CorpusModelsMatchTheCpuSequentially) {
    std::vector<CorpusModel> models = readManifest();
    ASSERT_GE(models.size(), 60u) << "the corpus manifest was not found or is incomplete at " << kCorpus;
    Tally tally;
    for (const CorpusModel& model : models)
        compareFile(context(), kCorpus / "models" / model.folder / model.file, model.folder, tally,
                    gpu::GpuStrategy::Sequential);
    tally.expectSupportedShare("corpus models, sequential strategy");
}

// The generator itself, on the CPU alone: every grammar parses and derives, few outgrow the budget, the same
// seed gives the same text, and each feature shows up often enough to be tested.
TEST(RandomGrammarTest, GeneratedGrammarsDeriveOnTheCpu) {
    EXPECT_EQ(randomGrammarText(42), randomGrammarText(42));
    EXPECT_NE(randomGrammarText(42), randomGrammarText(43));
    int skipped = 0;
    std::vector<std::string> errors;
    struct Feature {
        const char* name;
        int count = 0;
    };
    Feature stochastic{"seed: and factors"}, contextFilter{"ignore:/consider:"}, decomposition{"decomposition"},
        leftContext{"left context"}, branchContext{"right context with a branch"}, condition{"condition"},
        statements{"statement block"}, deletion{"deletion"}, cut{"cut %"}, random{"ran()"}, ifElse{"if/else"},
        parameters3{"three parameters"};
    for (int i = 0; i < kRandomGrammars; ++i) {
        std::uint64_t seed = static_cast<std::uint64_t>(i) + 1;
        std::string text = randomGrammarText(seed);
        try {
            ir::Grammar g = simeco::testing::grammarFromText(text);
            stream::DeriveOptions options;
            options.maxModules = kRandomModuleBudget;
            try {
                cpu::deriveCpu(g, options);
            } catch (const ir::LimitError&) {
                ++skipped;
            }
            bool left = false, branch = false, cond = false, block = false, erase = false, cuts = false;
            for (const ir::RuleSet* rules : {&g.productions, &g.decomposition}) {
                for (const ir::Production& p : rules->productions) {
                    left = left || !p.left.empty();
                    for (const ir::PatternModule& m : p.right)
                        branch = branch || m.sym == ir::kBranchOpen;
                    cond = cond || p.condition.has_value();
                    block = block || !p.before.empty() || !p.after.empty();
                    erase = erase || p.alternatives.front().modules.empty();
                    for (const ir::SuccessorModule& m : p.alternatives.front().modules)
                        cuts = cuts || m.sym == ir::kCut;
                }
            }
            stochastic.count += text.find("\nseed:") != std::string::npos;
            contextFilter.count += std::find(g.contextSkip.begin(), g.contextSkip.end(), true) != g.contextSkip.end();
            decomposition.count += !g.decomposition.productions.empty();
            leftContext.count += left;
            branchContext.count += branch;
            condition.count += cond;
            statements.count += block;
            deletion.count += erase;
            cut.count += cuts;
            random.count += text.find("ran(") != std::string::npos;
            ifElse.count += text.find("if (") != std::string::npos;
            parameters3.count += g.maxParams() >= 3;
        } catch (const std::exception& e) {
            errors.push_back("seed " + std::to_string(seed) + ": " + describeError(e) + "\n" + text);
        }
    }
    for (const std::string& e : errors)
        ADD_FAILURE() << e;
    EXPECT_LE(skipped, kRandomGrammars / 10) << "too many random grammars outgrow the module budget";
    for (const Feature* f : {&stochastic, &contextFilter, &decomposition, &leftContext, &branchContext, &condition,
                             &statements, &deletion, &cut, &random, &ifElse, &parameters3}) {
        std::printf("%-28s in %3d of %d random grammars\n", f->name, f->count, kRandomGrammars);
        EXPECT_GE(f->count, kRandomGrammars / 20) << "the generator rarely writes: " << f->name;
    }
}

void compareRandomGrammars(const vk::Context& context, std::uint64_t first, std::uint64_t count,
                           gpu::GpuStrategy strategy, gpu::GpuLoads loads = gpu::GpuLoads::Auto,
                           gpu::GpuContextMatch contexts = gpu::GpuContextMatch::Auto) {
    constexpr int kTextsShown = 5; // a broken pass tends to break hundreds
    std::uint64_t matched = 0, skipped = 0, failed = 0;
    for (std::uint64_t seed = first; seed < first + count; ++seed) {
        std::string text = randomGrammarText(seed);
        std::string failure;
        try {
            ir::Grammar g = simeco::testing::grammarFromText(text);
            stream::DeriveOptions options;
            options.maxModules = kRandomModuleBudget;
            Outcome outcome = compareEngines(context, g, options, strategy, loads, contexts);
            switch (outcome.verdict) {
            case Verdict::Match:
                ++matched;
                break;
            case Verdict::OverBudget:
                ++skipped;
                break;
            case Verdict::Unsupported:
                failure = "unsupported on the GPU: " + outcome.detail;
                break;
            case Verdict::Differ:
                failure = "GPU differs from CPU: " + outcome.detail;
                break;
            }
        } catch (const std::exception& e) {
            failure = describeError(e);
        }
        if (failure.empty()) continue;
        ++failed;
        ADD_FAILURE() << "random grammar seed " << seed << ": " << failure
                      << (failed <= kTextsShown ? "\n" + text : std::string());
    }
    std::printf("random grammars: %llu of %llu match the CPU, %llu over the module budget\n",
                static_cast<unsigned long long>(matched), static_cast<unsigned long long>(count),
                static_cast<unsigned long long>(skipped));
    EXPECT_LE(skipped * 10, count) << "too many random grammars outgrow the module budget";
}

// The random grammars in shards, so that each test stays well inside its time limit and ctest can run shards
// side by side; SIMECO_RANDOM_FIRST_SEED and SIMECO_RANDOM_GRAMMARS choose the range they share.
constexpr int kRandomShards = 5;

class RandomGrammarShard : public GpuTest, public ::testing::WithParamInterface<int> {};

TEST_P(RandomGrammarShard, MatchesTheCpu) {
    std::uint64_t first = envOr("SIMECO_RANDOM_FIRST_SEED", 1);
    std::uint64_t count = envOr("SIMECO_RANDOM_GRAMMARS", kRandomGrammars);
    std::uint64_t perShard = (count + kRandomShards - 1) / kRandomShards;
    std::uint64_t begin = std::min(count, perShard * static_cast<std::uint64_t>(GetParam()));
    std::uint64_t end = std::min(count, begin + perShard);
    if (begin == end) GTEST_SKIP() << "SIMECO_RANDOM_GRAMMARS=" << count << " leaves this shard empty";
    compareRandomGrammars(context(), first + begin, end - begin, gpu::GpuStrategy::Auto);
}

INSTANTIATE_TEST_SUITE_P(RandomGrammars, RandomGrammarShard, ::testing::Range(0, kRandomShards));

// The sequential strategy on random grammars too (fewer: one invocation per plant is slow on lavapipe;
// SIMECO_RANDOM_SEQUENTIAL=500 runs more).
TEST_F(DeriveGpuTest, RandomGrammarsMatchTheCpuSequentially) {
    compareRandomGrammars(context(), envOr("SIMECO_RANDOM_FIRST_SEED", 1), envOr("SIMECO_RANDOM_SEQUENTIAL", 25),
                          gpu::GpuStrategy::Sequential);
}

// A stochastic grammar with random parameters, for the tests of many plants.
ir::Grammar plantGrammar() {
    return simeco::testing::grammarFromText("Lsystem: 1\n"
                                            "seed: 11\n"
                                            "derivation length: 5\n"
                                            "Axiom: A(1)\n"
                                            "A(x) --> F(x)[+A(x*0.8)]F(ran(1))A(x*0.9) : 2\n"
                                            "A(x) --> F(x)[-A(x*0.7)]A(x+ran(0.5)) : 1\n"
                                            "A(x) --> F(x)A(x*1.1) : 1\n"
                                            "F(l) : l > 0.95 --> F(l*0.5)F(l*0.5)\n"
                                            "endlsystem\n");
}

// The kernels read their inputs through storage buffers or texel buffers (gpu::GpuLoads). The other tests take
// the device's choice (texel buffers on CPU devices, storage buffers on GPUs); here the other one, on the
// example grammars with both strategies and on random grammars.
TEST_F(DeriveGpuTest, TheOtherLoadPathMatchesTheCpu) {
    std::vector<fs::path> files = exampleGrammarFiles();
    ASSERT_GE(files.size(), 15u) << "example grammars not found under " << kGrammars;
    gpu::GpuLoads chosen = gpu::GpuDeriver(context(), plantGrammar()).loads();
    gpu::GpuLoads other = chosen == gpu::GpuLoads::TexelBuffers ? gpu::GpuLoads::StorageBuffers : gpu::GpuLoads::TexelBuffers;
    ASSERT_EQ(gpu::GpuDeriver(context(), plantGrammar(), gpu::GpuStrategy::Auto, other).loads(), other);
    Tally tally, sequential;
    for (const fs::path& file : files) {
        std::string name = fs::relative(file, kGrammars).string();
        compareFile(context(), file, name, tally, gpu::GpuStrategy::Auto, other);
        compareFile(context(), file, name, sequential, gpu::GpuStrategy::Sequential, other);
    }
    tally.expectSupportedShare("example grammars, the other load path");
    sequential.expectSupportedShare("example grammars, the other load path, sequential strategy");
    compareRandomGrammars(context(), envOr("SIMECO_RANDOM_FIRST_SEED", 1), 100, gpu::GpuStrategy::Auto, other);
}

// A step's match pass finds context modules by a walk per module or by chunks of modules (gpu::GpuContextMatch).
// The other tests take the device's choice (chunks on CPU devices, walks on GPUs); here the other one, on the
// example grammars and on random grammars.
TEST_F(DeriveGpuTest, TheOtherContextMatchMatchesTheCpu) {
    std::vector<fs::path> files = exampleGrammarFiles();
    ASSERT_GE(files.size(), 15u) << "example grammars not found under " << kGrammars;
    gpu::GpuContextMatch chosen = gpu::GpuDeriver(context(), plantGrammar()).contextMatch();
    gpu::GpuContextMatch other =
        chosen == gpu::GpuContextMatch::Chunks ? gpu::GpuContextMatch::Walks : gpu::GpuContextMatch::Chunks;
    ASSERT_EQ(gpu::GpuDeriver(context(), plantGrammar(), gpu::GpuStrategy::Auto, gpu::GpuLoads::Auto, other)
                  .contextMatch(),
              other);
    Tally tally;
    for (const fs::path& file : files)
        compareFile(context(), file, fs::relative(file, kGrammars).string(), tally, gpu::GpuStrategy::Auto,
                    gpu::GpuLoads::Auto, other);
    tally.expectSupportedShare("example grammars, the other context match");
    compareRandomGrammars(context(), envOr("SIMECO_RANDOM_FIRST_SEED", 1), 100, gpu::GpuStrategy::Auto,
                          gpu::GpuLoads::Auto, other);
}

// `--plants`: plant k draws from its own random stream on both engines, so any number of plants must match.
TEST_F(DeriveGpuTest, ManyPlantsMatchTheCpu) {
    ir::Grammar g = plantGrammar();
    ASSERT_FALSE(codegen::gpuUnsupportedReason(g).has_value()) << *codegen::gpuUnsupportedReason(g);
    for (std::uint32_t plants : {1u, 7u, 1000u}) {
        SCOPED_TRACE(std::to_string(plants) + " plants");
        stream::DeriveOptions options;
        options.plants = plants;
        stream::DeriveResult want = cpu::deriveCpu(g, options);
        ASSERT_EQ(want.string.plants(), plants);
        if (plants > 1) {
            // The plants differ, or the test would not see streams mixed up between plants.
            std::set<std::string> distinct;
            for (std::uint32_t p = 0; p < std::min(plants, 7u); ++p)
                distinct.insert(stream::formatModules(want.string, g.alphabet, want.string.plantStart[p],
                                                   want.string.plantStart[p + 1]));
            ASSERT_GT(distinct.size(), 1u);
        }
        gpu::GpuDeriver deriver(context(), g);
        EXPECT_EQ(firstDifference(want, deriver.derive(options), g.alphabet), "");
    }
}

// Predecessors of three modules claim their neighbours left to right (the greedy walk); X and the odd successor
// lengths shift the triples, so that they straddle chunk and block boundaries. At 380,000 modules the walk's
// chunks form several blocks of greedy_scan.comp.
TEST_F(DeriveGpuTest, PredecessorsOfSeveralModulesMatchTheCpu) {
    ir::Grammar g = simeco::testing::grammarFromText(
        simeco::testing::lsystem("XA(0)A(1)A(2)",
                                 "A(a)A(b)A(c) --> A(a+1)A(b)A(c)B(a)A(b+c)A(a)A(c)\nB(n) --> A(n)\n", 16));
    stream::DeriveResult want = cpu::deriveCpu(g, {});
    ASSERT_GT(want.string.size(), 4u * 256u * 256u);
    gpu::GpuDeriver deriver(context(), g);
    EXPECT_EQ(firstDifference(want, deriver.derive({}), g.alphabet), "");
}

// cpfg's sub-L-systems: each L-system rewrites the modules of its calls with symbols of its own, which context
// (and a predecessor's further modules) match by name, in parallel passes and sequentially as on the CPU; each
// L-system's homomorphism draws its own modules.
TEST_F(DeriveGpuTest, SubLsystemsMatchTheCpu) {
    ir::Grammar g = simeco::testing::grammarFromText(
        "Lsystem: 1\nderivation length: 5\nAxiom: A(0)?(2,0.5)B(0)$\nignore: ?\n"
        "A(n) > B(m) --> A(n+1)?(2,0.5)B(m+n)$\nB(n) --> X\nC --> Y\nhomomorphism:\nD(m) --> Z\nendlsystem\n"
        "Lsystem: 2\nAxiom: B(0)\nignore: ?\nA(n) < B(m) --> B(m+n)C\nB(m)C --> D(m)\n"
        "homomorphism:\nD(m) --> F(m)+F\nendlsystem\n");
    for (bool homomorphism : {false, true}) {
        stream::DeriveOptions options;
        options.homomorphism = homomorphism;
        stream::DeriveResult want = cpu::deriveCpu(g, options);
        const std::string text = stream::formatModules(want.string, g.alphabet, 0, want.string.size());
        for (const char* produced : {homomorphism ? "F(" : "D(", "C$"})
            EXPECT_NE(text.find(produced), std::string::npos) << text;
        // Main's B, C and D are never in the string.
        for (char never : {'X', 'Y', 'Z'}) EXPECT_EQ(text.find(never), std::string::npos) << text;
        for (gpu::GpuStrategy strategy : {gpu::GpuStrategy::Parallel, gpu::GpuStrategy::Sequential}) {
            gpu::GpuDeriver deriver(context(), g, strategy);
            EXPECT_EQ(firstDifference(want, deriver.derive(options), g.alphabet), "");
        }
    }
}

// Parameters that overflow to infinity and then become NaN (inf - inf, inf * 0) follow IEEE arithmetic on both
// engines, as cpfg's: a driver may fold x - x to 0 unless told to keep infinities and NaN, and lavapipe folds x * 0
// even then (the kernels multiply by a zero it cannot see). Conditions then compare NaN as false, so B(nan) takes
// neither production.
TEST_F(DeriveGpuTest, InfinitiesAndNanMatchTheCpu) {
    ir::Grammar g = simeco::testing::grammarFromText(
        simeco::testing::lsystem("A(1e30)",
                                 "A(x) --> B(x - x)C(x * 0)C(0 * x)A(x * 1e30)\n"
                                 "B(x) : x == x --> D(x)\n"
                                 "B(x) : x > 0 --> E\n",
                                 3));
    stream::DeriveResult want = cpu::deriveCpu(g, {});
    std::string text = stream::formatModules(want.string, g.alphabet, 0, want.string.size());
    EXPECT_EQ(text, "D(0)C(0)C(0)B(nan)C(nan)C(nan)B(nan)C(nan)C(nan)A(inf)");
    for (int strategy : {0, 1}) {
        gpu::GpuDeriver deriver(context(), g, strategy ? gpu::GpuStrategy::Sequential : gpu::GpuStrategy::Parallel);
        EXPECT_EQ(firstDifference(want, deriver.derive({}), g.alphabet), "") << (strategy ? "sequential" : "parallel");
    }
}

// The sequential kernel keeps each production's locals between its applications and hands the parameters its test
// bound (and its statements changed) to the production applied. Stochastic, so that every production of A is tested
// before the drawn one is applied: each must apply its own parameters, not those of the last one tested.
TEST_F(DeriveGpuTest, SequentialLocalsCarryOverAndParametersReachTheSuccessor) {
    ir::Grammar g = simeco::testing::grammarFromText(
        simeco::testing::lsystem("A(1)E(0)A(2)",
                                 "A(x) : { if (x > 3) { c = x; } x = x * 2; } 1 --> A(x)B(c) : 1\n"
                                 "A(x) : { if (x < 9) { d = x; } } 1 --> A(x + 1)C(d) : 2\n"
                                 "B(y) > C(z) : { y = y + z + 1; } y > 0 --> B(y)\n"
                                 "E(z) : { if (z < 5) { n = z + 1; } } 1 --> E(z + n)\n",
                                 6));
    stream::DeriveResult want = cpu::deriveCpu(g, {});
    gpu::GpuDeriver deriver(context(), g, gpu::GpuStrategy::Sequential);
    EXPECT_EQ(firstDifference(want, deriver.derive({}), g.alphabet), "");
    std::string text = stream::formatModules(want.string, g.alphabet, 0, want.string.size());
    EXPECT_NE(text.find('B'), std::string::npos) << text;
    EXPECT_NE(text.find('C'), std::string::npos) << text;
}

// The write pass applies the production its match chose without evaluating a pure condition again, but one that
// draws random numbers it evaluates again, so that the successor's draws follow the condition's as on the CPU,
// walking the context whose parameter only that condition reads.
TEST_F(DeriveGpuTest, ConditionsThatDrawMatchTheCpu) {
    ir::Grammar g = simeco::testing::grammarFromText(
        simeco::testing::lsystem("B(0.5)A(0)",
                                 "B(y) < A(x) : y + ran(1) > 1 --> A(x + ran(3))B(ran(2))\n"
                                 "A(x) : ran(1) < 0.5 --> A(x + ran(1))B(ran(2))\n"
                                 "A(x) : x > 2 --> A(x - 1)B(x)\n"
                                 "A(x) --> A(x + 1)\n",
                                 12));
    expectParallelMatch(g, 20);
}

// A module walks its contexts only when its own parameters pass the comparisons its productions' conditions start
// with; until the first part that may draw or fail, as the CPU reference evaluates the condition from the left.
// Each symbol has one case, and draws in a later production that would shift if a draw were skipped: A a draw
// before the comparison, C a draw in the statements before the condition, D a context's parameter compared first,
// on 20 plants whose parameters pass the comparisons now and then.
TEST_F(DeriveGpuTest, ContextWalksGuardedByOwnParametersMatchTheCpu) {
    ir::Grammar g = simeco::testing::grammarFromText(
        simeco::testing::lsystem("B(0.5)A(0)B(2)C(3)B(1)D(2)B(3)A(1)C(2)B(2)D(1)B(4)",
                                 "B(y) < A(x) : ran(1) < 0.7 && x == 3 --> A(x + 1)B(y + 1)\n"
                                 "A(x) : ran(1) < 0.4 --> A(x + 1)\n"
                                 "A(x) : x > 4 --> A(0)B(x - 4)\n"
                                 "A(x) --> A(x + 1)\n"
                                 "B(y) < C(x) : { z = ran(1); } x == 2 --> C(floor(x + z * 3))B(z)\n"
                                 "C(x) : ran(1) < 0.4 --> C(x + 1)\n"
                                 "C(x) : x > 4 --> C(0)\n"
                                 "C(x) --> C(x + 1)\n"
                                 "D(x) > B(y) : y > 1 && x < 2 && y + ran(2) > 1.5 --> D(x + 1)B(y - 1)\n"
                                 "D(x) : ran(1) < 0.4 --> D(x + 2)\n"
                                 "D(x) : x > 4 --> D(0)\n"
                                 "D(x) --> D(x - 1)\n"
                                 "B(y) : y > 3 --> B(0)\n",
                                 10));
    expectParallelMatch(g, 20);
}

// Ring L-systems: contexts go on from the other end of their own plant, once per pattern, with branches, ignored
// symbols and decomposition.
TEST_F(DeriveGpuTest, RingLSystemsMatchTheCpu) {
    const std::string grammars[] = {
        simeco::testing::lsystem("S(1)B(0)[+B(0)]B(0)+B(0)",
                                 "ring lsystem\nignore: +\nS(n) --> B(n)\nS(n) < B(m) --> S(n+m+1)\n"
                                 "B(m) > S(n) --> B(m+n)\n",
                                 9),
        simeco::testing::lsystem("ABABB", "ring lsystem\nA > BAB --> X\nBAB < A --> Y\nA > BABAB --> Z\n"
                                          "B > AB --> C\nC --> AB\nX --> BA\nY --> A\n",
                                 6),
        "Lsystem: 1\nring lsystem\nDerivation length: 5\nAxiom: A(0)B(1)C(2)\nA(x) --> A(x+1)B(x)\n"
        "decomposition\nmaximum depth: 2\nC(z) < A(x) --> D(z+x)\nB(y) > A(x) --> E(x)\nD(v) --> C(v)A(1)\n"
        "endlsystem\n",
    };
    for (const std::string& text : grammars) {
        SCOPED_TRACE(text);
        ir::Grammar g = simeco::testing::grammarFromText(text);
        ASSERT_TRUE(g.ring);
        stream::DeriveOptions options;
        options.plants = 3;
        for (gpu::GpuStrategy strategy : {gpu::GpuStrategy::Parallel, gpu::GpuStrategy::Sequential}) {
            Outcome outcome = compareEngines(context(), g, options, strategy);
            EXPECT_EQ(outcome.verdict, Verdict::Match) << outcome.detail;
        }
    }
}

// A step whose successors are balanced writes the partners of the brackets it writes, so that only the axioms
// need a bracket tree: branches nested ten deep and longer than a workgroup, contexts skipping them and entering
// them, on 40 stochastic plants. A cut, or an unbalanced axiom (which no parser lets through, but a grammar built
// in code may hold), makes every step build its tree. Contexts found by walks and by chunks, whose partners
// and walks cross the chunks' ends.
TEST_F(DeriveGpuTest, CarriedBracketPartnersMatchTheCpu) {
    const std::string rules = "seed: 3\nignore: + - F\n"
                              "A(x) < A(y) > [B(z)] --> A(y+z)\n"
                              "A(x) < B(y) --> B(y+x)F[-B(y)F]\n"
                              "B(y) > A(z) --> B(y+z)\n"
                              "F > A(z) : z < 0.2 --> G\n"
                              "A(x) --> F[+A(x+1)F[-B(x)]F]A(x*0.5) : 1\n"
                              "A(x) --> A(x)[-F B(x)] : 2\n";
    constexpr int kSteps = 9;
    struct Case {
        const char* what;
        std::string rules;
        bool openBranchAtTheEnd;
        std::uint32_t bracketTrees;
    };
    for (const Case& c : {Case{"balanced", rules, false, 1},
                          Case{"cut", rules + "B(y) : y > 30 --> %\n", false, kSteps},
                          Case{"unbalanced axiom", rules, true, kSteps}}) {
        SCOPED_TRACE(c.what);
        ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem("A(1)[+B(1)]A(2)", c.rules, kSteps));
        if (c.openBranchAtTheEnd) {
            ir::SuccessorModule open;
            open.sym = ir::kBranchOpen;
            g.axiom.push_back(open);
        }
        stream::DeriveOptions options;
        options.plants = 40;
        stream::DeriveResult want = cpu::deriveCpu(g, options);
        std::vector<std::size_t> open;
        std::size_t longest = 0, deepest = 0;
        for (std::size_t i = 0; i < want.string.size(); ++i) {
            if (want.string.sym[i] == ir::kBranchOpen) open.push_back(i);
            if (want.string.sym[i] == ir::kBranchClose && !open.empty()) {
                longest = std::max(longest, i - open.back());
                open.pop_back();
            }
            deepest = std::max(deepest, open.size());
        }
        ASSERT_GT(longest, 4u * shared::kDeriveWorkgroupSize) << "no branch spans several workgroups";
        ASSERT_GT(longest, 4u * shared::kContextChunk) << "no branch spans several chunks";
        ASSERT_GE(deepest, 8u);
        for (gpu::GpuContextMatch contexts : {gpu::GpuContextMatch::Walks, gpu::GpuContextMatch::Chunks}) {
            SCOPED_TRACE(contexts == gpu::GpuContextMatch::Walks ? "walks" : "chunks");
            gpu::GpuDeriver deriver(context(), g, gpu::GpuStrategy::Parallel, gpu::GpuLoads::Auto, contexts);
            gpu::GpuDeriveStats stats;
            EXPECT_EQ(firstDifference(want, deriver.derive(options, /*readBack=*/true, &stats), g.alphabet), "");
            EXPECT_EQ(stats.bracketTrees, c.bracketTrees);
        }
    }
}

// Successors longer than 16 modules are stored in a loop as long as the subgroup's longest successor
// (codegen::slotStoreCode), shorter ones one slot at a time: parameters, brackets whose partners the write pass
// carries, deletions and copies around them, in one plant and in many.
TEST_F(DeriveGpuTest, LongSuccessorsMatchTheCpu) {
    const std::string rules =
        "seed: 5\nignore: + -\n"
        "A(x) : x < 1000 --> F(x)[+A(x+1)]F(x+1)[-B(x)]G(x,x*3)[+[C(x)]H]F(1)F(2)F(3)[A(x+5)]E(x)D : 3\n"
        "A(x) --> F(x)A(x+1) : 1\n"
        "B(x) < C(y) --> *\n"
        "B(x) --> B(x+1)[C(x)]\n"
        "D --> *\n";
    ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem("A(1)B(2)[C(0)]A(3)", rules, 9));
    codegen::GeneratedKernels kernels = codegen::generateDeriveKernels({g});
    ASSERT_NE(kernels.write.find("slotWordAt"), std::string::npos) << "the successor of 26 modules is not stored in a loop";
    ASSERT_TRUE(kernels.carriesPartners);
    for (std::uint32_t plants : {1u, 37u}) {
        SCOPED_TRACE(std::to_string(plants) + " plants");
        stream::DeriveOptions options;
        options.plants = plants;
        stream::DeriveResult want = cpu::deriveCpu(g, options);
        ASSERT_GT(want.string.size(), 5000u * plants);
        gpu::GpuDeriver deriver(context(), g, gpu::GpuStrategy::Parallel);
        EXPECT_EQ(firstDifference(want, deriver.derive(options), g.alphabet), "");
    }
}

// One deriver derives again and again: with and without reading back, with more plants, then fewer.
TEST_F(DeriveGpuTest, DeriverDerivesRepeatedly) {
    ir::Grammar g = plantGrammar();
    gpu::GpuDeriver deriver(context(), g);
    for (std::uint32_t plants : {7u, 1u, 1000u, 7u}) {
        SCOPED_TRACE(std::to_string(plants) + " plants");
        stream::DeriveOptions options;
        options.plants = plants;
        stream::DeriveResult want = cpu::deriveCpu(g, options);
        EXPECT_EQ(firstDifference(want, deriver.derive(options), g.alphabet), "");

        gpu::GpuDeriveStats stats;
        stream::DeriveResult sizesOnly = deriver.derive(options, /*readBack=*/false, &stats);
        EXPECT_EQ(sizesOnly.string.size(), 0u);
        EXPECT_EQ(stats.modules, want.string.size());
    }
}

// A symbol with a hundred and twenty productions, each applying once in turn: the last ones apply on the device
// too (a driver that keeps 80 levels of nested control flow loses every test nested below them).
TEST_F(DeriveGpuTest, EveryOneOfASymbolsManyProductionsApplies) {
    const int productions = 120;
    std::string rules;
    for (int k = 0; k < productions; ++k) rules += "A(x) : x == " + std::to_string(k) + " --> F(x)A(x+1)\n";
    ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem("A(0)", rules, productions));
    stream::DeriveResult want = cpu::deriveCpu(g, {});
    ASSERT_EQ(want.string.size(), size_t(productions) + 1) << "the reference did not apply every production";
    for (gpu::GpuStrategy strategy : {gpu::GpuStrategy::Parallel, gpu::GpuStrategy::Sequential}) {
        SCOPED_TRACE(strategy == gpu::GpuStrategy::Parallel ? "parallel" : "sequential");
        gpu::GpuDeriver deriver(context(), g, strategy);
        EXPECT_EQ(firstDifference(want, deriver.derive({}), g.alphabet), "");
    }
}

} // namespace
} // namespace simeco::test
