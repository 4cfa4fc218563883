#version 460
// The indirect draw records of a frame, from the organ table on the device: one indexed draw per organ kind
// (its mesh's index range, the kind's instance count and first instance), then one per leaf shape (the shape's
// triangles of the leaf mesh, its leaves' count and first place in the leaf order, which the same invocation lays
// out: leaf_shapes.comp), and the shadow volumes' draw, so the host never reads instance counts. The leaf kind's own
// record draws nothing.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"

layout(local_size_x = kDrawWorkgroupSize) in;

struct DrawIndexedCommand {  // VkDrawIndexedIndirectCommand
    uint indexCount;
    uint instanceCount;
    uint firstIndex;
    int vertexOffset;
    uint firstInstance;
};

layout(std430, binding = 0) readonly buffer Table {
    OrganTable table;
};
layout(std430, binding = 1) writeonly buffer Commands {
    DrawIndexedCommand commands[];
};
layout(std430, binding = 2) buffer Volumes {
    VolumeDraw volumes;
};
layout(std430, binding = 3) buffer Buckets {
    uint counts[kDrawMaxLeafShapes];
    uint cursors[kDrawMaxLeafShapes];
};
layout(std430, binding = 4) readonly buffer LeafShapeTriangles {
    uvec2 leafShapeTriangles[];  // per shape: its first triangle in the leaf mesh, and its count
};
layout(push_constant) uniform Push {
    DrawArgsPush push;
};

void main() {
    uint kind = gl_GlobalInvocationID.x;
    if (kind < kOrganKinds) {
        uint count = kind == kOrganLeaf ? 0u : table.count[kind];
        commands[kind] = DrawIndexedCommand(push.indexCount[kind], count, push.firstIndex[kind],
                                            push.vertexOffset[kind], count > 0u ? table.first[kind] : 0u);
    }
    if (kind == 0u) {
        uint first = 0u;
        for (uint shape = 0u; shape < push.leafShapes; ++shape) {
            const uvec2 triangles = leafShapeTriangles[shape];
            commands[kOrganKinds + shape] =
                DrawIndexedCommand(3u * triangles.y, counts[shape], push.firstIndex[kOrganLeaf] + 3u * triangles.x,
                                   push.vertexOffset[kOrganLeaf], first);
            cursors[shape] = first;
            first += counts[shape];
        }
        volumes.vertexCount = kVolumeCorners;
        volumes.instanceCount = min(volumes.allocated, push.volumeCapacity) / kVolumeVerticesPerTriangle;
        volumes.firstVertex = 0u;
        volumes.firstInstance = 0u;
    }
}
