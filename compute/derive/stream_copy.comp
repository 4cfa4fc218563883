// A string copied from one stream into another with a count only the device knows, the last entry of the source's
// plant table (at most pc.bound): the result of a step's depths into the stream the step writes, when the last
// depth wrote the other one (kCopySettle: with each module's origin), or the derived string into the stream the
// homomorphism starts from (kCopyHomomorphism: every module is examined at depth 0, and its contexts are read
// around itself, so its origin is its own index).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer FromSymbols { uint fromSymbols[]; };
layout(set = 0, binding = 1, std430) readonly buffer FromParameters { float fromParameters[]; };
layout(set = 0, binding = 2, std430) readonly buffer FromStarts { uint fromStarts[]; };
layout(set = 0, binding = 3, std430) readonly buffer FromOrigin { uint fromOrigin[]; };
layout(set = 0, binding = 4, std430) writeonly buffer ToSymbols { uint toSymbols[]; };
layout(set = 0, binding = 5, std430) writeonly buffer ToParameters { float toParameters[]; };
layout(set = 0, binding = 6, std430) writeonly buffer ToStarts { uint toStarts[]; };
layout(set = 0, binding = 7, std430) writeonly buffer ToOrigin { uint toOrigin[]; };
layout(set = 0, binding = 8, std430) writeonly buffer ToLive { uint toLive[]; };
layout(push_constant) uniform Push { StreamCopyPush pc; };

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i <= pc.plants) toStarts[i] = fromStarts[i];
    if (i >= min(fromStarts[pc.plants], pc.bound)) return;
    toSymbols[i] = fromSymbols[i];
    uint count = fromSymbols[i] >> kSymbolBits;
    for (uint k = 0u; k < count; ++k) toParameters[i * pc.stride + k] = fromParameters[i * pc.stride + k];
    if (pc.mode == kCopySettle) {
        toOrigin[i] = fromOrigin[i];
    } else {
        toOrigin[i] = i;
        toLive[i] = 1u;
    }
}
