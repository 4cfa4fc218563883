// Output files appear together or not at all (draw/atomic_file.h): a failed file takes its batch's others with
// it, a batch dropped before its commit leaves nothing, SIGTERM during a write leaves no temporary, and the
// temporaries that processes no longer running left behind are removed by the next write of their file.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "draw/atomic_file.h"
#include "temporary_folder.h"

namespace {

namespace fs = std::filesystem;
using simeco::draw::OutputBatch;
using simeco::draw::OutputError;

class OutputBatchTest : public simeco::testing::TemporaryFolderTest {
protected:
    // The folder's file names, sorted.
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const fs::directory_entry& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    }
};

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

TEST_F(OutputBatchTest, ACommittedBatchLeavesEveryFileAndNoTemporary) {
    OutputBatch batch;
    batch.write(dir_ / "a.exr", [](const fs::path& t) { writeText(t, "a"); });
    batch.write(dir_ / "a.png", [](const fs::path& t) { writeText(t, "b"); });
    EXPECT_FALSE(fs::exists(dir_ / "a.exr")); // nothing appears before the commit
    batch.commit();
    EXPECT_EQ(files(), (std::vector<std::string>{"a.exr", "a.png"}));
}

TEST_F(OutputBatchTest, AFailedFileLeavesNoneOfItsBatch) {
    OutputBatch batch;
    batch.write(dir_ / "ok.exr", [](const fs::path& t) { writeText(t, "a"); });
    EXPECT_THROW(batch.write(dir_ / "missing" / "a.png", [](const fs::path& t) { writeText(t, "b"); }), OutputError);
    EXPECT_TRUE(files().empty());
}

TEST_F(OutputBatchTest, ABatchDroppedBeforeItsCommitLeavesNothing) {
    {
        OutputBatch batch;
        batch.write(dir_ / "a.exr", [](const fs::path& t) { writeText(t, "a"); });
        EXPECT_EQ(files().size(), 1u);
    }
    EXPECT_TRUE(files().empty());
}

TEST_F(OutputBatchTest, SigtermDuringAWriteLeavesNoTemporary) {
    fs::path destination = dir_ / "field.exr";
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        OutputBatch batch;
        batch.write(destination, [](const fs::path& t) {
            writeText(t, "partial");
            std::raise(SIGTERM);
        });
        ::_exit(0); // not reached: SIGTERM ends the process
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
    EXPECT_TRUE(files().empty());
}

TEST_F(OutputBatchTest, TemporariesOfProcessesNoLongerRunningAreRemoved) {
    pid_t gone = ::fork();
    ASSERT_GE(gone, 0);
    if (gone == 0) ::_exit(0);
    ASSERT_EQ(::waitpid(gone, nullptr, 0), gone);
    std::string stale = "field.png.tmp" + std::to_string(gone);
    std::string live = "field.png.tmp" + std::to_string(::getppid()); // a running process's write stays
    writeText(dir_ / stale, "stale");
    writeText(dir_ / live, "live");
    writeText(dir_ / "other.png.tmp1", "another file's");
    simeco::draw::writeAtomically(dir_ / "field.png", [](const fs::path& t) { writeText(t, "new"); });
    EXPECT_EQ(files(), (std::vector<std::string>{"field.png", live, "other.png.tmp1"}));
}

} // namespace
