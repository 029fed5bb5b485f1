// GL's edge flags (GL 2.1 §2.6.2, §3.5.4), shared by edges.geom and the fragment stages of the
// `_edges` builds: a polygon drawn in LINE mode shows only its boundary edges, and in POINT mode
// only the vertices that start one. ffvk's quads and polygons are triangles, whose inner edges
// (a quad's diagonal, a polygon's fan) GL never draws; a vertex's glEdgeFlag hides the edge
// that starts at it.
//
// The draw's indices say which edges are boundary ones, as a triangle list with adjacency
// (draw/gl_primitives.rs, `edge_flagged`): triangle (c0, c1, c2) is the six indices
// (c0, a0, c1, a1, c2, a2), where a_e = c_e when edge e (corner e to corner e + 1) is a boundary
// edge and c_(e+1) when it is not. The vertex stage passes gl_VertexIndex at EDGE_LOCATION; the
// geometry stage turns the six into the triangle, with the corner weights and the mask of
// boundary edges at EDGE_LOCATION (xyz: corner weights, noperspective; w: the mask, bits 0-2,
// and the triangle's facing, bit 3, which the `_edges` fragment stages take for
// gl_FrontFacing: FRONT_FACING).
#ifndef FFVK_EDGES_GLSL
#define FFVK_EDGES_GLSL

// A location no other varying of the build takes: the fragment mode's builds leave 2 free, the
// per-vertex modes' 6 (every build stays within Vulkan's 16 guaranteed locations).
#ifdef EDGES_OF_FRAGMENT_MODE
#define EDGE_LOCATION 2
#define VERTEX_INDEX_LOCATION 14
#else
#define EDGE_LOCATION 6
#define VERTEX_INDEX_LOCATION 7
#endif

#ifdef EDGES_FRAGMENT_STAGE
layout(location = EDGE_LOCATION) noperspective in vec4 edge;

// Whether the fragment lies on a boundary edge of its triangle. Vulkan draws a polygon's edges
// in LINE mode as lines between two corners, so along edge e the opposite corner's weight is
// zero (both ends weigh it zero; the mode's interpolation keeps it zero, or within a rounding
// of it); a point of POINT mode carries its corner's weights, 1 and two zeros. A fragment with
// two weights at zero is at a corner k: it belongs to the edge that starts there (GL draws a
// line's first pixel, and its last only where the line leaves the pixel's diamond, never at a
// vertex on a pixel center), and in POINT mode GL draws the vertices that start a boundary edge.
bool on_boundary_edge() {
    uint mask = uint(edge.w + 0.5) & 7u;
    vec3 w = abs(edge.xyz);
    const float zero = 1e-6;
    for (int k = 0; k < 3; k++) {
        if (w[(k + 1) % 3] <= zero && w[(k + 2) % 3] <= zero) return (mask & (1u << k)) != 0u;
    }
    // Edge e runs from corner e to corner e + 1; corner e + 2 is opposite it.
    int e = w.x <= w.y ? (w.x <= w.z ? 1 : 0) : (w.y <= w.z ? 2 : 0);
    return (mask & (1u << e)) != 0u;
}

// The polygon's facing, as the geometry stage found it (edges.geom).
#define FRONT_FACING ((uint(edge.w + 0.5) & 8u) != 0u)
#endif

#endif
