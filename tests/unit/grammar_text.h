// Test helper: load a grammar from text (through a scratch file, as users load them) and derive it.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cpu/derive.h"
#include "lang/load_grammar.h"

namespace simeco::testing {

inline ir::Grammar grammarFromText(const std::string& text, const std::string& fileName = "grammar.l") {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("simeco-unit-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path path = dir / fileName;
    std::ofstream(path, std::ios::binary) << text;
    struct Cleanup {
        fs::path dir;
        ~Cleanup() { fs::remove_all(dir); }
    } cleanup{dir};
    return lang::loadGrammarFile(path.string());
}

// The derived string of the first plant in cpfg notation.
inline std::string deriveText(const std::string& text, int steps = -1, int64_t seed = -1) {
    ir::Grammar g = grammarFromText(text);
    stream::DeriveOptions options;
    options.steps = steps;
    options.seed = seed;
    stream::DeriveResult r = cpu::deriveCpu(g, options);
    return stream::formatModules(r.string, g.alphabet, r.string.plantStart[0], r.string.plantStart[1]);
}

// Wraps productions into a minimal cpfg file.
inline std::string lsystem(const std::string& axiom, const std::string& body, int length = 1) {
    return "Lsystem: 1\nderivation length: " + std::to_string(length) + "\nAxiom: " + axiom + "\n" + body +
           "\nendlsystem\n";
}

} // namespace simeco::testing
