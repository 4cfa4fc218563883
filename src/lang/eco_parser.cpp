// The scene part of SimEco scripts (appendix B: Ecosystem, Plant, Organ, Stage and their properties).
//
// The generator's example (seed 002, appendix) was extracted from a PDF whose page breaks duplicated
// closing braces: stages continue after their organ block has closed, and a Plant block sees `}` before its
// Grow block. Such scripts are accepted with warnings: a `}` in a Plant block before its Grow block is
// ignored when an organ, Stage or Grow follows it, and a Stage outside any organ block joins the organ
// block just before it. Everything else about braces is strict.
#include "lang/eco_parser.h"

#include <algorithm>
#include <array>
#include <cmath>

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
        for (const ir::EcoPopulation& pop : scene_.populations) {
            const bool known = std::any_of(scene_.plants.begin(), scene_.plants.end(),
                                           [&](const ir::EcoPlant& plant) { return plant.name == pop.plant; });
            if (!known)
                throw ir::InputError(pop.plantLoc, fmt::format("Population \"{}\" names Plant \"{}\", which the "
                                                               "scene does not define",
                                                               pop.name, pop.plant));
        }
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
            if (fieldItem(seen)) continue;
            unknown(t, "the EcoSystem block",
                    "SoilPH, RainRate, DayLight, Gravity, SunDirection, SunIntensity, SkyLight, GroundSize, Plant, "
                    "Population, Box or Wall");
        }
    }

    // ---- simeco's field extensions (ir/eco_field.h) ----

    // A constant: `rand` has no meaning where the scene, not a plant, is described.
    float constant(const std::string& property) {
        const ir::EcoNumber n = number(fmt::format("for {}", property));
        if (n.random) throw ir::InputError(n.loc, fmt::format("{} takes a number, not a range", property));
        return n.min;
    }
    float positive(const std::string& property) {
        const ir::SourceLoc loc = cur_.loc(cur_.peek());
        const float v = constant(property);
        if (!(v > 0.0f)) throw ir::InputError(loc, fmt::format("{} must be above 0", property));
        return v;
    }
    float nonNegative(const std::string& property) {
        const ir::SourceLoc loc = cur_.loc(cur_.peek());
        const float v = constant(property);
        if (!(v >= 0.0f)) throw ir::InputError(loc, fmt::format("{} must not be below 0", property));
        return v;
    }
    std::array<float, 3> constantVector(const std::string& property) {
        const ir::EcoVector v = vector(property);
        for (const ir::EcoNumber* n : {&v.x, &v.y, &v.z})
            if (n->random) throw ir::InputError(n->loc, fmt::format("{} takes numbers, not ranges", property));
        return {v.x.min, v.y.min, v.z.min};
    }
    // `Property = value;` for a value `read` parses.
    template <typename Read>
    void property(std::vector<std::pair<std::string, ir::SourceLoc>>& seen, const char* name, const char* where,
                  Read read) {
        propertyStart(seen, name, where);
        read();
        cur_.expectPunct(";", fmt::format("after the value of {}", name));
    }

    // An item of the EcoSystem block that simeco adds; false when the next token starts none.
    bool fieldItem(std::vector<std::pair<std::string, ir::SourceLoc>>& seen) {
        ir::EcoLight& light = scene_.light;
        const char* where = "the EcoSystem block";
        if (cur_.atKeyword("SunDirection")) {
            const ir::SourceLoc loc = cur_.loc(cur_.peek());
            property(seen, "SunDirection", where, [&] { light.sunDirection = constantVector("SunDirection"); });
            const auto& d = *light.sunDirection;
            if (d[0] == 0.0f && d[1] == 0.0f && d[2] == 0.0f)
                throw ir::InputError(loc, "SunDirection must not be vector(0, 0, 0)");
        } else if (cur_.atKeyword("SunIntensity")) {
            property(seen, "SunIntensity", where, [&] { light.sunIntensity = nonNegative("SunIntensity"); });
        } else if (cur_.atKeyword("SkyLight")) {
            property(seen, "SkyLight", where, [&] { light.skyLight = nonNegative("SkyLight"); });
        } else if (cur_.atKeyword("GroundSize")) {
            property(seen, "GroundSize", where, [&] { light.groundSize = positive("GroundSize"); });
        } else if (cur_.atKeyword("Population")) {
            population();
        } else if (cur_.atKeyword("Box") || cur_.atKeyword("Wall")) {
            obstacle();
        } else {
            return false;
        }
        return true;
    }

    // `{ items }` of a named block: `item(seen)` parses each; `close` names the block in messages.
    template <typename Item>
    void block(const std::string& what, const ir::SourceLoc& opened, Item item) {
        cur_.expectPunct("{", fmt::format("to open {}", what));
        std::vector<std::pair<std::string, ir::SourceLoc>> seen;
        for (;;) {
            const EcoToken& t = cur_.peek();
            if (cur_.acceptPunct("}")) return;
            if (t.kind == EcoTokenKind::End)
                cur_.failAt(t, fmt::format("missing '}}' closing {} opened at line {}", what, opened.line));
            item(seen, t);
        }
    }

    void population() {
        const EcoToken& keyword = cur_.next();
        ir::EcoPopulation pop;
        pop.loc = cur_.loc(keyword);
        pop.name = name("after Population");
        const std::string what = fmt::format("Population \"{}\"", pop.name);
        block(what, pop.loc, [&](auto& seen, const EcoToken& t) {
            if (cur_.atKeyword("Plant")) {
                property(seen, "Plant", what.c_str(), [&] {
                    pop.plantLoc = cur_.loc(cur_.peek());
                    pop.plant = name("as the Plant block of the population");
                });
            } else if (cur_.atKeyword("Count")) {
                property(seen, "Count", what.c_str(), [&] {
                    const EcoToken& n = cur_.next();
                    if (n.kind != EcoTokenKind::Number || n.text.find_first_not_of("0123456789") != std::string::npos ||
                        n.number < 1 || n.number > 1e7)
                        cur_.failAt(n, fmt::format("Count is a whole number of plants from 1 to 10000000, found {}",
                                                   EcoTokenCursor::describe(n)));
                    pop.count = static_cast<uint32_t>(n.number);
                });
            } else if (cur_.atKeyword("Density")) {
                property(seen, "Density", what.c_str(), [&] { pop.density = positive("Density"); });
            } else if (cur_.atKeyword("Center")) {
                property(seen, "Center", what.c_str(), [&] {
                    const std::array<float, 3> c = constantVector("Center");
                    pop.centerX = c[0];
                    pop.centerZ = c[2];
                });
            } else if (cur_.atKeyword("Size")) {
                property(seen, "Size", what.c_str(), [&] {
                    const ir::SourceLoc loc = cur_.loc(cur_.peek());
                    const std::array<float, 3> size = constantVector("Size");
                    if (!(size[0] > 0.0f && size[2] > 0.0f))
                        throw ir::InputError(loc, "Size is vector(width, 0, depth) with width and depth above 0");
                    pop.width = size[0];
                    pop.depth = size[2];
                });
            } else if (cur_.atKeyword("Placement")) {
                property(seen, "Placement", what.c_str(), [&] {
                    const EcoToken& kind = cur_.next();
                    if (kind.kind == EcoTokenKind::Identifier && equalsIgnoreCase(kind.text, "poisson"))
                        pop.placement = ir::EcoPlacement::Poisson;
                    else if (kind.kind == EcoTokenKind::Identifier && equalsIgnoreCase(kind.text, "jittered"))
                        pop.placement = ir::EcoPlacement::Jittered;
                    else
                        cur_.failAt(kind, fmt::format("Placement is poisson or jittered, found {}",
                                                      EcoTokenCursor::describe(kind)));
                });
            } else if (cur_.atKeyword("Spacing")) {
                property(seen, "Spacing", what.c_str(), [&] { pop.spacing = positive("Spacing"); });
            } else if (cur_.atKeyword("Seed")) {
                property(seen, "Seed", what.c_str(), [&] {
                    const ir::SourceLoc loc = cur_.loc(cur_.peek());
                    const float seed = constant("Seed");
                    if (seed < 0.0f || seed > 4294967295.0f || seed != float(int64_t(seed)))
                        throw ir::InputError(loc, "Seed is a whole number from 0 to 4294967295");
                    pop.seed = static_cast<uint32_t>(seed);
                });
            } else if (cur_.atKeyword("Variation")) {
                property(seen, "Variation", what.c_str(), [&] {
                    const ir::SourceLoc loc = cur_.loc(cur_.peek());
                    pop.variation = constant("Variation");
                    if (pop.variation < 0.0f || pop.variation >= 1.0f)
                        throw ir::InputError(loc, "Variation is a fraction from 0 to below 1");
                });
            } else {
                unknown(t, what.c_str(), "Plant, Count, Density, Center, Size, Placement, Spacing, Seed or Variation");
            }
        });
        if (pop.plant.empty()) cur_.failAt(keyword, fmt::format("{} names no Plant (`Plant = \"...\";`)", what));
        if (pop.count.has_value() == pop.density.has_value())
            cur_.failAt(keyword, fmt::format("{} needs either a Count or a Density", what));
        scene_.populations.push_back(std::move(pop));
    }

    void obstacle() {
        const EcoToken& keyword = cur_.next();
        const bool wall = equalsIgnoreCase(keyword.text, "Wall");
        ir::EcoObstacle o;
        o.loc = cur_.loc(keyword);
        o.name = name(fmt::format("after {}", keyword.text));
        const std::string what = fmt::format("{} \"{}\"", keyword.text, o.name);
        std::optional<std::array<float, 3>> a, b;
        float height = 1.0f, thickness = 0.2f;
        block(what, o.loc, [&](auto& seen, const EcoToken& t) {
            const char* first = wall ? "From" : "Min";
            const char* second = wall ? "To" : "Max";
            if (cur_.atKeyword(first)) {
                property(seen, first, what.c_str(), [&] { a = constantVector(first); });
            } else if (cur_.atKeyword(second)) {
                property(seen, second, what.c_str(), [&] { b = constantVector(second); });
            } else if (wall && cur_.atKeyword("Height")) {
                property(seen, "Height", what.c_str(), [&] { height = positive("Height"); });
            } else if (wall && cur_.atKeyword("Thickness")) {
                property(seen, "Thickness", what.c_str(), [&] { thickness = positive("Thickness"); });
            } else if (cur_.atKeyword("Color")) {
                property(seen, "Color", what.c_str(), [&] {
                    const ir::EcoColor c = color("Color");
                    o.color[0] = c.r.typical();
                    o.color[1] = c.g.typical();
                    o.color[2] = c.b.typical();
                });
            } else {
                unknown(t, what.c_str(), wall ? "From, To, Height, Thickness or Color" : "Min, Max or Color");
            }
        });
        if (!a || !b)
            cur_.failAt(keyword, fmt::format("{} needs {} and {}", what, wall ? "From" : "Min", wall ? "To" : "Max"));
        if (wall) {
            const float dx = (*b)[0] - (*a)[0], dz = (*b)[2] - (*a)[2];
            const float length = std::sqrt(dx * dx + dz * dz);
            if (!(length > 0.0f)) cur_.failAt(keyword, fmt::format("{} runs from a point to the same point", what));
            o.center[0] = 0.5f * ((*a)[0] + (*b)[0]);
            o.center[1] = (*a)[1] + 0.5f * height;
            o.center[2] = 0.5f * ((*a)[2] + (*b)[2]);
            o.halfSize[0] = 0.5f * length;
            o.halfSize[1] = 0.5f * height;
            o.halfSize[2] = 0.5f * thickness;
            o.yaw = std::atan2(-dz, dx);
        } else {
            for (int k = 0; k < 3; ++k) {
                if (!((*b)[k] > (*a)[k]))
                    cur_.failAt(keyword, fmt::format("{}: Max must be above Min along every axis", what));
                o.center[k] = 0.5f * ((*a)[k] + (*b)[k]);
                o.halfSize[k] = 0.5f * ((*b)[k] - (*a)[k]);
            }
        }
        scene_.obstacles.push_back(std::move(o));
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
                if (!p.grammar.empty()) {
                    if (hasGrow || lastOrgan)
                        cur_.failAt(t, fmt::format("Plant \"{}\" takes its grammar from \"{}\": it has no organ or "
                                                   "Grow blocks of its own",
                                                   p.name, p.grammar));
                    cur_.next();
                    break;
                }
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
            } else if (cur_.atKeyword("Grammar")) {
                p.grammarLoc = cur_.loc(propertyStart(seen, "Grammar", "the Plant block"));
                p.grammar = name("as the grammar file of Grammar");
                if (p.grammar.empty()) throw ir::InputError(p.grammarLoc, "Grammar names no file");
                cur_.expectPunct(";", "after the value of Grammar");
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
                        "Position, Direction, DeriveTime, Grammar, an organ (Apex, Stem, Leaf, Flower, Fruit, Root) "
                        "or Grow");
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
            {"Geotropism", &ir::EcoStage::geotropism},   {"Phototropism", &ir::EcoStage::phototropism},
            {"ShadeTime", &ir::EcoStage::shadeTime},
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
                                   "NoiseTime, Strength, Geotropism, Phototropism or ShadeTime)",
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
