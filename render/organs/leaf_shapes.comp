#version 460
// The leaves of a frame gathered by shape: the leaf mesh holds every shape, and a leaf drawn with all of them would
// run the vertex stage over every shape's vertices. Pass kLeafShapesCount counts each shape's leaves; draw_args.comp
// turns the counts into each shape's first place in the order (`cursors`) and writes a draw per shape; pass
// kLeafShapesScatter writes each leaf's instance into its shape's places, which organ.vert reads its instance by.
// A shape's leaves come in the order the device claims their places, which does not change what is drawn.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"

layout(local_size_x = kDrawWorkgroupSize) in;

layout(std430, binding = 0) readonly buffer Instances {
    OrganInstance instances[];
};
layout(std430, binding = 1) readonly buffer Table {
    OrganTable table;
};
layout(std430, binding = 2) buffer Buckets {
    uint counts[kDrawMaxLeafShapes];
    uint cursors[kDrawMaxLeafShapes];
};
layout(std430, binding = 3) writeonly buffer Order {
    uint order[];
};
layout(push_constant) uniform Push {
    LeafShapesPush push;
};

void main() {
    const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    const uint index = group * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (index >= table.count[kOrganLeaf]) return;
    const uint instance = table.first[kOrganLeaf] + index;
    const uint shape = instances[instance].shape;
    if (shape >= push.shapes) return; // a shape the mesh does not hold draws nothing
    if (push.pass == kLeafShapesCount) {
        atomicAdd(counts[shape], 1u);
    } else {
        order[atomicAdd(cursors[shape], 1u)] = instance;
    }
}
