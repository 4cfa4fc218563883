// The turtle kernels against the CPU reference turtle: every example grammar and every corpus model is derived
// on the CPU (under its homomorphism) and interpreted by both turtles; the instance buffers must hold the same
// organs in the same order, with positions and directions within a tolerance relative to the plant's size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "compute/shared/organ_layout.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "lang/load_grammar.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_gpu.h"

#include "../unit/square_surface.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

const fs::path kGrammars = fs::path(SIMECO_SOURCE_DIR) / "grammars";
const fs::path kCorpus = fs::path(SIMECO_SHARED_DIR) / "corpus" / "cpfg-vlab";
const fs::path kSeedScripts = fs::path(SIMECO_SHARED_DIR) / "seed-scripts";

// Strings longer than this are not interpreted here (lavapipe's time, not correctness, is the limit).
constexpr uint64_t kModuleBudget = 400'000;

glm::vec3 v3(const shared::vec4& v) { return {v.x, v.y, v.z}; }
std::string text(const shared::vec4& v) { return fmt::format("({:.5g}, {:.5g}, {:.5g}; {:.5g})", v.x, v.y, v.z, v.w); }

// The first organ where the two interpretations differ, or "".
std::string firstDifference(const turtle::Interpretation& want, const turtle::Interpretation& got) {
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k)
        if (want.count[k] != got.count[k] || want.first[k] != got.first[k]) {
            // The first module whose organ only one side drew.
            uint32_t i = 0;
            while (i < std::min(want.count[k], got.count[k]) &&
                   want.organs[want.first[k] + i].module == got.organs[got.first[k] + i].module)
                ++i;
            auto moduleAt = [&](const turtle::Interpretation& t) {
                return i < t.count[k] ? int64_t(t.organs[t.first[k] + i].module) : int64_t(-1);
            };
            return fmt::format("organ kind {}: {} at {} on the CPU, {} at {} on the GPU; the first organ "
                               "only one drew: CPU at module {}, GPU at module {}",
                               k, want.count[k], want.first[k], got.count[k], got.first[k], moduleAt(want), moduleAt(got));
        }
    if (want.organs.size() != got.organs.size()) return "instance counts differ";
    // Positions are compared relative to the field's size: long strings accumulate float rounding in
    // different orders (a sequential walk against composed steps).
    glm::vec3 extent = want.bounds.empty() ? glm::vec3(1.0f) : want.bounds.max - want.bounds.min;
    float size = std::max({1.0f, extent.x, extent.y, extent.z});
    float positionTolerance = 2e-3f * size, directionTolerance = 2e-3f;
    for (size_t i = 0; i < want.organs.size(); ++i) {
        const shared::OrganInstance &a = want.organs[i], &b = got.organs[i];
        auto differ = [&](const char* what, auto x, auto y) {
            return fmt::format("organ {} (kind {}, module {}): {} differ: CPU {} GPU {}", i, a.kind, a.module, what, x, y);
        };
        if (a.kind != b.kind || a.module != b.module || a.plant != b.plant || a.shape != b.shape)
            return differ("identities", fmt::format("{}/{}/{}/{}", a.kind, a.module, a.plant, a.shape),
                          fmt::format("{}/{}/{}/{}", b.kind, b.module, b.plant, b.shape));
        bool triangle = a.kind == shared::kOrganTriangle;
        float along = triangle ? positionTolerance : directionTolerance;
        auto far = [](glm::vec3 x, glm::vec3 y, float tolerance) { return glm::length(x - y) > tolerance; };
        if (far(v3(a.position), v3(b.position), positionTolerance))
            return differ("positions", text(a.position), text(b.position));
        if (far(v3(a.heading), v3(b.heading), along)) return differ("headings", text(a.heading), text(b.heading));
        if (far(v3(a.up), v3(b.up), along)) return differ("ups", text(a.up), text(b.up));
        float sizeTolerance = 1e-3f * std::max(1.0f, std::abs(a.position.w));
        if (std::abs(a.position.w - b.position.w) > sizeTolerance || std::abs(a.heading.w - b.heading.w) > sizeTolerance ||
            std::abs(a.up.w - b.up.w) > sizeTolerance)
            return differ("sizes", fmt::format("{} {} {}", a.position.w, a.heading.w, a.up.w),
                          fmt::format("{} {} {}", b.position.w, b.heading.w, b.up.w));
        if (far(v3(a.previousHeading), v3(b.previousHeading), directionTolerance) ||
            far(v3(a.nextHeading), v3(b.nextHeading), directionTolerance))
            return differ("joints", text(a.previousHeading) + text(a.nextHeading),
                          text(b.previousHeading) + text(b.nextHeading));
        if (a.color.x != b.color.x || a.color.y != b.color.y || a.color.z != b.color.z)
            return differ("colours", text(a.color), text(b.color));
    }
    if (std::abs(want.spacing - got.spacing) > 1e-3f * want.spacing)
        return fmt::format("field spacing differs: CPU {} GPU {}", want.spacing, got.spacing);
    for (int axis = 0; axis < 3; ++axis)
        if (std::abs(want.bounds.min[axis] - got.bounds.min[axis]) > positionTolerance ||
            std::abs(want.bounds.max[axis] - got.bounds.max[axis]) > positionTolerance)
            return fmt::format("bounds differ on axis {}", axis);
    return "";
}

struct Tally {
    int compared = 0, organs = 0;
    int nonlinear = 0; // strings with commands resolved level by level (tropism, `$`, @R, @M, world rotations)
    std::vector<std::string> skipped;
};

// Interprets a grammar's derived string with both turtles; fails the test on a difference.
void compareTurtles(const vk::Context& context, const fs::path& file, const std::string& name, uint32_t plants,
                    Tally& tally) {
    SCOPED_TRACE(name);
    ir::Grammar g = lang::loadGrammarFile(file.string());
    stream::DeriveOptions options;
    options.homomorphism = true;
    options.plants = plants;
    options.maxModules = kModuleBudget;
    stream::ModuleString string;
    try {
        string = cpu::deriveCpu(g, options).string;
    } catch (const ir::LimitError&) {
        tally.skipped.push_back(name);
        return;
    }
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    std::vector<turtle::TurtleSettings> species{turtle::turtleSettings(g, g.alphabet)};
    turtle::Interpretation want = turtle::interpretCpu(string, commands, species, {});
    if (string.size() == 0) return;

    turtle::GpuTurtle turtle(context, commands, species);
    turtle::UploadedModules modules(context, string);
    const turtle::DeviceOrgans& organs = turtle.interpret(modules.view(), {});
    turtle::Interpretation got = turtle::readBack(context, organs, uint32_t(string.plants()));
    std::string difference = firstDifference(want, got);
    if (size_t at = difference.rfind("module "); at != std::string::npos) {
        // The modules around the first difference, to see which commands are involved.
        size_t module = std::strtoull(difference.c_str() + at + 7, nullptr, 10);
        size_t from = module >= 8 ? module - 8 : 0, to = std::min(string.size(), module + 4);
        difference += fmt::format("; modules {}..{}: {}", from, to, stream::formatModules(string, g.alphabet, from, to));
    }
    EXPECT_EQ(difference, "") << name << " (" << string.size() << " modules, " << turtle.lastLevels()
                              << " levels of non-linear commands)";
    if (!difference.empty()) return;
    const uint32_t levels = turtle.lastLevels();
    // Recorded again within the room it took, with only the searches its marks ask for, as a growing field draws a
    // string it drew before: the same organs.
    turtle::TurtleRoom room = turtle.lastRoom();
    room.marks = turtle.lastMarks();
    const turtle::DeviceOrgans* recorded = nullptr;
    context.submitAndWait([&](VkCommandBuffer cmd) { recorded = &turtle.record(cmd, modules.view(), {}, room); });
    EXPECT_TRUE(turtle.recorded().fit) << name;
    EXPECT_EQ(firstDifference(want, turtle::readBack(context, *recorded, uint32_t(string.plants()))), "")
        << name << " recorded within its room";
    ++tally.compared;
    if (levels > 0) ++tally.nonlinear;
    tally.organs += int(want.organs.size());
}

using TurtleGpuTest = GpuTest;

// The example grammars, the example scenes and the seed documents' SimEco scripts (their organs drawn by the
// stage homomorphism, their branches by rotr and rotu).
TEST_F(TurtleGpuTest, ExampleGrammarsMatchTheCpuTurtle) {
    std::vector<fs::path> files;
    auto collect = [&](const fs::path& folder, std::initializer_list<const char*> extensions) {
        for (const auto& entry : fs::recursive_directory_iterator(folder))
            for (const char* ext : extensions)
                if (entry.path().extension() == ext) files.push_back(entry.path());
    };
    collect(kGrammars, {".l", ".lsys"});
    collect(kGrammars.parent_path() / "scenes", {".eco"});
    collect(kSeedScripts, {".eco"});
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 24u) << "example grammars not found under " << kGrammars;
    Tally tally;
    for (const fs::path& f : files) {
        try {
            compareTurtles(context(), f, f.filename().string(), 1, tally);
        } catch (const std::exception& e) {
            ADD_FAILURE() << f << ": " << e.what();
        }
    }
    std::printf("example grammars: %d interpreted alike (%d organs, %d with non-linear commands), %zu over %llu "
                "modules\n",
                tally.compared, tally.organs, tally.nonlinear, tally.skipped.size(),
                static_cast<unsigned long long>(kModuleBudget));
    EXPECT_EQ(tally.compared + int(tally.skipped.size()), int(files.size()));
    EXPECT_LE(tally.skipped.size(), 2u);
    EXPECT_GT(tally.organs, 1000);
}

TEST_F(TurtleGpuTest, CorpusModelsMatchTheCpuTurtle) {
    std::ifstream in(kCorpus / "MANIFEST.tsv");
    std::string line;
    std::getline(in, line); // header
    Tally tally;
    int models = 0;
    char scratch[] = "/tmp/simeco-gpu-turtle-XXXXXX"; // models may write files relative to the working directory
    ASSERT_NE(mkdtemp(scratch), nullptr);
    fs::path previous = fs::current_path();
    fs::current_path(scratch);
    while (std::getline(in, line)) {
        std::stringstream row(line);
        std::string folder, file;
        std::getline(row, folder, '\t');
        std::getline(row, file, '\t');
        if (folder.empty() || file.empty()) continue;
        ++models;
        try {
            compareTurtles(context(), kCorpus / "models" / folder / file, folder, 1, tally);
        } catch (const std::exception& e) {
            ADD_FAILURE() << folder << ": " << e.what();
        }
    }
    fs::current_path(previous);
    fs::remove_all(scratch);
    ASSERT_GE(models, 60) << "the corpus manifest was not found or is incomplete at " << kCorpus;
    std::printf("corpus models: %d interpreted alike (%d organs, %d with non-linear commands), %zu over %llu "
                "modules:",
                tally.compared, tally.organs, tally.nonlinear, tally.skipped.size(),
                static_cast<unsigned long long>(kModuleBudget));
    for (const std::string& s : tally.skipped) std::printf(" %s", s.c_str());
    std::printf("\n");
    EXPECT_EQ(tally.compared + int(tally.skipped.size()), models);
    EXPECT_LE(tally.skipped.size(), 6u);
    EXPECT_GE(tally.nonlinear, 5) << "the corpus should exercise tropism and absolute commands";
}

// A folder for a test's model files, removed with it.
struct ModelFolder {
    fs::path path;
    explicit ModelFolder(const std::string& name)
        : path(fs::temp_directory_path() / ("simeco-gpu-" + name + "-" + std::to_string(::getpid()))) {
        fs::create_directories(path);
    }
    ~ModelFolder() { fs::remove_all(path); }
    ModelFolder(const ModelFolder&) = delete;
    ModelFolder& operator=(const ModelFolder&) = delete;
};

// A cpfg view's surfaces (drawn scaled one way or three, moving the turtle to their end point, one the view does
// not define drawing nothing), initial scale, `@D` (scaling the widths set after it) and `tropism:` line (bending
// before every move), in a field of plants.
TEST_F(TurtleGpuTest, ACpfgViewsSurfacesScaleAndTropismDrawAsOnTheCpu) {
    const ModelFolder scratch("surface");
    const fs::path& folder = scratch.path;
    std::ofstream(folder / "sq.s") << testing::squareSurface();
    std::ofstream(folder / "m.v") << "surface: s sq.s 2 3 2\nangle increment: 30\ninitial scale: 1.5\n"
                                     "tropism: T: 1,0,0 E: 0.2\n";
    std::ofstream(folder / "m.l") << "Lsystem: 1\nAxiom: F~s(1.5)F(1)[+@D(2)~s(1,2,3)!(0.3)F#F@O]/~q(2)fF~s-F\n"
                                     "endlsystem\n";
    Tally tally;
    compareTurtles(context(), folder / "m.l", "surfaces", 3, tally);
    EXPECT_EQ(tally.compared, 1);
    EXPECT_EQ(tally.organs, 3 * (6 + 3 + 1)); // per plant six segments, three surfaces and a sphere
}

// Generalized cylinders drawn as cpfg's meshes (`line style: cylinder`): a contour and the circle (an id no
// `contour:` line gives), `@Gt` tangents, both kinds of `@Gr`, a branch that continues from the cylinder's last
// point, turns and rolls between points; with the frame carried along the cylinder and with the view's twist.
TEST_F(TurtleGpuTest, CpfgCylinderMeshesDrawAsOnTheCpu) {
    const ModelFolder scratch("cylinder");
    const fs::path& folder = scratch.path;
    std::ofstream(folder / "c.con") << "cver 1 3\nname: c\npoints: 5 5\ntype: cr\nsamples: 5\n"
                                       "1 0 0 1\n0.2 1 0 1\n-1 0.5 0 1\n-0.5 -1 0 1\n0.6 -0.8 0 1\n";
    std::ofstream(folder / "m.l")
        << "Lsystem: 1\nAxiom: #(0.2)@Gs F(1)+(30)/(40)@Gc(3)@#(3)@Gt(0.8,1.5)F(1)&(25)\\(15)#(0.3)@Gc(2)"
           "[+(60)@Gr(0,0,-45,0.1)F(1)@Gc(4)@#(7)F(1)/(90)@Ge]@Gr(2)@Gr(30,0.2,10,0.1)-(40)F(1)^(20)@Ge(5)\n"
           "endlsystem\n";
    for (const char* twist : {"off", "on"}) {
        std::ofstream(folder / "m.v") << "line style: cylinder\ncontour sides: 6\ncontour: 3 c.con\n"
                                      << "twist of cylinders: " << twist << "\n";
        Tally tally;
        compareTurtles(context(), folder / "m.l", std::string("cylinders, twist ") + twist, 2, tally);
        EXPECT_EQ(tally.compared, 1);
        // Per plant 18 strips of 12 triangles, and five segments.
        EXPECT_EQ(tally.organs, 2 * (18 * 12 + 5));
    }
}

// cpfg's torque lines roll the turtle before every move, after the tropism lines' bend (a large elasticity turning
// as cpfg's quaternion does), on the device as on the CPU.
TEST_F(TurtleGpuTest, CpfgTorqueRollsAsOnTheCpu) {
    const ModelFolder scratch("torque");
    std::ofstream(scratch.path / "m.l")
        << "Lsystem: 1\nderivation length: 3\nAxiom: A\nA --> F[+(30)A]/(20)F[-(25)&(10)A]fA\nendlsystem\n";
    std::ofstream(scratch.path / "m.v")
        << "line style: cylinder\ntropism: T: 0,-1,0 E: 1.5\ntorque: T: 1,0,0.5 E: 0.3\ntorque: T: 0,0,1 E: 0.2\n";
    Tally tally;
    compareTurtles(context(), scratch.path / "m.l", "torque", 2, tally);
    EXPECT_EQ(tally.compared, 1);
    EXPECT_EQ(tally.nonlinear, 1);
}

// cpfg's tubes in its polygon and pixel line styles: pieces through the curve's points (tangents from `@Gt`,
// spaced by the radius curve `@Gr` gives), as wide as their start, the last tapering where polygons do.
TEST_F(TurtleGpuTest, CpfgTubesDrawAsOnTheCpu) {
    const ModelFolder scratch("tubes");
    const fs::path& folder = scratch.path;
    std::ofstream(folder / "m.l")
        << "Lsystem: 1\nAxiom: !(0.2)@Gt(1)@Gs f(1)+(30)/(40)!(0.15)@Gc(3)@Gt(0.8,1.5)f(1)&(25)@Gc"
           "[+(60)@Gr(0,0,-45,0.1)f(1)!(0.05)@Gc(5)]@Gr(2)@Gr(30,0.2,10,0.1)-(40)f(1)@Ge(4.5)\nendlsystem\n";
    for (const char* style : {"polygon", "pixel"}) {
        std::ofstream(folder / "m.v") << "line style: " << style << "\n";
        Tally tally;
        compareTurtles(context(), folder / "m.l", std::string("tubes, ") + style, 2, tally);
        EXPECT_EQ(tally.compared, 1);
        EXPECT_EQ(tally.organs, 2 * (3 + 4 + 5 + 4)); // per plant: @Gc(3), @Gc, @Gc(5), @Ge(4.5)
    }
}

// cpfg's sub-L-system calls scale lengths and widths until their `$`, nested, across branches and with `@D`
// scaling between them; the device finds each `$`'s call as the CPU's stack does.
TEST_F(TurtleGpuTest, SubLsystemCallsScaleAsOnTheCpu) {
    const ModelFolder scratch("sub-lsystems");
    const fs::path& folder = scratch.path;
    std::ofstream(folder / "m.l")
        << "Lsystem: 1\nderivation length: 4\nAxiom: !(0.4)A\nA --> F[+(40)?(2,0.6)B$]@Di(1.1)/(90)A\n"
           "endlsystem\nLsystem: 2\nAxiom: B\nB --> F?(3,0.5)[-(30)!(0.3)C]$#B\nendlsystem\n"
           "Lsystem: 3\nAxiom: C\nC --> F(2)C\nendlsystem\n";
    std::ofstream(folder / "m.v") << "line style: cylinder\n";
    Tally tally;
    compareTurtles(context(), folder / "m.l", "sub-L-systems", 3, tally);
    EXPECT_EQ(tally.compared, 1);
    // Per plant: the main axis's four segments; the branches of steps 1 to 3 add three, two and one of L-system 2
    // and three, one and none of L-system 3.
    EXPECT_EQ(tally.organs, 3 * 14);
}

// Many plants in one stream: each plant keeps its own root and the field places them as the CPU does.
TEST_F(TurtleGpuTest, AFieldOfPlantsMatchesTheCpuTurtle) {
    Tally tally;
    compareTurtles(context(), kGrammars / "abop" / "fig2.8-ternary.l", "ternary field", 16, tally);
    compareTurtles(context(), kGrammars / "abop" / "fig1.24d.l", "plant field", 7, tally);
    EXPECT_EQ(tally.compared, 2);
}

// Plants placed by the field (turtle::FieldOptions::placements): turned, tilted and moved as their placements say,
// on the device as on the CPU; a trunk starts at its plant's place and grows along its direction.
TEST_F(TurtleGpuTest, PlacedPlantsStandWhereTheirPlacementsPutThem) {
    ir::Grammar g = lang::loadGrammarFile((kGrammars / "abop" / "fig2.8-ternary.l").string());
    stream::DeriveOptions options;
    options.plants = 4;
    options.steps = 3;
    stream::ModuleString string = cpu::deriveCpu(g, options).string;
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    std::vector<turtle::TurtleSettings> species{turtle::turtleSettings(g, g.alphabet)};
    turtle::FieldOptions field;
    const std::vector<glm::vec3> places{{3, 0, -2}, {-5, 1, 0}, {0, 0, 7}, {2, -1, 2}};
    const std::vector<glm::vec3> directions{{0, 1, 0}, {1, 1, 0}, {0, 0.1f, 0}, {0, -1, 0}};
    for (size_t p = 0; p < places.size(); ++p)
        field.placements.push_back(turtle::placementAt(places[p], directions[p], 0.7f * float(p)));
    turtle::Interpretation want = turtle::interpretCpu(string, commands, species, field);
    turtle::GpuTurtle turtle(context(), commands, species);
    turtle::UploadedModules modules(context(), string);
    turtle::Interpretation got = turtle::readBack(context(), turtle.interpret(modules.view(), field), 4);
    EXPECT_EQ(firstDifference(want, got), "");
    ASSERT_EQ(got.plantOrigins.size(), 4u);
    for (uint32_t p = 0; p < 4; ++p) {
        EXPECT_LT(glm::length(got.plantOrigins[p] - places[p]), 1e-6f) << p;
        // The plant's first stem: its trunk.
        const shared::OrganInstance* trunk = nullptr;
        for (uint32_t i = 0; i < want.count[shared::kOrganStem] && !trunk; ++i)
            if (want.organs[want.first[shared::kOrganStem] + i].plant == p)
                trunk = &want.organs[want.first[shared::kOrganStem] + i];
        ASSERT_NE(trunk, nullptr) << p;
        EXPECT_LT(glm::length(v3(trunk->position) - places[p]), 1e-5f) << p;
        EXPECT_GT(glm::dot(v3(trunk->heading), glm::normalize(directions[p])), 0.9999f) << p;
    }
}

// A field without placements, scattered about its grid (turtle::FieldOptions::scattered), on the device as on the CPU.
TEST_F(TurtleGpuTest, AScatteredFieldStandsAsOnTheCpu) {
    ir::Grammar g = lang::loadGrammarFile((kGrammars / "abop" / "fig1.24d.l").string());
    stream::DeriveOptions options;
    options.plants = 5;
    options.steps = 3;
    stream::ModuleString string = cpu::deriveCpu(g, options).string;
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    std::vector<turtle::TurtleSettings> species{turtle::turtleSettings(g, g.alphabet)};
    turtle::FieldOptions field;
    field.scattered = true;
    turtle::Interpretation want = turtle::interpretCpu(string, commands, species, field);
    turtle::GpuTurtle turtle(context(), commands, species);
    turtle::UploadedModules modules(context(), string);
    turtle::Interpretation got = turtle::readBack(context(), turtle.interpret(modules.view(), field), 5);
    EXPECT_EQ(firstDifference(want, got), "");
    ASSERT_EQ(got.plantOrigins.size(), 5u);
    for (uint32_t p = 0; p < 5; ++p) {
        EXPECT_LT(glm::length(got.plantOrigins[p] - want.plantOrigins[p]), 1e-5f) << p;
        EXPECT_GT(glm::length(want.plantOrigins[p] - turtle::fieldCell(p, 5) * want.spacing), 1e-3f) << p;
    }
}

// Derivation and turtle without the host in between: the turtle kernels read the string the derivation
// kernels left on the device (what `simeco render` does when there is no homomorphism to apply).
TEST_F(TurtleGpuTest, TheDerivedStringOnTheDeviceMatchesTheCpuTurtle) {
    int compared = 0;
    for (const char* file : {"abop/fig2.8-ternary.l", "abop/fig1.27-stochastic.l", "abop/fig1.31b.l", "abop/fig2.6-monopodial.l"}) {
        SCOPED_TRACE(file);
        ir::Grammar g = lang::loadGrammarFile((kGrammars / file).string());
        ASSERT_FALSE(g.homomorphism.present && !g.homomorphism.productions.empty());
        stream::DeriveOptions options;
        options.plants = 5;
        stream::ModuleString string = cpu::deriveCpu(g, options).string;
        turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
        std::vector<turtle::TurtleSettings> species{turtle::turtleSettings(g, g.alphabet)};
        turtle::Interpretation want = turtle::interpretCpu(string, commands, species, {});

        gpu::GpuDeriver deriver(context(), g);
        deriver.derive(options, /*readBack=*/false);
        stream::DeviceModules modules = deriver.lastString();
        ASSERT_EQ(modules.count, string.size());
        turtle::GpuTurtle turtle(context(), commands, species);
        turtle::Interpretation got = turtle::readBack(context(), turtle.interpret(modules, {}), modules.plants);
        EXPECT_EQ(firstDifference(want, got), "");
        EXPECT_GT(want.organs.size(), 100u);
        ++compared;
    }
    EXPECT_EQ(compared, 4);
}

// One turtle interprets fields that grow and shrink in turn: its buffers, kept and grown between
// interpretations, hold what a larger field left beyond a smaller one's modules, which must change nothing.
TEST_F(TurtleGpuTest, OneTurtleInterpretsFieldsOfEverySize) {
    ir::Grammar g = lang::loadGrammarFile((kGrammars / "abop" / "fig2.8-ternary.l").string());
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    std::vector<turtle::TurtleSettings> species{turtle::turtleSettings(g, g.alphabet)};
    turtle::GpuTurtle turtle(context(), commands, species);
    struct Field {
        int steps;
        uint32_t plants;
    };
    int compared = 0;
    for (Field f : {Field{5, 3}, Field{2, 1}, Field{6, 4}, Field{1, 2}, Field{4, 9}}) {
        SCOPED_TRACE(fmt::format("{} steps, {} plants", f.steps, f.plants));
        stream::DeriveOptions options;
        options.steps = f.steps;
        options.plants = f.plants;
        stream::ModuleString string = cpu::deriveCpu(g, options).string;
        turtle::Interpretation want = turtle::interpretCpu(string, commands, species, {});
        turtle::UploadedModules modules(context(), string);
        turtle::Interpretation got = turtle::readBack(context(), turtle.interpret(modules.view(), {}), f.plants);
        EXPECT_EQ(firstDifference(want, got), "");
        EXPECT_GT(want.organs.size(), 0u);
        ++compared;
    }
    EXPECT_EQ(compared, 5);
}

// Plants without modules: an empty table, no instances, nothing dispatched over nothing.
TEST_F(TurtleGpuTest, EmptyPlantsDrawNothing) {
    ir::Grammar g = lang::loadGrammarFile((kGrammars / "abop" / "fig1.24a.l").string());
    stream::ModuleString empty;
    empty.plantStart = {0, 0, 0};
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    turtle::UploadedModules modules(context(), empty);
    turtle::Interpretation got = turtle::readBack(context(), turtle.interpret(modules.view(), {}), 2);
    EXPECT_TRUE(got.organs.empty());
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k) EXPECT_EQ(got.count[k], 0u);
    EXPECT_TRUE(got.bounds.empty());
}

} // namespace
} // namespace simeco::test
