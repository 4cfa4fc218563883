// Malformed `.l` input: each case must give `file:line:col: error: message` (as an InputError), never a
// crash, a hang or a partial result. Derive-time errors (division by zero, ...) are reported the same way.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cpu/derive.h"
#include "lang/load_grammar.h"
#include "temporary_folder.h"

namespace {

namespace fs = std::filesystem;

struct MalformedCase {
    const char* name;
    std::string text;
    int line;            // expected line of the error
    int col;             // expected column, 0 when not checked
    const char* message; // a part of the expected message
};

// Writes `text` to a fresh file and loads and derives it; returns the error it reported.
std::optional<simeco::ir::InputError> loadAndDerive(const std::string& text, const std::string& fileName,
                                                    fs::path& pathOut) {
    fs::path dir = fs::temp_directory_path() / ("simeco-malformed-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    pathOut = dir / fileName;
    {
        std::ofstream out(pathOut, std::ios::binary);
        out << text;
    }
    try {
        simeco::ir::Grammar g = simeco::lang::loadGrammarFile(pathOut.string());
        simeco::stream::DeriveOptions options;
        options.maxModules = 100000;
        simeco::cpu::deriveCpu(g, options);
    } catch (const simeco::ir::InputError& e) {
        fs::remove_all(dir);
        return e;
    }
    fs::remove_all(dir);
    return std::nullopt;
}

std::string lsys(const std::string& body) { return "Lsystem: 1\nderivation length: 2\n" + body + "\nendlsystem\n"; }

const std::vector<MalformedCase>& cases() {
    static const std::vector<MalformedCase> all = {
        {"unbalanced_open_bracket", lsys("Axiom: F\nF --> F[+F"), 4, 8, "unbalanced '['"},
        {"unbalanced_close_bracket", lsys("Axiom: F\nF --> F]+F"), 4, 8, "unbalanced ']'"},
        {"unbalanced_axiom", lsys("Axiom: F[[F]"), 3, 9, "unbalanced '['"},
        {"bad_expression_operator", lsys("Axiom: A(1)\nA(x) --> A(x+*2)"), 4, 14, "unexpected '*'"},
        {"missing_close_paren", lsys("Axiom: A(1)\nA(x) --> A((x+1)"), 4, 17, "expected ',' or ')'"},
        {"undefined_name", lsys("Axiom: A(1)\nA(x) --> A(y)"), 4, 12, "undefined name 'y'"},
        {"undefined_name_in_condition", lsys("Axiom: A(1)\nA(x) : z > 1 --> A(x)"), 4, 8, "undefined name 'z'"},
        {"unknown_function", lsys("Axiom: A(1)\nA(x) --> A(foo(x))"), 4, 12, "unknown function 'foo'"},
        {"wrong_argument_count", lsys("Axiom: A(1)\nA(x) --> A(sqrt(x, 2))"), 4, 12, "'sqrt' takes 1 argument"},
        {"division_by_zero", lsys("Axiom: A(1)\nA(x) --> A(x/0)"), 4, 13, "division by zero"},
        {"division_by_zero_variable", lsys("Axiom: A(1,0)\nA(x,z) --> A(x/z,z)"), 4, 15, "division by zero"},
        {"remainder_by_zero", lsys("Axiom: A(5)\nA(x) --> A(x%0)"), 4, 13, "remainder by zero"},
        {"missing_arrow", lsys("Axiom: F\nF FF"), 4, 5, "expected '-->'"},
        {"empty_successor_needs_star", lsys("Axiom: F\nF -->"), 4, 0, "the successor is empty"},
        {"missing_axiom", "Lsystem: 1\nderivation length: 2\nF --> FF\nendlsystem\n", 3, 1, "expected 'Axiom:'"},
        {"missing_lsystem", "derivation length: 2\nAxiom: F\n", 1, 1, "expected 'Lsystem:'"},
        {"missing_endlsystem", "Lsystem: 1\nAxiom: F\nF --> FF\n", 3, 0, "missing 'endlsystem'"},
        {"bad_derivation_length", lsys("derivation length: -3\nAxiom: F"), 3, 1, "derivation length"},
        {"non_constant_derivation_length", "Lsystem: 1\nderivation length: q\nAxiom: F\nendlsystem\n", 2, 20, "undefined name 'q'"},
        {"self_referential_define", "#define X (X+1)\nLsystem: 1\nderivation length: X\nAxiom: F\nendlsystem\n", 3, 20,
         "macro 'X' refers to itself"},
        {"mutually_recursive_defines", "#define A B\n#define B A\nLsystem: 1\nAxiom: F(A)\nendlsystem\n", 4, 10,
         "refers to itself"},
        {"macro_argument_count", "#define M(a,b) a+b\nLsystem: 1\nAxiom: F(M(1))\nendlsystem\n", 3, 10,
         "takes 2 argument(s), 1 given"},
        {"unterminated_comment", "Lsystem: 1\n/* never closed\nAxiom: F\nendlsystem\n", 2, 1, "unterminated comment"},
        {"unterminated_if", "#if 1\nLsystem: 1\nAxiom: F\nendlsystem\n", 1, 1, "unterminated #if"},
        {"else_without_if", "#else\nLsystem: 1\nAxiom: F\nendlsystem\n", 1, 1, "#else without #if"},
        {"duplicate_parameter", lsys("Axiom: A(1,2)\nA(x,x) --> A(x,x)"), 4, 5, "parameter 'x' defined twice"},
        {"parameter_without_name", lsys("Axiom: A(1)\nA(1) --> A(2)"), 4, 3, "expected a parameter name"},
        {"empty_parameter_list", lsys("Axiom: A()\nA(x) --> A(x)"), 3, 0, "empty parameter list"},
        {"paren_without_module", lsys("Axiom: (1)F"), 3, 8, "'(' without a module name"},
        {"array_index_out_of_range", "Lsystem: 1\ndefine: { array a[2] = {1, 2}; }\nderivation length: 1\nAxiom: A(5)\n"
                                     "A(x) --> A(a[x])\nendlsystem\n", 5, 12, "out of range for array 'a'"},
        {"too_many_array_values", "Lsystem: 1\ndefine: { array a[2] = {1, 2, 3}; }\nAxiom: F\nendlsystem\n", 2, 31,
         "too many values"},
        {"statement_block_without_braces", lsys("Axiom: A(1)\nA(x) : { if (x > 0) y = 1; } --> A(x)"), 4, 0,
         "blocks need braces"},
        {"missing_semicolon", lsys("Axiom: A(1)\nA(x) : { y = x } --> A(y)"), 4, 0, "expected ';'"},
        {"endless_loop", lsys("Axiom: A(1)\nA(x) : { while (1) { x = x + 1; } } --> A(x)"), 4, 10, "loop still running"},
        {"maximum_depth_outside_section", lsys("maximum depth: 3\nAxiom: F"), 3, 1, "'maximum depth' belongs"},
        {"unterminated_string", lsys("Axiom: A(1)\nA(x) : { printf(\"oops); } --> A(x)"), 4, 0, "unterminated string"},
        {"func_without_view_file", lsys("Axiom: A(func(1, 0.5))"), 3, 10, "no such function"},
        {"binary_junk", std::string("Lsystem: 1\nAxiom: F\x01\xff\xfe\nendlsystem\n"), 2, 10, "not text"},
        {"nul_byte", std::string("Lsystem: 1\nAxiom: F\0F\nendlsystem\n", 33), 2, 9, "not text"},
        {"include_missing_file", "#include \"nowhere.h\"\nLsystem: 1\nAxiom: F\nendlsystem\n", 1, 1,
         "cannot open included file"},
    };
    return all;
}

class MalformedInput : public ::testing::TestWithParam<size_t> {};

TEST_P(MalformedInput, ReportsFileLineColumnAndMessage) {
    const MalformedCase& c = cases()[GetParam()];
    fs::path path;
    std::optional<simeco::ir::InputError> error = loadAndDerive(c.text, "bad.l", path);
    ASSERT_TRUE(error.has_value()) << c.name << ": no error reported";
    EXPECT_EQ(error->loc().file, path.string()) << c.name;
    EXPECT_EQ(error->loc().line, c.line) << c.name << ": " << error->formatted();
    if (c.col) {
        EXPECT_EQ(error->loc().col, c.col) << c.name << ": " << error->formatted();
    }
    EXPECT_NE(std::string(error->what()).find(c.message), std::string::npos) << c.name << ": " << error->formatted();
    std::string formatted = error->formatted();
    EXPECT_EQ(formatted.rfind(path.string() + ":" + std::to_string(c.line) + ":", 0), 0u) << formatted;
    EXPECT_NE(formatted.find(": error: "), std::string::npos) << formatted;
}

INSTANTIATE_TEST_SUITE_P(Cpfg, MalformedInput, ::testing::Range<size_t>(0, cases().size()),
                         [](const ::testing::TestParamInfo<size_t>& param) { return cases()[param.param].name; });

TEST(MalformedInputCatalogue, HasAtLeastThirtyDistinctCases) { EXPECT_GE(cases().size(), 30u); }

TEST(MalformedInputCatalogue, ModuleBudgetEndsRunawayGrowth) {
    fs::path dir = fs::temp_directory_path() / ("simeco-budget-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path file = dir / "runaway.l";
    std::ofstream(file) << "Lsystem: 1\nderivation length: 40\nAxiom: F\nF --> FF\nendlsystem\n";
    simeco::ir::Grammar g = simeco::lang::loadGrammarFile(file.string());
    simeco::stream::DeriveOptions options;
    options.maxModules = 1000;
    try {
        simeco::cpu::deriveCpu(g, options);
        ADD_FAILURE() << "the module budget did not stop the derivation";
    } catch (const simeco::ir::LimitError& e) {
        EXPECT_NE(std::string(e.what()).find("module budget of 1000"), std::string::npos) << e.what();
    }
    // Several plants share the budget; the message names the field's whole budget, not what the last plant had
    // left of it.
    options.plants = 3;
    options.steps = 9; // 512 modules a plant: the second plant fits, the third does not
    try {
        simeco::cpu::deriveCpu(g, options);
        ADD_FAILURE() << "the module budget did not stop the derivation of three plants";
    } catch (const simeco::ir::LimitError& e) {
        EXPECT_NE(std::string(e.what()).find("module budget of 1000 modules"), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}

// A model folder of its own (see temporary_folder.h).
class ModelFolder : public simeco::testing::TemporaryFolderTest {
protected:
    void write(const std::string& name, const std::string& text) {
        std::ofstream out(dir_ / name, std::ios::binary);
        out << text;
    }
    // The error loading the folder's m.l reports.
    simeco::ir::InputError loadError() {
        try {
            simeco::lang::loadGrammarFile((dir_ / "m.l").string());
        } catch (const simeco::ir::InputError& e) {
            return e;
        }
        ADD_FAILURE() << "m.l loaded without error";
        return simeco::ir::InputError({}, "");
    }
};

const char* const kModel = "#define STEPS 3\nLsystem: 1\nderivation length: STEPS\nAxiom: A(1)\n"
                           "A(x) --> F(func(1, x / 2)) [+A(x + 1)] A(x + 1)\nendlsystem\n";
const char* const kFunction = "fver 1 1\nname: f\nsamples: 10\nflip: off\npoints: 4\n"
                              "0 0 1\n0.3 0.5 1\n0.7 0.5 1\n1 1 1\n";

using LineEnds = ModelFolder;

// A file whose lines end in a lone CR (classic Mac OS) reads as the same file with LF or CR LF ends.
TEST_F(LineEnds, CrOnlyCrLfAndLfFilesDeriveAlike) {
    std::vector<std::string> strings;
    for (const char* end : {"\n", "\r\n", "\r"}) {
        auto withEnds = [&](std::string text) {
            std::string out;
            for (char c : text) out += c == '\n' ? std::string(end) : std::string(1, c);
            return out;
        };
        write("m.l", withEnds(kModel));
        write("m.v", withEnds("angle increment: 30\nfunction: f.func\n"));
        write("f.func", withEnds(kFunction));
        simeco::ir::Grammar g = simeco::lang::loadGrammarFile((dir_ / "m.l").string());
        simeco::stream::DeriveOptions options;
        simeco::stream::ModuleString s = simeco::cpu::deriveCpu(g, options).string;
        strings.push_back(simeco::stream::formatModules(s, g.alphabet, 0, s.size()));
        EXPECT_EQ(g.view.angleIncrement, 30.0f) << "line ends " << int(end[0]);
    }
    EXPECT_GT(strings[0].size(), 20u);
    EXPECT_EQ(strings[1], strings[0]);
    EXPECT_EQ(strings[2], strings[0]);
}

using ViewFiles = ModelFolder;

TEST_F(ViewFiles, AFileTheViewNamesThatCannotBeOpenedIsReportedAtItsLine) {
    write("m.l", kModel);
    write("m.v", "angle increment: 30\nfunction: missing.func 100\n");
    simeco::ir::InputError e = loadError();
    EXPECT_EQ(fs::path(e.loc().file).filename(), "m.v");
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_EQ(e.loc().col, 11);
    EXPECT_NE(std::string(e.what()).find("cannot open the function file"), std::string::npos) << e.formatted();
}

TEST_F(ViewFiles, CountsReadFromFilesAreBounded) {
    write("m.l", kModel);
    write("m.v", "angle increment: 30\nfunction: f.func\n");
    std::string huge = kFunction;
    huge.replace(huge.find("samples: 10"), 11, "samples: 2000000000");
    write("f.func", huge);
    simeco::ir::InputError e = loadError();
    EXPECT_EQ(fs::path(e.loc().file).filename(), "f.func");
    EXPECT_EQ(e.loc().line, 3);
    EXPECT_NE(std::string(e.what()).find("samples is a whole number from 0 to 1048576"), std::string::npos)
        << e.formatted();

    write("f.func", kFunction);
    write("m.v", "angle increment: 30\nfunction: f.func 2000000000\n");
    e = loadError();
    EXPECT_EQ(fs::path(e.loc().file).filename(), "m.v");
    EXPECT_EQ(e.loc().line, 2);

    std::string manyPoints = kFunction;
    manyPoints.replace(manyPoints.find("points: 4"), 9, "points: 3000000000");
    write("f.func", manyPoints);
    write("m.v", "angle increment: 30\nfunction: f.func\n");
    e = loadError();
    EXPECT_EQ(e.loc().line, 5);
    EXPECT_NE(std::string(e.what()).find("points is a whole number"), std::string::npos) << e.formatted();

    // Samples and control points each within bounds, but too much work together (found by the fuzzer: 1,015,710
    // samples of 7 points, then 70,902 of 5 whose curve doubles back, which the bisection never settles).
    for (const char* samples : {"samples: 1048576", "samples: 40000"}) {
        std::string slow = kFunction;
        slow.replace(slow.find("samples: 10"), 11, samples);
        write("f.func", slow);
        e = loadError();
        EXPECT_EQ(e.loc().line, 5) << samples;
        EXPECT_NE(std::string(e.what()).find("their product may be at most"), std::string::npos) << e.formatted();
    }

    // A multiplicity far outside int's range (found by the fuzzer: its conversion was undefined).
    for (const char* multiplicity : {"66666666666", "-3e9", "17"}) {
        std::string far = kFunction;
        far.replace(far.find("0 0 1\n"), 6, std::string("0 0 ") + multiplicity + "\n");
        write("f.func", far);
        e = loadError();
        EXPECT_EQ(e.loc().line, 6) << multiplicity;
        EXPECT_NE(std::string(e.what()).find("multiplicity out of range"), std::string::npos) << e.formatted();
    }
}

} // namespace
