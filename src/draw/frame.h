// A rendered frame on the host: linear colour, depth and the ids of what each pixel shows. Rows run from the
// top of the image down.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace simeco::draw {

struct Frame {
    // Plant and organ id of pixels that show no organ (background and ground).
    static constexpr std::uint32_t kNoId = 0xFFFFFFFFu;

    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> rgba;          // linear RGBA, 4 floats per pixel; alpha 0 where nothing is drawn
    std::vector<float> depth;         // distance from the camera plane along the view axis; +inf for none
    std::vector<std::uint32_t> plant; // OrganInstance.plant, or kNoId
    std::vector<std::uint32_t> organ; // OrganInstance.module, or kNoId

    std::size_t pixelCount() const { return std::size_t{width} * height; }
    std::size_t index(std::uint32_t x, std::uint32_t y) const { return std::size_t{y} * width + x; }
};

} // namespace simeco::draw
