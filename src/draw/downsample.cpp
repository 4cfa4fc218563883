#include "draw/downsample.h"

#include <stdexcept>

namespace simeco::draw {

Frame downsample(const Frame& frame, std::uint32_t factor) {
    if (factor == 0 || frame.width % factor != 0 || frame.height % factor != 0)
        throw std::invalid_argument("downsample: the frame's sides are not multiples of the factor");
    Frame out;
    out.width = frame.width / factor;
    out.height = frame.height / factor;
    out.rgba.assign(4 * out.pixelCount(), 0.0f);
    out.depth.resize(out.pixelCount());
    out.plant.resize(out.pixelCount());
    out.organ.resize(out.pixelCount());
    const float weight = 1.0f / float(factor * factor);
    for (std::uint32_t y = 0; y < out.height; ++y)
        for (std::uint32_t x = 0; x < out.width; ++x) {
            const std::size_t to = out.index(x, y);
            std::size_t nearest = frame.index(x * factor, y * factor);
            for (std::uint32_t sy = 0; sy < factor; ++sy)
                for (std::uint32_t sx = 0; sx < factor; ++sx) {
                    const std::size_t from = frame.index(x * factor + sx, y * factor + sy);
                    for (int c = 0; c < 4; ++c) out.rgba[4 * to + c] += weight * frame.rgba[4 * from + c];
                    if (frame.depth[from] < frame.depth[nearest]) nearest = from;
                }
            out.depth[to] = frame.depth[nearest];
            out.plant[to] = frame.plant[nearest];
            out.organ[to] = frame.organ[nearest];
        }
    return out;
}

} // namespace simeco::draw
