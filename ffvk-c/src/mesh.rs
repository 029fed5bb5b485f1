//! Host helpers: the teapot ffvk's examples draw, and GL's primitive modes that Vulkan lacks
//! turned into index lists.

use ffvk::draw::gl_primitives;
use ffvk::mesh::MeshData;

use crate::enums::*;
use crate::result::{check_ptr, fail, guard, FfvkResult};

/// A host mesh made by ffvk (`ffvkCreateTeapot`): arrays the caller copies into its buffers.
pub struct FfvkMesh {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    colors: Vec<[f32; 4]>,
    indices: Vec<u32>,
}

/// A view of an `FfvkMesh`'s arrays, valid until `ffvkDestroyMesh`. It never changes (it has
/// no `struct_size`).
#[repr(C)]
pub struct FfvkMeshArrays {
    /// How many vertices.
    pub vertex_count: u32,
    /// `vertex_count` object-space positions, x y z.
    pub positions: *const f32,
    /// `vertex_count` normals, x y z.
    pub normals: *const f32,
    /// `vertex_count` colors, r g b a in [0, 1].
    pub colors: *const f32,
    /// How many indices.
    pub index_count: u32,
    /// `index_count` indices: counter-clockwise triangles (`GL_TRIANGLES`).
    pub indices: *const u32,
}

/// Newell's teapot tessellated at `level` (1 ..= 64 steps per patch side), the mesh ffvk's
/// examples and tests draw: y up (the lid), the spout toward +x and the handle toward −x,
/// centred on the origin within x in [−1, 1], y in [−0.483, 0.483], z in [−0.613, 0.613]
/// (Newell's patches closed by their bottom); counter-clockwise front faces, unit normals,
/// colors in [0, 1]. Errors: `FFVK_ERROR_INVALID_ARGUMENT` for another level or a null
/// `mesh`.
///
/// # Safety
///
/// `mesh` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkCreateTeapot(level: u32, mesh: *mut *mut FfvkMesh) -> FfvkResult {
    guard(|| {
        if let Err(code) = check_ptr("ffvkCreateTeapot", "mesh", mesh, "where to write the mesh") {
            return code;
        }
        // SAFETY: checked non-null and aligned; writable by the caller's contract.
        unsafe { *mesh = std::ptr::null_mut() };
        let data: MeshData = match ffvk::mesh::teapot::teapot(level) {
            Ok(d) => d,
            Err(e) => {
                return fail(
                    FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                    format!("ffvkCreateTeapot: {e}"),
                )
            }
        };
        let made = FfvkMesh {
            positions: data.vertices.iter().map(|v| v.position).collect(),
            normals: data.vertices.iter().map(|v| v.normal).collect(),
            colors: data.vertices.iter().map(|v| v.color).collect(),
            indices: data.indices,
        };
        // SAFETY: checked non-null.
        unsafe { *mesh = Box::into_raw(Box::new(made)) };
        FfvkResult::FFVK_SUCCESS
    })
}

/// The mesh's arrays. Returns `FFVK_ERROR_INVALID_ARGUMENT` for a null pointer.
///
/// # Safety
///
/// `mesh` is null or live; `arrays` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetMeshArrays(mesh: *const FfvkMesh, arrays: *mut FfvkMeshArrays) -> FfvkResult {
    guard(|| {
        const F: &str = "ffvkGetMeshArrays";
        let checked = check_ptr(F, "mesh", mesh, "a mesh from ffvkCreateTeapot")
            .and_then(|()| check_ptr(F, "arrays", arrays, "where to write the mesh's arrays"));
        if let Err(code) = checked {
            return code;
        }
        // SAFETY: checked non-null and aligned; live by the caller's contract.
        let m = unsafe { &*mesh };
        let view = FfvkMeshArrays {
            vertex_count: m.positions.len() as u32,
            positions: m.positions.as_ptr().cast(),
            normals: m.normals.as_ptr().cast(),
            colors: m.colors.as_ptr().cast(),
            index_count: m.indices.len() as u32,
            indices: m.indices.as_ptr(),
        };
        // SAFETY: checked non-null; writable by the caller's contract.
        unsafe { arrays.write(view) };
        FfvkResult::FFVK_SUCCESS
    })
}

/// Frees a mesh; null is ignored.
///
/// # Safety
///
/// `mesh` is null or from `ffvkCreateTeapot`, not yet destroyed.
#[no_mangle]
pub unsafe extern "C" fn ffvkDestroyMesh(mesh: *mut FfvkMesh) {
    // SAFETY: the caller's contract: made by this API, destroyed once.
    unsafe { crate::result::free(mesh) }
}

/// GL's modes that Vulkan lacks, as indices of a mode it has, keeping GL's winding and
/// provoking vertex: `GL_QUADS`, `GL_QUAD_STRIP` and `GL_POLYGON` become `GL_TRIANGLES`,
/// `GL_LINE_LOOP` becomes `GL_LINES`; the other modes are copied unchanged. `vertices` are
/// the `count` vertex numbers GL would read (the index array of glDrawElements; for
/// glDrawArrays' `first + i`, `ffvkPrimitiveIndicesRange` needs no array). Writes at most
/// `capacity` indices to `out` (null to ask the size) and the needed count to `*written`, and
/// the mode to draw them with to `*draw_mode`. A size query (null `out`) reads nothing from
/// `vertices`; nothing is allocated, whatever the count. Errors:
/// `FFVK_ERROR_INVALID_ARGUMENT` for an unknown mode, a null `vertices` (with a count), a
/// null `written` or `draw_mode`, a count whose indices would number more than a `uint32_t`
/// holds (e.g. `GL_POLYGON` of more than 1431655767 vertices; nothing written then), or a
/// `capacity` below the needed count (nothing written to `out` then).
///
/// # Safety
///
/// `vertices` points at `count` values (unless `out` is null); `out` is null or has room for
/// `capacity`.
#[no_mangle]
pub unsafe extern "C" fn ffvkPrimitiveIndices(
    mode: u32,
    vertices: *const u32,
    count: u32,
    out: *mut u32,
    capacity: u32,
    written: *mut u32,
    draw_mode: *mut u32,
) -> FfvkResult {
    let request = Request {
        function: "ffvkPrimitiveIndices",
        mode,
        vertices: Vertices::Listed(vertices),
        count,
    };
    // SAFETY: the caller's contract, passed on.
    unsafe { primitive_indices(&request, out, capacity, written, draw_mode) }
}

/// `ffvkPrimitiveIndices` for `glDrawArrays(mode, first, count)`: the vertex numbers are
/// `first`, `first + 1`, … `first + count - 1`, so no array is passed. The outputs, the size
/// query and the errors are `ffvkPrimitiveIndices`'s, and: `FFVK_ERROR_INVALID_ARGUMENT` when
/// `first + count` passes 2^32 (the last vertex number would not fit a `uint32_t`);
/// `FFVK_ERROR_OUT_OF_MEMORY` when the host cannot hold the `count` vertex numbers ffvk makes
/// while it writes `GL_QUADS`, `GL_QUAD_STRIP`, `GL_POLYGON` or `GL_LINE_LOOP` indices (4 bytes
/// each, freed before it returns; the other modes and a size query allocate nothing).
///
/// # Safety
///
/// `out` is null or has room for `capacity`.
#[no_mangle]
pub unsafe extern "C" fn ffvkPrimitiveIndicesRange(
    mode: u32,
    first: u32,
    count: u32,
    out: *mut u32,
    capacity: u32,
    written: *mut u32,
    draw_mode: *mut u32,
) -> FfvkResult {
    let request = Request {
        function: "ffvkPrimitiveIndicesRange",
        mode,
        vertices: Vertices::Consecutive(first),
        count,
    };
    // SAFETY: the caller's contract, passed on.
    unsafe { primitive_indices(&request, out, capacity, written, draw_mode) }
}

/// Where the `count` vertex numbers of a primitive list come from.
#[derive(Clone, Copy)]
enum Vertices {
    /// The caller's array (glDrawElements' indices).
    Listed(*const u32),
    /// `first`, `first + 1`, … (glDrawArrays).
    Consecutive(u32),
}

/// What `ffvkPrimitiveIndices` or `ffvkPrimitiveIndicesRange` was asked.
struct Request {
    function: &'static str,
    mode: u32,
    vertices: Vertices,
    count: u32,
}

/// The two entry points' work: every check from the count alone, then the indices.
///
/// # Safety
///
/// A listed `vertices` points at `count` values (unless `out` is null); `out` is null or has
/// room for `capacity`; `written` and `draw_mode` are null or writable.
unsafe fn primitive_indices(
    request: &Request,
    out: *mut u32,
    capacity: u32,
    written: *mut u32,
    draw_mode: *mut u32,
) -> FfvkResult {
    let &Request {
        function: f,
        mode,
        vertices,
        count,
    } = request;
    guard(|| {
        let mut checked = check_ptr(f, "written", written, "where to write the index count")
            .and_then(|()| check_ptr(f, "draw_mode", draw_mode, "where to write the mode to draw with"));
        match vertices {
            Vertices::Listed(vertices) if count > 0 => {
                let expected = format!("the {count} vertex numbers of count");
                checked = checked.and_then(|()| check_ptr(f, "vertices", vertices, &expected));
            }
            Vertices::Listed(_) => {}
            Vertices::Consecutive(first) => {
                if u64::from(first) + u64::from(count) > 1 << 32 {
                    return fail(
                        FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                        format!(
                            "{f}: first {first} + count {count} passes 2^32: expected first + count <= 4294967296 (the last vertex number, first + count - 1, a uint32_t)"
                        ),
                    );
                }
            }
        }
        if !out.is_null() {
            checked = checked.and_then(|()| check_ptr(f, "out", out, "room for capacity indices, or null"));
        }
        if let Err(code) = checked {
            return code;
        }
        // The size first, from the count alone: nothing is read or allocated for a query.
        let n = u64::from(count);
        let (needed, as_mode) = match mode {
            GL_QUADS => (gl_primitives::quads_count(n), GL_TRIANGLES),
            GL_QUAD_STRIP => (gl_primitives::quad_strip_count(n), GL_TRIANGLES),
            GL_POLYGON => (gl_primitives::polygon_count(n), GL_TRIANGLES),
            GL_LINE_LOOP => (gl_primitives::line_loop_count(n), GL_LINES),
            GL_POINTS | GL_LINES | GL_LINE_STRIP | GL_TRIANGLES | GL_TRIANGLE_STRIP | GL_TRIANGLE_FAN => (n, mode),
            other => {
                return fail(
                    FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                    format!("{f}: mode {} is not one of GL's ten primitive modes: expected GL_POINTS (0x0000) .. GL_POLYGON (0x0009)", enum_name(other)),
                )
            }
        };
        let Ok(needed) = u32::try_from(needed) else {
            return too_many_indices(f, count, mode, needed);
        };
        // SAFETY: checked non-null; writable by the caller's contract.
        unsafe {
            written.write(needed);
            draw_mode.write(as_mode);
        }
        if out.is_null() {
            return FfvkResult::FFVK_SUCCESS;
        }
        if capacity < needed {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{f}: capacity {capacity} is too small: expected at least {needed}"),
            );
        }
        let consecutive;
        let input: &[u32] = match vertices {
            Vertices::Listed(_) if count == 0 => &[],
            // SAFETY: the caller's contract: count values at vertices (checked non-null and
            // aligned above).
            Vertices::Listed(vertices) => unsafe { std::slice::from_raw_parts(vertices, count as usize) },
            Vertices::Consecutive(first) => {
                let numbers = (0..count).map(|i| first + i);
                if as_mode == mode {
                    // Copied unchanged: written straight into the caller's room (capacity >=
                    // needed = count).
                    // SAFETY: out has room for `count` values; the iterator yields `count`.
                    unsafe { fill(out, numbers) };
                    return FfvkResult::FFVK_SUCCESS;
                }
                let mut held = Vec::new();
                if held.try_reserve_exact(count as usize).is_err() {
                    return fail(
                        FfvkResult::FFVK_ERROR_OUT_OF_MEMORY,
                        format!(
                            "{f}: no host memory for the {count} vertex numbers first .. first + count - 1"
                        ),
                    );
                }
                held.extend(numbers);
                consecutive = held;
                &consecutive
            }
        };
        // Written straight into the caller's room, which holds capacity >= needed values.
        // SAFETY: out has room for `needed` values; each iterator yields exactly `needed`.
        unsafe {
            match mode {
                GL_QUADS => fill(out, gl_primitives::quads_iter(input)),
                GL_QUAD_STRIP => fill(out, gl_primitives::quad_strip_iter(input)),
                GL_POLYGON => fill(out, gl_primitives::polygon_iter(input)),
                GL_LINE_LOOP => fill(out, gl_primitives::line_loop_iter(input)),
                _ => std::ptr::copy_nonoverlapping(input.as_ptr(), out, input.len()),
            }
        }
        FfvkResult::FFVK_SUCCESS
    })
}

/// GL's polygons with their edge flags (GL 2.1 §2.6.2), for draws in polygon mode `GL_LINE` or
/// `GL_POINT`: `GL_TRIANGLES`, `GL_QUADS`, `GL_QUAD_STRIP` or `GL_POLYGON` over the `count`
/// vertex numbers `vertices` (as `ffvkPrimitiveIndices` takes them), as indices to draw with
/// mode `GL_TRIANGLES_ADJACENCY` (`ffvkDraw`; the device's `geometryShader`,
/// `FFVK_FEATURE_GEOMETRY_SHADER`): the same triangles as `ffvkPrimitiveIndices` makes, six
/// indices each, whose adjacency indices mark the edges GL draws: a quad's four sides and not
/// its diagonal, a polygon's sides and not its fan, and of those only the edges whose first
/// vertex's edge flag is `GL_TRUE`. `edge_flags` is null (every flag `GL_TRUE`, GL's default
/// edge flag) or GL's edge flag array (`glEdgeFlagPointer`): `flag_count` flags (non-zero:
/// `GL_TRUE`), one per vertex number; a caller whose current edge flag (`glEdgeFlag`) is
/// `GL_FALSE` passes flags of zero. `GL_QUAD_STRIP` takes no flags, as in GL (every side of
/// every quad is drawn). Filled, such a draw looks as the `ffvkPrimitiveIndices` draw does.
/// Writes at most `capacity` indices to `out` (null to ask the size) and the needed count to
/// `*written`. Errors: `FFVK_ERROR_INVALID_ARGUMENT` for another mode, a null `vertices` (with
/// a count) or `written`, a vertex number at or past `flag_count` (with flags; nothing written
/// to `out` then), a count whose indices would number more than a `uint32_t` holds, or a
/// `capacity` below the needed count (nothing written to `out` then).
///
/// # Safety
///
/// `vertices` points at `count` values and `edge_flags` at `flag_count` (neither is read when
/// `out` is null, but `vertices` must not be null with a count); `out` is null or has room for
/// `capacity`. A size query (null `out`) checks the mode, the count and the pointers only: the
/// flags are checked when the indices are written.
#[no_mangle]
pub unsafe extern "C" fn ffvkEdgeFlaggedIndices(
    mode: u32,
    vertices: *const u32,
    count: u32,
    edge_flags: *const u8,
    flag_count: u32,
    out: *mut u32,
    capacity: u32,
    written: *mut u32,
) -> FfvkResult {
    let f = "ffvkEdgeFlaggedIndices";
    guard(|| {
        let mut checked = check_ptr(f, "written", written, "where to write the index count");
        if count > 0 {
            let expected = format!("the {count} vertex numbers of count");
            checked = checked.and_then(|()| check_ptr(f, "vertices", vertices, &expected));
        }
        if !out.is_null() {
            checked = checked.and_then(|()| check_ptr(f, "out", out, "room for capacity indices, or null"));
        }
        if let Err(code) = checked {
            return code;
        }
        let n = u64::from(count);
        let triangles = match mode {
            GL_TRIANGLES => n / 3 * 3,
            GL_QUADS => gl_primitives::quads_count(n),
            GL_QUAD_STRIP => gl_primitives::quad_strip_count(n),
            GL_POLYGON => gl_primitives::polygon_count(n),
            other => {
                return fail(
                    FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                    format!(
                        "{f}: mode {} has no edge flags: expected GL_TRIANGLES, GL_QUADS, GL_QUAD_STRIP or GL_POLYGON",
                        mode_name(other)
                    ),
                )
            }
        };
        let needed = gl_primitives::edge_flagged_count(triangles);
        let Ok(needed) = u32::try_from(needed) else {
            return too_many_indices(f, count, mode, needed);
        };
        // SAFETY: checked non-null; writable by the caller's contract.
        unsafe { written.write(needed) };
        if out.is_null() {
            return FfvkResult::FFVK_SUCCESS;
        }
        if capacity < needed {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{f}: capacity {capacity} is too small: expected at least {needed}"),
            );
        }
        let input: &[u32] = if count == 0 {
            &[]
        } else {
            // SAFETY: the caller's contract: count values at vertices (checked non-null above).
            unsafe { std::slice::from_raw_parts(vertices, count as usize) }
        };
        let flags: Option<&[u8]> = if edge_flags.is_null() || flag_count == 0 {
            None
        } else {
            // SAFETY: the caller's contract: flag_count flags at edge_flags.
            Some(unsafe { std::slice::from_raw_parts(edge_flags, flag_count as usize) })
        };
        if edge_flags.is_null() && flag_count > 0 {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!(
                    "{f}: edge_flags is a null pointer with flag_count {flag_count}: expected flag_count flags, or null with flag_count 0 (every flag GL_TRUE)"
                ),
            );
        }
        // GL applies no edge flags to quad strips: theirs are not read.
        if !edge_flags.is_null() && mode != GL_QUAD_STRIP {
            let have = flags.map_or(0, <[u8]>::len);
            if let Some(&v) = input.iter().find(|&&v| v as usize >= have) {
                return fail(
                    FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                    format!(
                        "{f}: vertex number {v} has no edge flag: expected every vertex number below flag_count {flag_count}"
                    ),
                );
            }
        }
        let flag = move |v: u32| flags.is_none_or(|f| f[v as usize] != 0);
        // Written straight into the caller's room, which holds capacity >= needed values.
        // SAFETY: out has room for `needed` values; each iterator yields exactly `needed`.
        unsafe {
            match mode {
                GL_TRIANGLES => fill(out, gl_primitives::triangles_edge_flagged_iter(input, flag)),
                GL_QUADS => fill(out, gl_primitives::quads_edge_flagged_iter(input, flag)),
                GL_QUAD_STRIP => fill(out, gl_primitives::quad_strip_edge_flagged_iter(input)),
                _ => fill(out, gl_primitives::polygon_edge_flagged_iter(input, flag)),
            }
        }
        FfvkResult::FFVK_SUCCESS
    })
}

/// The error for `count` vertices of `mode` whose `needed` indices pass a `uint32_t`.
fn too_many_indices(f: &str, count: u32, mode: u32, needed: u64) -> FfvkResult {
    fail(
        FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
        format!(
            "{f}: count {count} of mode {} makes {needed} indices, more than written (a uint32_t) holds: expected a count whose indices number at most {}",
            mode_name(mode),
            u32::MAX
        ),
    )
}

/// Writes each index of `indices` to `out`, one after another.
///
/// # Safety
///
/// `out` has room for as many values as `indices` yields.
unsafe fn fill(out: *mut u32, indices: impl Iterator<Item = u32>) {
    for (i, index) in indices.enumerate() {
        // SAFETY: the caller's contract: room for every value yielded.
        unsafe { out.add(i).write(index) };
    }
}
