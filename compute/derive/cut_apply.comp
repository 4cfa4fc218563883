// Cut `%`: modules covered by a cut (the prefix sum of +1 at each cutting `%` and -1 at the end of its branch
// is positive) leave the string: no successor, and the write pass skips them.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer CutDelta { uint cutDelta[]; };
layout(set = 0, binding = 1, std430) readonly buffer CutBefore { uint cutBefore[]; };
layout(set = 0, binding = 2, std430) buffer Counts { uint counts[]; };
layout(set = 0, binding = 3, std430) buffer Choices { uint choices[]; };
// The plant table, whose last entry counts the modules when pc.count is kCountOnDevice (a recorded step).
layout(set = 0, binding = 4, std430) readonly buffer PlantStart { uint plantStart[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= (pc.count != kCountOnDevice ? pc.count : plantStart[pc.plants])) return;
    if (int(cutBefore[i] + cutDelta[i]) > 0) {
        counts[i] = 0u;
        choices[i] = kChoiceDropped;
    }
}
