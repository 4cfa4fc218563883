// The homomorphism on the device against the CPU reference's: every example grammar, scene and corpus model
// with a homomorphism is derived under it by both engines, and the strings must match as derived strings do.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compare_strings.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/source_loc.h"
#include "lang/load_grammar.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = fs::path(SIMECO_SOURCE_DIR);
const fs::path kCorpus = fs::path(SIMECO_SHARED_DIR) / "corpus" / "cpfg-vlab";

struct Tally {
    int withHomomorphism = 0, matched = 0;
    std::vector<std::string> onHost; // homomorphisms the parallel passes cannot run (the host applies them)
};

void compareHomomorphism(const vk::Context& context, const fs::path& file, const std::string& name, Tally& tally) {
    SCOPED_TRACE(name);
    ir::Grammar g = lang::loadGrammarFile(file.string());
    if (!g.homomorphism.present || g.homomorphism.productions.empty()) return;
    if (codegen::gpuUnsupportedReason(g)) return; // the GPU does not derive it at all
    ++tally.withHomomorphism;
    stream::DeriveOptions options;
    options.homomorphism = true;
    options.plants = 3;
    options.maxModules = 2'000'000;
    stream::DeriveResult want;
    try {
        want = cpu::deriveCpu(g, options);
    } catch (const ir::LimitError&) {
        return;
    }
    gpu::GpuDeriver deriver(context, g);
    if (!deriver.appliesHomomorphism()) {
        tally.onHost.push_back(name);
        return;
    }
    stream::DeriveResult got = deriver.derive(options);
    std::string difference = firstDifference(want, got, g.alphabet);
    EXPECT_EQ(difference, "");
    if (difference.empty()) ++tally.matched;
}

using HomomorphismGpuTest = GpuTest;

TEST_F(HomomorphismGpuTest, ExamplesAndCorpusModelsMatchTheCpu) {
    char scratch[] = "/tmp/simeco-gpu-homomorphism-XXXXXX"; // models may write files where they run
    ASSERT_NE(mkdtemp(scratch), nullptr);
    fs::path previous = fs::current_path();
    fs::current_path(scratch);
    Tally tally;
    std::vector<fs::path> files;
    for (const fs::path& folder : {kSource / "grammars", kSource / "scenes"})
        for (const auto& entry : fs::recursive_directory_iterator(folder))
            if (entry.path().extension() == ".l" || entry.path().extension() == ".eco") files.push_back(entry.path());
    std::ifstream manifest(kCorpus / "MANIFEST.tsv");
    std::string line;
    std::getline(manifest, line); // header
    while (std::getline(manifest, line)) {
        std::stringstream row(line);
        std::string folder, file;
        std::getline(row, folder, '\t');
        std::getline(row, file, '\t');
        if (!folder.empty() && !file.empty()) files.push_back(kCorpus / "models" / folder / file);
    }
    for (const fs::path& f : files) {
        try {
            compareHomomorphism(context(), f, f.parent_path().filename().string() + "/" + f.filename().string(), tally);
        } catch (const std::exception& e) {
            ADD_FAILURE() << f << ": " << e.what();
        }
    }
    fs::current_path(previous);
    fs::remove_all(scratch);
    std::printf("homomorphisms: %d of %d match the CPU on the device; applied on the host:", tally.matched,
                tally.withHomomorphism);
    for (const std::string& n : tally.onHost) std::printf(" %s", n.c_str());
    std::printf("\n");
    EXPECT_GE(tally.withHomomorphism, 40) << "the corpus and scenes should bring homomorphisms";
    EXPECT_EQ(tally.matched + int(tally.onHost.size()), tally.withHomomorphism);
    EXPECT_LE(tally.onHost.size() * 10, size_t(tally.withHomomorphism)) << "most homomorphisms run on the device";
}

} // namespace
} // namespace simeco::test
