#include "lang/eco_assets.h"

#include <algorithm>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "compute/shared/organ_layout.h"
#include "lang/obj_leaf_model.h"
#include "lang/texture_file.h"

namespace simeco::lang {

namespace {

// The files of one kind that could not be read, for one warning.
struct Unread {
    std::vector<std::string> names;
    std::optional<ir::SourceLoc> first;
    std::string firstWhy;

    bool contains(const std::string& name) const {
        return std::find(names.begin(), names.end(), name) != names.end();
    }
    void add(const std::string& name, const ir::SourceLoc& loc, const std::string& why) {
        names.push_back(name);
        if (!first) first = loc, firstWhy = why;
    }
    void warn(const char* what, const char* instead, std::vector<ir::EcoWarning>* warnings) const {
        if (names.empty() || !warnings) return;
        std::string list;
        for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
        warnings->push_back({*first, fmt::format("{}{} {} not read, {} (the first: {})", what,
                                                 names.size() > 1 ? "s" : "", list, instead, firstWhy)});
    }
};

} // namespace

EcoAssets loadEcoAssets(const ir::EcoScene& scene, ir::DrawAssets& assets, std::vector<ir::EcoWarning>* warnings) {
    EcoAssets found;
    Unread unreadModels, unreadTextures;
    const std::filesystem::path folder = std::filesystem::path(scene.file).parent_path();
    auto considerModel = [&](const ir::EcoStage& stage, bool leafStage) {
        if (!stage.model) return;
        if (auto known = found.modelShapes.find(*stage.model); known != found.modelShapes.end()) {
            assets.models[known->second - shared::kSurfaceLastShape - 1].leaf |= leafStage;
            return;
        }
        if (unreadModels.contains(*stage.model)) return;
        const std::filesystem::path path = folder / *stage.model;
        std::string why = "it is not a Wavefront .obj file";
        std::optional<ir::LeafModel> model;
        if (path.extension() == ".obj") model = readObjLeafModel(path.string(), why);
        if (!model) return unreadModels.add(*stage.model, stage.loc, why);
        found.modelShapes[*stage.model] = shared::kSurfaceLastShape + 1 + uint32_t(assets.models.size());
        model->leaf = leafStage;
        assets.models.push_back(std::move(*model));
    };
    auto considerTexture = [&](const ir::EcoStage& stage) {
        if (!stage.texture || found.textureLayers.count(*stage.texture) || unreadTextures.contains(*stage.texture))
            return;
        std::string why;
        std::optional<ir::TextureImage> image = readTextureFile((folder / *stage.texture).string(), why);
        if (!image) return unreadTextures.add(*stage.texture, stage.loc, why);
        found.textureLayers[*stage.texture] = uint32_t(assets.textures.size());
        assets.textures.push_back(std::move(*image));
    };
    for (const ir::EcoPlant& plant : scene.plants) {
        if (!plant.grammar.empty()) continue;
        for (size_t k = 0; k < ir::kEcoOrganKinds; ++k) {
            const auto kind = static_cast<ir::EcoOrganKind>(k);
            const ir::EcoOrgan& organ = plant.organ(kind);
            const bool modelled = kind == ir::EcoOrganKind::Leaf || kind == ir::EcoOrganKind::Flower ||
                                  kind == ir::EcoOrganKind::Fruit;
            auto consider = [&](const ir::EcoStage& stage) {
                if (modelled) considerModel(stage, kind == ir::EcoOrganKind::Leaf);
                considerTexture(stage);
            };
            for (const auto& [number, stage] : organ.stages) consider(stage);
            if (organ.defaultStage) consider(*organ.defaultStage);
        }
    }
    unreadModels.warn("Model", "drawn with the built-in organs", warnings);
    unreadTextures.warn("Texture", "drawn in their colours", warnings);
    return found;
}

} // namespace simeco::lang
