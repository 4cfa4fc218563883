// Two interpretations of one field compared organ by organ: empty when they hold the same organs in the same
// order (plant, module, kind) at the same places and sizes, within 1e-4 of the field's size.
#pragma once

#include <string>

#include "turtle/interpretation.h"

namespace simeco::test {

std::string organDifference(const turtle::Interpretation& want, const turtle::Interpretation& got);

} // namespace simeco::test
