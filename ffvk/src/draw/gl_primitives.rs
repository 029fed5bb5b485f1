//! GL's primitive modes that Vulkan has no topology for, as index lists of one it has, keeping
//! GL's winding and GL's provoking vertex (GL 2.1 §2.14.7, table 2.12), so that flat shading
//! picks the vertex GL picks: draw the result with the [`Topology`](super::record::Topology)
//! each function names, from pipelines whose provoking vertex is the last (ffvk's).
//!
//! Each takes the vertices in GL's order (the indices `glDrawElements` would read, or
//! `first..first + count` for `glDrawArrays`) and drops what GL drops: an incomplete last
//! primitive.

/// `GL_QUADS` as `TriangleList`: quad (v0, v1, v2, v3) becomes (v0, v1, v3) and (v1, v2, v3).
/// GL's provoking vertex of a quad is its fourth, which ends both triangles; both keep the
/// quad's winding. Trailing vertices that make no quad are dropped.
pub fn quads(vertices: &[u32]) -> Vec<u32> {
    quads_iter(vertices).collect()
}

/// [`quads`] one index at a time, allocating nothing.
pub fn quads_iter(vertices: &[u32]) -> impl Iterator<Item = u32> + '_ {
    vertices
        .chunks_exact(4)
        .flat_map(|q| [q[0], q[1], q[3], q[1], q[2], q[3]])
}

/// How many indices [`quads`] makes of `vertices` vertices.
pub fn quads_count(vertices: u64) -> u64 {
    vertices / 4 * 6
}

/// `GL_QUAD_STRIP` as `TriangleList`: quad i is (v2i, v2i+1, v2i+3, v2i+2) in GL's winding,
/// with v2i+3 its provoking vertex (table 2.12: vertex 2i + 2, counting from 1), which ends
/// both triangles: (v2i, v2i+1, v2i+3) and (v2i+2, v2i, v2i+3). A last unpaired vertex is
/// dropped; fewer than four vertices draw nothing.
pub fn quad_strip(vertices: &[u32]) -> Vec<u32> {
    quad_strip_iter(vertices).collect()
}

/// [`quad_strip`] one index at a time, allocating nothing.
pub fn quad_strip_iter(vertices: &[u32]) -> impl Iterator<Item = u32> + '_ {
    let pairs = vertices.len() / 2;
    (1..pairs).flat_map(move |i| {
        let (a, b, c, d) = (
            vertices[2 * i - 2],
            vertices[2 * i - 1],
            vertices[2 * i + 1],
            vertices[2 * i],
        );
        [a, b, c, d, a, c]
    })
}

/// How many indices [`quad_strip`] makes of `vertices` vertices.
pub fn quad_strip_count(vertices: u64) -> u64 {
    (vertices / 2).saturating_sub(1) * 6
}

/// `GL_POLYGON` as `TriangleList`: a fan around v0 whose triangles (vi, vi+1, v0) end with v0,
/// GL's provoking vertex of a polygon (the first); each is a rotation of (v0, vi, vi+1), so the
/// winding is the polygon's. Fewer than three vertices draw nothing.
pub fn polygon(vertices: &[u32]) -> Vec<u32> {
    polygon_iter(vertices).collect()
}

/// [`polygon`] one index at a time, allocating nothing.
pub fn polygon_iter(vertices: &[u32]) -> impl Iterator<Item = u32> + '_ {
    let (v0, rest) = match vertices.split_first() {
        Some((&v0, rest)) => (v0, rest),
        None => (0, vertices),
    };
    // Fewer than two after v0 make no window, so no triangle.
    rest.windows(2).flat_map(move |w| [w[0], w[1], v0])
}

/// How many indices [`polygon`] makes of `vertices` vertices.
pub fn polygon_count(vertices: u64) -> u64 {
    vertices.saturating_sub(2) * 3
}

/// `GL_LINE_LOOP` as `LineList`: each vertex to the next, and the last back to the first; each
/// segment's second vertex is its provoking one, as in GL's loop. Fewer than two vertices
/// draw nothing.
pub fn line_loop(vertices: &[u32]) -> Vec<u32> {
    line_loop_iter(vertices).collect()
}

/// [`line_loop`] one index at a time, allocating nothing.
pub fn line_loop_iter(vertices: &[u32]) -> impl Iterator<Item = u32> + '_ {
    let n = if vertices.len() < 2 { 0 } else { vertices.len() };
    (0..n).flat_map(move |i| [vertices[i], vertices[(i + 1) % n]])
}

/// How many indices [`line_loop`] makes of `vertices` vertices.
pub fn line_loop_count(vertices: u64) -> u64 {
    if vertices < 2 {
        0
    } else {
        vertices * 2
    }
}

/// Triangles with their edge flags, as [`Topology::EdgeFlaggedTriangles`] draws them: triangle
/// t of `triangles` (three indices each; a trailing partial one is dropped), its edge e (from
/// corner e to corner e + 1) a boundary edge where `boundary(t)[e]` holds, becomes
/// (c0, a0, c1, a1, c2, a2) with a_e = c_e on a boundary edge and c_(e+1) on an inner one. An
/// edge whose two corners are the same vertex cannot be marked inner (it draws nothing in GL).
///
/// [`Topology::EdgeFlaggedTriangles`]: crate::draw::record::Topology::EdgeFlaggedTriangles
pub fn edge_flagged(triangles: &[u32], boundary: impl Fn(usize) -> [bool; 3]) -> Vec<u32> {
    edge_flagged_iter(triangles.iter().copied(), boundary).collect()
}

/// [`edge_flagged`] one index at a time, allocating nothing.
pub fn edge_flagged_iter(
    mut triangles: impl Iterator<Item = u32>,
    boundary: impl Fn(usize) -> [bool; 3],
) -> impl Iterator<Item = u32> {
    let mut t = 0;
    std::iter::from_fn(move || {
        let c = [triangles.next()?, triangles.next()?, triangles.next()?];
        let b = boundary(t);
        t += 1;
        let a = |e: usize| if b[e] { c[e] } else { c[(e + 1) % 3] };
        Some([c[0], a(0), c[1], a(1), c[2], a(2)])
    })
    .flatten()
}

/// `GL_TRIANGLES` with GL's per-vertex edge flags: each vertex's `flag` (glEdgeFlag, or
/// the edge flag array at that vertex's index) says whether the edge that starts at it is a
/// boundary edge. Six indices per triangle ([`edge_flagged`]).
pub fn triangles_edge_flagged(vertices: &[u32], flag: impl Fn(u32) -> bool) -> Vec<u32> {
    triangles_edge_flagged_iter(vertices, flag).collect()
}

/// [`triangles_edge_flagged`] one index at a time, allocating nothing.
pub fn triangles_edge_flagged_iter<'a>(
    vertices: &'a [u32],
    flag: impl Fn(u32) -> bool + 'a,
) -> impl Iterator<Item = u32> + 'a {
    edge_flagged_iter(vertices.iter().copied(), move |t| {
        let v = &vertices[3 * t..3 * t + 3];
        [flag(v[0]), flag(v[1]), flag(v[2])]
    })
}

/// `GL_QUADS` as [`quads`] makes them, with each quad's diagonal an inner edge and its four
/// sides taking their first vertex's `flag` (GL's edge flags: a quad drawn with `GL_LINE`
/// shows its outline). Six indices per triangle ([`edge_flagged`]).
pub fn quads_edge_flagged(vertices: &[u32], flag: impl Fn(u32) -> bool) -> Vec<u32> {
    quads_edge_flagged_iter(vertices, flag).collect()
}

/// [`quads_edge_flagged`] one index at a time, allocating nothing.
pub fn quads_edge_flagged_iter<'a>(
    vertices: &'a [u32],
    flag: impl Fn(u32) -> bool + 'a,
) -> impl Iterator<Item = u32> + 'a {
    edge_flagged_iter(quads_iter(vertices), move |t| {
        let q = &vertices[4 * (t / 2)..4 * (t / 2) + 4];
        // (v0, v1, v3): v0-v1, the diagonal, v3-v0; (v1, v2, v3): v1-v2, v2-v3, the diagonal.
        if t % 2 == 0 {
            [flag(q[0]), false, flag(q[3])]
        } else {
            [flag(q[1]), flag(q[2]), false]
        }
    })
}

/// `GL_QUAD_STRIP` as [`quad_strip`] makes it, each quad's diagonal an inner edge. GL applies
/// no edge flags to strips: every side of every quad is a boundary edge.
pub fn quad_strip_edge_flagged(vertices: &[u32]) -> Vec<u32> {
    quad_strip_edge_flagged_iter(vertices).collect()
}

/// [`quad_strip_edge_flagged`] one index at a time, allocating nothing.
pub fn quad_strip_edge_flagged_iter(vertices: &[u32]) -> impl Iterator<Item = u32> + '_ {
    // (v2i, v2i+1, v2i+3): bottom, right, the diagonal; (v2i+2, v2i, v2i+3): left, the
    // diagonal, top.
    edge_flagged_iter(quad_strip_iter(vertices), |t| {
        if t % 2 == 0 {
            [true, true, false]
        } else {
            [true, false, true]
        }
    })
}

/// `GL_POLYGON` as [`polygon`] makes it, the fan's inner edges inner and the polygon's sides
/// taking their first vertex's `flag`. Six indices per triangle ([`edge_flagged`]).
pub fn polygon_edge_flagged(vertices: &[u32], flag: impl Fn(u32) -> bool) -> Vec<u32> {
    polygon_edge_flagged_iter(vertices, flag).collect()
}

/// [`polygon_edge_flagged`] one index at a time, allocating nothing.
pub fn polygon_edge_flagged_iter<'a>(
    vertices: &'a [u32],
    flag: impl Fn(u32) -> bool + 'a,
) -> impl Iterator<Item = u32> + 'a {
    let last = vertices.len().saturating_sub(2);
    edge_flagged_iter(polygon_iter(vertices), move |t| {
        // (v_t+1, v_t+2, v0): a side; the side v_n-1 to v0 on the last; v0 to v1 on the first.
        [
            flag(vertices[t + 1]),
            t + 1 == last && flag(vertices[t + 2]),
            t == 0 && flag(vertices[0]),
        ]
    })
}

/// How many indices the `_edge_flagged` functions make of a triangle list of `indices`.
pub fn edge_flagged_count(indices: u64) -> u64 {
    indices / 3 * 6
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Twice the signed area of triangle (a, b, c) of `points`: positive counter-clockwise.
    fn winding(points: &[(f64, f64)], t: &[u32]) -> f64 {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| points[i as usize]);
        (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1)
    }

    #[test]
    fn a_quad_is_two_triangles_ending_with_its_fourth_vertex_in_its_winding() {
        let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        let t = quads(&[0, 1, 2, 3, 9]);
        assert_eq!(t, [0, 1, 3, 1, 2, 3], "the trailing vertex 9 makes no quad");
        for tri in t.chunks(3) {
            assert_eq!(tri[2], 3, "GL's provoking vertex of a quad is its fourth");
            assert!(winding(&square, tri) > 0.0);
        }
        // The two triangles cover the quad: their areas add up to it.
        let area: f64 = t.chunks(3).map(|tri| winding(&square, tri) / 2.0).sum();
        assert_eq!(area, 1.0);
    }

    #[test]
    fn a_quad_strips_quads_end_with_vertex_2i_plus_2_counting_from_1() {
        // Two quads side by side: 0-1 at the bottom, 2-3 above, 4-5 above that.
        let points = [
            (0.0, 0.0),
            (1.0, 0.0),
            (0.0, 1.0),
            (1.0, 1.0),
            (0.0, 2.0),
            (1.0, 2.0),
        ];
        let t = quad_strip(&[0, 1, 2, 3, 4, 5, 6]);
        assert_eq!(t.len(), 12, "two quads; the unpaired 6 is dropped");
        for (q, quad) in t.chunks(6).enumerate() {
            let provoking = 2 * q as u32 + 3;
            for tri in quad.chunks(3) {
                assert_eq!(tri[2], provoking);
                assert!(winding(&points, tri) > 0.0, "{tri:?}");
            }
        }
        assert!(quad_strip(&[0, 1, 2]).is_empty());
    }

    #[test]
    fn a_polygon_is_a_fan_ending_with_its_first_vertex() {
        let pentagon: Vec<(f64, f64)> = (0..5)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 5.0;
                (a.cos(), a.sin())
            })
            .collect();
        let t = polygon(&[0, 1, 2, 3, 4]);
        assert_eq!(t, [1, 2, 0, 2, 3, 0, 3, 4, 0]);
        for tri in t.chunks(3) {
            assert!(winding(&pentagon, tri) > 0.0);
        }
        assert!(polygon(&[0, 1]).is_empty());
    }

    #[test]
    fn a_line_loop_closes_back_to_its_first_vertex() {
        assert_eq!(line_loop(&[4, 5, 6]), [4, 5, 5, 6, 6, 4]);
        assert_eq!(line_loop(&[4, 5]), [4, 5, 5, 4]);
        assert!(line_loop(&[4]).is_empty());
    }

    /// The boundary edges an edge-flagged list marks, as (from, to) vertex pairs, and its
    /// triangles, as the plain list.
    fn decode(list: &[u32]) -> (Vec<(u32, u32)>, Vec<u32>) {
        let mut edges = Vec::new();
        let mut triangles = Vec::new();
        for p in list.chunks_exact(6) {
            let c = [p[0], p[2], p[4]];
            triangles.extend(c);
            for e in 0..3 {
                let adjacent = p[2 * e + 1];
                assert!(adjacent == c[e] || adjacent == c[(e + 1) % 3], "{p:?}: edge {e}");
                if adjacent == c[e] {
                    edges.push((c[e], c[(e + 1) % 3]));
                }
            }
        }
        edges.sort_unstable();
        (edges, triangles)
    }

    fn sorted(mut edges: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
        edges.sort_unstable();
        edges
    }

    #[test]
    fn edge_flagged_quads_keep_their_four_sides_and_hide_the_diagonal() {
        let v = [10, 11, 12, 13, 20, 21, 22, 23, 99];
        let list = quads_edge_flagged(&v, |_| true);
        assert_eq!(list[..12], [10, 10, 11, 13, 13, 13, 11, 11, 12, 12, 13, 11]);
        let (edges, triangles) = decode(&list);
        assert_eq!(triangles, quads(&v), "the same triangles as the filled form");
        let want = [
            (10, 11),
            (11, 12),
            (12, 13),
            (13, 10),
            (20, 21),
            (21, 22),
            (22, 23),
            (23, 20),
        ];
        assert_eq!(edges, sorted(want.to_vec()));
        // A vertex's flag hides the side that starts at it (glEdgeFlag(GL_FALSE) before it).
        let (edges, _) = decode(&quads_edge_flagged(&v, |i| i != 12 && i != 20));
        let want = [(10, 11), (11, 12), (13, 10), (21, 22), (22, 23), (23, 20)];
        assert_eq!(edges, sorted(want.to_vec()));
    }

    #[test]
    fn edge_flagged_quad_strips_show_every_side_of_every_quad_and_no_diagonal() {
        let v = [0, 1, 2, 3, 4, 5];
        let (edges, triangles) = decode(&quad_strip_edge_flagged(&v));
        assert_eq!(triangles, quad_strip(&v));
        // Quads (0, 1, 3, 2) and (2, 3, 5, 4): their shared side 2-3 is drawn by each.
        let want = [(0, 1), (1, 3), (3, 2), (2, 0), (2, 3), (3, 5), (5, 4), (4, 2)];
        assert_eq!(edges, sorted(want.to_vec()));
    }

    #[test]
    fn edge_flagged_polygons_show_their_sides_and_not_their_fan() {
        let v = [5, 6, 7, 8, 9];
        let (edges, triangles) = decode(&polygon_edge_flagged(&v, |_| true));
        assert_eq!(triangles, polygon(&v));
        let want = [(5, 6), (6, 7), (7, 8), (8, 9), (9, 5)];
        assert_eq!(edges, sorted(want.to_vec()));
        let (edges, _) = decode(&polygon_edge_flagged(&v, |i| i != 5 && i != 9));
        assert_eq!(edges, sorted(vec![(6, 7), (7, 8), (8, 9)]));
        // A triangle as a polygon: one triangle with all three sides.
        let (edges, _) = decode(&polygon_edge_flagged(&[1, 2, 3], |_| true));
        assert_eq!(edges, sorted(vec![(1, 2), (2, 3), (3, 1)]));
    }

    #[test]
    fn edge_flagged_triangles_take_each_vertexs_flag_for_the_edge_it_starts() {
        let (edges, triangles) = decode(&triangles_edge_flagged(&[0, 1, 2, 3, 4, 5, 6], |i| i % 2 == 0));
        assert_eq!(
            triangles,
            [0, 1, 2, 3, 4, 5],
            "the partial last triangle is dropped"
        );
        assert_eq!(edges, sorted(vec![(0, 1), (2, 0), (4, 5)]));
    }

    #[test]
    fn each_count_is_the_length_of_the_list_it_counts() {
        let v: Vec<u32> = (100..120).collect();
        for n in 0..v.len() {
            let part = &v[..n];
            let n = n as u64;
            assert_eq!(quads(part).len() as u64, quads_count(n), "quads of {n}");
            assert_eq!(quad_strip(part).len() as u64, quad_strip_count(n), "strip of {n}");
            assert_eq!(polygon(part).len() as u64, polygon_count(n), "polygon of {n}");
            assert_eq!(line_loop(part).len() as u64, line_loop_count(n), "loop of {n}");
            let flagged = quads_edge_flagged(part, |_| true).len() as u64;
            assert_eq!(
                flagged,
                edge_flagged_count(quads_count(n)),
                "flagged quads of {n}"
            );
        }
        assert_eq!(polygon_count(u64::from(u32::MAX)), 3 * (u64::from(u32::MAX) - 2));
    }
}
