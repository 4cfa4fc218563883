// The bindings every turtle kernel that reads modules shares (0 to 4), its push constants and its index.
// Kernels declare their own buffers from binding 5 on.
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Symbols { uint symbols[]; };
layout(set = 0, binding = 1, std430) readonly buffer Params { float params[]; };
layout(set = 0, binding = 2, std430) readonly buffer PlantStarts { uint plantStarts[]; };
layout(set = 0, binding = 3, std430) readonly buffer CommandTable { uint commandTable[]; };
layout(set = 0, binding = 4, std430) readonly buffer SpeciesTable { TurtleSpecies speciesTable[]; };
layout(push_constant) uniform Push { TurtlePush pc; };

uint invocationIndex() {
    return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
}
