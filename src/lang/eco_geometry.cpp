#include "lang/eco_geometry.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>

#include "compute/shared/growth_layout.h"
#include "lang/color_map.h"

namespace simeco::lang {

namespace {

using ir::EcoOrganKind;

// A stage's property, else the organ's Default stage's, else nothing.
template <typename Member>
std::optional<float> property(const ir::EcoOrgan& organ, const ir::EcoStage* stage, Member member) {
    if (stage && stage->*member) return (stage->*member)->typical();
    if (organ.defaultStage && (*organ.defaultStage).*member) return ((*organ.defaultStage).*member)->typical();
    return std::nullopt;
}

// How much the organ grows during a stage: GrowRate x GrowTime (0 when the stage sets no growth).
float growth(const ir::EcoOrgan& organ, const ir::EcoStage* stage) {
    std::optional<float> rate = property(organ, stage, &ir::EcoStage::growRate);
    if (!rate) return 0.0f;
    return *rate * property(organ, stage, &ir::EcoStage::growTime).value_or(kEcoDefaultGrowTime);
}

class GeometryBuilder {
public:
    GeometryBuilder(const ir::EcoPlant& plant, ir::Grammar& g, EcoDrawing drawing, const EcoAssets* assets)
        : plant_(plant), g_(g), drawing_(drawing), assets_(assets) {
        // Index 0 stays black and 1 bark-brown, as in simeco's default palette; stage colours follow.
        g_.view.palette = {{0.0f, 0.0f, 0.0f}, {0.20f, 0.11f, 0.05f}, {0.09f, 0.30f, 0.05f}};
    }

    void build() {
        addOrgan(EcoOrganKind::Stem);
        addOrgan(EcoOrganKind::Root);
        addOrgan(EcoOrganKind::Leaf);
        addOrgan(EcoOrganKind::Flower);
        addOrgan(EcoOrganKind::Fruit);
        addOrgan(EcoOrganKind::Apex);
        g_.homomorphism.present = true;
        g_.homomorphism.maxDepth = 1;
        // The leaf surface takes its shape from the plant's name (a rose's leaves are compound, an oxalis's
        // cordate: turtle::surfaceShapeOf).
        g_.view.surfaces.push_back({"leaf", plant_.name, 1.0f, std::nullopt, nullptr});
        // So does its flowers' blossom (turtle::surfaceShapeOf: Lantana's flower head, a rose's).
        g_.view.surfaces.push_back({"blossom", plant_.name, 1.0f, std::nullopt, nullptr});
    }

private:
    const ir::EcoPlant& plant_;
    ir::Grammar& g_;
    EcoDrawing drawing_;
    const EcoAssets* assets_;
    std::map<std::pair<std::array<float, 3>, int>, int> colorIndex_; // a colour and its texture layer (or -1)
    std::map<int, int> leafShades_; // a mature leaf colour's index: the first of its shades

    // The stage's Color, tinted by its Material's diffuse factor (MTRL's first three numbers, scaled so that
    // the largest is 1: the tint changes the hue, the Color keeps its brightness).
    int colorOf(const ir::EcoOrgan& organ, const ir::EcoStage* stage, EcoOrganKind kind) {
        const ir::EcoColor* c = nullptr;
        if (stage && stage->color) c = &*stage->color;
        else if (organ.defaultStage && organ.defaultStage->color) c = &*organ.defaultStage->color;
        const int texture = textureOf(organ, stage);
        if (!c && texture < 0) return kind == EcoOrganKind::Stem || kind == EcoOrganKind::Root ? 1 : 2;
        if (!c) return paletteEntry({1.0f, 1.0f, 1.0f}, texture); // the texture in its own colours
        std::array<float, 3> tint = {1.0f, 1.0f, 1.0f};
        const ir::EcoMaterial* material = nullptr;
        if (stage && stage->material) material = &*stage->material;
        else if (organ.defaultStage && organ.defaultStage->material) material = &*organ.defaultStage->material;
        if (material) {
            for (size_t k = 0; k < 3; ++k) tint[k] = std::max(material->values[k].typical(), 0.0f);
            float largest = std::max({tint[0], tint[1], tint[2]});
            if (largest > 0.0f)
                for (float& t : tint) t /= largest;
            else
                tint = {1.0f, 1.0f, 1.0f};
        }
        std::array<float, 3> rgb = {srgbToLinear(std::clamp(c->r.typical() * tint[0], 0.0f, 1.0f)),
                                     srgbToLinear(std::clamp(c->g.typical() * tint[1], 0.0f, 1.0f)),
                                     srgbToLinear(std::clamp(c->b.typical() * tint[2], 0.0f, 1.0f))};
        return paletteEntry(rgb, texture);
    }

    // The texture layer of the stage's Texture where the renderer holds it, else -1.
    int textureOf(const ir::EcoOrgan& organ, const ir::EcoStage* stage) const {
        const std::optional<std::string>* texture = nullptr;
        if (stage && stage->texture) texture = &stage->texture;
        else if (organ.defaultStage && organ.defaultStage->texture) texture = &organ.defaultStage->texture;
        if (!assets_ || !texture) return -1;
        auto it = assets_->textureLayers.find(**texture);
        return it == assets_->textureLayers.end() ? -1 : static_cast<int>(it->second);
    }

    // The palette entry of a colour tinting texture layer `texture` (-1: none), added where it is new.
    int paletteEntry(const std::array<float, 3>& rgb, int texture) {
        auto it = colorIndex_.find({rgb, texture});
        if (it != colorIndex_.end()) return it->second;
        if (g_.view.palette.size() >= 256) return 2; // a palette holds 256 colours
        int index = static_cast<int>(g_.view.palette.size());
        addPaletteEntry(rgb, texture);
        colorIndex_[{rgb, texture}] = index;
        return index;
    }

    void addPaletteEntry(const std::array<float, 3>& rgb, int texture) {
        g_.view.palette.push_back(rgb);
        g_.view.paletteTextures.resize(g_.view.palette.size(), -1);
        g_.view.paletteTextures.back() = texture;
    }

    // A leaf colour's three palette entries, for code kGrownLeafColor + the first: mature, young (lighter and
    // yellower, while it unfolds) and old (yellow). Nullopt where the palette has no room.
    std::optional<int> leafShadesOf(int mature) {
        auto it = leafShades_.find(mature);
        if (it != leafShades_.end()) return it->second;
        if (g_.view.palette.size() + 3 > 256) return std::nullopt;
        const std::array<float, 3> rgb = g_.view.palette[size_t(mature)];
        const std::array<float, 3> spring = {srgbToLinear(0.62f), srgbToLinear(0.80f), srgbToLinear(0.25f)};
        const std::array<float, 3> autumn = {srgbToLinear(0.82f), srgbToLinear(0.66f), srgbToLinear(0.16f)};
        std::array<float, 3> young;
        for (size_t k = 0; k < 3; ++k) young[k] = 0.5f * (rgb[k] + spring[k]);
        const int first = static_cast<int>(g_.view.palette.size());
        const std::vector<int>& textures = g_.view.paletteTextures;
        const int texture = size_t(mature) < textures.size() ? textures[size_t(mature)] : -1;
        addPaletteEntry(rgb, texture);
        addPaletteEntry(young, texture);
        addPaletteEntry(autumn, texture);
        leafShades_[mature] = first;
        return first;
    }

    // The surface an organ of the stage is drawn with: its Model's where the renderer holds it, else `builtIn`
    // (`leaf`, `blossom`: the built-in shapes of the plant's name; empty: none, a fruit's sphere).
    std::string surfaceOf(const ir::EcoOrgan& organ, const ir::EcoStage* stage, const std::string& builtIn) {
        const std::optional<std::string>* model = nullptr;
        if (stage && stage->model) model = &stage->model;
        else if (organ.defaultStage && organ.defaultStage->model) model = &organ.defaultStage->model;
        if (!assets_ || !model) return builtIn;
        auto it = assets_->modelShapes.find(**model);
        if (it == assets_->modelShapes.end()) return builtIn;
        const std::string name = "leafModel" + std::to_string(it->second);
        const bool known = std::any_of(g_.view.surfaces.begin(), g_.view.surfaces.end(),
                                       [&](const ir::ViewSettings::Surface& s) { return s.name == name; });
        if (!known) g_.view.surfaces.push_back({name, **model, 1.0f, it->second, nullptr});
        return name;
    }

    ir::SuccessorModule module(const std::string& name, std::vector<float> args, const ir::SourceLoc& loc) {
        ir::SuccessorModule m;
        m.sym = g_.symbol(name);
        for (float a : args) m.args.push_back(ir::Expr::constant(a, loc));
        m.loc = loc;
        return m;
    }

    // The modules that draw the organ at `stage` (nullptr: a stage the script does not describe).
    std::vector<ir::SuccessorModule> drawing(EcoOrganKind kind, const ir::EcoOrgan& organ, const ir::EcoStage* stage,
                                             int stageNumber, const ir::SourceLoc& loc) {
        std::vector<ir::SuccessorModule> out;
        if (kind == EcoOrganKind::Apex) return out;
        if (drawing_ == EcoDrawing::Grown) {
            grownDrawing(kind, organ, colorOf(organ, stage, kind), surfaceOf(organ, stage, builtInSurface(kind)), loc,
                         out);
            return out;
        }
        out.push_back(module(";", {float(colorOf(organ, stage, kind))}, loc));
        float grown = growth(organ, stage);
        switch (kind) {
        case EcoOrganKind::Stem:
        case EcoOrganKind::Root: {
            float time = property(organ, stage, &ir::EcoStage::growTime).value_or(kEcoDefaultGrowTime);
            std::optional<float> broaden = property(organ, stage, &ir::EcoStage::broadenRate);
            float width = broaden ? *broaden * time : kEcoDefaultStemWidth;
            out.push_back(module("!", {width}, loc));
            out.push_back(module("G", {grown > 0 ? grown : kEcoDefaultStemLength}, loc));
            break;
        }
        case EcoOrganKind::Leaf: {
            // A leaf particle scales a leaf model up from its initial size; leaves step through their stages in
            // order, so a leaf at stage s has grown in every stage up to s.
            float grownSince = 0;
            for (int k = 0; k <= std::max(stageNumber, 0); ++k) grownSince += growth(organ, organ.stageFor(k));
            out.push_back(module("~", {}, loc));
            out.push_back(module(surfaceOf(organ, stage, "leaf"), {kEcoLeafModelSize * (1.0f + grownSince)}, loc));
            break;
        }
        case EcoOrganKind::Flower:
        case EcoOrganKind::Fruit:
            bloomDrawing(surfaceOf(organ, stage, builtInSurface(kind)), grown > 0 ? grown : kEcoDefaultFlowerSize,
                         loc, out);
            break;
        default: break;
        }
        return out;
    }

    static std::string builtInSurface(EcoOrganKind kind) {
        return kind == EcoOrganKind::Leaf ? "leaf" : kind == EcoOrganKind::Flower ? "blossom" : "";
    }

    // A flower or fruit of diameter `size`: a surface (a blossom, a model), else a sphere.
    void bloomDrawing(const std::string& surface, float size, const ir::SourceLoc& loc,
                      std::vector<ir::SuccessorModule>& out) {
        if (surface.empty()) {
            out.push_back(module("@", {}, loc));
            out.push_back(module("O", {size}, loc));
            return;
        }
        out.push_back(module("~", {}, loc));
        out.push_back(module(surface, {size}, loc));
    }

    // The drawing at the sizes the particle has grown to: each size a code the growth simulation replaces. Stems
    // bend (`tropism`) only where a stage sets Geotropism or WeightFactor, turn toward the light (`phototropism`)
    // only where one sets Phototropism, and are shed (`alive`) only where one sets a LifeTime or a ShadeTime, so
    // that plants without them draw no more modules.
    void grownDrawing(EcoOrganKind kind, const ir::EcoOrgan& organ, int color, const std::string& surface,
                      const ir::SourceLoc& loc, std::vector<ir::SuccessorModule>& out) {
        auto code = [](uint32_t c) { return shared::kGrownValue - float(c); };
        std::optional<int> shades = kind == EcoOrganKind::Leaf ? leafShadesOf(color) : std::nullopt;
        out.push_back(module(";", {shades ? code(shared::kGrownLeafColor + uint32_t(*shades)) : float(color)}, loc));
        switch (kind) {
        case EcoOrganKind::Stem:
        case EcoOrganKind::Root:
            // Shed before the width is set, which takes the scale of its time: a shed stem is no width and no length.
            if (anySet(organ, &ir::EcoStage::lifeTime) || anySet(organ, &ir::EcoStage::shadeTime))
                out.push_back(module("alive", {code(shared::kGrownAlive)}, loc));
            out.push_back(module("!", {code(shared::kGrownWidth)}, loc));
            if (anySet(organ, &ir::EcoStage::geotropism) || anySet(organ, &ir::EcoStage::weightFactor))
                out.push_back(module("tropism", {code(shared::kGrownBend)}, loc));
            out.push_back(module("tilt", {code(shared::kGrownPitch), code(shared::kGrownRoll)}, loc));
            if (anySet(organ, &ir::EcoStage::phototropism))
                out.push_back(module("phototropism",
                                     {code(shared::kGrownLightBend), code(shared::kGrownLightX),
                                      code(shared::kGrownLightY), code(shared::kGrownLightZ)},
                                     loc));
            out.push_back(module("G", {code(shared::kGrownLength)}, loc));
            break;
        case EcoOrganKind::Leaf:
            out.push_back(module("~", {}, loc));
            out.push_back(module(surface, {code(shared::kGrownLeafSize)}, loc));
            break;
        case EcoOrganKind::Flower:
        case EcoOrganKind::Fruit:
            bloomDrawing(surface, code(shared::kGrownLength), loc, out);
            break;
        default: break;
        }
    }

    // Whether any stage of the organ (its Default included) sets the property to other than 0.
    template <typename Member>
    static bool anySet(const ir::EcoOrgan& organ, Member member) {
        auto set = [&](const ir::EcoStage& stage) {
            return (stage.*member) && ((stage.*member)->min != 0.0f || (stage.*member)->max != 0.0f);
        };
        if (organ.defaultStage && set(*organ.defaultStage)) return true;
        return std::any_of(organ.stages.begin(), organ.stages.end(), [&](const auto& s) { return set(s.second); });
    }

    // `X(s) : s == stage --> drawing` for each described stage, then `X(s) --> default drawing`.
    void addOrgan(EcoOrganKind kind) {
        const ir::EcoOrgan& organ = plant_.organ(kind);
        ir::SymbolId sym = g_.symbol(std::string(1, ir::kEcoSegmentLetters[static_cast<int>(kind)]));
        ir::SourceLoc loc = organ.present ? organ.loc : plant_.loc;
        auto production = [&](std::optional<int> stage) {
            ir::Production p;
            p.strict.push_back({sym, {0}, loc});
            p.frameSize = 1;
            p.slotNames = {"stage"};
            p.loc = loc;
            if (stage) {
                ir::Expr slot;
                slot.op = ir::Op::Local;
                slot.slot = 0;
                slot.loc = loc;
                ir::Expr test;
                test.op = ir::Op::Eq;
                test.args = {slot, ir::Expr::constant(*stage, loc)};
                test.loc = loc;
                p.condition = test;
            }
            // The default production stands for stages past the described ones: a leaf there has grown through
            // all of them.
            const ir::EcoStage* settings = stage ? organ.stageFor(*stage)
                                                 : (organ.defaultStage ? &*organ.defaultStage : nullptr);
            int lastDescribed = organ.stages.empty() ? 0 : organ.stages.rbegin()->first;
            ir::Alternative alt;
            alt.modules = drawing(kind, organ, settings, stage.value_or(lastDescribed), loc);
            p.alternatives.push_back(std::move(alt));
            g_.homomorphism.productions.push_back(std::move(p));
        };
        for (const auto& [stage, settings] : organ.stages) production(stage);
        production(std::nullopt);
    }
};

} // namespace

void addEcoOrganGeometry(const ir::EcoPlant& plant, ir::Grammar& g, EcoDrawing drawing,
                         const EcoAssets* assets) {
    GeometryBuilder(plant, g, drawing, assets).build();
}

} // namespace simeco::lang
