// A saved run's file (field/saved_run.h): what is written reads back the same, and a file that is not one, is
// truncated anywhere or has bytes changed is refused with an input error or read as some consistent state, never
// a crash or an allocation of what the file claims.
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "compute/shared/random.h"
#include "field/saved_run.h"
#include "ir/source_loc.h"

namespace simeco {
namespace {

field::SavedRun sampleRun() {
    field::SavedRun run;
    run.options.file = "garden.eco";
    run.options.sceneText = "EcoSystem 1.0 \"g\" { }";
    run.options.plants = 2;
    run.options.density = 1.5f;
    run.options.seed = 7;
    run.options.dt = 0.5f;
    run.state.ticks = 9;
    run.state.nextStep = {6.0f, 7.5f};
    stream::SteppedState& plants = run.state.plants;
    plants.fieldStep = 3;
    plants.string.stride = 2;
    plants.string.plantStart = {0, 2, 3};
    for (uint32_t i = 0; i < 3; ++i) {
        const float p[2] = {float(i), 2.0f * float(i)};
        plants.string.push(i, p, i % 3);
        shared::ParticleState state;
        state.value[shared::kParticleAge] = 1.5f * float(i);
        plants.string.particles.push_back(state);
    }
    plants.plants = {{{1.0, 2.0}, {{3.0, 4.0, 5.0}}, false, 3}, {{6.0, 7.0}, {{8.0, 9.0, 10.0}}, true, 2}};
    return run;
}

TEST(SavedRun, ReadsBackWhatItWrote) {
    const field::SavedRun run = sampleRun();
    const field::SavedRun back = field::decodeSavedRun(field::encodeSavedRun(run), "state.bin");
    EXPECT_EQ(back.options.file, run.options.file);
    EXPECT_EQ(back.options.sceneText, run.options.sceneText);
    EXPECT_EQ(back.options.plants, 2u);
    EXPECT_EQ(back.options.density, 1.5f);
    EXPECT_EQ(back.options.seed, 7);
    EXPECT_EQ(back.options.dt, 0.5f);
    EXPECT_EQ(back.state.ticks, 9u);
    EXPECT_EQ(back.state.nextStep, run.state.nextStep);
    const stream::SteppedState &a = run.state.plants, &b = back.state.plants;
    EXPECT_EQ(b.fieldStep, 3u);
    EXPECT_EQ(b.string.sym, a.string.sym);
    EXPECT_EQ(b.string.paramCount, a.string.paramCount);
    EXPECT_EQ(b.string.params, a.string.params);
    EXPECT_EQ(b.string.particles, a.string.particles);
    EXPECT_EQ(b.string.plantStart, a.string.plantStart);
    EXPECT_EQ(b.plants, a.plants);
}

TEST(SavedRun, DamagedFilesAreRefusedNotTrusted) {
    const std::string bytes = field::encodeSavedRun(sampleRun());
    // Cut anywhere short of its end.
    for (size_t length = 0; length < bytes.size(); ++length)
        EXPECT_THROW(field::decodeSavedRun(bytes.substr(0, length), "cut.bin"), ir::InputError) << length;
    // Each byte changed in turn: refused, or read as some consistent state.
    for (size_t at = 0; at < bytes.size(); ++at) {
        std::string damaged = bytes;
        damaged[at] = char(damaged[at] ^ char(1 + shared::randomBits(1, 0, 0, uint32_t(at), 0) % 255));
        try {
            const field::SavedRun run = field::decodeSavedRun(damaged, "damaged.bin");
            const stream::SteppedState& b = run.state.plants;
            EXPECT_EQ(b.string.plantStart.back(), b.string.size()) << at;
            EXPECT_EQ(b.plants.size(), run.state.nextStep.size()) << at;
        } catch (const ir::InputError& e) {
            EXPECT_NE(std::string(e.what()).find("not a state simeco can resume"), std::string::npos) << at;
        }
    }
    EXPECT_THROW(field::decodeSavedRun("PNG and more", "image.png"), ir::InputError);
}

} // namespace
} // namespace simeco
