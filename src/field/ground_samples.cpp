#include "field/ground_samples.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "compute/shared/growth_layout.h"
#include "compute/shared/random.h"

namespace simeco::field {

namespace {

// The random streams of a population's placement: plant `key`, the growth property pass, module 2.
constexpr uint32_t kGroundModule = 2;

float draw(uint32_t seed, uint32_t key, uint32_t number) {
    return shared::randomUnit(seed, key, shared::kGrowPropertyPass, kGroundModule, number);
}

} // namespace

std::vector<glm::vec2> poissonDiskPoints(const GroundRect& rect, uint32_t count, float distance, uint32_t seed,
                                         uint32_t key) {
    std::vector<glm::vec2> points;
    if (count == 0) return points;
    const float area = rect.size.x * rect.size.y;
    const float r = distance > 0.0f ? distance : 0.75f * std::sqrt(area / float(count));
    // A grid of cells r / sqrt(2) wide holds at most one point each: a candidate's neighbours are in the 5x5
    // cells about its own.
    const float cell = r / std::sqrt(2.0f);
    const int columns = std::max(1, int(std::ceil(rect.size.x / cell)));
    const int rows = std::max(1, int(std::ceil(rect.size.y / cell)));
    std::vector<int32_t> grid(size_t(columns) * size_t(rows), -1);
    const glm::vec2 origin = rect.center - 0.5f * rect.size;
    const uint64_t attempts = 30ull * count;
    for (uint64_t a = 0; a < attempts && points.size() < count; ++a) {
        const glm::vec2 local(draw(seed, key, uint32_t(2 * a)) * rect.size.x,
                              draw(seed, key, uint32_t(2 * a + 1)) * rect.size.y);
        const int cx = std::min(columns - 1, int(local.x / cell)), cz = std::min(rows - 1, int(local.y / cell));
        bool free = true;
        for (int z = std::max(0, cz - 2); free && z <= std::min(rows - 1, cz + 2); ++z)
            for (int x = std::max(0, cx - 2); free && x <= std::min(columns - 1, cx + 2); ++x) {
                const int32_t other = grid[size_t(z) * size_t(columns) + size_t(x)];
                if (other >= 0) {
                    const glm::vec2 d = points[size_t(other)] - (origin + local);
                    free = d.x * d.x + d.y * d.y >= r * r;
                }
            }
        if (!free) continue;
        grid[size_t(cz) * size_t(columns) + size_t(cx)] = int32_t(points.size());
        points.push_back(origin + local);
    }
    return points;
}

std::vector<glm::vec2> jitteredPoints(const GroundRect& rect, uint32_t count, uint32_t seed, uint32_t key) {
    std::vector<glm::vec2> points;
    if (count == 0) return points;
    const uint32_t columns =
        std::max(1u, uint32_t(std::lround(std::sqrt(double(count) * rect.size.x / rect.size.y))));
    const uint32_t rows = (count + columns - 1) / columns;
    const glm::vec2 cell(rect.size.x / float(columns), rect.size.y / float(rows));
    // The cells in a random order (Fisher-Yates), the first `count` taken.
    const uint32_t shuffled = columns * rows;
    std::vector<uint32_t> cells(shuffled);
    std::iota(cells.begin(), cells.end(), 0u);
    for (size_t i = cells.size() - 1; i > 0; --i) {
        const size_t j = std::min(i, size_t(draw(seed, key, uint32_t(i)) * float(i + 1)));
        std::swap(cells[i], cells[j]);
    }
    cells.resize(count);
    std::sort(cells.begin(), cells.end()); // row by row, as a field is read
    const glm::vec2 origin = rect.center - 0.5f * rect.size;
    for (uint32_t c : cells) {
        const uint32_t n = shuffled + c; // draws past the shuffle's
        const glm::vec2 jitter(0.7f * (draw(seed, key, 2 * n) - 0.5f), 0.7f * (draw(seed, key, 2 * n + 1) - 0.5f));
        points.push_back(origin + (glm::vec2(float(c % columns), float(c / columns)) + 0.5f + jitter) * cell);
    }
    return points;
}

} // namespace simeco::field
