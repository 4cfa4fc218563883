#version 460
// Organs, instanced: a draw per draw list (a kind or a leaf shape at a level of detail, organs/draw_lists.comp),
// whose instances come through the frame's order by gl_InstanceIndex (the draw's firstInstance is the list's first
// place). The ground plane is drawn with the same shader.
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
layout(std430, set = 0, binding = 3) readonly buffer Order {
    uint order[];
};
layout(push_constant) uniform Push {
    DrawPush push;
};

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) flat out vec3 outAlbedo;
layout(location = 3) flat out uint outPlant;
layout(location = 4) flat out uint outOrgan;
layout(location = 5) out vec2 outUv;
layout(location = 6) flat out int outTexture; // the texture layer the albedo tints, or -1

// Where a mesh vertex samples its organ's texture: a surface (leaf, blossom, model) by its plane, x along the
// midrib and y across; a stem around (mirrored, so that no seam shows) and along; a cap, a disc or a sphere by
// its cross-section; a polygon's triangle by its corners.
vec2 organUv(uint kind, vec4 local, vec4 localNormal) {
    if (kind == kOrganLeaf) return vec2(local.x, 0.5 - local.y);
    if (kind == kOrganStem) {
        if (localNormal.w > 0.5 && !isStemBandVertex(localNormal)) return 0.5 + 0.5 * local.yz;
        return vec2(acos(clamp(local.y, -1.0, 1.0)) / 3.14159265, local.w);
    }
    if (kind == kOrganTriangle) return local.x < 0.5 ? vec2(0.0) : (local.x < 1.5 ? vec2(1.0, 0.0) : vec2(0.0, 1.0));
    return 0.5 + 0.5 * (kind == kOrganDisc ? local.xy : local.yz);
}

// Positions without fused or reordered arithmetic: the same in every pipeline built from this shader (with and
// without back-face culling), whatever one pipeline's compilation would choose.
precise gl_Position;

void main() {
    precise vec3 world;
    if (push.kind == kDrawGround) {
        world = frame.groundPlane.xyz + frame.groundPlane.w * vec3(inPosition.x, 0.0, inPosition.z);
        outNormal = vec3(0.0, 1.0, 0.0);
        outAlbedo = frame.groundColor.rgb;
        outPlant = 0xFFFFFFFFu;
        outOrgan = 0xFFFFFFFFu;
        outUv = vec2(0.0);
        outTexture = -1;
    } else {
        OrganInstance o = instances[order[gl_InstanceIndex]];
        OrganVertex v = organVertex(o, push.kind, inPosition, inNormal, frame.cameraRight.xyz, frame.cameraUp.xyz,
                                    frame.cameraPosition, frame.options.w != 0u);
        world = v.position;
        outNormal = v.normal;
        outAlbedo = o.color.rgb;
        if (push.kind == kOrganLeaf)
            outAlbedo = mix(outAlbedo, vec3(kBlossomEyeRed, kBlossomEyeGreen, kBlossomEyeBlue), inPosition.w);
        outPlant = o.plant;
        outOrgan = o.module;
        outUv = organUv(push.kind, inPosition, inNormal);
        outTexture = o.color.w >= kColorFirstTexture - 0.5 ? int(o.color.w - kColorFirstTexture + 0.5) : -1;
    }
    outWorld = world;
    gl_Position = frame.viewProj * vec4(world, 1.0);
}
