// The index of a workgroup in a dispatch that may be split over two dimensions.
#ifndef SIMECO_SCAN_WORKGROUP_INDEX_GLSL
#define SIMECO_SCAN_WORKGROUP_INDEX_GLSL

// Dispatches beyond the device's x limit (65535 on many devices) are split over y by the host
// (vk::ComputePipeline::dispatch); workgroups are numbered row-major.
uint linearWorkgroupIndex() {
    return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
}

#endif
