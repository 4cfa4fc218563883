#version 460
// Organs, instanced: one draw per organ kind whose instances come from the instance buffer by gl_InstanceIndex
// (the draw's firstInstance is the kind's first instance). The ground plane is drawn with the same shader.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"
#include "render/organs/organ_transform.glsl"

layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inNormal;

layout(std430, set = 0, binding = 0) readonly buffer Instances {
    OrganInstance instances[];
};
layout(std140, set = 0, binding = 1) uniform Frame {
    DrawFrame frame;
};
layout(push_constant) uniform Push {
    DrawPush push;
};

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) flat out vec3 outAlbedo;
layout(location = 3) flat out uint outPlant;
layout(location = 4) flat out uint outOrgan;

// The sun pass redraws with depth test EQUAL, so positions must come out the same in every pass: no fused or
// reordered arithmetic that one pipeline's compilation could choose differently from another's.
precise gl_Position;


void main() {
    precise vec3 world;
    if (push.kind == kDrawGround) {
        world = frame.groundPlane.xyz + frame.groundPlane.w * vec3(inPosition.x, 0.0, inPosition.z);
        outNormal = vec3(0.0, 1.0, 0.0);
        outAlbedo = frame.groundColor.rgb;
        outPlant = 0xFFFFFFFFu;
        outOrgan = 0xFFFFFFFFu;
    } else {
        OrganInstance o = instances[gl_InstanceIndex];
        OrganVertex v = organVertex(o, push.kind, inPosition, inNormal, frame.cameraRight.xyz, frame.cameraUp.xyz);
        world = v.position;
        outNormal = v.normal;
        outAlbedo = o.color.rgb;
        if (push.kind == kOrganLeaf)
            outAlbedo = mix(outAlbedo, vec3(kBlossomEyeRed, kBlossomEyeGreen, kBlossomEyeBlue), inPosition.w);
        outPlant = o.plant;
        outOrgan = o.module;
    }
    outWorld = world;
    gl_Position = frame.viewProj * vec4(world, 1.0);
}
