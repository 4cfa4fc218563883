#include "corpus.h"

#include <stdlib.h>

#include <fstream>
#include <sstream>

namespace simeco::test {

std::vector<CorpusModel> readManifest() {
    std::vector<CorpusModel> models;
    std::ifstream in(kCorpus / "MANIFEST.tsv");
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream row(line);
        for (std::string cell; std::getline(row, cell, '\t');) cells.push_back(cell);
        if (cells.size() < 5) continue;
        models.push_back({cells[0], cells[1], cells[3], cells[4]});
    }
    return models;
}

void ScratchFolderTest::SetUp() {
    char pattern[] = "/tmp/simeco-corpus-XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    scratch_ = pattern;
    previous_ = std::filesystem::current_path();
    std::filesystem::current_path(scratch_);
}

void ScratchFolderTest::TearDown() {
    std::filesystem::current_path(previous_);
    std::filesystem::remove_all(scratch_);
}

} // namespace simeco::test
