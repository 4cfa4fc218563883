#version 460
// A frame's draw lists (render/shared/draw_layout.h): each organ goes into the bucket of its kind, or its leaf shape,
// at the level of detail its size on screen asks for, unless it lies wholly outside the view. Pass kDrawListsCount
// counts each bucket's organs; draw_args.comp turns the counts into each bucket's first place in the order
// (`cursors`) and writes a draw per bucket; pass kDrawListsScatter writes each organ's instance into its bucket's
// places, which organ.vert reads its instance by. A bucket's organs come in the order the device claims their places,
// which does not change what is drawn.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"
#include "render/organs/view_sides.glsl"

layout(local_size_x = kDrawWorkgroupSize) in;

layout(std430, binding = 0) readonly buffer Instances {
    OrganInstance instances[];
};
layout(std430, binding = 1) readonly buffer Table {
    OrganTable table;
};
layout(std430, binding = 2) buffer Buckets {
    uint counts[kDrawBuckets];
    uint cursors[kDrawBuckets];
};
layout(std430, binding = 3) writeonly buffer Order {
    uint order[];
};
layout(std430, binding = 4) readonly buffer Frame {
    DrawFrame frame;
};
layout(push_constant) uniform Push {
    DrawListsPush push;
};

// Whether an organ is drawn far: its size on screen below its kind's threshold. A stem drawn flat (cpfg's lines and
// polygons) is the same band with either mesh, so always far.
bool drawnFar(OrganInstance o, vec4 sphere) {
    if (push.levels == 0u || o.kind == kOrganTriangle) return false;
    if (o.kind == kOrganStem && o.shape != kLineCylinder) return true;
    // The world's size of a pixel at the organ: clip w is its depth along the view (1 in a parallel projection).
    const float depth = dot(vec4(frame.viewProj[0][3], frame.viewProj[1][3], frame.viewProj[2][3],
                                 frame.viewProj[3][3]), vec4(sphere.xyz, 1.0));
    if (depth <= 0.0) return false;
    const float pixel = frame.cameraPosition.w * depth;
    if (o.kind == kOrganStem) return 2.0 * max(o.heading.w, o.up.w) < push.farStemPixels * pixel;
    if (o.kind == kOrganLeaf) return max(o.position.w, o.heading.w) < push.farLeafPixels * pixel;
    return 2.0 * o.heading.w < push.farRoundPixels * pixel;
}

void main() {
    const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    const uint index = group * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    const uint last = kOrganKinds - 1u;
    if (index >= table.first[last] + table.count[last]) return;
    const OrganInstance o = instances[index];
    // Only what the table counts is drawn: each kind's instances from its first, as many as its count.
    if (o.kind >= kOrganKinds || index < table.first[o.kind] || index - table.first[o.kind] >= table.count[o.kind])
        return;
    uint slot = o.kind;
    if (o.kind == kOrganLeaf) {
        if (o.shape >= push.shapes) return; // a shape the mesh does not hold draws nothing
        slot = kOrganKinds + o.shape;
    }
    const vec4 sphere = organBounds(o);
    const bool pixelLine = o.kind == kOrganStem && o.shape == kLinePixel; // as wide as the picture says
    if (push.cull != 0u && !pixelLine && sidesOutside(frame.viewProj, sphere) != 0u) return;
    const uint bucket = slot + (drawnFar(o, sphere) ? kDrawLevelFar : kDrawLevelNear) * kDrawSlots;
    if (push.pass == kDrawListsCount) {
        atomicAdd(counts[bucket], 1u);
    } else {
        order[atomicAdd(cursors[bucket], 1u)] = index;
    }
}
