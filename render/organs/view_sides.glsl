// Where organs lie against the view (draw_lists.comp leaves out of the draws what is wholly outside it,
// shadow_volumes.comp the volumes wholly outside it). Needs shared/organ_layout.h.

// A sphere around everything an organ may draw: a stem's ends are cut on the planes between its segment and the
// next (organ_transform.glsl), up to five radii along it; a leaf model may reach past its length and width.
vec4 organBounds(OrganInstance o) {
    if (o.kind == kOrganTriangle) {
        const vec3 centre = (o.position.xyz + o.heading.xyz + o.up.xyz) / 3.0;
        const float reach = max(distance(centre, o.position.xyz),
                                max(distance(centre, o.heading.xyz), distance(centre, o.up.xyz)));
        return vec4(centre, reach);
    }
    if (o.kind == kOrganStem) {
        const float radius = max(o.heading.w, o.up.w);
        return vec4(o.position.xyz + 0.5 * o.position.w * o.heading.xyz, 0.5 * o.position.w + 6.0 * radius);
    }
    if (o.kind == kOrganLeaf)
        return vec4(o.position.xyz, 2.0 * (o.position.w + o.heading.w + abs(o.up.w)));
    return vec4(o.position.xyz, o.heading.w);
}

// The view's sides a sphere lies wholly outside, a bit each (the planes of viewProj's rows, Gribb and Hartmann); not
// its near and far planes: the depth is clamped there, so what lies beyond them is still drawn.
uint sidesOutside(mat4 viewProj, vec4 sphere) {
    const vec4 w = vec4(viewProj[0][3], viewProj[1][3], viewProj[2][3], viewProj[3][3]);
    uint sides = 0u;
    for (uint axis = 0u; axis < 2u; ++axis) {
        const vec4 row = vec4(viewProj[0][axis], viewProj[1][axis], viewProj[2][axis], viewProj[3][axis]);
        for (uint side = 0u; side < 2u; ++side) {
            const vec4 plane = w + (side == 0u ? -1.0 : 1.0) * row;
            const float reach = length(plane.xyz);
            if (reach > 0.0 && dot(plane.xyz, sphere.xyz) + plane.w < -sphere.w * reach)
                sides |= 1u << (2u * axis + side);
        }
    }
    return sides;
}
