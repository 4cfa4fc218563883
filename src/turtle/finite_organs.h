// Organs whose values are not all finite numbers: what a parameter that became infinite or NaN draws. Every
// output refuses a field with one, with the same message, rather than writing NaN vertices into some formats
// and drawing or dropping them in others. The turtles make such an organ's bounds infinite (organBounds here,
// organBox in compute/turtle/organ_bounds.glsl), so a renderer that reads only the field's bounds finds it too.
#pragma once

#include <stdexcept>
#include <string>

#include "compute/shared/organ_layout.h"

namespace simeco::turtle {

// Whether every float of the organ (placement, sizes, joints, colour) is a finite number.
bool organIsFinite(const shared::OrganInstance& o);

// The error of a field with a non-finite organ; `where` names it (plant and module) where that is known.
std::runtime_error nonFiniteOrganError(const std::string& where = {});

} // namespace simeco::turtle
