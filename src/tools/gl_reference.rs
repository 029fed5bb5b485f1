//! Mesa's fixed-function OpenGL through OSMesa: the reference renderer of the conformance
//! tests and the anchor of `ffvk bench` (cargo feature `osmesa`, Debian's libosmesa6-dev).
//!
//! It maps a [`LightingState`] onto the legacy GL entry points one to one (glLight, glMaterial,
//! glLightModel, glColorMaterial, glShadeModel, glEnable) and lets Mesa evaluate the lighting.
//!
//! Every call creates its own OSMesa context, renders into its own buffer and destroys the
//! context, all on the calling thread. Calls are serialized by a process-wide lock so that
//! threads (parallel tests, for one) never drive Mesa concurrently.

use std::ffi::{c_void, CStr};
use std::os::raw::{c_char, c_int, c_uchar, c_uint};
use std::sync::Mutex;

use std::time::Instant;

use glam::{Mat4, Vec4};

use crate::gl::state::{
    Cap, ColorControl, ColorMaterialMode, Face, Light, LightingMode, LightingState, Material,
};
use crate::mesh::{MeshData, Vertex};
use crate::tools::{Error, Result};

/// Errors inside this module are messages; the public entry points wrap them in [`Error::Gl`].
type GlResult<T> = std::result::Result<T, String>;

/// One frame: a cleared framebuffer and the draws, in order.
pub struct GlScene<'a> {
    pub width: u32,
    pub height: u32,
    pub clear_color: [f32; 4],
    pub depth_test: bool,
    pub draws: Vec<GlDraw<'a>>,
}

/// One draw call: a triangle list with the matrices and lighting state in force for it.
pub struct GlDraw<'a> {
    /// Triangle list, counter-clockwise front, per-vertex position, normal and color.
    pub mesh: &'a MeshData,
    /// GL modelview for this draw.
    pub modelview: Mat4,
    /// GL projection (GL clip space, z in [-w, w]).
    pub projection: Mat4,
    /// Lighting state; light positions and spot directions are already in eye space. Its
    /// current color is GL's current color when the draw starts (`glColor4fv`, before the
    /// materials and the `GL_COLOR_MATERIAL` enable).
    pub state: LightingState,
    /// Whether the mesh's colors are a color array; `false` draws with GL's current color.
    pub color_array: bool,
    /// GL calls made after the state is set and before the draw, so that GL's own rules
    /// (the current color, color-material tracking and write-back) apply to them.
    pub calls: Vec<GlCall>,
}

impl<'a> GlDraw<'a> {
    /// A draw of `mesh` with its color array and no extra calls.
    pub fn new(mesh: &'a MeshData, modelview: Mat4, projection: Mat4, state: LightingState) -> Self {
        GlDraw {
            mesh,
            modelview,
            projection,
            state,
            color_array: true,
            calls: Vec::new(),
        }
    }
}

/// A GL call replayed before a draw ([`GlDraw::calls`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GlCall {
    /// `glColor4f`.
    Color(Vec4),
    /// `glEnable`.
    Enable(Cap),
    /// `glDisable`.
    Disable(Cap),
    /// `glColorMaterial`.
    ColorMaterial(Face, ColorMaterialMode),
}

/// What the OSMesa context reports about itself.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GlInfo {
    pub version: String,
    pub renderer: String,
    pub vendor: String,
    pub max_lights: i32,
    /// How the context was made: `OSMesaCreateContextAttribs` (compatibility profile) or
    /// the `OSMesaCreateContextExt` fallback.
    pub created_with: &'static str,
}

// ---------------------------------------------------------------------------------------------
// The C interface: only what this module calls.

type GLenum = c_uint;
type GLint = c_int;
type GLsizei = c_int;
type GLfloat = f32;
type GLclampf = f32;
type GLbitfield = c_uint;
type GLboolean = c_uchar;
type GLuint = c_uint;
type GLsizeiptr = isize;

#[repr(C)]
struct OsMesaContextOpaque {
    _private: [u8; 0],
}
type OsMesaContext = *mut OsMesaContextOpaque;

const OSMESA_RGBA: GLenum = 0x1908;
const OSMESA_FORMAT: c_int = 0x22;
const OSMESA_DEPTH_BITS: c_int = 0x30;
const OSMESA_STENCIL_BITS: c_int = 0x31;
const OSMESA_ACCUM_BITS: c_int = 0x32;
const OSMESA_PROFILE: c_int = 0x33;
const OSMESA_COMPAT_PROFILE: c_int = 0x35;
const OSMESA_CONTEXT_MAJOR_VERSION: c_int = 0x36;
const OSMESA_CONTEXT_MINOR_VERSION: c_int = 0x37;

const GL_NO_ERROR: GLenum = 0;
const GL_FALSE: GLint = 0;
const GL_TRUE: GLint = 1;
const GL_TRIANGLES: GLenum = 0x0004;
const GL_LESS: GLenum = 0x0201;
const GL_FRONT: GLenum = 0x0404;
const GL_BACK: GLenum = 0x0405;
const GL_FRONT_AND_BACK: GLenum = 0x0408;
const GL_CCW: GLenum = 0x0901;
const GL_CULL_FACE: GLenum = 0x0B44;
const GL_LIGHTING: GLenum = 0x0B50;
const GL_LIGHT_MODEL_LOCAL_VIEWER: GLenum = 0x0B51;
const GL_LIGHT_MODEL_TWO_SIDE: GLenum = 0x0B52;
const GL_LIGHT_MODEL_AMBIENT: GLenum = 0x0B53;
const GL_COLOR_MATERIAL: GLenum = 0x0B57;
const GL_DEPTH_TEST: GLenum = 0x0B71;
const GL_NORMALIZE: GLenum = 0x0BA1;
const GL_BLEND: GLenum = 0x0BE2;
const GL_DITHER: GLenum = 0x0BD0;
const GL_PACK_ALIGNMENT: GLenum = 0x0D05;
const GL_MAX_LIGHTS: GLenum = 0x0D31;
const GL_UNSIGNED_BYTE: GLenum = 0x1401;
const GL_UNSIGNED_INT: GLenum = 0x1405;
const GL_FLOAT: GLenum = 0x1406;
const GL_AMBIENT: GLenum = 0x1200;
const GL_DIFFUSE: GLenum = 0x1201;
const GL_SPECULAR: GLenum = 0x1202;
const GL_POSITION: GLenum = 0x1203;
const GL_SPOT_DIRECTION: GLenum = 0x1204;
const GL_SPOT_EXPONENT: GLenum = 0x1205;
const GL_SPOT_CUTOFF: GLenum = 0x1206;
const GL_CONSTANT_ATTENUATION: GLenum = 0x1207;
const GL_LINEAR_ATTENUATION: GLenum = 0x1208;
const GL_QUADRATIC_ATTENUATION: GLenum = 0x1209;
const GL_EMISSION: GLenum = 0x1600;
const GL_SHININESS: GLenum = 0x1601;
const GL_AMBIENT_AND_DIFFUSE: GLenum = 0x1602;
const GL_MODELVIEW: GLenum = 0x1700;
const GL_PROJECTION: GLenum = 0x1701;
const GL_RGBA: GLenum = 0x1908;
const GL_FLAT: GLenum = 0x1D00;
const GL_SMOOTH: GLenum = 0x1D01;
const GL_VENDOR: GLenum = 0x1F00;
const GL_RENDERER: GLenum = 0x1F01;
const GL_VERSION: GLenum = 0x1F02;
const GL_LIGHT0: GLenum = 0x4000;
const GL_VERTEX_ARRAY: GLenum = 0x8074;
const GL_NORMAL_ARRAY: GLenum = 0x8075;
const GL_COLOR_ARRAY: GLenum = 0x8076;
const GL_RESCALE_NORMAL: GLenum = 0x803A;
const GL_LIGHT_MODEL_COLOR_CONTROL: GLenum = 0x81F8;
const GL_SINGLE_COLOR: GLenum = 0x81F9;
const GL_SEPARATE_SPECULAR_COLOR: GLenum = 0x81FA;
const GL_ARRAY_BUFFER: GLenum = 0x8892;
const GL_ELEMENT_ARRAY_BUFFER: GLenum = 0x8893;
const GL_STATIC_DRAW: GLenum = 0x88E4;
const GL_DEPTH_BUFFER_BIT: GLbitfield = 0x0000_0100;
const GL_COLOR_BUFFER_BIT: GLbitfield = 0x0000_4000;

// libOSMesa exports the gl* entry points as well as the OSMesa* ones.
#[link(name = "OSMesa")]
extern "C" {
    fn OSMesaCreateContextAttribs(attrib_list: *const c_int, sharelist: OsMesaContext) -> OsMesaContext;
    fn OSMesaCreateContextExt(
        format: GLenum,
        depth_bits: GLint,
        stencil_bits: GLint,
        accum_bits: GLint,
        sharelist: OsMesaContext,
    ) -> OsMesaContext;
    fn OSMesaMakeCurrent(
        ctx: OsMesaContext,
        buffer: *mut c_void,
        kind: GLenum,
        width: GLsizei,
        height: GLsizei,
    ) -> GLboolean;
    fn OSMesaDestroyContext(ctx: OsMesaContext);

    fn glGetError() -> GLenum;
    fn glGetString(name: GLenum) -> *const c_uchar;
    fn glGetIntegerv(pname: GLenum, params: *mut GLint);
    fn glEnable(cap: GLenum);
    fn glDisable(cap: GLenum);
    fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei);
    fn glClearColor(r: GLclampf, g: GLclampf, b: GLclampf, a: GLclampf);
    fn glClearDepth(depth: f64);
    fn glClear(mask: GLbitfield);
    fn glDepthFunc(func: GLenum);
    fn glFrontFace(mode: GLenum);
    fn glShadeModel(mode: GLenum);
    fn glMatrixMode(mode: GLenum);
    fn glLoadIdentity();
    fn glLoadMatrixf(m: *const GLfloat);
    fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat);
    fn glLightf(light: GLenum, pname: GLenum, param: GLfloat);
    fn glLightModelfv(pname: GLenum, params: *const GLfloat);
    fn glLightModeli(pname: GLenum, param: GLint);
    fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat);
    fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat);
    fn glColorMaterial(face: GLenum, mode: GLenum);
    fn glEnableClientState(array: GLenum);
    fn glDisableClientState(array: GLenum);
    fn glVertexPointer(size: GLint, kind: GLenum, stride: GLsizei, pointer: *const c_void);
    fn glNormalPointer(kind: GLenum, stride: GLsizei, pointer: *const c_void);
    fn glColorPointer(size: GLint, kind: GLenum, stride: GLsizei, pointer: *const c_void);
    fn glColor4fv(v: *const GLfloat);
    fn glDrawElements(mode: GLenum, count: GLsizei, kind: GLenum, indices: *const c_void);
    fn glPixelStorei(pname: GLenum, param: GLint);
    fn glReadPixels(
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        kind: GLenum,
        pixels: *mut c_void,
    );
    fn glFinish();
    fn glGenBuffers(n: GLsizei, buffers: *mut GLuint);
    fn glDeleteBuffers(n: GLsizei, buffers: *const GLuint);
    fn glBindBuffer(target: GLenum, buffer: GLuint);
    fn glBufferData(target: GLenum, size: GLsizeiptr, data: *const c_void, usage: GLenum);
}

// ---------------------------------------------------------------------------------------------
// The context: created, made current on this thread, and always released and destroyed.

/// Serializes every use of OSMesa in this process (see the module documentation).
static OSMESA_LOCK: Mutex<()> = Mutex::new(());

/// An OSMesa context current on the calling thread, bound to its own RGBA8 color buffer.
/// Dropping it unbinds and destroys the context (before the buffer is freed).
struct Context {
    ctx: OsMesaContext,
    created_with: &'static str,
    /// OSMesa renders into this buffer; it must outlive the binding, and never reallocates.
    _buffer: Vec<u8>,
}

impl Context {
    fn new(width: u32, height: u32) -> GlResult<Context> {
        if width == 0 || height == 0 {
            return Err(format!("OSMesa: framebuffer size {width}x{height} is empty"));
        }
        let w = GLsizei::try_from(width).map_err(|_| format!("OSMesa: width {width} is too large"))?;
        let h = GLsizei::try_from(height).map_err(|_| format!("OSMesa: height {height} is too large"))?;
        let bytes = (width as usize)
            .checked_mul(height as usize)
            .and_then(|n| n.checked_mul(4))
            .ok_or_else(|| format!("OSMesa: framebuffer size {width}x{height} is too large"))?;

        // A compatibility profile keeps the fixed-function pipeline; ask for at least 2.1.
        let attribs: [c_int; 15] = [
            OSMESA_FORMAT,
            OSMESA_RGBA as c_int,
            OSMESA_DEPTH_BITS,
            24,
            OSMESA_STENCIL_BITS,
            0,
            OSMESA_ACCUM_BITS,
            0,
            OSMESA_PROFILE,
            OSMESA_COMPAT_PROFILE,
            OSMESA_CONTEXT_MAJOR_VERSION,
            2,
            OSMESA_CONTEXT_MINOR_VERSION,
            1,
            0,
        ];
        // SAFETY: the attribute list is zero-terminated; no context is shared.
        let mut ctx = unsafe { OSMesaCreateContextAttribs(attribs.as_ptr(), std::ptr::null_mut()) };
        let mut created_with = "OSMesaCreateContextAttribs (compatibility profile, >= 2.1)";
        if ctx.is_null() {
            // SAFETY: plain constructor call; a null result is handled below.
            ctx = unsafe { OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, std::ptr::null_mut()) };
            created_with = "OSMesaCreateContextExt (RGBA, 24-bit depth)";
        }
        if ctx.is_null() {
            return Err(
                "OSMesa: could not create a context (OSMesaCreateContextAttribs and \
                        OSMesaCreateContextExt both returned NULL)"
                    .to_string(),
            );
        }
        let mut context = Context {
            ctx,
            created_with,
            _buffer: vec![0u8; bytes],
        };
        let buffer = context._buffer.as_mut_ptr().cast::<c_void>();
        // SAFETY: the buffer holds width * height RGBA8 pixels and lives as long as `context`,
        // whose Drop unbinds the context before the buffer is freed.
        let ok = unsafe { OSMesaMakeCurrent(context.ctx, buffer, GL_UNSIGNED_BYTE, w, h) };
        if ok == 0 {
            // `context` drops here and destroys the context.
            return Err(format!(
                "OSMesa: OSMesaMakeCurrent failed for a {width}x{height} RGBA8 buffer"
            ));
        }
        Ok(context)
    }

    fn info(&self) -> GlResult<GlInfo> {
        let mut max_lights: GLint = 0;
        // SAFETY: this context is current on this thread; one GLint is written.
        unsafe { glGetIntegerv(GL_MAX_LIGHTS, &mut max_lights) };
        Ok(GlInfo {
            version: gl_string(GL_VERSION)?,
            renderer: gl_string(GL_RENDERER)?,
            vendor: gl_string(GL_VENDOR)?,
            max_lights,
            created_with: self.created_with,
        })
    }
}

impl Drop for Context {
    fn drop(&mut self) {
        // SAFETY: `ctx` was created by OSMesa and is destroyed exactly once; a NULL context
        // unbinds whatever is current on this thread, so nothing refers to it afterwards.
        unsafe {
            OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
            OSMesaDestroyContext(self.ctx);
        }
    }
}

/// Takes the global OSMesa lock; a panic in another test while it held the lock does not
/// leave GL state behind (each call has its own context), so a poisoned lock is still usable.
fn lock() -> std::sync::MutexGuard<'static, ()> {
    OSMESA_LOCK
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

fn gl_string(name: GLenum) -> GlResult<String> {
    // SAFETY: a context is current; glGetString returns a static NUL-terminated string or NULL.
    let s = unsafe { glGetString(name) };
    if s.is_null() {
        return Err(format!("glGetString(0x{name:04X}) returned NULL"));
    }
    // SAFETY: non-NULL, NUL-terminated, owned by the GL implementation.
    let text = unsafe { CStr::from_ptr(s.cast::<c_char>()) };
    Ok(text.to_string_lossy().into_owned())
}

/// Returns Err naming `what` if GL has recorded an error (draining every pending error flag).
fn check_gl_error(what: &str) -> GlResult<()> {
    let mut codes = Vec::new();
    loop {
        // SAFETY: a context is current on this thread.
        let code = unsafe { glGetError() };
        if code == GL_NO_ERROR || codes.len() >= 16 {
            break;
        }
        codes.push(format!("0x{code:04X}"));
    }
    if codes.is_empty() {
        Ok(())
    } else {
        Err(format!("GL error {} {what}", codes.join(", ")))
    }
}

// ---------------------------------------------------------------------------------------------
// Public entry points.

/// Reports GL_VERSION, GL_RENDERER, GL_VENDOR and GL_MAX_LIGHTS of the context
/// [`render_gl`] uses.
pub fn gl_info() -> Result<GlInfo> {
    let _guard = lock();
    let context = Context::new(1, 1).map_err(Error::Gl)?;
    context.info().map_err(Error::Gl)
}

/// Renders `scene` with Mesa's fixed-function OpenGL and returns the color buffer, row 0 at
/// the top of the view.
pub fn render_gl(scene: &GlScene) -> Result<image::RgbaImage> {
    let _guard = lock();
    let context = Context::new(scene.width, scene.height).map_err(Error::Gl)?;
    let result = render_current(scene);
    drop(context);
    result.map_err(Error::Gl)
}

/// Host times of [`time_frames`], in nanoseconds.
#[derive(Debug, Clone, PartialEq)]
pub struct GlTiming {
    /// The first warm-up frame: Mesa builds and compiles its fixed-function shaders for the
    /// state then.
    pub first_frame_ns: f64,
    /// Each measured frame: clear, state and draw calls, then glFinish.
    pub frame_ns: Vec<f64>,
}

/// Draws `scene` `warmup` + `frames` times in one context and times each frame on the host
/// clock, from the clear to the return of glFinish (which waits for llvmpipe's rasterizer
/// threads). Meshes are uploaded once into buffer objects first, as ffvk uploads them once,
/// so that frames do not copy client arrays. `warmup` must be at least 1.
pub fn time_frames(scene: &GlScene, warmup: u32, frames: u32) -> Result<GlTiming> {
    if warmup == 0 {
        return Err(Error::Gl("time_frames needs at least one warm-up frame".into()));
    }
    let _guard = lock();
    let context = Context::new(scene.width, scene.height).map_err(Error::Gl)?;
    let result = time_current(scene, warmup, frames);
    drop(context);
    result.map_err(Error::Gl)
}

fn time_current(scene: &GlScene, warmup: u32, frames: u32) -> GlResult<GlTiming> {
    let mut max_lights: GLint = 0;
    // SAFETY: a context is current on this thread; one GLint is written.
    unsafe { glGetIntegerv(GL_MAX_LIGHTS, &mut max_lights) };
    let max_lights = usize::try_from(max_lights).unwrap_or(0);
    // Buffer objects die (are deleted) before the context, at the end of this function.
    let buffers = scene
        .draws
        .iter()
        .map(|d| MeshBuffers::upload(d.mesh))
        .collect::<GlResult<Vec<_>>>()?;
    check_gl_error("while uploading the meshes")?;
    let mut first_frame_ns = 0.0;
    let mut frame_ns = Vec::with_capacity(frames as usize);
    for i in 0..warmup + frames {
        let start = Instant::now();
        begin_frame(scene);
        for (index, (draw, b)) in scene.draws.iter().zip(&buffers).enumerate() {
            draw_one(draw, max_lights, Arrays::Buffers(b)).map_err(|e| format!("draw {index}: {e}"))?;
        }
        // SAFETY: a context is current on this thread.
        unsafe { glFinish() };
        let ns = start.elapsed().as_nanos() as f64;
        check_gl_error(&format!("in frame {i}"))?;
        if i == 0 {
            first_frame_ns = ns;
        } else if i >= warmup {
            frame_ns.push(ns);
        }
    }
    Ok(GlTiming {
        first_frame_ns,
        frame_ns,
    })
}

/// A mesh in a vertex and an index buffer object of the current context.
struct MeshBuffers {
    vertices: GLuint,
    indices: GLuint,
}

impl MeshBuffers {
    fn upload(mesh: &MeshData) -> GlResult<MeshBuffers> {
        check_indices(mesh)?;
        let vertex_bytes: &[u8] = bytemuck::cast_slice(&mesh.vertices);
        let index_bytes: &[u8] = bytemuck::cast_slice(&mesh.indices);
        let size = |bytes: &[u8]| {
            GLsizeiptr::try_from(bytes.len())
                .map_err(|_| format!("{} bytes are too many for a buffer", bytes.len()))
        };
        let (vertex_size, index_size) = (size(vertex_bytes)?, size(index_bytes)?);
        let mut names: [GLuint; 2] = [0; 2];
        // SAFETY: a context is current on this thread; glGenBuffers writes two names, and
        // glBufferData copies `size` bytes from slices that are at least that long.
        unsafe {
            glGenBuffers(2, names.as_mut_ptr());
            glBindBuffer(GL_ARRAY_BUFFER, names[0]);
            glBufferData(
                GL_ARRAY_BUFFER,
                vertex_size,
                vertex_bytes.as_ptr().cast(),
                GL_STATIC_DRAW,
            );
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, names[1]);
            glBufferData(
                GL_ELEMENT_ARRAY_BUFFER,
                index_size,
                index_bytes.as_ptr().cast(),
                GL_STATIC_DRAW,
            );
            glBindBuffer(GL_ARRAY_BUFFER, 0);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        }
        Ok(MeshBuffers {
            vertices: names[0],
            indices: names[1],
        })
    }
}

impl Drop for MeshBuffers {
    fn drop(&mut self) {
        let names = [self.vertices, self.indices];
        // SAFETY: the context that made the names is current (MeshBuffers never outlive
        // `time_current`, which runs inside its context).
        unsafe { glDeleteBuffers(2, names.as_ptr()) };
    }
}

/// Where a draw's vertex and index arrays are.
#[derive(Clone, Copy)]
enum Arrays<'a> {
    /// In the mesh's own memory (client arrays).
    Client,
    /// In buffer objects of the current context.
    Buffers(&'a MeshBuffers),
}

/// Every index of `mesh` within its vertices.
fn check_indices(mesh: &MeshData) -> GlResult<()> {
    let count = mesh.triangle_count() * 3;
    match mesh.indices[..count]
        .iter()
        .find(|&&i| i as usize >= mesh.vertices.len())
    {
        Some(&bad) => Err(format!(
            "index {bad} is out of range for a mesh of {} vertices",
            mesh.vertices.len()
        )),
        None => Ok(()),
    }
}

/// Viewport, clear and the per-frame fixed state.
fn begin_frame(scene: &GlScene) {
    // SAFETY: a context is current on this thread.
    unsafe {
        glViewport(0, 0, scene.width as GLsizei, scene.height as GLsizei);
        let [r, g, b, a] = scene.clear_color;
        glClearColor(r, g, b, a);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if scene.depth_test {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
        } else {
            glDisable(GL_DEPTH_TEST);
        }
        glFrontFace(GL_CCW);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        // Dithering is on by default in GL; the Vulkan side never dithers.
        glDisable(GL_DITHER);
    }
}

/// Renders with the context that is current on this thread.
fn render_current(scene: &GlScene) -> GlResult<image::RgbaImage> {
    let (width, height) = (scene.width, scene.height);
    let mut max_lights: GLint = 0;
    // SAFETY: a context is current on this thread; one GLint is written.
    unsafe { glGetIntegerv(GL_MAX_LIGHTS, &mut max_lights) };
    begin_frame(scene);
    check_gl_error("while setting up the framebuffer")?;
    let max_lights = usize::try_from(max_lights).unwrap_or(0);

    for (index, draw) in scene.draws.iter().enumerate() {
        draw_one(draw, max_lights, Arrays::Client).map_err(|e| format!("draw {index}: {e}"))?;
        check_gl_error(&format!("after draw {index}"))?;
    }

    let mut pixels = vec![0u8; width as usize * height as usize * 4];
    // SAFETY: `pixels` holds exactly width * height RGBA8 pixels with no row padding
    // (PACK_ALIGNMENT 1).
    unsafe {
        glFinish();
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(
            0,
            0,
            width as GLsizei,
            height as GLsizei,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            pixels.as_mut_ptr().cast::<c_void>(),
        );
    }
    check_gl_error("from glReadPixels")?;

    // glReadPixels returns the bottom row first; the image wants the top row first.
    let row = width as usize * 4;
    let mut flipped = Vec::with_capacity(pixels.len());
    for y in (0..height as usize).rev() {
        flipped.extend_from_slice(&pixels[y * row..(y + 1) * row]);
    }
    image::RgbaImage::from_raw(width, height, flipped)
        .ok_or_else(|| "internal error: readback size does not match the image".to_string())
}

/// Makes one replayed call.
fn replay(call: GlCall) {
    let cap_enum = |cap: Cap| match cap {
        Cap::Lighting => GL_LIGHTING,
        Cap::Light(i) => GL_LIGHT0 + i as GLenum,
        Cap::ColorMaterial => GL_COLOR_MATERIAL,
        Cap::Normalize => GL_NORMALIZE,
        Cap::RescaleNormal => GL_RESCALE_NORMAL,
    };
    match call {
        // SAFETY: a context is current on this thread; the color has four components.
        GlCall::Color(c) => unsafe { glColor4fv(c.to_array().as_ptr()) },
        GlCall::Enable(cap) => set_enabled(cap_enum(cap), true),
        GlCall::Disable(cap) => set_enabled(cap_enum(cap), false),
        // SAFETY: a context is current on this thread.
        GlCall::ColorMaterial(face, mode) => unsafe {
            glColorMaterial(face_enum(face), color_material_enum(mode))
        },
    }
}

fn face_enum(face: Face) -> GLenum {
    match face {
        Face::Front => GL_FRONT,
        Face::Back => GL_BACK,
        Face::FrontAndBack => GL_FRONT_AND_BACK,
    }
}

fn color_material_enum(mode: ColorMaterialMode) -> GLenum {
    match mode {
        ColorMaterialMode::Emission => GL_EMISSION,
        ColorMaterialMode::Ambient => GL_AMBIENT,
        ColorMaterialMode::Diffuse => GL_DIFFUSE,
        ColorMaterialMode::Specular => GL_SPECULAR,
        ColorMaterialMode::AmbientAndDiffuse => GL_AMBIENT_AND_DIFFUSE,
    }
}

fn set_enabled(cap: GLenum, on: bool) {
    // SAFETY: a context is current on this thread.
    unsafe {
        if on {
            glEnable(cap)
        } else {
            glDisable(cap)
        }
    }
}

/// glLight for every parameter of light `index`, with the MODELVIEW matrix at identity so the
/// eye-space position and spot direction are stored unchanged.
fn set_light(index: usize, light: &Light) {
    let id = GL_LIGHT0 + index as GLenum;
    let spot = light.spot_direction.to_array();
    // SAFETY: a context is current on this thread; every array has the length GL reads.
    unsafe {
        glLightfv(id, GL_AMBIENT, light.ambient.to_array().as_ptr());
        glLightfv(id, GL_DIFFUSE, light.diffuse.to_array().as_ptr());
        glLightfv(id, GL_SPECULAR, light.specular.to_array().as_ptr());
        glLightfv(id, GL_POSITION, light.position.to_array().as_ptr());
        glLightfv(id, GL_SPOT_DIRECTION, spot.as_ptr());
        glLightf(id, GL_SPOT_EXPONENT, light.spot_exponent);
        glLightf(id, GL_SPOT_CUTOFF, light.spot_cutoff);
        glLightf(id, GL_CONSTANT_ATTENUATION, light.constant_attenuation);
        glLightf(id, GL_LINEAR_ATTENUATION, light.linear_attenuation);
        glLightf(id, GL_QUADRATIC_ATTENUATION, light.quadratic_attenuation);
    }
    set_enabled(id, light.enabled);
}

fn set_material(face: GLenum, m: &Material) {
    // SAFETY: a context is current on this thread; every array has four components.
    unsafe {
        glMaterialfv(face, GL_AMBIENT, m.ambient.to_array().as_ptr());
        glMaterialfv(face, GL_DIFFUSE, m.diffuse.to_array().as_ptr());
        glMaterialfv(face, GL_SPECULAR, m.specular.to_array().as_ptr());
        glMaterialfv(face, GL_EMISSION, m.emission.to_array().as_ptr());
        glMaterialf(face, GL_SHININESS, m.shininess);
    }
}

fn draw_one(draw: &GlDraw, max_lights: usize, arrays: Arrays) -> GlResult<()> {
    let state = &draw.state;
    if let Some((index, _)) = state
        .lights
        .iter()
        .enumerate()
        .find(|(i, l)| *i >= max_lights && l.enabled)
    {
        return Err(format!(
            "light {index} is enabled but this GL has GL_MAX_LIGHTS = {max_lights}"
        ));
    }
    let mesh = draw.mesh;
    let count = mesh.triangle_count() * 3;
    if let Arrays::Client = arrays {
        // Buffer objects were checked when they were filled.
        check_indices(mesh)?;
    }
    let count = GLsizei::try_from(count).map_err(|_| format!("{count} indices are too many for one draw"))?;

    // SAFETY: a context is current on this thread; matrices are 16 floats, column-major as
    // both glam and GL store them.
    unsafe {
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(draw.projection.to_cols_array().as_ptr());
        // Light positions and spot directions are already in eye space.
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
    }
    for (index, light) in state.lights.iter().enumerate().take(max_lights) {
        set_light(index, light);
    }

    // Materials first, with COLOR_MATERIAL off so no parameter is tracking the color and every
    // glMaterial call takes effect; then glColorMaterial, then the enable (which, in GL, writes
    // the current color into the tracked parameters).
    set_enabled(GL_COLOR_MATERIAL, false);
    // SAFETY: a context is current on this thread; the color has four components.
    unsafe { glColor4fv(state.current_color.to_array().as_ptr()) };
    set_material(GL_FRONT, &state.front);
    set_material(GL_BACK, &state.back);
    let model = &state.model;
    let color_control = match model.color_control {
        ColorControl::SingleColor => GL_SINGLE_COLOR,
        ColorControl::SeparateSpecularColor => GL_SEPARATE_SPECULAR_COLOR,
    };
    // SAFETY: a context is current on this thread; the ambient array has four components.
    unsafe {
        glColorMaterial(
            face_enum(state.color_material.face),
            color_material_enum(state.color_material.mode),
        );
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model.ambient.to_array().as_ptr());
        glLightModeli(
            GL_LIGHT_MODEL_LOCAL_VIEWER,
            if model.local_viewer { GL_TRUE } else { GL_FALSE },
        );
        glLightModeli(
            GL_LIGHT_MODEL_TWO_SIDE,
            if model.two_side { GL_TRUE } else { GL_FALSE },
        );
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, color_control as GLint);
        // ffvk's per-fragment mode has no GL counterpart: compare it with SMOOTH.
        glShadeModel(if state.mode == LightingMode::Flat {
            GL_FLAT
        } else {
            GL_SMOOTH
        });
    }
    set_enabled(GL_COLOR_MATERIAL, state.color_material.enabled);
    set_enabled(GL_NORMALIZE, state.normalize);
    set_enabled(GL_RESCALE_NORMAL, state.rescale_normal);
    set_enabled(GL_LIGHTING, state.lighting);
    for call in &draw.calls {
        replay(*call);
    }
    check_gl_error("from the replayed calls")?;

    if count == 0 {
        return Ok(());
    }
    let stride = std::mem::size_of::<Vertex>() as GLsizei;
    // Client arrays are addresses in the mesh; with buffer objects bound, GL reads the same
    // arguments as offsets into them (from a null base).
    let (vertex_base, index_base): (*const u8, *const c_void) = match arrays {
        Arrays::Client => (mesh.vertices.as_ptr().cast(), mesh.indices.as_ptr().cast()),
        Arrays::Buffers(b) => {
            // SAFETY: a context is current on this thread; both names are buffers it made.
            unsafe {
                glBindBuffer(GL_ARRAY_BUFFER, b.vertices);
                glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.indices);
            }
            (std::ptr::null(), std::ptr::null())
        }
    };
    let field = |offset: usize| vertex_base.wrapping_add(offset).cast::<c_void>();
    // SAFETY: a context is current on this thread. Client arrays point into `mesh.vertices`
    // (repr(C) f32 fields, `stride` bytes apart) and glDrawElements reads them before it
    // returns; buffer objects hold the same bytes. Every index was checked against the vertex
    // count, and the arrays are disabled (and buffers unbound) after the draw.
    unsafe {
        glMatrixMode(GL_MODELVIEW);
        glLoadMatrixf(draw.modelview.to_cols_array().as_ptr());
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        if draw.color_array {
            glEnableClientState(GL_COLOR_ARRAY);
        }
        glVertexPointer(3, GL_FLOAT, stride, field(std::mem::offset_of!(Vertex, position)));
        glNormalPointer(GL_FLOAT, stride, field(std::mem::offset_of!(Vertex, normal)));
        glColorPointer(4, GL_FLOAT, stride, field(std::mem::offset_of!(Vertex, color)));
        glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, index_base);
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_NORMAL_ARRAY);
        glDisableClientState(GL_COLOR_ARRAY);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    }
    Ok(())
}
