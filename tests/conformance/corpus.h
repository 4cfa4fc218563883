// The shared cpfg corpus as the conformance tests read it: its folder, its manifest of models, and a test fixture
// that runs in a scratch folder (models may write files relative to the working folder).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace simeco::test {

inline const std::filesystem::path kCorpus = std::filesystem::path(SIMECO_SHARED_DIR) / "corpus" / "cpfg-vlab";

// A row of MANIFEST.tsv: the model's folder under models/, its L-system file, its features, and how it compares
// with cpfg (`exact` strings and geometry, or `structure`).
struct CorpusModel {
    std::string folder, file, features, compare;
};

std::vector<CorpusModel> readManifest();

class ScratchFolderTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
    std::filesystem::path scratch_, previous_;
};

} // namespace simeco::test
