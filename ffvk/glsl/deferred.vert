#version 450
// The deferred lighting pass: one triangle over the whole target (its corners at (-1, -1),
// (3, -1) and (-1, 3) in clip space) at depth 1, so that every pixel a draw covered (its
// depth nearer than 1: the pipeline tests GREATER) runs deferred.frag once.
void main() {
    vec2 corner = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
}
