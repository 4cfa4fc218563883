// The scene part of SimEco scripts (appendix B: Ecosystem, Plant, Organ, Stage and their properties).
//
// The generator's example (seed 002, appendix) was extracted from a PDF whose page breaks duplicated
// closing braces: stages continue after their organ block has closed, and a Plant block sees `}` before its
// Grow block. Such scripts are accepted with warnings: a `}` in a Plant block before its Grow block is
// ignored when an organ, Stage or Grow follows it, and a Stage outside any organ block joins the organ
// block just before it. Everything else about braces is strict.
#include "lang/eco_parser.h"

#include <fmt/format.h>

#include "lang/eco_grow_parser.h"
#include "lang/eco_lexer.h"

namespace simeco::lang {

namespace {

class SceneParser {
public:
    SceneParser(const std::string& text, const std::string& file) : cur_(text, file) {}

    ir::EcoScene scene() {
        scene_.file = cur_.file();
        const EcoToken& keyword = cur_.peek();
        if (!cur_.acceptKeyword("Ecosystem"))
            cur_.failAt(keyword, fmt::format("a script starts with `EcoSystem 1.0 \"name\" {{`, found {}",
                                             EcoTokenCursor::describe(keyword)));
        scene_.loc = cur_.loc(keyword);
        scene_.version = static_cast<float>(plainNumber("as the version after EcoSystem"));
        scene_.name = name("after the version");
        cur_.expectPunct("{", "to open the EcoSystem block");
        ecosystemItems();
        if (!cur_.atEnd())
            cur_.failAt(cur_.peek(), fmt::format("unexpected {} after the end of the EcoSystem block",
                                                 EcoTokenCursor::describe(cur_.peek())));
        return std::move(scene_);
    }

private:
    // ---- values ----

    double plainNumber(const std::string& what) {
        bool negative = cur_.acceptPunct("-");
        const EcoToken& t = cur_.next();
        if (t.kind != EcoTokenKind::Number)
            cur_.failAt(t, fmt::format("expected a number {}, found {}", what, EcoTokenCursor::describe(t)));
        return negative ? -t.number : t.number;
    }

    // Number = RealNumber | NaturalNumber | rand(a, b) (signs allowed: scripts set Geotropism = -0.5).
    ir::EcoNumber number(const std::string& what) {
        const EcoToken& start = cur_.peek();
        ir::SourceLoc loc = cur_.loc(start);
        if (cur_.atKeyword("rand")) {
            cur_.next();
            cur_.expectPunct("(", "after rand");
            double lo = plainNumber("as the lower bound of rand(a, b)");
            cur_.expectPunct(",", "between the bounds of rand(a, b)");
            double hi = plainNumber("as the upper bound of rand(a, b)");
            cur_.expectPunct(")", "after rand(a, b)");
            if (lo > hi)
                cur_.failAt(start, fmt::format("rand({}, {}): the lower bound is above the upper", lo, hi));
            return ir::EcoNumber::range(static_cast<float>(lo), static_cast<float>(hi), loc);
        }
        return ir::EcoNumber::constant(static_cast<float>(plainNumber(what)), loc);
    }

    std::string name(const std::string& what) {
        const EcoToken& t = cur_.next();
        if (t.kind != EcoTokenKind::String)
            cur_.failAt(t, fmt::format("expected a quoted name {}, found {}", what, EcoTokenCursor::describe(t)));
        return t.text;
    }

    // `keyword ( n, n, ... )` with `count` numbers.
    std::vector<ir::EcoNumber> tuple(const char* keyword, size_t count, const std::string& property) {
        const EcoToken& t = cur_.peek();
        if (!cur_.acceptKeyword(keyword))
            cur_.failAt(t, fmt::format("{} takes {}({} numbers), found {}", property, keyword, count,
                                       EcoTokenCursor::describe(t)));
        cur_.expectPunct("(", fmt::format("after {}", keyword));
        std::vector<ir::EcoNumber> values;
        for (size_t i = 0; i < count; ++i) {
            if (i > 0) cur_.expectPunct(",", fmt::format("between the {} numbers of {}", count, keyword));
            values.push_back(number(fmt::format("in {}", keyword)));
        }
        cur_.expectPunct(")", fmt::format("after the {} numbers of {}", count, keyword));
        return values;
    }

    ir::EcoVector vector(const std::string& property) {
        std::vector<ir::EcoNumber> v = tuple("vector", 3, property);
        return {v[0], v[1], v[2]};
    }

    ir::EcoColor color(const std::string& property) {
        std::vector<ir::EcoNumber> v = tuple("RGBA", 4, property);
        return {v[0], v[1], v[2], v[3]};
    }

    ir::EcoMaterial material(const std::string& property) {
        std::vector<ir::EcoNumber> v = tuple("MTRL", 6, property);
        ir::EcoMaterial m;
        for (size_t i = 0; i < 6; ++i) m.values[i] = v[i];
        return m;
    }

    // `Name =` ... `;` around a value; remembers where each property was set to refuse setting it twice.
    const EcoToken& propertyStart(std::vector<std::pair<std::string, ir::SourceLoc>>& seen,
                                  const std::string& canonical, const std::string& where) {
        const EcoToken& t = cur_.next();
        for (const auto& [name, loc] : seen)
            if (name == canonical)
                cur_.failAt(t, fmt::format("{} is set twice in {} (first at line {})", canonical, where, loc.line));
        seen.emplace_back(canonical, cur_.loc(t));
        cur_.expectPunct("=", fmt::format("after {}", t.text));
        return t;
    }

    // ---- blocks ----

    void ecosystemItems() {
        std::vector<std::pair<std::string, ir::SourceLoc>> seen;
        for (;;) {
            const EcoToken& t = cur_.peek();
            if (cur_.atPunct("}")) {
                cur_.next();
                return;
            }
            if (t.kind == EcoTokenKind::End)
                cur_.failAt(t, fmt::format("missing '}}' closing the EcoSystem block opened at line {}",
                                           scene_.loc.line));
            if (cur_.atKeyword("Plant")) {
                plant();
                continue;
            }
            const char* numeric[] = {"SoilPH", "RainRate", "DayLight"};
            ir::EcoNumber* targets[] = {&scene_.soilPH, &scene_.rainRate, &scene_.dayLight};
            bool done = false;
            for (int i = 0; i < 3 && !done; ++i) {
                if (cur_.atKeyword(numeric[i])) {
                    propertyStart(seen, numeric[i], "the EcoSystem block");
                    *targets[i] = number(fmt::format("for {}", numeric[i]));
                    cur_.expectPunct(";", fmt::format("after the value of {}", numeric[i]));
                    done = true;
                }
            }
            if (done) continue;
            if (cur_.atKeyword("Gravity")) {
                propertyStart(seen, "Gravity", "the EcoSystem block");
                scene_.gravity = vector("Gravity");
                cur_.expectPunct(";", "after the value of Gravity");
                continue;
            }
            unknown(t, "the EcoSystem block", "SoilPH, RainRate, DayLight, Gravity or Plant");
        }
    }

    [[noreturn]] void unknown(const EcoToken& t, const char* where, const char* expected) {
        if (t.kind == EcoTokenKind::Identifier)
            cur_.failAt(t, fmt::format("unknown keyword '{}' in {} (expected {})", t.text, where, expected));
        cur_.failAt(t, fmt::format("expected {} in {}, found {}", expected, where, EcoTokenCursor::describe(t)));
    }

    std::optional<ir::EcoOrganKind> organAt() const {
        for (int k = 0; k < ir::kEcoOrganKinds; ++k)
            if (cur_.atKeyword(ir::kEcoOrganNames[k])) return static_cast<ir::EcoOrganKind>(k);
        return std::nullopt;
    }

    bool stageAt() const { return cur_.atKeyword("Stage") || cur_.atKeyword("Default"); }

    void plant() {
        const EcoToken& keyword = cur_.next();
        ir::EcoPlant p;
        p.loc = cur_.loc(keyword);
        p.name = name("after Plant");
        cur_.expectPunct("{", "to open the Plant block");
        std::vector<std::pair<std::string, ir::SourceLoc>> seen;
        std::optional<ir::EcoOrganKind> lastOrgan;
        bool hasGrow = false;
        bool continuingOrgan = false; // one warning for a run of stages outside their organ block
        for (;;) {
            const EcoToken& t = cur_.peek();
            if (!stageAt()) continuingOrgan = false;
            if (cur_.atPunct("}")) {
                if (hasGrow) {
                    cur_.next();
                    break;
                }
                strayBrace(p, lastOrgan);
                continue;
            }
            if (t.kind == EcoTokenKind::End)
                cur_.failAt(t, fmt::format("missing '}}' closing the Plant block \"{}\" opened at line {}", p.name,
                                           p.loc.line));
            if (hasGrow)
                cur_.failAt(t, fmt::format("expected '}}' closing Plant \"{}\" after its Grow block, found {}", p.name,
                                           EcoTokenCursor::describe(t)));
            if (cur_.atKeyword("Position") || cur_.atKeyword("Direction")) {
                bool position = cur_.atKeyword("Position");
                const char* prop = position ? "Position" : "Direction";
                propertyStart(seen, prop, "the Plant block");
                (position ? p.position : p.direction) = vector(prop);
                cur_.expectPunct(";", fmt::format("after the value of {}", prop));
            } else if (cur_.atKeyword("DeriveTime")) {
                propertyStart(seen, "DeriveTime", "the Plant block");
                p.deriveTime = number("for DeriveTime");
                if (p.deriveTime.min <= 0.0f)
                    throw ir::InputError(p.deriveTime.loc, "DeriveTime must be above 0 seconds");
                cur_.expectPunct(";", "after the value of DeriveTime");
            } else if (cur_.atKeyword("DerivationLength")) {
                propertyStart(seen, "DerivationLength", "the Plant block");
                const EcoToken& n = cur_.next();
                if (n.kind != EcoTokenKind::Number || n.text.find_first_not_of("0123456789") != std::string::npos ||
                    n.number > 1e6)
                    cur_.failAt(n, fmt::format("DerivationLength is a whole number of steps, found {}",
                                               EcoTokenCursor::describe(n)));
                p.derivationLength = static_cast<int>(n.number);
                cur_.expectPunct(";", "after the value of DerivationLength");
            } else if (std::optional<ir::EcoOrganKind> kind = organAt()) {
                organ(p, *kind);
                lastOrgan = kind;
            } else if (stageAt()) {
                if (!lastOrgan)
                    cur_.failAt(t, fmt::format("{} outside an organ block (Apex, Stem, Leaf, Flower, Fruit, Root)",
                                               t.text));
                if (!continuingOrgan)
                    scene_.warnings.push_back(
                        {cur_.loc(t), fmt::format("{} outside an organ block: added to the {} block before it",
                                                  t.text, ir::kEcoOrganNames[static_cast<int>(*lastOrgan)])});
                stage(p.organs[static_cast<int>(*lastOrgan)], *lastOrgan);
                continuingOrgan = true;
                continue;
            } else if (cur_.atKeyword("Grow")) {
                cur_.next();
                p.grow = parseEcoGrowBlock(cur_, scene_.warnings);
                hasGrow = true;
            } else {
                unknown(t, "the Plant block",
                        "Position, Direction, DeriveTime, an organ (Apex, Stem, Leaf, Flower, Fruit, Root) or Grow");
            }
        }
        scene_.plants.push_back(std::move(p));
    }

    // A `}` in a Plant block before its Grow block: a duplicated organ close when an organ, Stage or Grow
    // follows (after any further braces); otherwise the Grow block is missing.
    void strayBrace(const ir::EcoPlant& p, const std::optional<ir::EcoOrganKind>& lastOrgan) {
        const EcoToken& brace = cur_.peek();
        size_t ahead = 1;
        while (cur_.atPunct("}", ahead)) ++ahead;
        bool continues = lastOrgan && (cur_.atKeyword("Stage", ahead) || cur_.atKeyword("Default", ahead) ||
                                       cur_.atKeyword("Grow", ahead));
        for (int k = 0; k < ir::kEcoOrganKinds && lastOrgan; ++k)
            continues |= cur_.atKeyword(ir::kEcoOrganNames[k], ahead);
        if (!continues)
            cur_.failAt(brace, fmt::format("Plant \"{}\" ends without a Grow block (`Grow {{ w = A(0); ... }}`)",
                                           p.name));
        scene_.warnings.push_back({cur_.loc(brace), "stray '}' before the Grow block ignored"});
        cur_.next();
    }

    void organ(ir::EcoPlant& p, ir::EcoOrganKind kind) {
        const EcoToken& keyword = cur_.next();
        ir::EcoOrgan& o = p.organs[static_cast<int>(kind)];
        const char* organName = ir::kEcoOrganNames[static_cast<int>(kind)];
        if (o.present)
            cur_.failAt(keyword, fmt::format("{} block defined twice in Plant \"{}\" (first at line {})", organName,
                                             p.name, o.loc.line));
        o.present = true;
        o.loc = cur_.loc(keyword);
        cur_.expectPunct("{", fmt::format("after {}", organName));
        for (;;) {
            const EcoToken& t = cur_.peek();
            if (cur_.acceptPunct("}")) return;
            if (t.kind == EcoTokenKind::End)
                cur_.failAt(t, fmt::format("missing '}}' closing the {} block opened at line {}", organName,
                                           o.loc.line));
            if (organAt() || cur_.atKeyword("Grow") || cur_.atKeyword("Plant"))
                cur_.failAt(t, fmt::format("missing '}}' closing the {} block before {}", organName, t.text));
            if (!stageAt())
                unknown(t, fmt::format("the {} block", organName).c_str(), "Stage N, Default or '}'");
            stage(o, kind);
        }
    }

    void stage(ir::EcoOrgan& o, ir::EcoOrganKind kind) {
        const EcoToken& keyword = cur_.next();
        const char* organName = ir::kEcoOrganNames[static_cast<int>(kind)];
        ir::EcoStage s;
        s.loc = cur_.loc(keyword);
        std::string where;
        std::optional<int> number;
        if (equalsIgnoreCase(keyword.text, "Default")) {
            if (o.defaultStage)
                cur_.failAt(keyword, fmt::format("{} has two Default stages (first at line {})", organName,
                                                 o.defaultStage->loc.line));
            where = fmt::format("{} Default", organName);
        } else {
            const EcoToken& n = cur_.next();
            if (n.kind != EcoTokenKind::Number || n.text.find_first_not_of("0123456789") != std::string::npos ||
                n.number > ir::kMostStage)
                cur_.failAt(n, fmt::format("a stage is a whole number from 0 to {}, found {}", ir::kMostStage,
                                           EcoTokenCursor::describe(n)));
            number = static_cast<int>(n.number);
            auto it = o.stages.find(*number);
            if (it != o.stages.end())
                cur_.failAt(n, fmt::format("{} Stage {} is defined twice (first at line {})", organName, *number,
                                           it->second.loc.line));
            where = fmt::format("{} Stage {}", organName, *number);
        }
        cur_.expectPunct("{", fmt::format("to open {}", where));
        std::vector<std::pair<std::string, ir::SourceLoc>> seen;
        for (;;) {
            const EcoToken& t = cur_.peek();
            if (cur_.acceptPunct("}")) break;
            if (t.kind == EcoTokenKind::End)
                cur_.failAt(t, fmt::format("missing '}}' closing {} opened at line {}", where, s.loc.line));
            stageProperty(s, seen, where);
        }
        if (number) o.stages.emplace(*number, std::move(s));
        else o.defaultStage = std::move(s);
    }

    // StageProperty of appendix B, plus GrowTime (every thesis script sets it) and the Front/Back variants
    // of Texture, Color and Material that the L-grammar generator writes.
    void stageProperty(ir::EcoStage& s, std::vector<std::pair<std::string, ir::SourceLoc>>& seen,
                       const std::string& where) {
        const EcoToken& t = cur_.peek();
        if (t.kind != EcoTokenKind::Identifier)
            cur_.failAt(t, fmt::format("expected a property or '}}' in {}, found {}", where,
                                       EcoTokenCursor::describe(t)));
        if (stageAt() || organAt() || cur_.atKeyword("Grow") || cur_.atKeyword("Plant"))
            cur_.failAt(t, fmt::format("missing '}}' closing {} before {}", where, t.text));
        struct NumberProperty {
            const char* name;
            std::optional<ir::EcoNumber> ir::EcoStage::*field;
        };
        static const NumberProperty numbers[] = {
            {"GrowRate", &ir::EcoStage::growRate},       {"GrowTime", &ir::EcoStage::growTime},
            {"LifeTime", &ir::EcoStage::lifeTime},       {"BroadenRate", &ir::EcoStage::broadenRate},
            {"WeightFactor", &ir::EcoStage::weightFactor}, {"ConeNoise", &ir::EcoStage::coneNoise},
            {"NoiseTime", &ir::EcoStage::noiseTime},     {"Strength", &ir::EcoStage::strength},
            {"Geotropism", &ir::EcoStage::geotropism},
        };
        struct NamedProperty {
            const char* name;
            const char* canonical;
        };
        static const NamedProperty strings[] = {
            {"Model", "Model"}, {"Texture", "Texture"}, {"TextureFront", "Texture"}, {"TextureBack", "TextureBack"}};
        static const NamedProperty colors[] = {{"Color", "Color"}, {"ColorFront", "Color"}, {"ColorBack", "ColorBack"}};
        static const NamedProperty materials[] = {
            {"Material", "Material"}, {"MaterialFront", "Material"}, {"MaterialBack", "MaterialBack"}};

        for (const NumberProperty& prop : numbers) {
            if (cur_.atKeyword(prop.name)) {
                propertyStart(seen, prop.name, where);
                s.*prop.field = number(fmt::format("for {}", prop.name));
                cur_.expectPunct(";", fmt::format("after the value of {}", prop.name));
                return;
            }
        }
        for (const NamedProperty& prop : strings) {
            if (cur_.atKeyword(prop.name)) {
                propertyStart(seen, prop.canonical, where);
                std::string value = name(fmt::format("for {}", prop.name));
                std::string canonical = prop.canonical;
                (canonical == "Model" ? s.model : canonical == "Texture" ? s.texture : s.textureBack) = value;
                cur_.expectPunct(";", fmt::format("after the value of {}", prop.name));
                return;
            }
        }
        for (const NamedProperty& prop : colors) {
            if (cur_.atKeyword(prop.name)) {
                propertyStart(seen, prop.canonical, where);
                (std::string(prop.canonical) == "Color" ? s.color : s.colorBack) = color(prop.name);
                cur_.expectPunct(";", fmt::format("after the value of {}", prop.name));
                return;
            }
        }
        for (const NamedProperty& prop : materials) {
            if (cur_.atKeyword(prop.name)) {
                propertyStart(seen, prop.canonical, where);
                (std::string(prop.canonical) == "Material" ? s.material : s.materialBack) = material(prop.name);
                cur_.expectPunct(";", fmt::format("after the value of {}", prop.name));
                return;
            }
        }
        cur_.failAt(t, fmt::format("unknown stage property '{}' in {} (expected Model, Texture, GrowRate, "
                                   "GrowTime, LifeTime, BroadenRate, WeightFactor, Color, Material, ConeNoise, "
                                   "NoiseTime, Strength or Geotropism)",
                                   t.text, where));
    }

    EcoTokenCursor cur_;
    ir::EcoScene scene_;
};

} // namespace

ir::EcoScene parseEcoText(const std::string& text, const std::string& file) {
    requireText(text, file);
    return SceneParser(text, file).scene();
}

ir::EcoScene parseEcoFile(const std::string& path) {
    std::string text = readSourceFile(path);
    return SceneParser(text, path).scene();
}

} // namespace simeco::lang
