#include "ray_geometry.h"

#include <lzma.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

namespace simeco::test {

namespace {

std::string decompressXz(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + file.string());
    const std::string packed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    lzma_stream stream = LZMA_STREAM_INIT;
    if (lzma_stream_decoder(&stream, UINT64_MAX, 0) != LZMA_OK)
        throw std::runtime_error("cannot start an xz decoder for " + file.string());
    std::string text;
    char buffer[1 << 16];
    stream.next_in = reinterpret_cast<const uint8_t*>(packed.data());
    stream.avail_in = packed.size();
    lzma_ret status = LZMA_OK;
    while (status == LZMA_OK) {
        stream.next_out = reinterpret_cast<uint8_t*>(buffer);
        stream.avail_out = sizeof buffer;
        status = lzma_code(&stream, LZMA_FINISH);
        text.append(buffer, sizeof buffer - stream.avail_out);
    }
    lzma_end(&stream);
    if (status != LZMA_STREAM_END) throw std::runtime_error(file.string() + " is not a whole xz stream");
    return text;
}

bool isNumber(const std::string& token) {
    char* end = nullptr;
    std::strtod(token.c_str(), &end);
    return !token.empty() && end == token.c_str() + token.size();
}

// The file's words, without its preprocessor lines (#ifdef ... #endif: the geometry is inside both branches'
// guards, which only choose headers and surfaces).
std::vector<std::string> words(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        const size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream row(line);
        for (std::string w; row >> w;) out.push_back(w);
    }
    return out;
}

} // namespace

float RayGeometry::size() const {
    const glm::vec3 side = max - min;
    return std::max({side.x, side.y, side.z, 0.0f});
}

// rayshade's `rotate x y z degrees`: the right-handed rotation about the axis, as cpfg writes a turtle frame that
// turns about a single axis.
glm::mat3 rayRotation(glm::vec3 axis, float degrees) {
    const float a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
    axis = glm::normalize(axis);
    glm::mat3 m(0.0f);
    for (int col = 0; col < 3; ++col) {
        glm::vec3 e(0.0f);
        e[col] = 1.0f;
        m[col] = e * c + glm::cross(axis, e) * s + axis * glm::dot(axis, e) * (1.0f - c);
    }
    return m;
}

RayGeometry readRayGeometry(const std::filesystem::path& xzFile) {
    const std::vector<std::string> w = words(decompressXz(xzFile));
    RayGeometry g;
    size_t i = 0;
    auto number = [&]() {
        if (i >= w.size() || !isNumber(w[i])) throw std::runtime_error(xzFile.string() + ": a number expected");
        return std::strtof(w[i++].c_str(), nullptr);
    };
    auto vector = [&]() {
        const float x = number(), y = number(), z = number();
        return glm::vec3(x, y, z);
    };
    auto point = [&]() {
        const glm::vec3 p = vector();
        g.min = glm::min(g.min, p);
        g.max = glm::max(g.max, p);
        return p;
    };
    auto skipNumbers = [&]() {
        while (i < w.size() && isNumber(w[i])) ++i;
    };
    // A triangle's corners, each followed by its normal (and texture coordinates for `triangleuv`).
    auto triangle = [&](bool plants) {
        if (i < w.size() && !isNumber(w[i])) ++i; // a surface
        size_t numbers = 0;
        while (i + numbers < w.size() && isNumber(w[i + numbers])) ++numbers;
        const size_t perCorner = numbers / 3, end = i + numbers;
        RayTriangle t;
        for (glm::vec3& corner : t.corners) {
            const size_t next = i + perCorner;
            corner = plants ? point() : vector();
            i = next;
        }
        i = end;
        return t;
    };
    // Everything before the first `name` is the header: the camera, the screen, the lights.
    while (i < w.size() && w[i] != "name") ++i;
    while (i < w.size()) {
        const std::string keyword = w[i++];
        if (keyword == "name" && i < w.size() && w[i] != "cpfg.ray") {
            // A surface's definition: its triangles until `end`.
            std::vector<RayTriangle>& mesh = g.surfaceMeshes[w[i++]];
            while (i < w.size() && w[i] != "end") {
                const std::string word = w[i++];
                if (word == "triangle" || word == "triangleuv") mesh.push_back(triangle(false));
            }
            ++i;
        } else if (keyword == "cylinder" || keyword == "cone") {
            ++i; // the surface
            RaySegment s;
            s.fromRadius = number();
            s.from = point();
            s.toRadius = keyword == "cone" ? number() : s.fromRadius;
            s.to = point();
            g.segments.push_back(s);
        } else if (keyword == "sphere" || keyword == "disc") {
            ++i;
            RaySphere s;
            s.radius = number();
            s.centre = point();
            (keyword == "sphere" ? g.spheres : g.discs).push_back(s);
            skipNumbers(); // a disc's normal
        } else if (keyword == "poly") {
            ++i;
            std::vector<glm::vec3> vertices;
            while (i + 2 < w.size() && isNumber(w[i])) vertices.push_back(point());
            for (size_t k = 1; k + 1 < vertices.size(); ++k)
                g.polygonFans.push_back({{vertices[0], vertices[k], vertices[k + 1]}});
        } else if (keyword == "object" && i + 1 < w.size() && w[i + 1] == "scale") {
            // `object id scale sx sy sz [transform L H U | rotate axis degrees] [translate P]`
            RaySurface s;
            s.id = w[i];
            i += 2;
            s.scale = vector();
            glm::mat3 frame(1.0f);
            if (i < w.size() && w[i] == "transform") {
                ++i;
                for (int row = 0; row < 3; ++row) frame[row] = vector();
            } else if (i < w.size() && w[i] == "rotate") {
                ++i;
                const glm::vec3 axis = vector();
                frame = rayRotation(axis, number());
            }
            s.left = frame[0], s.heading = frame[1], s.up = frame[2];
            if (i < w.size() && w[i] == "translate") {
                ++i;
                s.position = point();
            }
            g.surfaces.push_back(s);
        } else if (keyword == "triangle" || keyword == "triangleuv") {
            g.cylinderTriangles.push_back(triangle(true));
        } else {
            if (i < w.size() && !isNumber(w[i])) ++i; // a surface or a name
            skipNumbers();
        }
    }
    return g;
}

} // namespace simeco::test
