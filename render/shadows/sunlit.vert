#version 460
// One triangle over the whole frame: the sunlit pass (render/shadows/sunlit.frag adds the sun where it reaches)
// and a multisampled frame's resolve (render/samples/resolve_samples.frag).
void main() {
    const vec2 corner = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
    gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
