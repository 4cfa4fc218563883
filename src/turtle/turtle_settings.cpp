#include "turtle/turtle_settings.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <glm/geometric.hpp>

#include "compute/shared/organ_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "turtle/contour_ring.h"

namespace simeco::turtle {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool mentions(const std::string& text, std::initializer_list<const char*> words) {
    return std::any_of(words.begin(), words.end(), [&](const char* w) { return text.find(w) != std::string::npos; });
}

} // namespace

glm::vec4 TurtleSettings::color(float index) const {
    long i = std::lround(index);
    i = std::clamp<long>(i, 0, long(palette.size()) - 1);
    return palette[size_t(i)];
}

uint32_t lineStyleCode(ir::LineStyle style) {
    switch (style) {
    case ir::LineStyle::Polygon: return shared::kLinePolygon;
    case ir::LineStyle::Pixel: return shared::kLinePixel;
    default: return shared::kLineCylinder;
    }
}

std::vector<glm::vec4> defaultPalette() {
    std::vector<glm::vec4> p(kPaletteSize);
    const glm::vec4 named[] = {
        {0.00f, 0.00f, 0.00f, 1}, // 0 black
        {0.20f, 0.11f, 0.05f, 1}, // 1 bark
        {0.09f, 0.30f, 0.05f, 1}, // 2 leaf green
        {0.04f, 0.16f, 0.03f, 1}, // 3 dark green
        {0.80f, 0.62f, 0.05f, 1}, // 4 yellow
        {0.60f, 0.04f, 0.05f, 1}, // 5 red
        {0.85f, 0.85f, 0.80f, 1}, // 6 white
        {0.35f, 0.10f, 0.45f, 1}, // 7 purple
        {0.85f, 0.30f, 0.45f, 1}, // 8 pink
        {0.25f, 0.45f, 0.08f, 1}, // 9 light green
    };
    std::copy(std::begin(named), std::end(named), p.begin());
    for (size_t i = std::size(named); i < p.size(); ++i) {
        // A hue ramp, so neighbouring indices stay distinguishable.
        float h = float(i) * 0.618034f;
        h -= std::floor(h);
        glm::vec3 rgb = glm::clamp(glm::abs(glm::mod(h * 6.0f + glm::vec3(0, 4, 2), 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f);
        p[i] = glm::vec4(rgb * rgb * 0.6f + 0.05f, 1.0f);
    }
    return p;
}

uint32_t surfaceShapeOf(const std::string& name) {
    std::string n = lower(name);
    if (mentions(n, {"blossom", "flower"}) && !mentions(n, {"leaf"})) { // a sunflower's leaf is a leaf
        if (mentions(n, {"lantan", "verben", "head", "umbel"})) return shared::kBlossomHead;
        if (mentions(n, {"rosa", "rose"})) return shared::kBlossomRose;
        return shared::kBlossomStar;
    }
    if (mentions(n, {"oxalis", "clover", "trifol", "shamrock"})) return shared::kLeafTrifoliate;
    if (mentions(n, {"cord", "heart"})) return shared::kLeafCordate;
    if (mentions(n, {"lanc", "grass", "narrow", "needle", "blade"})) return shared::kLeafLanceolate;
    if (mentions(n, {"comp", "pinna", "fern", "rosa", "rose"})) return shared::kLeafCompound;
    if (mentions(n, {"lantan", "serr", "tooth", "nettle"})) return shared::kLeafSerrate;
    return shared::kLeafOvate;
}

TurtleSettings turtleSettings(const ir::Grammar& grammar, const ir::Alphabet& alphabet) {
    const ir::ViewSettings& v = grammar.view;
    TurtleSettings t;
    t.angleDegrees = v.angleIncrement;
    t.step = v.stepSize;
    t.width = v.lineWidth;
    t.widthIncrement = v.widthIncrement;
    t.colorIncrement = v.colorIncrement;
    t.initialColor = v.initialColor;
    glm::vec3 tropism(v.tropismDirection[0], v.tropismDirection[1], v.tropismDirection[2]);
    t.tropism = glm::length(tropism) > 0 ? glm::normalize(tropism) : glm::vec3(0, -1, 0);
    t.elasticity = v.initialElasticity;
    t.elasticityIncrement = v.elasticityIncrement;
    t.initialScale = v.initialScale;
    t.taperedLines = v.taperedLines;
    t.tropismRule = v.tropismRule;
    t.lineStyle = v.lineStyle;
    t.dollarRolls = v.dollarRolls;
    t.torque = glm::vec3(v.torque[0], v.torque[1], v.torque[2]);
    t.subLsystems = grammar.lsystems > 1;
    t.cylinderMeshes = v.cpfgCylinders && v.lineStyle == ir::LineStyle::Cylinder;
    t.cpfgTubes = v.cpfgCylinders && v.lineStyle != ir::LineStyle::Cylinder;
    t.cylinderTwist = v.cylinderTwist;
    t.cylinderSides = v.cylinderSides;
    t.contourIds = {0};
    t.contourRings = contourRing(nullptr, t.cylinderSides);
    for (const ir::CylinderContour& c : v.contours) {
        t.contourIds.push_back(c.id);
        const std::vector<glm::vec3> ring = contourRing(&c, t.cylinderSides);
        t.contourRings.insert(t.contourRings.end(), ring.begin(), ring.end());
    }
    if (v.palette.empty()) {
        t.palette = defaultPalette();
    } else {
        t.palette.assign(kPaletteSize, glm::vec4(0, 0, 0, 1));
        for (size_t i = 0; i < std::min(kPaletteSize, v.palette.size()); ++i) {
            const int texture = i < v.paletteTextures.size() ? v.paletteTextures[i] : -1;
            const float w = texture < 0 ? shared::kColorUntextured : shared::kColorFirstTexture + float(texture);
            t.palette[i] = glm::vec4(v.palette[i][0], v.palette[i][1], v.palette[i][2], w);
        }
    }
    // Any symbol can follow `~` as a surface id: scale 1 and a shape from its name unless the view names it (or,
    // in cpfg's way, nothing drawn unless it does).
    t.surfaceScale.assign(alphabet.size(), 1.0f);
    t.surfaceShape.assign(alphabet.size(), shared::kLeafOvate);
    t.surfaceEnd.assign(alphabet.size(), glm::vec3(0.0f));
    t.surfaceDrawn.assign(alphabet.size(),
                          v.undefinedSurfacesDrawn ? shared::kSurfaceAlongHeading : shared::kSurfaceNone);
    for (size_t s = 0; s < alphabet.size(); ++s) {
        const std::string& id = alphabet.name(ir::SymbolId(s));
        t.surfaceShape[s] = surfaceShapeOf(id);
        for (const ir::ViewSettings::Surface& surface : v.surfaces) {
            if (surface.name != id) continue;
            t.surfaceShape[s] = surface.shape ? *surface.shape : surfaceShapeOf(surface.file + " " + id);
            if (surface.model) { // its triangles are in units of its reach
                const std::array<float, 3>& e = surface.model->endPoint;
                t.surfaceScale[s] = surface.model->reach;
                t.surfaceEnd[s] = glm::vec3(e[0], e[1], e[2]);
                t.surfaceDrawn[s] = shared::kSurfaceAroundBase;
            } else {
                t.surfaceScale[s] = surface.scale;
                t.surfaceDrawn[s] = shared::kSurfaceAlongHeading;
            }
        }
    }
    return t;
}

} // namespace simeco::turtle
