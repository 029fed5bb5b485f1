//! The GL side: a scene's state and draws as legacy GL calls, the readback, and the timing
//! loop. Everything here runs with a context current on this thread and the framebuffer
//! object bound ([`super::egl::with_context`]).

use std::ffi::c_void;

use ffvk::gl::state::{ColorControl, FixedFunctionState, Light, LightingMode, Material};
use ffvk::mesh::{MeshData, Vertex};

use super::bindings::types::{GLenum, GLint, GLsizei, GLsizeiptr, GLuint};
use super::bindings::{self as gl, Gl};
use super::calls::{color_material_enum, face_enum, replay, set_enabled};
use super::egl::{check_draw, drain_errors, gl_string};
use super::error::{DrawError, GlError};
use super::texture_object::{upload_textures, DrawUnits};
use super::texture_unit::set_texture_unit;
use super::{GlDraw, GlInfo, GlScene};

/// GL_VERSION, GL_RENDERER, GL_VENDOR and GL_MAX_LIGHTS of the current context.
pub(super) fn info(gl: &Gl, created_with: &str) -> Result<GlInfo, GlError> {
    Ok(GlInfo {
        version: gl_string(gl, gl::VERSION)?,
        renderer: gl_string(gl, gl::RENDERER)?,
        vendor: gl_string(gl, gl::VENDOR)?,
        max_lights: max_lights(gl),
        created_with: created_with.to_string(),
    })
}

pub(super) fn max_lights(gl: &Gl) -> GLint {
    let mut max_lights: GLint = 0;
    // SAFETY: a context is current on this thread; one GLint is written.
    unsafe { gl.GetIntegerv(gl::MAX_LIGHTS, &mut max_lights) };
    max_lights
}

/// Err with `when` if GL has recorded an error (draining every pending error flag).
pub(super) fn check(gl: &Gl, when: impl FnOnce() -> String) -> Result<(), GlError> {
    let codes = drain_errors(gl);
    if codes.is_empty() {
        Ok(())
    } else {
        Err(GlError::Gl { codes, when: when() })
    }
}

/// Renders `scene` into the bound framebuffer and reads it back, row 0 at the top.
pub(super) fn render(gl: &Gl, scene: &GlScene) -> Result<image::RgbaImage, GlError> {
    let (width, height) = (scene.width, scene.height);
    let max_lights = usize::try_from(max_lights(gl)).unwrap_or(0);
    begin_frame(gl, scene);
    check(gl, || "while setting up the frame".into())?;

    let units = scene.units_used();
    for (index, draw) in scene.draws.iter().enumerate() {
        // The draw's texture objects live for the draw only (deleted when dropped).
        let textures = upload_textures(gl, draw).map_err(|problem| GlError::Draw { index, problem })?;
        let bound = DrawUnits::of(&textures, units);
        draw_one(gl, draw, max_lights, &bound).map_err(|problem| GlError::Draw { index, problem })?;
        drop(textures);
        check(gl, || format!("after draw {index}"))?;
    }

    read_back(gl, width, height)
}

/// The current framebuffer's `width` × `height` pixels, row 0 at the top.
pub(super) fn read_back(gl: &Gl, width: u32, height: u32) -> Result<image::RgbaImage, GlError> {
    // The framebuffer object was made at this size, so it fits in memory's terms already;
    // the product is checked anyway rather than trusted.
    let row = width as usize * 4;
    let bytes = row.checked_mul(height as usize).ok_or_else(|| GlError::Size {
        width,
        height,
        problem: "too large to read back".into(),
    })?;
    let mut pixels = vec![0u8; bytes];
    // SAFETY: a context is current on this thread; `pixels` holds exactly width * height
    // RGBA8 pixels with no row padding (PACK_ALIGNMENT 1), and the size fits the
    // framebuffer object, whose sizes are GLsizei.
    unsafe {
        gl.Finish();
        gl.PixelStorei(gl::PACK_ALIGNMENT, 1);
        gl.ReadPixels(
            0,
            0,
            width as GLsizei,
            height as GLsizei,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            pixels.as_mut_ptr().cast::<c_void>(),
        );
    }
    check(gl, || "from glReadPixels".into())?;

    // glReadPixels returns the bottom row first; the image wants the top row first.
    let flipped: Vec<u8> = pixels.chunks_exact(row).rev().flatten().copied().collect();
    Ok(image::RgbaImage::from_raw(width, height, flipped).expect("the readback has width * height pixels"))
}

/// A mesh in a vertex and an index buffer object of the current context.
pub(super) struct MeshBuffers<'g> {
    gl: &'g Gl,
    /// Vertex buffer, index buffer.
    pub(super) names: [GLuint; 2],
}

impl<'g> MeshBuffers<'g> {
    pub(super) fn upload(gl: &'g Gl, mesh: &MeshData) -> Result<MeshBuffers<'g>, DrawError> {
        check_indices(mesh)?;
        let vertex_bytes: &[u8] = bytemuck::cast_slice(&mesh.vertices);
        let index_bytes: &[u8] = bytemuck::cast_slice(&mesh.indices);
        let size = |bytes: &[u8]| {
            GLsizeiptr::try_from(bytes.len()).map_err(|_| DrawError::TooManyBytes(bytes.len()))
        };
        let (vertex_size, index_size) = (size(vertex_bytes)?, size(index_bytes)?);
        let mut buffers = MeshBuffers { gl, names: [0; 2] };
        // SAFETY: a context is current on this thread; glGenBuffers writes two names (owned by
        // `buffers` from here on), and glBufferData copies `size` bytes from slices that are
        // at least that long.
        unsafe {
            gl.GenBuffers(2, buffers.names.as_mut_ptr());
            gl.BindBuffer(gl::ARRAY_BUFFER, buffers.names[0]);
            gl.BufferData(
                gl::ARRAY_BUFFER,
                vertex_size,
                vertex_bytes.as_ptr().cast(),
                gl::STATIC_DRAW,
            );
            gl.BindBuffer(gl::ELEMENT_ARRAY_BUFFER, buffers.names[1]);
            gl.BufferData(
                gl::ELEMENT_ARRAY_BUFFER,
                index_size,
                index_bytes.as_ptr().cast(),
                gl::STATIC_DRAW,
            );
            gl.BindBuffer(gl::ARRAY_BUFFER, 0);
            gl.BindBuffer(gl::ELEMENT_ARRAY_BUFFER, 0);
        }
        Ok(buffers)
    }
}

impl Drop for MeshBuffers<'_> {
    fn drop(&mut self) {
        // SAFETY: the context that made the names is current (MeshBuffers never outlive
        // `time`, which runs inside its context).
        unsafe { self.gl.DeleteBuffers(2, self.names.as_ptr()) };
    }
}

/// Every index of `mesh` within its vertices.
fn check_indices(mesh: &MeshData) -> Result<(), DrawError> {
    match mesh.indices.iter().find(|&&i| i as usize >= mesh.vertices.len()) {
        Some(&index) => Err(DrawError::IndexOutOfRange {
            index,
            vertices: mesh.vertices.len(),
        }),
        None => Ok(()),
    }
}

/// Viewport, clear and the per-frame fixed state.
pub(super) fn begin_frame(gl: &Gl, scene: &GlScene) {
    // SAFETY: a context is current on this thread; the framebuffer object was made at the
    // scene's size, so the sizes fit a GLsizei.
    unsafe {
        gl.Viewport(0, 0, scene.width as GLsizei, scene.height as GLsizei);
        let [r, g, b, a] = scene.clear_color;
        gl.ClearColor(r, g, b, a);
        gl.ClearDepth(1.0);
        // glColorMask and glStencilMask mask glClear too: the whole image is cleared.
        gl.ColorMask(1, 1, 1, 1);
        gl.StencilMask(!0);
        gl.DepthMask(1);
        gl.ClearStencil(0);
        gl.Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
        if scene.depth_test {
            gl.Enable(gl::DEPTH_TEST);
            gl.DepthFunc(gl::LESS);
        } else {
            gl.Disable(gl::DEPTH_TEST);
        }
        gl.FrontFace(gl::CCW);
        gl.Disable(gl::CULL_FACE);
        gl.Disable(gl::BLEND);
        // Dithering is on by default in GL; the Vulkan side never dithers.
        gl.Disable(gl::DITHER);
    }
}

/// glLight for every parameter of light `index`, with the MODELVIEW matrix at identity so the
/// eye-space position and spot direction are stored unchanged.
pub(super) fn set_light(gl: &Gl, index: usize, light: &Light) {
    let id = gl::LIGHT0 + index as GLenum;
    let spot = light.spot_direction.to_array();
    // SAFETY: a context is current on this thread; every array has the length GL reads.
    unsafe {
        gl.Lightfv(id, gl::AMBIENT, light.ambient.to_array().as_ptr());
        gl.Lightfv(id, gl::DIFFUSE, light.diffuse.to_array().as_ptr());
        gl.Lightfv(id, gl::SPECULAR, light.specular.to_array().as_ptr());
        gl.Lightfv(id, gl::POSITION, light.position.to_array().as_ptr());
        gl.Lightfv(id, gl::SPOT_DIRECTION, spot.as_ptr());
        gl.Lightf(id, gl::SPOT_EXPONENT, light.spot_exponent);
        gl.Lightf(id, gl::SPOT_CUTOFF, light.spot_cutoff);
        gl.Lightf(id, gl::CONSTANT_ATTENUATION, light.constant_attenuation);
        gl.Lightf(id, gl::LINEAR_ATTENUATION, light.linear_attenuation);
        gl.Lightf(id, gl::QUADRATIC_ATTENUATION, light.quadratic_attenuation);
    }
    set_enabled(gl, id, light.enabled);
}

fn set_material(gl: &Gl, face: GLenum, m: &Material) {
    // SAFETY: a context is current on this thread; every array has four components.
    unsafe {
        gl.Materialfv(face, gl::AMBIENT, m.ambient.to_array().as_ptr());
        gl.Materialfv(face, gl::DIFFUSE, m.diffuse.to_array().as_ptr());
        gl.Materialfv(face, gl::SPECULAR, m.specular.to_array().as_ptr());
        gl.Materialfv(face, gl::EMISSION, m.emission.to_array().as_ptr());
        gl.Materialf(face, gl::SHININESS, m.shininess);
    }
}

/// An enabled light past `GL_MAX_LIGHTS` is an error.
pub(super) fn check_lights(state: &FixedFunctionState, max_lights: usize) -> Result<(), DrawError> {
    match state
        .lights
        .iter()
        .enumerate()
        .find(|(i, l)| *i >= max_lights && l.enabled)
    {
        Some((index, _)) => Err(DrawError::TooManyLights { index, max_lights }),
        None => Ok(()),
    }
}

/// The indices `glDrawElements` draws: whole triangles for `GL_TRIANGLES` (as ffvk draws a
/// mesh); every index for other modes, whose incomplete last primitives GL drops itself.
pub(super) fn index_count(draw: &GlDraw) -> Result<GLsizei, DrawError> {
    let count = match draw.mode {
        super::GlMode::Triangles => draw.mesh.triangle_count() * 3,
        _ => draw.mesh.indices.len(),
    };
    GLsizei::try_from(count).map_err(|_| DrawError::TooManyIndices(count))
}

/// Points the vertex, normal, color and texture coordinate arrays at the [`Vertex`] fields from
/// `base` (a client address, or null for the bound buffer object) and enables those the draw
/// reads: colors with a color array, the mesh's texture coordinates on the units of
/// `texcoords` (a bit each, of the first `units`; as in ffvk, each vertex's (s, t, 0, 1) then
/// goes through the unit's texture matrix).
pub(super) fn set_arrays(gl: &Gl, base: *const u8, colors: bool, (texcoords, units): (u32, usize)) {
    let stride = std::mem::size_of::<Vertex>() as GLsizei;
    let field = |offset: usize| base.wrapping_add(offset).cast::<c_void>();
    // SAFETY: a context is current on this thread; the pointers are read by later draws only,
    // which the callers make while the arrays (client memory or the bound buffer) live.
    unsafe {
        gl.EnableClientState(gl::VERTEX_ARRAY);
        gl.EnableClientState(gl::NORMAL_ARRAY);
        if colors {
            gl.EnableClientState(gl::COLOR_ARRAY);
        } else {
            gl.DisableClientState(gl::COLOR_ARRAY);
        }
        for unit in (0..units).rev() {
            if units > 1 {
                gl.ClientActiveTexture(gl::TEXTURE0 + unit as u32);
            }
            if texcoords & 1 << unit != 0 {
                gl.EnableClientState(gl::TEXTURE_COORD_ARRAY);
            } else {
                gl.DisableClientState(gl::TEXTURE_COORD_ARRAY);
            }
            gl.TexCoordPointer(
                2,
                gl::FLOAT,
                stride,
                field(std::mem::offset_of!(Vertex, texcoord)),
            );
        }
        gl.VertexPointer(
            3,
            gl::FLOAT,
            stride,
            field(std::mem::offset_of!(Vertex, position)),
        );
        gl.NormalPointer(gl::FLOAT, stride, field(std::mem::offset_of!(Vertex, normal)));
        gl.ColorPointer(4, gl::FLOAT, stride, field(std::mem::offset_of!(Vertex, color)));
    }
}

/// Points the texture coordinate arrays of the units `units` names (a bit each, enabled by
/// [`set_arrays`]) at `st`, the mesh's second set in client memory (two floats a vertex,
/// tightly packed), and leaves the client active texture at `GL_TEXTURE0`.
fn set_second_arrays(gl: &Gl, st: &[[f32; 2]], units: u32) {
    if units == 0 {
        return;
    }
    for unit in 1..ffvk::gl::texture::MAX_TEXTURE_UNITS as u32 {
        if units & 1 << unit == 0 {
            continue;
        }
        // SAFETY: a context is current on this thread; `st` is read by the draw that follows,
        // which the callers make while it lives.
        unsafe {
            gl.ClientActiveTexture(gl::TEXTURE0 + unit);
            gl.TexCoordPointer(2, gl::FLOAT, 0, st.as_ptr().cast());
        }
    }
    // SAFETY: as above.
    unsafe { gl.ClientActiveTexture(gl::TEXTURE0) };
}

/// Disables the arrays (the texture coordinates of the first `units` units) and unbinds the
/// buffers.
pub(super) fn end_arrays(gl: &Gl, units: usize) {
    // SAFETY: a context is current on this thread.
    unsafe {
        gl.DisableClientState(gl::VERTEX_ARRAY);
        gl.DisableClientState(gl::NORMAL_ARRAY);
        gl.DisableClientState(gl::COLOR_ARRAY);
        for unit in (0..units).rev() {
            if units > 1 {
                gl.ClientActiveTexture(gl::TEXTURE0 + unit as u32);
            }
            gl.DisableClientState(gl::TEXTURE_COORD_ARRAY);
        }
        gl.BindBuffer(gl::ARRAY_BUFFER, 0);
        gl.BindBuffer(gl::ELEMENT_ARRAY_BUFFER, 0);
    }
}

/// One draw from client arrays with every state set first: the conformance reference's form.
fn draw_one(gl: &Gl, draw: &GlDraw, max_lights: usize, units: &DrawUnits) -> Result<(), DrawError> {
    check_lights(&draw.state, max_lights)?;
    let mesh = draw.mesh;
    check_indices(mesh)?;
    let second = draw.second_texcoords & !1;
    let arrays = (units.texcoord_arrays(draw.mesh_texcoords | second), units.count);
    if second & arrays.0 != 0 && mesh.second_texcoords.len() != mesh.vertices.len() {
        return Err(DrawError::SecondTexcoordCount {
            count: mesh.second_texcoords.len(),
            vertices: mesh.vertices.len(),
        });
    }
    if mesh.topology == ffvk::Topology::EdgeFlaggedTriangles {
        set_state(gl, draw, max_lights, units)?;
        return draw_edge_flagged(gl, draw, arrays);
    }
    let count = index_count(draw)?;
    set_state(gl, draw, max_lights, units)?;
    if count == 0 {
        return Ok(());
    }
    set_arrays(gl, mesh.vertices.as_ptr().cast(), draw.color_array, arrays);
    set_second_arrays(gl, &mesh.second_texcoords, second & arrays.0);
    if let Some(flags) = draw.edge_flags {
        if flags.len() != mesh.vertices.len() {
            end_arrays(gl, units.count);
            return Err(DrawError::EdgeFlagCount {
                flags: flags.len(),
                vertices: mesh.vertices.len(),
            });
        }
        // SAFETY: a context is current on this thread; `flags` (one byte per vertex, checked
        // above) outlives the draw below, and the array is disabled by end_arrays' caller
        // below.
        unsafe {
            gl.EdgeFlagPointer(0, flags.as_ptr().cast());
            gl.EnableClientState(gl::EDGE_FLAG_ARRAY);
        }
    }
    // SAFETY: a context is current on this thread. The arrays point into `mesh.vertices`
    // (repr(C) f32 fields) and `mesh.second_texcoords` (one per vertex where a unit reads it,
    // checked above), and glDrawElements reads them and the indices before it returns.
    // Every index was checked against the vertex count, and the arrays are disabled after the
    // draw.
    unsafe {
        gl.MatrixMode(gl::MODELVIEW);
        gl.LoadMatrixf(draw.modelview.to_cols_array().as_ptr());
        gl.DrawElements(
            draw.mode.gl(),
            count,
            gl::UNSIGNED_INT,
            mesh.indices.as_ptr().cast(),
        );
        gl.DisableClientState(gl::EDGE_FLAG_ARRAY);
    }
    end_arrays(gl, units.count);
    Ok(())
}

/// A mesh of `Topology::EdgeFlaggedTriangles` as GL draws its meaning: `GL_TRIANGLES` of each
/// triangle's three corners (copied, so that each corner has its own flag), each corner with
/// the edge flag of the edge that starts at it (set where its adjacency index repeats it).
/// The indices were checked against the vertices.
fn draw_edge_flagged(gl: &Gl, draw: &GlDraw, arrays: (u32, usize)) -> Result<(), DrawError> {
    let mesh = draw.mesh;
    let (vertices, flags): (Vec<Vertex>, Vec<u8>) = mesh
        .indices
        .chunks_exact(6)
        .flat_map(|p| {
            (0..3).map(move |e| {
                (
                    mesh.vertices[p[2 * e] as usize],
                    u8::from(p[2 * e + 1] == p[2 * e]),
                )
            })
        })
        .unzip();
    let count = GLsizei::try_from(vertices.len()).map_err(|_| DrawError::TooManyIndices(vertices.len()))?;
    if count == 0 {
        return Ok(());
    }
    // Each corner's second coordinates, where a unit reads them (one per vertex, checked).
    let second_units = draw.second_texcoords & !1 & arrays.0;
    let second: Vec<[f32; 2]> = match second_units {
        0 => Vec::new(),
        _ => mesh
            .indices
            .chunks_exact(6)
            .flat_map(|p| (0..3).map(move |e| mesh.second_texcoords[p[2 * e] as usize]))
            .collect(),
    };
    set_arrays(gl, vertices.as_ptr().cast(), draw.color_array, arrays);
    set_second_arrays(gl, &second, second_units);
    // SAFETY: a context is current on this thread; `vertices`, `second` and `flags` (one per
    // corner) live until glDrawArrays has read them, and the arrays are disabled after it.
    unsafe {
        gl.EdgeFlagPointer(0, flags.as_ptr().cast());
        gl.EnableClientState(gl::EDGE_FLAG_ARRAY);
        gl.MatrixMode(gl::MODELVIEW);
        gl.LoadMatrixf(draw.modelview.to_cols_array().as_ptr());
        gl.DrawArrays(gl::TRIANGLES, 0, count);
        gl.DisableClientState(gl::EDGE_FLAG_ARRAY);
    }
    end_arrays(gl, arrays.1);
    Ok(())
}

/// Every state of `draw` but its modelview and arrays: the projection, the lights (with the
/// modelview at identity), the materials, the light model, the switches, the texture unit and
/// the replayed calls. Leaves the matrix mode at `GL_MODELVIEW`.
pub(super) fn set_state(
    gl: &Gl,
    draw: &GlDraw,
    max_lights: usize,
    units: &DrawUnits,
) -> Result<(), DrawError> {
    let state = &draw.state;
    // SAFETY: a context is current on this thread; matrices are 16 floats, column-major as
    // both glam and GL store them.
    unsafe {
        gl.PointSize(draw.point_size);
        gl.LineWidth(draw.line_width);
        gl.MatrixMode(gl::PROJECTION);
        gl.LoadMatrixf(draw.projection.to_cols_array().as_ptr());
        // Light positions and spot directions are already in eye space.
        gl.MatrixMode(gl::MODELVIEW);
        gl.LoadIdentity();
    }
    for (index, light) in state.lights.iter().enumerate().take(max_lights) {
        set_light(gl, index, light);
    }

    // Materials first, with COLOR_MATERIAL off so no parameter is tracking the color and every
    // glMaterial call takes effect; then glColorMaterial, then the enable (which, in GL, writes
    // the current color into the tracked parameters).
    set_enabled(gl, gl::COLOR_MATERIAL, false);
    // SAFETY: a context is current on this thread; the color has four components.
    unsafe { gl.Color4fv(state.current_color.to_array().as_ptr()) };
    set_material(gl, gl::FRONT, &state.front);
    set_material(gl, gl::BACK, &state.back);
    let model = &state.model;
    let color_control = match model.color_control {
        ColorControl::SingleColor => gl::SINGLE_COLOR,
        ColorControl::SeparateSpecularColor => gl::SEPARATE_SPECULAR_COLOR,
    };
    let boolean = |on: bool| (if on { gl::TRUE } else { gl::FALSE }) as GLint;
    // SAFETY: a context is current on this thread; the ambient array has four components.
    unsafe {
        gl.ColorMaterial(
            face_enum(state.color_material.face),
            color_material_enum(state.color_material.mode),
        );
        gl.LightModelfv(gl::LIGHT_MODEL_AMBIENT, model.ambient.to_array().as_ptr());
        gl.LightModeli(gl::LIGHT_MODEL_LOCAL_VIEWER, boolean(model.local_viewer));
        gl.LightModeli(gl::LIGHT_MODEL_TWO_SIDE, boolean(model.two_side));
        gl.LightModeli(gl::LIGHT_MODEL_COLOR_CONTROL, color_control as GLint);
        // ffvk's per-fragment mode has no GL counterpart: compare it with SMOOTH.
        gl.ShadeModel(if state.mode == LightingMode::Flat {
            gl::FLAT
        } else {
            gl::SMOOTH
        });
    }
    set_enabled(gl, gl::COLOR_MATERIAL, state.color_material.enabled);
    set_enabled(gl, gl::NORMALIZE, state.normalize);
    set_enabled(gl, gl::RESCALE_NORMAL, state.rescale_normal);
    set_enabled(gl, gl::LIGHTING, state.lighting);
    // Units from the last, so that unit 0 stays active (and client-active) after, as a
    // one-unit program leaves it; only a scene of several units names a unit.
    for unit in (0..units.count).rev() {
        if units.count > 1 {
            // SAFETY: a context is current on this thread; the unit is below
            // GL_MAX_TEXTURE_UNITS (checked by the scene's units) and the coordinates have
            // four components.
            unsafe {
                gl.ActiveTexture(gl::TEXTURE0 + unit as u32);
                gl.MultiTexCoord4fv(
                    gl::TEXTURE0 + unit as u32,
                    state.current_texcoords[unit].to_array().as_ptr(),
                );
            }
        }
        set_texture_unit(
            gl,
            &state.texture_units[unit],
            (
                units.textures[unit].map(|t| t.name()),
                units.cube_maps[unit].map(|t| t.name()),
            ),
        );
    }
    set_stages(gl, state);
    // The raster state the calls may set, at GL's defaults for each draw.
    for cap in [
        gl::POLYGON_OFFSET_FILL,
        gl::POLYGON_OFFSET_LINE,
        gl::POLYGON_OFFSET_POINT,
        gl::BLEND,
        gl::STENCIL_TEST,
        gl::COLOR_LOGIC_OP,
        gl::LINE_STIPPLE,
        gl::CULL_FACE,
        gl::POLYGON_STIPPLE,
    ] {
        set_enabled(gl, cap, false);
    }
    // SAFETY: a context is current on this thread.
    unsafe {
        gl.ColorMask(1, 1, 1, 1);
        gl.BlendColor(0.0, 0.0, 0.0, 0.0);
        gl.PolygonMode(gl::FRONT_AND_BACK, gl::FILL);
        gl.DepthRange(0.0, 1.0);
        gl.DepthMask(1);
        gl.FrontFace(gl::CCW);
    }
    for call in &draw.calls {
        replay(gl, *call);
    }
    check_draw(gl, "from the replayed calls")
}

/// The stages around lighting: the color sum, fog, the alpha test and the user clip planes
/// (stored in eye space already: set with the identity modelview, as the lights are).
fn set_stages(gl: &Gl, state: &ffvk::gl::state::FixedFunctionState) {
    use ffvk::gl::state::{FogHint, FogMode, FogSource};
    let f = &state.fragment;
    let fog = &f.fog;
    // SAFETY: a context is current on this thread; the arrays have the lengths GL reads.
    unsafe {
        gl.Fogi(
            gl::FOG_MODE,
            match fog.mode {
                FogMode::Linear => gl::LINEAR,
                FogMode::Exp => gl::EXP,
                _ => gl::EXP2,
            } as GLint,
        );
        gl.Fogf(gl::FOG_DENSITY, fog.density);
        gl.Fogf(gl::FOG_START, fog.start);
        gl.Fogf(gl::FOG_END, fog.end);
        gl.Fogfv(gl::FOG_COLOR, fog.color.to_array().as_ptr());
        gl.Fogi(
            gl::FOG_COORD_SRC,
            match fog.source {
                FogSource::FogCoord => gl::FOG_COORD,
                _ => gl::FRAGMENT_DEPTH,
            } as GLint,
        );
        gl.FogCoordf(state.current_fog_coord);
        gl.Hint(
            gl::FOG_HINT,
            match fog.hint {
                FogHint::Fastest => gl::FASTEST,
                FogHint::Nicest => gl::NICEST,
                _ => gl::DONT_CARE,
            },
        );
        let c = state.current_secondary_color;
        gl.SecondaryColor3f(c.x, c.y, c.z);
        gl.AlphaFunc(gl::NEVER + f.alpha_test.func.code(), f.alpha_test.reference);
        for (i, p) in state.clip.planes.iter().enumerate() {
            gl.ClipPlane(gl::CLIP_PLANE0 + i as u32, p.as_dvec4().to_array().as_ptr());
        }
    }
    let p = &state.points;
    // SAFETY: as above.
    unsafe {
        gl.PointParameterf(gl::POINT_SIZE_MIN, p.size_min);
        gl.PointParameterf(gl::POINT_SIZE_MAX, p.size_max);
        gl.PointParameterf(gl::POINT_FADE_THRESHOLD_SIZE, p.fade_threshold);
        gl.PointParameterfv(
            gl::POINT_DISTANCE_ATTENUATION,
            p.distance_attenuation.to_array().as_ptr(),
        );
        gl.PointParameteri(
            gl::POINT_SPRITE_COORD_ORIGIN,
            match p.sprite_origin {
                ffvk::gl::state::SpriteOrigin::LowerLeft => gl::LOWER_LEFT,
                _ => gl::UPPER_LEFT,
            } as GLint,
        );
    }
    set_enabled(gl, gl::POINT_SPRITE, p.sprite);
    set_enabled(gl, gl::FOG, fog.enabled);
    set_enabled(gl, gl::COLOR_SUM, f.color_sum);
    set_enabled(gl, gl::ALPHA_TEST, f.alpha_test.enabled);
    for (i, &on) in state.clip.enabled.iter().enumerate() {
        set_enabled(gl, gl::CLIP_PLANE0 + i as u32, on);
    }
}
