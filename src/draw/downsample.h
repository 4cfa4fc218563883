// A supersampled frame brought to its size: each pixel from the `factor` x `factor` samples drawn for it.
#pragma once

#include <cstdint>

#include "draw/frame.h"

namespace simeco::draw {

// Colour and alpha are the samples' mean (in linear light, before any tone mapping); depth, plant and organ are
// those of the nearest sample, so ids stay ids. The frame's sides must be multiples of `factor`.
Frame downsample(const Frame& frame, std::uint32_t factor);

} // namespace simeco::draw
