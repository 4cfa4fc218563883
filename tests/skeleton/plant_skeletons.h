// Skeletons of grammar files and texts, derived and drawn by the CPU reference as `simeco skeleton` does, and the
// round trip skeleton -> inferred grammar -> skeleton.
#pragma once

#include <filesystem>
#include <string>

#include "skeleton/infer.h"
#include "skeleton/skeleton.h"
#include "skeleton/skeleton_compare.h"

namespace simeco::test {

// Plant 0 of a grammar or scene file, derived (`steps` steps, -1 for the file's derivation length) and drawn on
// the CPU.
skeleton::Plant skeletonOfFile(const std::filesystem::path& file, int steps = -1);

// Writes `text` to `file` and returns its skeleton.
skeleton::Plant skeletonOfText(const std::string& text, const std::filesystem::path& file);

struct RoundTrip {
    skeleton::SegmentMatch match;
    size_t internodes = 0;
    int levels = 0;
    double seconds = 0.0; // infer, derive and draw the inferred grammar
};

// Infers a grammar from `plant` (the initial state, as `simeco infer --initial-only` writes it, .eco or .l by
// `file`'s extension), writes it to `file`, and compares its skeleton with `plant`.
RoundTrip roundTrip(const skeleton::Plant& plant, const std::filesystem::path& file);

} // namespace simeco::test
