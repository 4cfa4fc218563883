#include "ray_geometry.h"

#include <lzma.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include <glm/common.hpp>

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

RayGeometry readRayGeometry(const std::filesystem::path& xzFile) {
    const std::vector<std::string> w = words(decompressXz(xzFile));
    RayGeometry g;
    size_t i = 0;
    auto number = [&]() {
        if (i >= w.size() || !isNumber(w[i])) throw std::runtime_error(xzFile.string() + ": a number expected");
        return std::strtof(w[i++].c_str(), nullptr);
    };
    auto point = [&]() {
        const float x = number(), y = number(), z = number();
        const glm::vec3 p(x, y, z);
        g.min = glm::min(g.min, p);
        g.max = glm::max(g.max, p);
        return p;
    };
    auto skipNumbers = [&]() {
        while (i < w.size() && isNumber(w[i])) ++i;
    };
    // Everything before `grid` is the header: the camera, the screen, the lights.
    while (i < w.size() && w[i] != "grid") ++i;
    while (i < w.size()) {
        const std::string keyword = w[i++];
        if (keyword == "cylinder" || keyword == "cone") {
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
        } else {
            if (keyword == "triangle" || keyword == "triangleuv") ++g.triangles;
            if (keyword == "transform") ++g.objects;
            if (i < w.size() && !isNumber(w[i])) ++i; // a surface or a name
            skipNumbers();
        }
    }
    return g;
}

} // namespace simeco::test
