// A plant's and an organ's ids (32-bit) as four floats, each a 16-bit half and so exact, for the id samples of a
// multisampled frame: few devices multisample integer images. The resolve subpass puts them back together.

vec4 idHalves(uint plant, uint organ) {
    return vec4(float(plant & 0xFFFFu), float(plant >> 16), float(organ & 0xFFFFu), float(organ >> 16));
}

uint plantOfHalves(vec4 halves) {
    return uint(halves.x) | (uint(halves.y) << 16);
}

uint organOfHalves(vec4 halves) {
    return uint(halves.z) | (uint(halves.w) << 16);
}
