// A field saved in the middle of its growth (`simeco run --save`), and read back (`--resume`): the options that
// made the field (the scene's text included, so that the file stands alone) and its whole state, in one binary
// file. A field made from the same options and resumed from the state goes on exactly as it would have.
#pragma once

#include <string>

#include "field/simulation.h"

namespace simeco::field {

struct SavedRun {
    SimulationOptions options; // file, sceneText, plants, seed, dt, spacing and plantsPerBatch are kept
    SimulationState state;
};

// The file's bytes: a magic line, a format version, the options, then the state; numbers in this machine's
// byte order (little-endian on every machine simeco runs on).
std::string encodeSavedRun(const SavedRun& run);
// Reads them back; a file that is not one, of another version, truncated or inconsistent is refused with an
// ir::InputError that names `name`.
SavedRun decodeSavedRun(const std::string& bytes, const std::string& name);

} // namespace simeco::field
