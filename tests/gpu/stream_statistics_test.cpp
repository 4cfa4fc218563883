// Statistics counted on the device (gpu/stream_statistics) equal the CPU's (stream/statistics) for derived
// fields and for made-up streams: alphabets counted in shared memory and in the buffer, unbalanced brackets
// (a `]` at depth 0 keeps the depth at 0), chunks cut anywhere, several plants, and an empty stream.
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compute/shared/statistics_layout.h"
#include "cpu/derive.h"
#include "gpu/stream_statistics.h"
#include "gpu_fixture.h"
#include "ir/species.h"
#include "lang/load_grammar.h"
#include "stream/statistics.h"
#include "turtle/turtle_gpu.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

// Empty when the device's statistics of `string` equal the CPU's, else the first difference.
std::string compareStatistics(const vk::Context& context, const stream::ModuleString& string,
                              const ir::Alphabet& alphabet) {
    stream::StringStatistics want = stream::computeStatistics(string, alphabet);
    turtle::UploadedModules uploaded(context, string);
    gpu::StreamStatistics statistics(context);
    stream::StringStatistics got = statistics.compute(uploaded.view(), alphabet);
    if (got.modules != want.modules) return fmt::format("{} modules, want {}", got.modules, want.modules);
    if (got.plants != want.plants) return fmt::format("{} plants, want {}", got.plants, want.plants);
    if (got.maxBranchDepth != want.maxBranchDepth)
        return fmt::format("max branch depth {}, want {}", got.maxBranchDepth, want.maxBranchDepth);
    if (got.perSymbol != want.perSymbol) {
        for (const auto& [name, count] : want.perSymbol)
            if (got.perSymbol[name] != count)
                return fmt::format("{} times '{}', want {}", got.perSymbol[name], name, count);
        return "a symbol counted that the CPU does not see";
    }
    return {};
}

// A made-up stream of `modules` modules over `symbols` symbols in `plants` plants, brackets among them with
// probability `brackets` each (so not balanced).
stream::ModuleString madeUpStream(ir::Alphabet& alphabet, std::uint32_t symbols, std::size_t modules,
                                  std::uint32_t plants, double brackets, std::uint32_t seed) {
    while (alphabet.size() < symbols) alphabet.intern(fmt::format("S{}", alphabet.size()));
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::uint32_t> symbol(2, symbols - 1);
    stream::ModuleString s;
    s.plantStart.push_back(0);
    for (std::size_t i = 0; i < modules; ++i) {
        double u = unit(random);
        // Opening a little more often than closing, so the depth climbs, falls and sometimes hits 0 with `]`.
        std::uint32_t sym = u < brackets * 0.55 ? ir::kBranchOpen : u < brackets ? ir::kBranchClose : symbol(random);
        s.push(sym, nullptr, 0);
        if (s.plantStart.size() < plants && (i + 1) % (modules / plants + 1) == 0) s.plantStart.push_back(s.size());
    }
    while (s.plantStart.size() < plants + 1) s.plantStart.push_back(s.size());
    return s;
}

using StreamStatisticsTest = GpuTest;

TEST_F(StreamStatisticsTest, DerivedFieldsCountAsOnTheCpu) {
    int compared = 0;
    for (const char* file : {"fig1.24a.l", "fig1.24d.l", "fig2.8-ternary.l", "fig1.31a.l"}) {
        std::vector<ir::Grammar> species =
            ir::unifySpecies(lang::loadSpecies((fs::path(SIMECO_SOURCE_DIR) / "grammars" / "abop" / file).string()));
        stream::DeriveOptions options;
        options.plants = 3;
        options.homomorphism = true;
        stream::DeriveResult derived = cpu::deriveSpeciesCpu(species, options);
        EXPECT_EQ(compareStatistics(context(), derived.string, species.front().alphabet), "") << file;
        ++compared;
    }
    EXPECT_EQ(compared, 4);
}

TEST_F(StreamStatisticsTest, MadeUpStreamsCountAsOnTheCpu) {
    struct Case {
        std::uint32_t symbols;
        std::size_t modules;
        std::uint32_t plants;
        double brackets;
    };
    const std::uint32_t shared = shared::kStatisticsSharedSymbols;
    const std::size_t chunk = shared::kStatisticsChunk;
    for (const Case& c : {Case{16, 5 * chunk + 17, 1, 0.3}, Case{shared, 70 * chunk * 3 + 1, 7, 0.2},
                          Case{shared + 1, 40 * chunk, 3, 0.25}, Case{3000, 100000, 50, 0.1},
                          Case{40, 3 * chunk - 1, 2, 0.9}}) {
        ir::Alphabet alphabet;
        stream::ModuleString s = madeUpStream(alphabet, c.symbols, c.modules, c.plants, c.brackets, c.symbols);
        EXPECT_EQ(compareStatistics(context(), s, alphabet), "")
            << c.symbols << " symbols, " << c.modules << " modules";
    }
}

TEST_F(StreamStatisticsTest, AnEmptyStreamHasNothing) {
    ir::Alphabet alphabet;
    stream::ModuleString s;
    s.plantStart = {0, 0};
    EXPECT_EQ(compareStatistics(context(), s, alphabet), "");
}

} // namespace
} // namespace simeco::test
