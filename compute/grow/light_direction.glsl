// The direction of most light as a particle keeps it: the two coordinates of the octahedron's unfolding, packed by
// packSnorm2x16 into a float's bits (src/grow/light_grid.cpp's packLightDirection and unpackLightDirection).

vec2 octahedral(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 e = n.xz;
    if (n.y < 0.0) e = (1.0 - abs(e.yx)) * vec2(e.x >= 0.0 ? 1.0 : -1.0, e.y >= 0.0 ? 1.0 : -1.0);
    return e;
}

float packLightDirection(vec3 unit) { return uintBitsToFloat(packSnorm2x16(octahedral(unit))); }

vec3 unpackLightDirection(float packed) {
    vec2 e = unpackSnorm2x16(floatBitsToUint(packed));
    vec3 n = vec3(e.x, 1.0 - abs(e.x) - abs(e.y), e.y);
    if (n.y < 0.0) n.xz = (1.0 - abs(e.yx)) * vec2(e.x >= 0.0 ? 1.0 : -1.0, e.y >= 0.0 ? 1.0 : -1.0);
    return normalize(n);
}
