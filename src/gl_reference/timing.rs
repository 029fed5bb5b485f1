//! The timing loop ([`time`]) and its frames' GL calls as an application issues them: every
//! state once per frame, then per draw only what changed since the draw before
//! ([`issue_frame`]).

use std::time::Instant;

use glam::Vec4;

use super::bindings::types::{GLenum, GLsizei, GLuint};
use super::bindings::{self as gl, Gl};
use super::draw::{
    begin_frame, check, check_lights, end_arrays, index_count, max_lights, set_arrays, set_light, set_state,
    MeshBuffers,
};
use super::egl::{gl_string, has_extension, version_number};
use super::error::{DrawError, GlError};
use super::texture_object::{upload_textures, DrawUnits, UploadedUnits};
use super::{GlDraw, GlScene, GlTiming};
use ffvk::gl::state::{FixedFunctionState, Material};

/// Draws `scene` `warmup` + `frames` times, timing each frame (see [`super::time_frames`]).
pub(super) fn time(gl: &Gl, scene: &GlScene, warmup: u32, frames: u32) -> Result<GlTiming, GlError> {
    let max_lights = usize::try_from(max_lights(gl)).unwrap_or(0);
    // Buffer objects die (are deleted) before the context, at the end of this function.
    let buffers = scene
        .draws
        .iter()
        .enumerate()
        .map(|(index, d)| MeshBuffers::upload(gl, d.mesh).map_err(|problem| GlError::Draw { index, problem }))
        .collect::<Result<Vec<_>, _>>()?;
    check(gl, || "while uploading the meshes".into())?;
    // Textures too are uploaded once, as ffvk uploads them once.
    let textures = scene
        .draws
        .iter()
        .enumerate()
        .map(|(index, d)| upload_textures(gl, d).map_err(|problem| GlError::Draw { index, problem }))
        .collect::<Result<Vec<_>, _>>()?;
    check(gl, || "while uploading the textures".into())?;
    // What each draw issues, worked out before the first frame is timed.
    let steps = plan(scene, max_lights)?;
    let timer = TimerQuery::new(gl);
    let mut first_frame_ns = 0.0;
    let mut frame_ns = Vec::with_capacity(frames as usize);
    let mut gpu_ns = timer.as_ref().map(|_| Vec::with_capacity(frames as usize));
    for i in 0..warmup + frames {
        let start = Instant::now();
        if let Some(t) = &timer {
            // SAFETY: a context is current on this thread; the query name is live and no
            // other GL_TIME_ELAPSED query is active.
            unsafe { gl.BeginQuery(gl::TIME_ELAPSED, t.name) };
        }
        begin_frame(gl, scene);
        issue_frame(gl, scene, (max_lights, &steps), &buffers, &textures)?;
        if timer.is_some() {
            // SAFETY: a context is current; ends the query begun above.
            unsafe { gl.EndQuery(gl::TIME_ELAPSED) };
        }
        // SAFETY: a context is current on this thread.
        unsafe { gl.Finish() };
        let ns = start.elapsed().as_nanos() as f64;
        check(gl, || format!("in frame {i}"))?;
        if i == 0 {
            first_frame_ns = ns;
        } else if i >= warmup {
            frame_ns.push(ns);
            if let (Some(t), Some(gpu)) = (&timer, gpu_ns.as_mut()) {
                gpu.push(t.result() as f64);
            }
        }
    }
    check(gl, || "reading the timer queries".into())?;
    Ok(GlTiming {
        first_frame_ns,
        frame_ns,
        gpu_ns,
    })
}

/// A GL_TIME_ELAPSED query object, where the context has timer queries (GL 3.3 or
/// GL_ARB_timer_query); deleted when dropped.
struct TimerQuery<'g> {
    gl: &'g Gl,
    name: GLuint,
}

impl<'g> TimerQuery<'g> {
    fn new(gl: &'g Gl) -> Option<Self> {
        let version = version_number(&gl_string(gl, gl::VERSION).unwrap_or_default());
        let listed = || gl_string(gl, gl::EXTENSIONS).is_ok_and(|e| has_extension(&e, "GL_ARB_timer_query"));
        if !gl.GetQueryObjectui64v.is_loaded() || !(version >= (3, 3) || listed()) {
            return None;
        }
        let mut name = 0;
        // SAFETY: a context is current on this thread; one name is written.
        unsafe { gl.GenQueries(1, &mut name) };
        Some(TimerQuery { gl, name })
    }

    /// The last query's nanoseconds (waits for it: called after glFinish).
    fn result(&self) -> u64 {
        let mut ns = 0u64;
        // SAFETY: a context is current; the query has ended; one GLuint64 is written.
        unsafe { self.gl.GetQueryObjectui64v(self.name, gl::QUERY_RESULT, &mut ns) };
        ns
    }
}

impl Drop for TimerQuery<'_> {
    fn drop(&mut self) {
        // SAFETY: the name was made by glGenQueries in the context still current here.
        unsafe { self.gl.DeleteQueries(1, &self.name) };
    }
}

/// What one draw of a timed frame issues before its `glLoadMatrix` and `glDrawElements`,
/// worked out once before the frames ([`plan`]): an application knows what it changes between
/// objects, it does not compare states while it draws.
pub(super) struct Step {
    /// Every state ([`set_state`]), or only the changes from the draw before.
    state: Option<Changes>,
    /// `glDrawElements`' count.
    count: GLsizei,
}

/// The calls that take one draw's state to the next's when only what an application changes
/// between objects differs.
struct Changes {
    /// Lights whose parameters changed (set with the modelview at identity).
    lights: Vec<usize>,
    /// `glMaterialfv` calls: face, parameter, value.
    materials: Vec<(GLenum, GLenum, [f32; 4])>,
    /// `glMaterialf(face, GL_SHININESS, value)` calls.
    shininess: Vec<(GLenum, f32)>,
    /// `glColor4fv`, when the current color changed.
    color: Option<Vec4>,
}

/// The steps of `scene`'s draws: the first sets every state; every later one only what
/// differs from the draw before it ([`changes`]), or every state when more than an
/// application's per-object calls differ. Fails on a draw GL cannot draw (too many lights, too
/// many indices), before anything is timed.
pub(super) fn plan(scene: &GlScene, max_lights: usize) -> Result<Vec<Step>, GlError> {
    let mut steps = Vec::with_capacity(scene.draws.len());
    let mut before: Option<&GlDraw> = None;
    for (index, draw) in scene.draws.iter().enumerate() {
        let at = |problem| GlError::Draw { index, problem };
        check_lights(&draw.state, max_lights).map_err(at)?;
        if draw.second_texcoords & 0b1110 != 0 {
            return Err(at(DrawError::SecondTexcoordsTimed));
        }
        steps.push(Step {
            state: before.and_then(|prev| changes(prev, draw, max_lights)),
            count: index_count(draw).map_err(at)?,
        });
        before = Some(draw);
    }
    Ok(steps)
}

/// A timed frame's calls as an application issues them, by `steps` ([`plan`]): the first draw
/// sets every state (the projection, the lights after the view matrix, here the identity since
/// their positions are in eye space, the light model, the switches and the materials); a later
/// draw issues only what changed: a `glMaterial` per changed parameter, `glColor`, the lights
/// that changed; then its `glLoadMatrix`, its arrays when its buffers differ, and
/// `glDrawElements`.
pub(super) fn issue_frame(
    gl: &Gl,
    scene: &GlScene,
    (max_lights, steps): (usize, &[Step]),
    buffers: &[MeshBuffers],
    textures: &[UploadedUnits],
) -> Result<(), GlError> {
    let units = scene.units_used();
    let mut bound: Option<[GLuint; 2]> = None;
    for (index, (((draw, b), t), step)) in scene
        .draws
        .iter()
        .zip(buffers)
        .zip(textures)
        .zip(steps)
        .enumerate()
    {
        match &step.state {
            Some(changes) => issue_changes(gl, draw, changes),
            None => set_state(gl, draw, max_lights, &DrawUnits::of(t, units))
                .map_err(|problem| GlError::Draw { index, problem })?,
        }
        // A draw's buffer objects are bound when they differ from the draw before's.
        if bound != Some(b.names) {
            bound = Some(b.names);
            // SAFETY: a context is current on this thread; both names are buffers it made.
            unsafe {
                gl.BindBuffer(gl::ARRAY_BUFFER, b.names[0]);
                gl.BindBuffer(gl::ELEMENT_ARRAY_BUFFER, b.names[1]);
            }
            let arrays = DrawUnits::of(t, units).texcoord_arrays(draw.mesh_texcoords);
            set_arrays(gl, std::ptr::null(), draw.color_array, (arrays, units));
        }
        if step.count > 0 {
            // SAFETY: a context is current; the modelview is 16 floats, column-major; the bound
            // buffers hold the mesh, whose indices were checked when they were uploaded.
            unsafe {
                gl.LoadMatrixf(draw.modelview.to_cols_array().as_ptr());
                gl.DrawElements(draw.mode.gl(), step.count, gl::UNSIGNED_INT, std::ptr::null());
            }
        }
    }
    end_arrays(gl, units);
    Ok(())
}

/// Issues `changes` for `draw`, leaving the matrix mode at `GL_MODELVIEW`.
fn issue_changes(gl: &Gl, draw: &GlDraw, changes: &Changes) {
    if !changes.lights.is_empty() {
        // SAFETY: a context is current on this thread.
        unsafe { gl.LoadIdentity() };
        for &i in &changes.lights {
            set_light(gl, i, &draw.state.lights[i]);
        }
    }
    for (face, name, value) in &changes.materials {
        // SAFETY: a context is current on this thread; the value has four components.
        unsafe { gl.Materialfv(*face, *name, value.as_ptr()) };
    }
    for &(face, value) in &changes.shininess {
        // SAFETY: a context is current on this thread.
        unsafe { gl.Materialf(face, gl::SHININESS, value) };
    }
    if let Some(color) = changes.color {
        // SAFETY: a context is current on this thread; the color has four components.
        unsafe { gl.Color4fv(color.to_array().as_ptr()) };
    }
}

/// The calls that take `prev`'s state to `draw`'s when only what an application changes
/// between objects differs (materials, the current color, lights; with `GL_COLOR_MATERIAL` off,
/// no replayed calls and the same texture, projection and everything else); `None` when
/// something else differs.
fn changes(prev: &GlDraw, draw: &GlDraw, max_lights: usize) -> Option<Changes> {
    let (a, b) = (&prev.state, &draw.state);
    let rest = |s: &FixedFunctionState| {
        let mut rest = *s;
        rest.lights = FixedFunctionState::default().lights;
        (rest.front, rest.back) = (Material::default(), Material::default());
        rest.current_color = Vec4::ONE;
        rest
    };
    let same_rest = rest(a) == rest(b)
        && prev.projection == draw.projection
        && prev.calls.is_empty()
        && draw.calls.is_empty()
        && prev.textures.iter().all(Option::is_none)
        && draw.textures.iter().all(Option::is_none)
        && (prev.color_array, prev.point_size, prev.line_width)
            == (draw.color_array, draw.point_size, draw.line_width);
    if !same_rest || a.color_material.enabled || b.color_material.enabled {
        return None;
    }
    let (materials, shininess) = material_changes((&a.front, &a.back), (&b.front, &b.back));
    Some(Changes {
        lights: (0..max_lights.min(a.lights.len()))
            .filter(|&i| a.lights[i] != b.lights[i])
            .collect(),
        materials,
        shininess,
        color: (a.current_color != b.current_color).then_some(b.current_color),
    })
}

/// The `glMaterial` calls for each parameter of either face that changed: one
/// `GL_FRONT_AND_BACK` call where both faces change to the same value, as an application sets a
/// one-sided material.
#[allow(clippy::type_complexity)]
fn material_changes(
    (front_a, back_a): (&Material, &Material),
    (front_b, back_b): (&Material, &Material),
) -> (Vec<(GLenum, GLenum, [f32; 4])>, Vec<(GLenum, f32)>) {
    let vectors = |m: &Material| [m.ambient, m.diffuse, m.specular, m.emission];
    let names = [gl::AMBIENT, gl::DIFFUSE, gl::SPECULAR, gl::EMISSION];
    let faces = |front: bool, back: bool, same: bool| match (front, back) {
        (true, true) if same => vec![gl::FRONT_AND_BACK],
        (true, true) => vec![gl::FRONT, gl::BACK],
        (true, false) => vec![gl::FRONT],
        (false, true) => vec![gl::BACK],
        (false, false) => vec![],
    };
    let mut materials = Vec::new();
    for (i, name) in names.into_iter().enumerate() {
        let (fa, ba, fb, bb) = (
            vectors(front_a)[i],
            vectors(back_a)[i],
            vectors(front_b)[i],
            vectors(back_b)[i],
        );
        for face in faces(fa != fb, ba != bb, fb == bb) {
            let value = if face == gl::BACK { bb } else { fb };
            materials.push((face, name, value.to_array()));
        }
    }
    let (sa, sb) = (
        (front_a.shininess, back_a.shininess),
        (front_b.shininess, back_b.shininess),
    );
    let shininess = faces(sa.0 != sb.0, sa.1 != sb.1, sb.0 == sb.1)
        .into_iter()
        .map(|face| (face, if face == gl::BACK { sb.1 } else { sb.0 }))
        .collect();
    (materials, shininess)
}
