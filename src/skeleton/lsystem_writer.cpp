#include "skeleton/lsystem_writer.h"

#include <fmt/format.h>

namespace simeco::skeleton {

namespace {

std::string number(float v) { return fmt::format("{:.9g}", double(v)); }

std::string turn(const Turn& t) { return fmt::format("/({})&({})", number(t.roll), number(t.pitch)); }

// Leaves and flowers have no surface without a view file, so they are drawn as cpfg draws a bud: a sphere (a
// fruit) or a disc (a leaf or flower) of the organ's size.
std::string organ(const Plant& plant, const GrownOrgan& o) {
    const Organ& organ = plant.organs[size_t(o.organ)];
    const std::string size = number(float(organ.size));
    if (organ.kind == OrganKind::Fruit) return fmt::format("[{}@O({})]", turn(o.turn), size);
    return fmt::format("[{}f({})@c({})]", turn(o.turn), number(float(organ.size * 0.5)), size);
}

} // namespace

std::string lsystemText(const Plant& plant, const Regrowth& g, const std::string& source) {
    std::string s = fmt::format("/* Inferred by simeco infer from {}: {} internodes in {} levels.\n", source,
                                g.internodes.size(), g.tree.levels);
    s += "   A(n) is the growth point of internode n: it draws the internode, !(width) F(length), and puts out\n"
         "   its branches and its main child, each turned by a roll / and a pitch & in degrees. */\n";
    s += "Lsystem: 1\n";
    s += fmt::format("derivation length: {}\n", g.tree.levels);
    s += "Axiom:";
    for (const GrownOrgan& o : g.baseOrgans) s += fmt::format(" {}", organ(plant, o));
    for (size_t k = 1; k < g.roots.size(); ++k)
        s += fmt::format(" [{}A({})]", turn(g.roots[k].turn), g.roots[k].internode + 1);
    s += fmt::format(" {}A({})\n", turn(g.roots.front().turn), g.roots.front().internode + 1);
    for (size_t i = 0; i < g.internodes.size(); ++i) {
        const GrownInternode& n = g.internodes[i];
        s += fmt::format("A(n) : n == {} --> !({})F({})", i + 1, number(n.width), number(n.length));
        if (n.rollAfter != 0.0f) s += fmt::format("/({})", number(n.rollAfter));
        for (const GrownOrgan& o : n.organs) s += organ(plant, o);
        for (size_t c = 1; c < n.children.size(); ++c)
            s += fmt::format("[{}A({})]", turn(n.children[c].turn), n.children[c].internode + 1);
        if (!n.children.empty())
            s += fmt::format("{}A({})", turn(n.children.front().turn), n.children.front().internode + 1);
        s += "\n";
    }
    return s + "endlsystem\n";
}

std::string lsystemView() { return "line style: cylinder\ninitial line width: 0.1\n"; }

} // namespace simeco::skeleton
