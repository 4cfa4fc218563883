// Round trips: grammar -> derive -> skeleton -> infer -> derive -> skeleton, the second equal to the first (every
// segment matched one to one within 1e-4 of the plant's size), on the ABOP trees, the three seed plants and random
// bracketed grammars, through the SimEco script and through the cpfg L-system.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "../unit/temporary_folder.h"
#include "plant_skeletons.h"
#include "random_plant_grammar.h"
#include "skeleton/skeleton_json.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;
const fs::path kGrammars = fs::path(SIMECO_SOURCE_DIR) / "grammars";
const fs::path kSeedScripts = fs::path(SIMECO_SHARED_DIR) / "seed-scripts";

class SkeletonRoundTrip : public simeco::testing::TemporaryFolderTest {
protected:
    void expectRegrown(const fs::path& grammar, const char* as) {
        SCOPED_TRACE(grammar.filename().string() + " as " + as);
        skeleton::Plant plant = skeletonOfFile(grammar);
        ASSERT_GT(skeleton::segmentCount(plant), 0u);
        RoundTrip trip = roundTrip(plant, dir_ / (std::string("inferred") + as));
        EXPECT_TRUE(trip.match.same()) << trip.match.matched << " of " << trip.match.segments << " segments matched, "
                                       << trip.match.otherSegments << " regrown; first unmatched: "
                                       << trip.match.firstUnmatched;
        std::printf("%-28s %-4s %6zu segments %6zu internodes %4d levels  worst %.2e  %.2f s\n",
                    grammar.filename().c_str(), as, trip.match.segments, trip.internodes, trip.levels,
                    trip.match.worst, trip.seconds);
    }
};

TEST_F(SkeletonRoundTrip, TheAbopTreesRegrowThroughTheSimEcoScript) {
    for (const char* name : {"fig1.24a.l", "fig1.24c.l", "fig1.24d.l", "fig1.27-stochastic.l", "fig1.31c.l",
                             "fig2.6-monopodial.l", "fig2.7-sympodial.l", "fig2.8-ternary.l"})
        expectRegrown(kGrammars / "abop" / name, ".eco");
}

TEST_F(SkeletonRoundTrip, TheAbopTreesRegrowThroughTheCpfgLSystem) {
    for (const char* name : {"fig1.24b.l", "fig1.24e.l", "fig1.24f.l", "fig1.31a.l", "fig1.31b.l", "fig1.31d.l",
                             "fig1.31e.l"})
        expectRegrown(kGrammars / "abop" / name, ".l");
}

TEST_F(SkeletonRoundTrip, TheSeedPlantsRegrow) {
    for (const char* name : {"lantana-camara.eco", "rosa-rugosa.eco", "oxalis-corniculata.eco"}) {
        expectRegrown(kSeedScripts / name, ".eco");
        expectRegrown(kSeedScripts / name, ".l");
    }
}

// 200 random grammars of up to 800 segments (larger ones are drawn again from the next seed), alternately through
// the script and the L-system. Every one must regrow exactly.
TEST_F(SkeletonRoundTrip, RandomBracketedGrammarsRegrow) {
    size_t exact = 0, tried = 0, slowest = 0;
    double slowestSeconds = 0.0, total = 0.0;
    for (uint64_t seed = 1; tried < 200; ++seed) {
        const std::string text = randomPlantGrammar(seed);
        skeleton::Plant plant = skeletonOfText(text, dir_ / "random.l");
        const size_t segments = skeleton::segmentCount(plant);
        if (segments == 0 || segments > 800) continue;
        ++tried;
        RoundTrip trip = roundTrip(plant, dir_ / (tried % 2 ? "inferred.eco" : "inferred.l"));
        EXPECT_TRUE(trip.match.same()) << "seed " << seed << ": " << trip.match.matched << " of "
                                       << trip.match.segments << " matched; first unmatched "
                                       << trip.match.firstUnmatched << "\n" << text;
        exact += trip.match.same();
        total += trip.seconds;
        if (trip.seconds > slowestSeconds) {
            slowestSeconds = trip.seconds;
            slowest = segments;
        }
    }
    std::printf("random grammars: %zu of %zu regrown exactly; %.3f s each on average, slowest %.3f s (%zu "
                "segments)\n",
                exact, tried, total / double(tried), slowestSeconds, slowest);
}

} // namespace
} // namespace simeco::test
