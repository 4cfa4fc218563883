#include "codegen/curve_codegen.h"

#include <fmt/format.h>

namespace simeco::codegen {

namespace {

// The record derive/contour_curve.glsl reads: type, points, samples, length, xs, ys, zs, arc-length table.
void appendCurveRecord(const ir::ContourCurve& c, std::vector<double>& tables) {
    tables.push_back(static_cast<double>(c.type));
    tables.push_back(static_cast<double>(c.xs.size()));
    tables.push_back(static_cast<double>(c.arcFraction.size()));
    tables.push_back(c.length);
    for (const std::vector<double>* coordinates : {&c.xs, &c.ys, &c.zs})
        tables.insert(tables.end(), coordinates->begin(), coordinates->end());
    tables.insert(tables.end(), c.arcFraction.begin(), c.arcFraction.end());
}

} // namespace

std::string curveTableCode(const ir::Grammar& g, size_t species, std::vector<double>& tables) {
    std::string code = fmt::format("double curveValue{}(double idValue, int axis, double t, uint errorSite) {{\n"
                                   "    int id = int(idValue);\n"
                                   "    uint record = 0xffffffffu;\n",
                                   species);
    for (size_t c = 0; c < g.curves.size(); ++c) {
        code += fmt::format("    if (id == {}) record = {}u;\n", c + 1, tables.size());
        appendCurveRecord(g.curves[c], tables);
    }
    code += "    if (record == 0xffffffffu) { reportError(errorSite); return 0.0LF; }\n"
            "    return axis == 3 ? curveLength(record) : curveCoordinate(record, axis, t);\n"
            "}\n\n";
    return code;
}

} // namespace simeco::codegen
