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
    // Where the model is a smooth surface: one unit normal per corner, as `corners`; empty for flat triangles.
    std::vector<std::array<float, 3>> cornerNormals;
    float area = 0.0f;                         // of the triangles, in units of the length squared
    bool leaf = true;                          // drawn by a leaf stage (else only by flowers' or fruits')
};

// A cpfg surface (`.s`, bicubic patches) as a `~` draws it: its triangles in the turtle's frame from the contact
// point (x along the heading, y to the left, z up) in units of its reach, the farthest any corner lies from the
// contact point at scale 1 (the view's size applied); and the point, in world units at scale 1 and the same frame,
// that the turtle moves to after drawing it (times the surface's first scale).
struct SurfaceModel {
    LeafModel mesh;
    float reach = 1.0f;
    std::array<float, 3> endPoint{};
};

} // namespace simeco::ir
