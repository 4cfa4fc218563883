// Reads a leaf model from a Wavefront `.obj` file (Debian's tinyobjloader): its faces, triangulated, placed in the
// leaf's frame (ir::LeafModel): the model's extent along x taken as its length, its smallest x as its base.
#pragma once

#include <optional>
#include <string>

#include "ir/leaf_model.h"

namespace simeco::lang {

// Nullopt, with the reason in `why`, for a file that cannot be read or holds no triangle with an extent along x.
std::optional<ir::LeafModel> readObjLeafModel(const std::string& path, std::string& why);

} // namespace simeco::lang
