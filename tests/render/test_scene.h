// Hand-made scenes for renderer tests: organ instances built on the host, grouped by kind and uploaded with
// their OrganTable, as the turtle kernels would leave them on the device; and where a camera puts a point.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "compute/shared/organ_layout.h"
#include "draw/bounds.h"
#include "draw/camera.h"
#include "draw/frame.h"
#include "draw/renderer.h"
#include "gpu_fixture.h"
#include "vk/buffer.h"

namespace simeco::test {

using shared::OrganInstance;

// A GPU test with one renderer per suite (its pipelines are built once), destroyed before the context.
class RenderTest : public GpuTest {
protected:
    static void TearDownTestSuite() {
        renderer_.reset(); // before the context goes
        GpuTest::TearDownTestSuite();
    }
    // One renderer for the suite: pipelines are built once.
    draw::Renderer& renderer() {
        if (!renderer_) {
            renderer_ = std::make_unique<draw::Renderer>(context());
        }
        return *renderer_;
    }
    static inline std::unique_ptr<draw::Renderer> renderer_;
};

OrganInstance makeStem(glm::vec3 base, glm::vec3 heading, glm::vec3 up, float length, float radius, std::uint32_t plant,
                       std::uint32_t module);
OrganInstance makeSphere(glm::vec3 centre, float radius, std::uint32_t plant, std::uint32_t module);
OrganInstance makeLeaf(glm::vec3 base, glm::vec3 heading, glm::vec3 up, float length, float width, std::uint32_t shape,
                       std::uint32_t plant, std::uint32_t module);
OrganInstance makeDisc(glm::vec3 centre, glm::vec3 heading, glm::vec3 up, float radius, std::uint32_t plant,
                       std::uint32_t module);
OrganInstance makeTriangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, std::uint32_t plant, std::uint32_t module);

// A box around everything the organs draw (generous: stems and leaves count their radius or width all round, but
// for pixel lines, whose width is the picture's).
draw::Bounds organBounds(const std::vector<OrganInstance>& organs);

struct TestScene {
    vk::Buffer instances;
    vk::Buffer table;
    shared::OrganTable tableData{};
    draw::Bounds bounds;
};

// Sorts the organs by kind, fills the table (counts, firsts, bounds) and uploads both buffers.
// `countOverride` replaces the table's counts (the instances stay), to check the draws follow the table.
TestScene uploadScene(const vk::Context& context, std::vector<OrganInstance> organs,
                      std::optional<std::vector<std::uint32_t>> countOverride = std::nullopt);

// The pixel (x right, y down, in pixel units) where `world` lands in a width x height image.
glm::vec2 projectToPixel(const draw::CameraView& camera, glm::vec3 world, std::uint32_t width, std::uint32_t height);

// Pixel bounding box of the pixels whose organ id is `organ` (any organ when kNoId); empty() when none.
struct PixelBox {
    int minX = 1 << 30, minY = 1 << 30, maxX = -1, maxY = -1;
    std::size_t pixels = 0;
    bool empty() const { return pixels == 0; }
};
PixelBox organPixels(const draw::Frame& frame, std::uint32_t organ = draw::Frame::kNoId);

// Linear luminance of a pixel.
float luminance(const draw::Frame& frame, std::uint32_t x, std::uint32_t y);

// Writes a PNG preview of the frame to $SIMECO_RENDER_TEST_IMAGES/<name>.png when that variable is set, so a
// person can look at what the tests render. Does nothing otherwise.
void maybeSavePreview(const draw::Frame& frame, const std::string& name);

} // namespace simeco::test
