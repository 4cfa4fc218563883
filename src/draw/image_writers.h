// Frames to files: PNG previews (tone-mapped 8-bit sRGB) and OpenEXR images with everything the frame holds
// (half RGBA, float Z, uint plant and organ ids). Both write atomically (see atomic_file.h), alone or with other files and throw an
// OutputError with the destination's name when the frame is inconsistent or the file cannot be written.
#pragma once

#include <cstdint>
#include <filesystem>

#include "draw/atomic_file.h"
#include "draw/frame.h"

namespace simeco::draw {

// A linear colour value as an 8-bit sRGB preview value: a filmic curve (Narkowicz's fit of ACES) so that
// bright sunlight rolls off instead of clipping, then the sRGB transfer function.
std::uint8_t previewByte(float linear);

// RGBA, 8 bits per channel, alpha 255 (a preview shows the background colour rather than transparency).
void writePng(const std::filesystem::path& path, const Frame& frame);

// Channels R, G, B, A (HALF, linear), Z (FLOAT, the frame's depth), plant and organ (UINT); ZIP compressed.
void writeExr(const std::filesystem::path& path, const Frame& frame);

// The same, as a file of `batch`: it appears when the batch is committed, with the batch's other files.
void writePng(OutputBatch& batch, const std::filesystem::path& path, const Frame& frame);
void writeExr(OutputBatch& batch, const std::filesystem::path& path, const Frame& frame);

} // namespace simeco::draw
