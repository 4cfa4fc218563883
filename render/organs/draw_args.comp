#version 460
// The indirect draw records of a frame, from its draw lists on the device (organs/draw_lists.comp): one indexed draw
// per bucket, a kind or a leaf shape at a level of detail (the mesh's index range for it: for a leaf shape, its
// triangles of the leaf mesh, or its far cut within the leaf hull; the bucket's count and first place in the order,
// which the same invocation lays out), and the shadow volumes' draw, so the host never reads instance counts.
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
    uint counts[kDrawBuckets];
    uint cursors[kDrawBuckets];
};
layout(std430, binding = 4) readonly buffer LeafShapeTriangles {
    uvec2 leafShapeTriangles[];  // per shape: its first triangle in the leaf mesh, and its count
};
layout(std430, binding = 5) readonly buffer LeafFarTriangles {
    uvec2 leafFarTriangles[];  // the same for its far cut in the leaf hull (what such a leaf casts from)
};
layout(push_constant) uniform Push {
    DrawArgsPush push;
};

void main() {
    if (gl_GlobalInvocationID.x != 0u) return;
    uint first = 0u;
    for (uint level = kDrawLevelNear; level <= kDrawLevelFar; ++level) {
        const bool far = level == kDrawLevelFar;
        for (uint slot = 0u; slot < kOrganKinds + push.leafShapes; ++slot) {
            const uint bucket = slot + level * kDrawSlots;
            const uint kind = slot < kOrganKinds ? slot : kOrganLeaf;
            DrawIndexedCommand command = DrawIndexedCommand(
                far ? push.farIndexCount[kind] : push.indexCount[kind], counts[bucket],
                far ? push.farFirstIndex[kind] : push.firstIndex[kind],
                far ? push.farVertexOffset[kind] : push.vertexOffset[kind], first);
            if (slot >= kOrganKinds) {
                const uvec2 triangles = far ? leafFarTriangles[slot - kOrganKinds]
                                            : leafShapeTriangles[slot - kOrganKinds];
                command.indexCount = 3u * triangles.y;
                command.firstIndex += 3u * triangles.x;
            }
            commands[bucket] = command;
            cursors[bucket] = first;
            first += counts[bucket];
        }
    }
    volumes.indexCount = kVolumeCorners;
    volumes.instanceCount = min(volumes.allocated, push.volumeCapacity) / kVolumeVerticesPerTriangle;
    volumes.firstIndex = 0u;
    volumes.vertexOffset = 0;
    volumes.firstInstance = 0u;
}
