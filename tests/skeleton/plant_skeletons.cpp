#include "plant_skeletons.h"

#include <chrono>
#include <fstream>

#include "field/field.h"
#include "skeleton/eco_writer.h"
#include "skeleton/lsystem_writer.h"
#include "skeleton/skeleton_check.h"
#include "skeleton/skeleton_from_turtle.h"

namespace simeco::test {

skeleton::Plant skeletonOfFile(const std::filesystem::path& file, int steps) {
    field::FieldSource source;
    source.file = file.string();
    source.steps = steps;
    source.backend = field::Backend::Cpu;
    field::Field f = field::deriveField(source, nullptr);
    turtle::Interpretation drawn = field::interpretOnHost(source, f, nullptr);
    return skeleton::plantFromTurtle(f.string, drawn, 0);
}

skeleton::Plant skeletonOfText(const std::string& text, const std::filesystem::path& file) {
    std::ofstream(file) << text;
    return skeletonOfFile(file);
}

RoundTrip roundTrip(const skeleton::Plant& plant, const std::filesystem::path& file) {
    const auto start = std::chrono::steady_clock::now();
    skeleton::Plant checked = plant;
    skeleton::checkPlant(checked, "skeleton", 0);
    const bool eco = file.extension() == ".eco";
    skeleton::Regrowth growth =
        skeleton::regrowth(checked, eco ? skeleton::Dialect::SimEco : skeleton::Dialect::Cpfg);
    std::string text;
    if (eco) {
        skeleton::EcoScriptOptions options;
        options.source = "a test";
        options.position = growth.tree.base;
        text = skeleton::ecoScript(checked, growth, options);
    } else {
        text = skeleton::lsystemText(checked, growth, "a test");
        std::filesystem::path view = file;
        std::ofstream(view.replace_extension(".v")) << skeleton::lsystemView();
    }
    skeleton::Plant again = skeletonOfText(text, file);
    RoundTrip out;
    out.match = skeleton::matchSegments(plant, again);
    out.internodes = growth.internodes.size();
    out.levels = growth.tree.levels;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace simeco::test
