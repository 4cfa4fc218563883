// A field interpreted in batches of plants: one batch's organs, kept after its interpretation, copied into the
// field's instances. Each kind's organs go after those of that kind the earlier batches wrote, so that the field's
// instances stay grouped by kind and in plant order within a kind; their plant and module indices become the
// field's (the batch's first plant and first module added). See turtle/organ_merge.h.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/organ_layout.h"
#include "compute/shared/turtle_state_layout.h"

layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Batch { OrganInstance batch[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Field { OrganInstance field[]; };
layout(push_constant) uniform Push { OrganMergePush pc; };

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= pc.organs) return;
    // The batch's kinds follow each other from its first instance: find the kind of instance i.
    uint k = 0u, first = 0u;
    while (k + 1u < kOrganKinds && i >= first + pc.count[k]) {
        first += pc.count[k];
        ++k;
    }
    OrganInstance o = batch[pc.source + i];
    o.plant += pc.firstPlant;
    o.module += pc.firstModule;
    field[pc.destination[k] + (i - first)] = o;
}
