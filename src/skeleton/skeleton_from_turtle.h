// The skeleton of a derived plant, from what the turtle drew: each axis of the bracketed string (the segments
// drawn one after another at one branching level) is a stem, a bracket's first segment starts a new stem on the
// point its parent had reached, and the leaves, flowers and fruits drawn along the way sit on the point the turtle
// stood on.
#pragma once

#include <cstdint>

#include "skeleton/skeleton.h"
#include "stream/module_string.h"
#include "turtle/interpretation.h"

namespace simeco::skeleton {

// Plant `plant` of `string` (the string the turtle read, after the homomorphism) as `interpretation` drew it, in
// the field's units and place. A stem's points are where its direction turns, where its width changes, or where a
// branch or organ sits: segments that continue one another straight on are one. Segments of no length draw
// nothing and are left out; a segment that does not start where the turtle's last one ended (after a move `f`)
// starts a stem of its own, without a parent. Stems drawn as pixel lines (cpfg's default line style) have width 0:
// their width is in pixels of the picture, not in the plant's units.
Plant plantFromTurtle(const stream::ModuleString& string, const turtle::Interpretation& interpretation,
                      uint32_t plant);

} // namespace simeco::skeleton
