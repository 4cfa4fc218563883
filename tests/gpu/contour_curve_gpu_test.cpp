// Contour curves (curveX/curveY/curveZ/curveGAL) on the device against the CPU reference: every curve type, arc-
// length tables of different sizes, parameters outside [0, 1], a curve of too few points, and an unknown curve id.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "compare_strings.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/source_loc.h"
#include "lang/load_grammar.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

// A model folder of its own: an L-system, its view file and the contour files the view file names.
class CurveModelGpuTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        if (HasFatalFailure()) return;
        dir_ = fs::temp_directory_path() / ("simeco-curves-gpu-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override {
        fs::remove_all(dir_);
        GpuTest::TearDown();
    }

    void write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name, std::ios::binary) << text;
    }
    ir::Grammar load() { return lang::loadGrammarFile((dir_ / "model.l").string()); }

    fs::path dir_;
};

// A contour of `type` through points with multiplicities, in the 1.4 file format.
std::string contour(const std::string& type, const std::string& points, int count) {
    return "version: 1.4\ncontact: 0 0 0\nend: 0 0 0\nheading: 0 1 0\nup: 0 0 -1\nsize: 1\npoints: " +
           std::to_string(count) + "\nrange: 0.0 1.0\ndimension: 4\ntype: " + type + "\n" + points;
}

const char* kPoints = "0 0 0 1\n1 0 0.5 1\n1 1 0 2\n0 1 -0.5 1\n0.5 2 1 1\n-0.25 2.5 0.75 1\n";

TEST_F(CurveModelGpuTest, EveryCurveTypeMatchesTheCpu) {
    const char* types[] = {"bspline", "bspline-closed", "bspline-endpoint", "bspline-phantom", "bezier"};
    std::string view;
    for (int c = 0; c < 5; ++c) {
        std::string file = fmt::format("c{}.con", c + 1);
        write(file, contour(types[c], kPoints, 6));
        // Arc-length tables of cpfg's default 100 samples, and of 7 and 400.
        view += fmt::format("curve: {}{}\n", file, c == 1 ? " 7" : c == 3 ? " 400" : "");
    }
    write("c6.con", contour("bspline", "0 0 0 1\n1 2 3 2\n", 2)); // three evaluation points: the origin, length 0
    view += "curve: c6.con\n";
    write("model.v", view);
    // One module per curve and parameter: its point and its length; t runs beyond both ends.
    std::string axiom;
    for (int c = 1; c <= 6; ++c)
        for (const char* t : {"-0.5", "0", "0.0101", "0.25", "0.3333", "0.5", "0.77", "0.999", "1", "1.5"})
            axiom += fmt::format("T({},{})", c, t);
    write("model.l", "Lsystem: 1\nDerivation length: 1\nAxiom: " + axiom +
                         "\nT(c,t) --> C(c,curveX(c,t),curveY(c,t),curveZ(c,t),curveGAL(c))\nendlsystem\n");
    ir::Grammar g = load();
    ASSERT_EQ(g.curves.size(), 6u);
    ASSERT_FALSE(codegen::gpuUnsupportedReason(g).has_value()) << *codegen::gpuUnsupportedReason(g);
    stream::DeriveResult want = cpu::deriveCpu(g, {});
    ASSERT_EQ(want.string.size(), 60u);
    for (gpu::GpuStrategy strategy : {gpu::GpuStrategy::Parallel, gpu::GpuStrategy::Sequential}) {
        SCOPED_TRACE(strategy == gpu::GpuStrategy::Parallel ? "parallel" : "sequential");
        gpu::GpuDeriver deriver(context(), g, strategy);
        EXPECT_EQ(firstDifference(want, deriver.derive({}), g.alphabet), "");
    }
}

// An id the view file does not define is reported at the call, on the device as on the CPU.
TEST_F(CurveModelGpuTest, UnknownCurveIsALocatedError) {
    write("c1.con", contour("bezier", kPoints, 6));
    write("model.v", "curve: c1.con\n");
    write("model.l", "Lsystem: 1\nDerivation length: 1\nAxiom: T(2)\nT(n) --> B(curveY(n, 0.5))\nendlsystem\n");
    ir::Grammar g = load();
    int cpuLine = 0, cpuCol = 0;
    try {
        cpu::deriveCpu(g, {});
        FAIL() << "the CPU reference derived an unknown curve";
    } catch (const ir::InputError& e) {
        cpuLine = e.loc().line;
        cpuCol = e.loc().col;
    }
    for (gpu::GpuStrategy strategy : {gpu::GpuStrategy::Parallel, gpu::GpuStrategy::Sequential}) {
        SCOPED_TRACE(strategy == gpu::GpuStrategy::Parallel ? "parallel" : "sequential");
        gpu::GpuDeriver deriver(context(), g, strategy);
        try {
            deriver.derive({});
            ADD_FAILURE() << "the device derived an unknown curve";
        } catch (const ir::InputError& e) {
            EXPECT_EQ(e.loc().line, cpuLine);
            EXPECT_EQ(e.loc().col, cpuCol);
            EXPECT_NE(std::string(e.what()).find("no such curve"), std::string::npos) << e.what();
        }
    }
}

} // namespace
} // namespace simeco::test
