#include "test_scene.h"

#include <algorithm>
#include <cstdlib>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "draw/image_writers.h"

namespace simeco::test {
namespace {

shared::vec4 v4(glm::vec3 v, float w) {
    return {v.x, v.y, v.z, w};
}

OrganInstance organ(std::uint32_t kind, std::uint32_t plant, std::uint32_t module) {
    OrganInstance o{};
    o.kind = kind;
    o.plant = plant;
    o.module = module;
    o.color = {0.25f, 0.55f, 0.18f, 1.0f};
    return o;
}

glm::vec3 xyz(const shared::vec4& v) {
    return {v.x, v.y, v.z};
}

} // namespace

OrganInstance makeStem(glm::vec3 base, glm::vec3 heading, glm::vec3 up, float length, float radius, std::uint32_t plant,
                       std::uint32_t module) {
    OrganInstance o = organ(shared::kOrganStem, plant, module);
    o.position = v4(base, length);
    o.heading = v4(glm::normalize(heading), radius);
    o.up = v4(glm::normalize(up), radius);
    o.color = {0.45f, 0.33f, 0.20f, 1.0f};
    return o;
}

OrganInstance makeSphere(glm::vec3 centre, float radius, std::uint32_t plant, std::uint32_t module) {
    OrganInstance o = organ(shared::kOrganSphere, plant, module);
    o.position = v4(centre, 0);
    o.heading = v4({0, 1, 0}, radius);
    o.up = v4({0, 0, 1}, 0);
    o.color = {0.7f, 0.15f, 0.1f, 1.0f};
    return o;
}

OrganInstance makeLeaf(glm::vec3 base, glm::vec3 heading, glm::vec3 up, float length, float width, std::uint32_t shape,
                       std::uint32_t plant, std::uint32_t module) {
    OrganInstance o = organ(shared::kOrganLeaf, plant, module);
    o.position = v4(base, length);
    o.heading = v4(glm::normalize(heading), width);
    o.up = v4(glm::normalize(up), 0);
    o.shape = shape;
    return o;
}

OrganInstance makeDisc(glm::vec3 centre, glm::vec3 heading, glm::vec3 up, float radius, std::uint32_t plant,
                       std::uint32_t module) {
    OrganInstance o = organ(shared::kOrganDisc, plant, module);
    o.position = v4(centre, 0);
    o.heading = v4(glm::normalize(heading), radius);
    o.up = v4(glm::normalize(up), 0);
    o.color = {0.9f, 0.8f, 0.2f, 1.0f};
    return o;
}

OrganInstance makeTriangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, std::uint32_t plant, std::uint32_t module) {
    OrganInstance o = organ(shared::kOrganTriangle, plant, module);
    o.position = v4(a, 0);
    o.heading = v4(b, 0);
    o.up = v4(c, 0);
    o.color = {0.3f, 0.3f, 0.8f, 1.0f};
    return o;
}

draw::Bounds organBounds(const std::vector<OrganInstance>& organs) {
    draw::Bounds b{glm::vec3(1e30f), glm::vec3(-1e30f)};
    auto add = [&](glm::vec3 p, float grow) {
        b.min = glm::min(b.min, p - glm::vec3(grow));
        b.max = glm::max(b.max, p + glm::vec3(grow));
    };
    for (const OrganInstance& o : organs) {
        glm::vec3 p = xyz(o.position);
        glm::vec3 h = xyz(o.heading);
        switch (o.kind) {
        case shared::kOrganStem: {
            // A pixel line's width is the picture's, as the field's bounds count it: the frame holds its ends.
            const float radius = o.shape == shared::kLinePixel ? 0.0f : std::max(o.heading.w, o.up.w);
            add(p, radius);
            add(p + o.position.w * h, radius);
            break;
        }
        case shared::kOrganLeaf:
            add(p, o.heading.w);
            add(p + o.position.w * h, o.heading.w);
            break;
        case shared::kOrganTriangle:
            add(p, 0);
            add(h, 0);
            add(xyz(o.up), 0);
            break;
        default:
            add(p, o.heading.w);
        }
    }
    return b;
}

TestScene uploadScene(const vk::Context& context, std::vector<OrganInstance> organs,
                      std::optional<std::vector<std::uint32_t>> countOverride) {
    std::stable_sort(organs.begin(), organs.end(),
                     [](const OrganInstance& a, const OrganInstance& b) { return a.kind < b.kind; });
    TestScene scene;
    shared::OrganTable& t = scene.tableData;
    for (std::uint32_t kind = 0; kind < shared::kOrganKinds; ++kind) {
        auto first = std::find_if(organs.begin(), organs.end(), [&](const auto& o) { return o.kind >= kind; });
        t.first[kind] = static_cast<std::uint32_t>(first - organs.begin());
        t.count[kind] = static_cast<std::uint32_t>(
            std::count_if(organs.begin(), organs.end(), [&](const auto& o) { return o.kind == kind; }));
        if (countOverride) {
            t.count[kind] = (*countOverride)[kind];
        }
    }
    scene.bounds = organs.empty() ? draw::Bounds{glm::vec3(1), glm::vec3(-1)} : organBounds(organs);
    draw::encodeBounds(scene.bounds, t);
    std::size_t bytes = std::max<std::size_t>(organs.size(), 1) * sizeof(OrganInstance);
    scene.instances = vk::Buffer(context, bytes, vk::MemoryUsage::DeviceLocal);
    scene.table = vk::Buffer(context, sizeof(shared::OrganTable), vk::MemoryUsage::DeviceLocal);
    vk::uploadSpan(context, scene.instances, std::span<const OrganInstance>(organs));
    vk::uploadSpan(context, scene.table, std::span<const shared::OrganTable>(&t, 1));
    return scene;
}

glm::vec2 projectToPixel(const draw::CameraView& camera, glm::vec3 world, std::uint32_t width, std::uint32_t height) {
    glm::vec4 clip = camera.viewProj * glm::vec4(world, 1.0f);
    glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
    return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width), (ndc.y * 0.5f + 0.5f) * static_cast<float>(height)};
}

PixelBox organPixels(const draw::Frame& frame, std::uint32_t organ) {
    PixelBox box;
    for (std::uint32_t y = 0; y < frame.height; ++y) {
        for (std::uint32_t x = 0; x < frame.width; ++x) {
            std::uint32_t id = frame.organ[frame.index(x, y)];
            if (id == draw::Frame::kNoId || (organ != draw::Frame::kNoId && id != organ)) {
                continue;
            }
            box.minX = std::min(box.minX, static_cast<int>(x));
            box.maxX = std::max(box.maxX, static_cast<int>(x));
            box.minY = std::min(box.minY, static_cast<int>(y));
            box.maxY = std::max(box.maxY, static_cast<int>(y));
            ++box.pixels;
        }
    }
    return box;
}

float luminance(const draw::Frame& frame, std::uint32_t x, std::uint32_t y) {
    const float* p = &frame.rgba[4 * frame.index(x, y)];
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

void maybeSavePreview(const draw::Frame& frame, const std::string& name) {
    const char* folder = std::getenv("SIMECO_RENDER_TEST_IMAGES");
    if (folder != nullptr && *folder != '\0') {
        draw::writePng(std::filesystem::path(folder) / (name + ".png"), frame);
    }
}

} // namespace simeco::test
