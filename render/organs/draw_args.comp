#version 460
// The indirect draw records of a frame, from the organ table on the device: one indexed draw per organ kind
// (its mesh's index range, the kind's instance count and first instance) and the shadow volumes' draw, so the
// host never reads instance counts.
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
layout(push_constant) uniform Push {
    DrawArgsPush push;
};

void main() {
    uint kind = gl_GlobalInvocationID.x;
    if (kind < kOrganKinds) {
        uint count = table.count[kind];
        commands[kind] = DrawIndexedCommand(push.indexCount[kind], count, push.firstIndex[kind],
                                            push.vertexOffset[kind], count > 0u ? table.first[kind] : 0u);
    }
    if (kind == 0u) {
        volumes.vertexCount = kVolumeCorners;
        volumes.instanceCount = min(volumes.allocated, push.volumeCapacity) / kVolumeVerticesPerTriangle;
        volumes.firstVertex = 0u;
        volumes.firstInstance = 0u;
    }
}
