// A libFuzzer target for one of the readers of user files, chosen at build time by SIMECO_FUZZ_READER. Each input
// is written to a file in a private folder and read the way `simeco` reads it: bad input must end in an
// exception (a located error or a limit), never in a crash, a sanitizer report, a hang or runaway memory.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "lang/cpfg_contour.h"
#include "lang/cpfg_view.h"
#include "lang/load_grammar.h"
#include "skeleton/skeleton_check.h"
#include "skeleton/skeleton_json.h"
#include "skeleton/skeleton_obj.h"
#include "skeleton/three_views.h"

namespace {

namespace fs = std::filesystem;

const fs::path& folder() {
    static const fs::path path = [] {
        fs::path p = fs::temp_directory_path() / ("simeco-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(p);
        return p;
    }();
    return path;
}

fs::path write(const std::string& name, const uint8_t* data, size_t size) {
    fs::path path = folder() / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

// A view file that names the fuzzed function, function set, cylinder contour or surface, so they are read as a model reads them.
fs::path viewNaming(const std::string& line) {
    fs::path path = folder() / "fuzz.v";
    std::ofstream(path, std::ios::trunc) << "angle factor: 8\n" << line << "\n";
    return path;
}

void readInput(const uint8_t* data, size_t size) {
    const std::string reader = SIMECO_FUZZ_READER;
    if (reader == "cpfg") {
        simeco::lang::loadGrammarFile(write("fuzz.l", data, size).string());
    } else if (reader == "eco") {
        simeco::lang::loadSpecies(write("fuzz.eco", data, size).string());
    } else if (reader == "quick") {
        simeco::lang::loadSpecies(write("fuzz.lsys", data, size).string());
    } else if (reader == "view") {
        simeco::lang::readCpfgView(write("fuzz.v", data, size).string());
    } else if (reader == "function") {
        write("fuzz.func", data, size);
        simeco::lang::readCpfgView(viewNaming("function: fuzz.func 100").string());
    } else if (reader == "function_set") {
        write("fuzz.fset", data, size);
        simeco::lang::readCpfgView(viewNaming("function set: fuzz.fset").string());
    } else if (reader == "contour") {
        simeco::lang::parseContourFile(write("fuzz.con", data, size).string());
    } else if (reader == "cylinder_contour") {
        write("fuzz.con", data, size);
        simeco::lang::readCpfgView(viewNaming("contour: 1 fuzz.con").string());
    } else if (reader == "surface") {
        write("fuzz.s", data, size);
        simeco::lang::readCpfgView(viewNaming("surface: s fuzz.s 1 10 10").string());
    } else if (reader == "skeleton") {
        simeco::skeleton::Skeleton s = simeco::skeleton::readSkeletonJson(write("fuzz.json", data, size).string());
        simeco::skeleton::checkSkeleton(s, "fuzz.json");
    } else if (reader == "skeleton_obj") {
        simeco::skeleton::Skeleton s = simeco::skeleton::readObjSkeleton(write("fuzz.obj", data, size).string());
        simeco::skeleton::checkSkeleton(s, "fuzz.obj");
    } else if (reader == "three_views") {
        simeco::skeleton::Skeleton s = simeco::skeleton::readThreeViews(write("fuzz.svg", data, size).string());
        simeco::skeleton::checkSkeleton(s, "fuzz.svg");
    } else {
        std::abort(); // a reader this target does not know: a build error, not a finding
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        readInput(data, size);
    } catch (const std::exception&) {
        // Refused with a message: what bad input should get.
    }
    return 0;
}
