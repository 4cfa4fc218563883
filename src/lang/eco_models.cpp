#include "lang/eco_models.h"

#include <algorithm>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "compute/shared/organ_layout.h"
#include "lang/obj_leaf_model.h"

namespace simeco::lang {

EcoModelShapes loadEcoModels(const ir::EcoScene& scene, std::vector<ir::LeafModel>& models,
                                    std::vector<ir::EcoWarning>* warnings) {
    EcoModelShapes shapes;
    std::vector<std::string> unread;
    std::optional<ir::SourceLoc> firstUnread;
    std::string firstWhy;
    auto consider = [&](const ir::EcoStage& stage, bool leafStage) {
        if (!stage.model) return;
        if (auto known = shapes.find(*stage.model); known != shapes.end()) {
            models[known->second - shared::kSurfaceLastShape - 1].leaf |= leafStage;
            return;
        }
        if (std::find(unread.begin(), unread.end(), *stage.model) != unread.end()) return;
        const std::filesystem::path path = std::filesystem::path(scene.file).parent_path() / *stage.model;
        std::string why = "it is not a Wavefront .obj file";
        std::optional<ir::LeafModel> model;
        if (path.extension() == ".obj") model = readObjLeafModel(path.string(), why);
        if (!model) {
            unread.push_back(*stage.model);
            if (!firstUnread) firstUnread = stage.loc, firstWhy = why;
            return;
        }
        shapes[*stage.model] = shared::kSurfaceLastShape + 1 + uint32_t(models.size());
        model->leaf = leafStage;
        models.push_back(std::move(*model));
    };
    for (const ir::EcoPlant& plant : scene.plants) {
        if (!plant.grammar.empty()) continue;
        for (ir::EcoOrganKind kind : {ir::EcoOrganKind::Leaf, ir::EcoOrganKind::Flower, ir::EcoOrganKind::Fruit}) {
            const ir::EcoOrgan& organ = plant.organ(kind);
            const bool leafStage = kind == ir::EcoOrganKind::Leaf;
            for (const auto& [number, stage] : organ.stages) consider(stage, leafStage);
            if (organ.defaultStage) consider(*organ.defaultStage, leafStage);
        }
    }
    if (!unread.empty() && warnings) {
        std::string names;
        for (const std::string& name : unread) names += (names.empty() ? "\"" : ", \"") + name + "\"";
        warnings->push_back(
            {*firstUnread, fmt::format("Model{} {} not read, drawn with the built-in organs (the first: {})",
                                       unread.size() > 1 ? "s" : "", names, firstWhy)});
    }
    return shapes;
}

} // namespace simeco::lang
