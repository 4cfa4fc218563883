#include "turtle/finite_organs.h"

#include <cmath>

namespace simeco::turtle {

bool organIsFinite(const shared::OrganInstance& o) {
    for (const shared::vec4* v : {&o.position, &o.heading, &o.up, &o.color, &o.previousHeading, &o.nextHeading})
        for (float value : {v->x, v->y, v->z, v->w})
            if (!std::isfinite(value)) return false;
    return true;
}

std::runtime_error nonFiniteOrganError(const std::string& where) {
    return std::runtime_error("the turtle drew an organ" + (where.empty() ? "" : " (" + where + ")") +
                              " whose position, size or colour is not a finite number: a parameter became infinite "
                              "or NaN; nothing is written");
}

} // namespace simeco::turtle
