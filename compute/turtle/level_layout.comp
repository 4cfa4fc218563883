// Lays the levels of non-linear modules out one after another in the resolution order, from their sizes
// (level_count.comp): each level's cursor at its slice's start, for level_scatter.comp to fill, and the
// workgroups of its resolve_level.comp dispatch. Lays out pc.items levels, as many as were recorded; the
// deepest level goes into the status words, so that a recording that read nothing back can tell whether it
// resolved them all. One invocation: the levels are few next to the modules.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer Counts { uint counts[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Cursors { uint cursors[]; };
// Level L's workgroups (x, y, z) at 3 (L - 1).
layout(set = 0, binding = 2, std430) writeonly buffer Arguments { uint arguments[]; };
layout(set = 0, binding = 3, std430) buffer Status { uint status[]; };
layout(push_constant) uniform Push { TurtlePush pc; };

void main() {
    uint deepest = counts[0];
    status[kTurtleStatusLevels] = deepest;
    uint next = 0u;
    for (uint level = 1u; level <= pc.items; ++level) {
        uint size = level <= deepest ? counts[level] : 0u;
        cursors[level] = next;
        next += size;
        // As vk::ComputePipeline::dispatch lays out its workgroups: over y when x cannot hold them.
        uint groups = (size + kTurtleWorkgroupSize - 1u) / kTurtleWorkgroupSize;
        uint y = max((groups + pc.maxGroupsX - 1u) / pc.maxGroupsX, 1u);
        arguments[3u * (level - 1u)] = (groups + y - 1u) / y;
        arguments[3u * (level - 1u) + 1u] = y;
        arguments[3u * (level - 1u) + 2u] = 1u;
    }
}
