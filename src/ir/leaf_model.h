// A leaf, flower or fruit drawn from a model file (a SimEco stage's `Model` naming a Wavefront `.obj`) instead of a
// built-in blade, blossom or sphere.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace simeco::ir {

// Triangles in the organ's frame: x along the midrib (the heading) from the base (0) to the tip (1), y across, z out
// of its upper face, in units of its length; each counter-clockwise seen from its outer side.
struct LeafModel {
    std::string file;
    std::vector<std::array<float, 3>> corners; // three per triangle
    std::vector<std::array<float, 3>> normals; // one per triangle, unit length
    float area = 0.0f;                         // of the triangles, in units of the length squared
    bool leaf = true;                          // drawn by a leaf stage (else only by flowers' or fruits')
};

} // namespace simeco::ir
