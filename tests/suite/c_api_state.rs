//! The differential state test of the C API: sequences of GL calls, valid and invalid, run
//! through ffvk's C entry points and through Mesa's GL (a compatibility context over EGL),
//! comparing the error after every call and every value queried.
//!
//! Where the two differ, the difference is either fixed in ffvk or listed in [`DEVIATIONS`]
//! with the section of the GL 2.1 specification that ffvk follows; a sequence that differs
//! without being listed, or is listed and no longer differs, fails the test.

use ffvk_c::gl::FfvkContext;
use ffvk_cli::gl_reference::{raw, with_raw_gl};

mod combine;
mod raster;
mod texgen;
mod units;

// GL's enums (the values of <GL/gl.h>).
const LIGHTING: u32 = 0x0B50;
const LIGHT0: u32 = 0x4000;
const COLOR_MATERIAL: u32 = 0x0B57;
const NORMALIZE: u32 = 0x0BA1;
const RESCALE_NORMAL: u32 = 0x803A;
const TEXTURE_2D: u32 = 0x0DE1;
const AMBIENT: u32 = 0x1200;
const DIFFUSE: u32 = 0x1201;
const SPECULAR: u32 = 0x1202;
const POSITION: u32 = 0x1203;
const SPOT_DIRECTION: u32 = 0x1204;
const SPOT_EXPONENT: u32 = 0x1205;
const SPOT_CUTOFF: u32 = 0x1206;
const CONSTANT_ATTENUATION: u32 = 0x1207;
const LINEAR_ATTENUATION: u32 = 0x1208;
const QUADRATIC_ATTENUATION: u32 = 0x1209;
const EMISSION: u32 = 0x1600;
const SHININESS: u32 = 0x1601;
const AMBIENT_AND_DIFFUSE: u32 = 0x1602;
const COLOR_INDEXES: u32 = 0x1603;
const FRONT: u32 = 0x0404;
const BACK: u32 = 0x0405;
const FRONT_AND_BACK: u32 = 0x0408;
const LIGHT_MODEL_LOCAL_VIEWER: u32 = 0x0B51;
const LIGHT_MODEL_TWO_SIDE: u32 = 0x0B52;
const LIGHT_MODEL_AMBIENT: u32 = 0x0B53;
const LIGHT_MODEL_COLOR_CONTROL: u32 = 0x81F8;
const SINGLE_COLOR: u32 = 0x81F9;
const SEPARATE_SPECULAR_COLOR: u32 = 0x81FA;
const SHADE_MODEL: u32 = 0x0B54;
const FLAT: u32 = 0x1D00;
const SMOOTH: u32 = 0x1D01;
const COLOR_MATERIAL_FACE: u32 = 0x0B55;
const COLOR_MATERIAL_PARAMETER: u32 = 0x0B56;
const CURRENT_COLOR: u32 = 0x0B00;
const MODELVIEW_MATRIX: u32 = 0x0BA6;
const PROJECTION_MATRIX: u32 = 0x0BA7;
const TEXTURE_MATRIX: u32 = 0x0BA8;
const TEXTURE_ENV: u32 = 0x2300;
const TEXTURE_ENV_MODE: u32 = 0x2200;
const TEXTURE_ENV_COLOR: u32 = 0x2201;
const MODULATE: u32 = 0x2100;
const DECAL: u32 = 0x2101;
const BLEND: u32 = 0x0BE2;
const REPLACE: u32 = 0x1E01;
const ADD: u32 = 0x0104;
const MAX_LIGHTS: u32 = 0x0D31;
/// Not an enum any lighting entry point takes.
const BOGUS: u32 = 0x1234;
/// Stands for `GL_LIGHT0 + GL_MAX_LIGHTS` of the implementation running the sequence (8 in
/// Mesa, 16 in ffvk: both are GL's "at least 8").
const LIGHT_PAST_MAX: u32 = 0xFFFF_0001;
/// Stands for `GL_LIGHT0 + GL_MAX_LIGHTS - 1`.
const LIGHT_LAST: u32 = 0xFFFF_0002;
/// Stands for `GL_TEXTURE0 + k` of the implementation running the sequence, where k is the
/// number of units glActiveTexture takes (GL 2.1 §2.7: the larger of `GL_MAX_TEXTURE_COORDS`
/// and `GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS`; 4 in ffvk, which has no image units beyond its
/// texture units). Each texture unit sentinel is a float exactly, so that glTexEnvf and
/// glTexEnvfv can pass it as glTexEnvi does.
const UNIT_PAST_ACTIVE: u32 = 0x7F00_0100;
/// Stands for `GL_TEXTURE0 + GL_MAX_TEXTURE_UNITS - 1`, the last fixed-function unit (3 in
/// ffvk, 7 in Mesa).
const UNIT_LAST: u32 = 0x7F00_0200;
/// Stands for `GL_TEXTURE0 + GL_MAX_TEXTURE_UNITS`: a `GL_TEXTUREn` source past the last unit.
const UNIT_PAST_LAST: u32 = 0x7F00_0300;
/// Stands for `GL_TEXTURE0 + GL_MAX_TEXTURE_COORDS`: a glMultiTexCoord target past the last
/// coordinate set.
const COORDS_PAST_LAST: u32 = 0x7F00_0400;
const TEXTURE0: u32 = 0x84C0;
const MAX_TEXTURE_UNITS: u32 = 0x84E2;
const MAX_TEXTURE_COORDS: u32 = 0x8871;
const MAX_COMBINED_TEXTURE_IMAGE_UNITS: u32 = 0x8B4D;

/// An implementation's texture unit limits (GL 2.1 table 6.44), as it answers them.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Units {
    /// `GL_MAX_TEXTURE_UNITS`: the fixed-function units.
    units: u32,
    /// `GL_MAX_TEXTURE_COORDS`.
    coords: u32,
    /// How many units glActiveTexture takes.
    active: u32,
}

/// One GL call.
#[derive(Debug, Clone)]
enum Call {
    Enable(u32),
    Disable(u32),
    Lightfv(u32, u32, Vec<f32>),
    Lightiv(u32, u32, Vec<i32>),
    Lightf(u32, u32, f32),
    Lighti(u32, u32, i32),
    Materialfv(u32, u32, Vec<f32>),
    Materialiv(u32, u32, Vec<i32>),
    Materialf(u32, u32, f32),
    Materiali(u32, u32, i32),
    LightModelfv(u32, Vec<f32>),
    LightModeliv(u32, Vec<i32>),
    LightModelf(u32, f32),
    LightModeli(u32, i32),
    ColorMaterial(u32, u32),
    Color4f([f32; 4]),
    Color3f([f32; 3]),
    Color4ub([u8; 4]),
    Color3ub([u8; 3]),
    ShadeModel(u32),
    TexEnvfv(u32, u32, Vec<f32>),
    TexEnviv(u32, u32, Vec<i32>),
    TexEnvi(u32, u32, i32),
    TexEnvf(u32, u32, f32),
    /// glMatrixMode(GL_MODELVIEW) + glLoadMatrixf.
    LoadModelview([f32; 16]),
    /// glMatrixMode(GL_PROJECTION) + glLoadMatrixf.
    LoadProjection([f32; 16]),
    Fogf(u32, f32),
    Fogi(u32, i32),
    Fogfv(u32, Vec<f32>),
    FogCoordf(f32),
    Hint(u32, u32),
    AlphaFunc(u32, f32),
    SecondaryColor3f([f32; 3]),
    Normal3f([f32; 3]),
    TexCoord4f([f32; 4]),
    ClipPlane(u32, [f64; 4]),
    PointParameterf(u32, f32),
    PointParameteri(u32, i32),
    PointParameterfv(u32, Vec<f32>),
    PolygonMode(u32, u32),
    PolygonOffset(f32, f32),
    EdgeFlag(u8),
    LineStipple(i32, u16),
    /// glPolygonStipple's 128 bytes.
    PolygonStipple(Vec<u8>),
    DepthRange(f64, f64),
    StencilFunc(u32, i32, u32),
    StencilFuncSeparate(u32, u32, i32, u32),
    StencilOp(u32, u32, u32),
    StencilOpSeparate(u32, u32, u32, u32),
    StencilMask(u32),
    StencilMaskSeparate(u32, u32),
    ClearStencil(i32),
    ColorMask([u8; 4]),
    DepthMask(u8),
    DepthFunc(u32),
    BlendFunc(u32, u32),
    BlendFuncSeparate([u32; 4]),
    BlendEquation(u32),
    BlendEquationSeparate(u32, u32),
    BlendColor([f32; 4]),
    LogicOp(u32),
    CullFace(u32),
    FrontFace(u32),
    PointSize(f32),
    LineWidth(f32),
    TexGeni(u32, u32, i32),
    TexGenf(u32, u32, f32),
    TexGend(u32, u32, f64),
    TexGeniv(u32, u32, Vec<i32>),
    TexGenfv(u32, u32, Vec<f32>),
    TexGendv(u32, u32, Vec<f64>),
    ActiveTexture(u32),
    MultiTexCoord4f(u32, [f32; 4]),
    MultiTexCoord2f(u32, [f32; 2]),
    MultiTexCoord4fv(u32, Vec<f32>),
    /// glMatrixMode(GL_TEXTURE) + glLoadMatrixf (the active unit's) + glMatrixMode(GL_MODELVIEW).
    LoadTextureMatrix([f32; 16]),
}

/// One query, with how many values it answers.
#[derive(Debug, Clone, Copy)]
enum Query {
    GetLightfv(u32, u32, usize),
    GetLightiv(u32, u32, usize),
    GetMaterialfv(u32, u32, usize),
    GetMaterialiv(u32, u32, usize),
    GetFloatv(u32, usize),
    GetIntegerv(u32, usize),
    GetBooleanv(u32, usize),
    GetTexEnvfv(u32, u32, usize),
    GetClipPlane(u32),
    GetPolygonStipple,
    GetTexEnviv(u32, u32, usize),
    GetTexGeniv(u32, u32, usize),
    GetTexGenfv(u32, u32, usize),
    GetTexGendv(u32, u32, usize),
    IsEnabled(u32),
}

#[derive(Debug, Clone)]
enum Step {
    /// A call, then glGetError.
    Call(Call),
    /// A call without reading the error after it (for GL's first-error-sticks rule).
    Quiet(Call),
    /// A query, then glGetError.
    Query(Query),
}

/// What one step answered: the values a query wrote (an untouched buffer shows as the
/// sentinel) and the error read right after it.
#[derive(Debug, Clone, PartialEq)]
struct Answer {
    values: Vec<f64>,
    error: u32,
}

/// The sentinel a query's buffer is filled with before the call.
const UNWRITTEN: f64 = -12345.0;

trait Gl {
    fn max_lights(&mut self) -> u32;
    fn units(&mut self) -> Units;
    fn call(&mut self, call: &Call);
    fn query(&mut self, query: Query) -> Vec<f64>;
    fn error(&mut self) -> u32;
    /// Back to GL's initial state with no error pending.
    fn reset(&mut self);

    fn resolve(&mut self, light: u32) -> u32 {
        match light {
            LIGHT_PAST_MAX => LIGHT0 + self.max_lights(),
            LIGHT_LAST => LIGHT0 + self.max_lights() - 1,
            other => other,
        }
    }
    fn run(&mut self, steps: &[Step]) -> Vec<Answer> {
        self.reset();
        steps
            .iter()
            .map(|step| {
                let values = match step {
                    Step::Quiet(call) => {
                        let call = self.resolve_call(call);
                        self.call(&call);
                        return Answer {
                            values: Vec::new(),
                            error: u32::MAX,
                        };
                    }
                    Step::Call(call) => {
                        let call = self.resolve_call(call);
                        self.call(&call);
                        Vec::new()
                    }
                    Step::Query(q) => {
                        let q = self.resolve_query(*q);
                        self.query(q)
                    }
                };
                Answer {
                    values,
                    error: self.error(),
                }
            })
            .collect()
    }
    /// The texture unit a sentinel stands for here; any other value as it is.
    fn resolve_unit(&mut self, texture: u32) -> u32 {
        if !matches!(
            texture,
            UNIT_PAST_ACTIVE | UNIT_LAST | UNIT_PAST_LAST | COORDS_PAST_LAST
        ) {
            return texture;
        }
        let units = self.units();
        match texture {
            UNIT_PAST_ACTIVE => TEXTURE0 + units.active,
            UNIT_LAST => TEXTURE0 + units.units - 1,
            UNIT_PAST_LAST => TEXTURE0 + units.units,
            _ => TEXTURE0 + units.coords,
        }
    }
    fn resolve_call(&mut self, call: &Call) -> Call {
        let mut call = call.clone();
        match &mut call {
            Call::Enable(l) | Call::Disable(l) => *l = self.resolve(*l),
            Call::Lightfv(l, ..) | Call::Lightiv(l, ..) | Call::Lightf(l, ..) | Call::Lighti(l, ..) => {
                *l = self.resolve(*l)
            }
            Call::ActiveTexture(t)
            | Call::MultiTexCoord4f(t, _)
            | Call::MultiTexCoord2f(t, _)
            | Call::MultiTexCoord4fv(t, _) => *t = self.resolve_unit(*t),
            // A GL_TEXTUREn source given as a sentinel, through each form.
            Call::TexEnvi(_, _, v) => *v = self.resolve_unit(*v as u32) as i32,
            Call::TexEnviv(_, _, v) if !v.is_empty() => v[0] = self.resolve_unit(v[0] as u32) as i32,
            Call::TexEnvf(_, _, v) if *v == v.trunc() && *v > 0.0 => *v = self.resolve_unit(*v as u32) as f32,
            Call::TexEnvfv(_, _, v) if v.first().is_some_and(|x| *x == x.trunc() && *x > 0.0) => {
                v[0] = self.resolve_unit(v[0] as u32) as f32
            }
            _ => {}
        }
        call
    }
    fn resolve_query(&mut self, q: Query) -> Query {
        match q {
            Query::GetLightfv(l, p, n) => Query::GetLightfv(self.resolve(l), p, n),
            Query::GetLightiv(l, p, n) => Query::GetLightiv(self.resolve(l), p, n),
            Query::IsEnabled(c) => Query::IsEnabled(self.resolve(c)),
            Query::GetBooleanv(c, n) => Query::GetBooleanv(self.resolve(c), n),
            other => other,
        }
    }
}

/// ffvk through its C entry points, as a C caller calls them.
struct Ffvk {
    ctx: *mut FfvkContext,
}

impl Drop for Ffvk {
    fn drop(&mut self) {
        // SAFETY: the context came from ffvkCreateContext and is not used after this.
        unsafe { ffvk_c::gl::ffvkDestroyContext(self.ctx) };
    }
}

impl Gl for Ffvk {
    fn max_lights(&mut self) -> u32 {
        let mut v = 0i32;
        // SAFETY: a live context; one value written.
        unsafe { ffvk_c::query::ffvkGetIntegerv(self.ctx, MAX_LIGHTS, &mut v) };
        v as u32
    }
    fn units(&mut self) -> Units {
        let (mut units, mut coords) = (0i32, 0i32);
        // SAFETY: a live context; one value written each.
        unsafe {
            ffvk_c::query::ffvkGetIntegerv(self.ctx, MAX_TEXTURE_UNITS, &mut units);
            ffvk_c::query::ffvkGetIntegerv(self.ctx, MAX_TEXTURE_COORDS, &mut coords);
        }
        // ffvk has no shader image units: glActiveTexture takes its texture units.
        Units {
            units: units as u32,
            coords: coords as u32,
            active: units.max(coords) as u32,
        }
    }
    fn call(&mut self, call: &Call) {
        use ffvk_c::gl::*;
        let c = self.ctx;
        // SAFETY: a live context; every vector has as many values as its name takes (the
        // table's sequences give GL's count; a short one would be a test bug GL shares).
        unsafe {
            match call {
                Call::Enable(cap) => ffvkEnable(c, *cap),
                Call::Disable(cap) => ffvkDisable(c, *cap),
                Call::Lightfv(l, p, v) => ffvkLightfv(c, *l, *p, padded(v).as_ptr()),
                Call::Lightiv(l, p, v) => ffvkLightiv(c, *l, *p, padded(v).as_ptr()),
                Call::Lightf(l, p, v) => ffvkLightf(c, *l, *p, *v),
                Call::Lighti(l, p, v) => ffvkLighti(c, *l, *p, *v),
                Call::Materialfv(f, p, v) => ffvkMaterialfv(c, *f, *p, padded(v).as_ptr()),
                Call::Materialiv(f, p, v) => ffvkMaterialiv(c, *f, *p, padded(v).as_ptr()),
                Call::Materialf(f, p, v) => ffvkMaterialf(c, *f, *p, *v),
                Call::Materiali(f, p, v) => ffvkMateriali(c, *f, *p, *v),
                Call::LightModelfv(p, v) => ffvkLightModelfv(c, *p, padded(v).as_ptr()),
                Call::LightModeliv(p, v) => ffvkLightModeliv(c, *p, padded(v).as_ptr()),
                Call::LightModelf(p, v) => ffvkLightModelf(c, *p, *v),
                Call::LightModeli(p, v) => ffvkLightModeli(c, *p, *v),
                Call::ColorMaterial(f, m) => ffvkColorMaterial(c, *f, *m),
                Call::Color4f([r, g, b, a]) => ffvkColor4f(c, *r, *g, *b, *a),
                Call::Color3f([r, g, b]) => ffvkColor3f(c, *r, *g, *b),
                Call::Color4ub([r, g, b, a]) => ffvkColor4ub(c, *r, *g, *b, *a),
                Call::Color3ub([r, g, b]) => ffvkColor3ub(c, *r, *g, *b),
                Call::ShadeModel(m) => ffvkShadeModel(c, *m),
                Call::TexEnvfv(t, p, v) => ffvkTexEnvfv(c, *t, *p, padded(v).as_ptr()),
                Call::TexEnviv(t, p, v) => ffvkTexEnviv(c, *t, *p, padded(v).as_ptr()),
                Call::TexEnvi(t, p, v) => ffvkTexEnvi(c, *t, *p, *v),
                Call::TexEnvf(t, p, v) => ffvkTexEnvf(c, *t, *p, *v),
                Call::LoadModelview(m) => ffvkLoadModelview(c, m.as_ptr()),
                Call::LoadProjection(m) => ffvkLoadProjection(c, m.as_ptr()),
                Call::Fogf(p, v) => ffvkFogf(c, *p, *v),
                Call::Fogi(p, v) => ffvkFogi(c, *p, *v),
                Call::Fogfv(p, v) => ffvkFogfv(c, *p, padded(v).as_ptr()),
                Call::FogCoordf(v) => ffvkFogCoordf(c, *v),
                Call::Hint(t, m) => ffvkHint(c, *t, *m),
                Call::AlphaFunc(f, r) => ffvkAlphaFunc(c, *f, *r),
                Call::SecondaryColor3f([r, g, b]) => ffvkSecondaryColor3f(c, *r, *g, *b),
                Call::Normal3f([x, y, z]) => ffvkNormal3f(c, *x, *y, *z),
                Call::TexCoord4f([s, t, r, q]) => ffvkTexCoord4f(c, *s, *t, *r, *q),
                Call::ClipPlane(p, e) => ffvkClipPlane(c, *p, e.as_ptr()),
                Call::PointParameterf(p, v) => ffvkPointParameterf(c, *p, *v),
                Call::PointParameteri(p, v) => ffvkPointParameteri(c, *p, *v),
                Call::PointParameterfv(p, v) => ffvkPointParameterfv(c, *p, padded(v).as_ptr()),
                Call::PolygonMode(f, m) => ffvkPolygonMode(c, *f, *m),
                Call::PolygonOffset(f, u) => ffvkPolygonOffset(c, *f, *u),
                Call::EdgeFlag(f) => ffvkEdgeFlag(c, *f),
                Call::LineStipple(f, p) => ffvkLineStipple(c, *f, *p),
                Call::PolygonStipple(m) => ffvkPolygonStipple(c, m.as_ptr()),
                Call::DepthRange(n, f) => ffvkDepthRange(c, *n, *f),
                Call::StencilFunc(f, r, m) => ffvkStencilFunc(c, *f, *r, *m),
                Call::StencilFuncSeparate(s, f, r, m) => ffvkStencilFuncSeparate(c, *s, *f, *r, *m),
                Call::StencilOp(a, b, d) => ffvkStencilOp(c, *a, *b, *d),
                Call::StencilOpSeparate(s, a, b, d) => ffvkStencilOpSeparate(c, *s, *a, *b, *d),
                Call::StencilMask(m) => ffvkStencilMask(c, *m),
                Call::StencilMaskSeparate(s, m) => ffvkStencilMaskSeparate(c, *s, *m),
                Call::ClearStencil(s) => ffvkClearStencil(c, *s),
                Call::ColorMask([r, g, b, a]) => ffvkColorMask(c, *r, *g, *b, *a),
                Call::DepthMask(f) => ffvkDepthMask(c, *f),
                Call::DepthFunc(f) => ffvkDepthFunc(c, *f),
                Call::BlendFunc(s, d) => ffvkBlendFunc(c, *s, *d),
                Call::BlendFuncSeparate([a, b, d, e]) => ffvkBlendFuncSeparate(c, *a, *b, *d, *e),
                Call::BlendEquation(m) => ffvkBlendEquation(c, *m),
                Call::BlendEquationSeparate(r, a) => ffvkBlendEquationSeparate(c, *r, *a),
                Call::BlendColor([r, g, b, a]) => ffvkBlendColor(c, *r, *g, *b, *a),
                Call::LogicOp(o) => ffvkLogicOp(c, *o),
                Call::CullFace(m) => ffvkCullFace(c, *m),
                Call::FrontFace(m) => ffvkFrontFace(c, *m),
                Call::PointSize(s) => ffvkPointSize(c, *s),
                Call::LineWidth(w) => ffvkLineWidth(c, *w),
                Call::TexGeni(t, p, v) => ffvkTexGeni(c, *t, *p, *v),
                Call::TexGenf(t, p, v) => ffvkTexGenf(c, *t, *p, *v),
                Call::TexGend(t, p, v) => ffvkTexGend(c, *t, *p, *v),
                Call::TexGeniv(t, p, v) => ffvkTexGeniv(c, *t, *p, padded(v).as_ptr()),
                Call::TexGenfv(t, p, v) => ffvkTexGenfv(c, *t, *p, padded(v).as_ptr()),
                Call::TexGendv(t, p, v) => ffvkTexGendv(c, *t, *p, padded(v).as_ptr()),
                Call::ActiveTexture(t) => ffvkActiveTexture(c, *t),
                Call::MultiTexCoord4f(t, [s, tt, r, q]) => ffvkMultiTexCoord4f(c, *t, *s, *tt, *r, *q),
                Call::MultiTexCoord2f(t, [s, tt]) => ffvkMultiTexCoord2f(c, *t, *s, *tt),
                Call::MultiTexCoord4fv(t, v) => ffvkMultiTexCoord4fv(c, *t, padded(v).as_ptr()),
                Call::LoadTextureMatrix(m) => ffvkLoadTextureMatrix(c, m.as_ptr()),
            }
        }
    }
    fn query(&mut self, query: Query) -> Vec<f64> {
        use ffvk_c::gl::ffvkIsEnabled;
        use ffvk_c::query::*;
        let c = self.ctx;
        let mut f = [UNWRITTEN as f32; 16];
        let mut i = [UNWRITTEN as i32; 16];
        let mut b = [0xAAu8; 16];
        let fs = |f: &[f32], n| f[..n].iter().map(|&v| v as f64).collect();
        let is = |i: &[i32], n| i[..n].iter().map(|&v| v as f64).collect();
        // SAFETY: a live context; each buffer has room for 16 values.
        unsafe {
            match query {
                Query::GetLightfv(l, p, n) => (ffvkGetLightfv(c, l, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetLightiv(l, p, n) => (ffvkGetLightiv(c, l, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetMaterialfv(fc, p, n) => (ffvkGetMaterialfv(c, fc, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetMaterialiv(fc, p, n) => (ffvkGetMaterialiv(c, fc, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetFloatv(p, n) => (ffvkGetFloatv(c, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetIntegerv(p, n) => (ffvkGetIntegerv(c, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetBooleanv(p, n) => {
                    ffvkGetBooleanv(c, p, b.as_mut_ptr());
                    booleans(&b[..n])
                }
                Query::GetTexEnvfv(t, p, n) => (ffvkGetTexEnvfv(c, t, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetTexEnviv(t, p, n) => (ffvkGetTexEnviv(c, t, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetTexGeniv(t, p, n) => (ffvkGetTexGeniv(c, t, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetTexGenfv(t, p, n) => (ffvkGetTexGenfv(c, t, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetTexGendv(t, p, n) => {
                    let mut d = [UNWRITTEN; 16];
                    ffvkGetTexGendv(c, t, p, d.as_mut_ptr());
                    d[..n].to_vec()
                }
                Query::GetClipPlane(p) => {
                    let mut d = [UNWRITTEN; 4];
                    ffvkGetClipPlane(c, p, d.as_mut_ptr());
                    d.to_vec()
                }
                Query::GetPolygonStipple => {
                    let mut m = [0x5Au8; 128];
                    ffvkGetPolygonStipple(c, m.as_mut_ptr());
                    m.map(f64::from).to_vec()
                }
                Query::IsEnabled(cap) => vec![ffvkIsEnabled(c, cap) as f64],
            }
        }
    }
    fn error(&mut self) -> u32 {
        // SAFETY: a live context.
        unsafe { ffvk_c::gl::ffvkGetError(self.ctx) }
    }
    fn reset(&mut self) {
        // SAFETY: the old context is not used after this; the new one is checked.
        unsafe { ffvk_c::gl::ffvkDestroyContext(self.ctx) };
        self.ctx = ffvk_c::gl::ffvkCreateContext();
        assert!(!self.ctx.is_null());
    }
}

/// A vector argument padded to 4 values, so a call GL reads 4 values for never reads past a
/// shorter table entry (GL does not know the length either).
fn padded<T: Copy + Default>(v: &[T]) -> Vec<T> {
    let mut p = v.to_vec();
    p.resize(p.len().max(16), T::default());
    p
}

fn booleans(b: &[u8]) -> Vec<f64> {
    b.iter()
        .map(|&v| if v == 0xAA { UNWRITTEN } else { v as f64 })
        .collect()
}

/// Mesa's GL through the generated entry points.
struct Mesa<'g> {
    gl: &'g raw::Gl,
}

impl Gl for Mesa<'_> {
    fn max_lights(&mut self) -> u32 {
        let mut v = 0i32;
        // SAFETY: the context is current; one value written.
        unsafe { self.gl.GetIntegerv(MAX_LIGHTS, &mut v) };
        v as u32
    }
    fn units(&mut self) -> Units {
        let [mut units, mut coords, mut images] = [0i32; 3];
        // SAFETY: the context is current; one value written each.
        unsafe {
            self.gl.GetIntegerv(MAX_TEXTURE_UNITS, &mut units);
            self.gl.GetIntegerv(MAX_TEXTURE_COORDS, &mut coords);
            self.gl.GetIntegerv(MAX_COMBINED_TEXTURE_IMAGE_UNITS, &mut images);
        }
        Units {
            units: units as u32,
            coords: coords as u32,
            active: coords.max(images) as u32,
        }
    }
    fn call(&mut self, call: &Call) {
        let gl = self.gl;
        // SAFETY: the context is current on this thread; vectors as for ffvk.
        unsafe {
            match call {
                Call::Enable(cap) => gl.Enable(*cap),
                Call::Disable(cap) => gl.Disable(*cap),
                Call::Lightfv(l, p, v) => gl.Lightfv(*l, *p, padded(v).as_ptr()),
                Call::Lightiv(l, p, v) => gl.Lightiv(*l, *p, padded(v).as_ptr()),
                Call::Lightf(l, p, v) => gl.Lightf(*l, *p, *v),
                Call::Lighti(l, p, v) => gl.Lighti(*l, *p, *v),
                Call::Materialfv(f, p, v) => gl.Materialfv(*f, *p, padded(v).as_ptr()),
                Call::Materialiv(f, p, v) => gl.Materialiv(*f, *p, padded(v).as_ptr()),
                Call::Materialf(f, p, v) => gl.Materialf(*f, *p, *v),
                Call::Materiali(f, p, v) => gl.Materiali(*f, *p, *v),
                Call::LightModelfv(p, v) => gl.LightModelfv(*p, padded(v).as_ptr()),
                Call::LightModeliv(p, v) => gl.LightModeliv(*p, padded(v).as_ptr()),
                Call::LightModelf(p, v) => gl.LightModelf(*p, *v),
                Call::LightModeli(p, v) => gl.LightModeli(*p, *v),
                Call::ColorMaterial(f, m) => gl.ColorMaterial(*f, *m),
                Call::Color4f([r, g, b, a]) => gl.Color4f(*r, *g, *b, *a),
                Call::Color3f([r, g, b]) => gl.Color3f(*r, *g, *b),
                Call::Color4ub([r, g, b, a]) => gl.Color4ub(*r, *g, *b, *a),
                Call::Color3ub([r, g, b]) => gl.Color3ub(*r, *g, *b),
                Call::ShadeModel(m) => gl.ShadeModel(*m),
                Call::TexEnvfv(t, p, v) => gl.TexEnvfv(*t, *p, padded(v).as_ptr()),
                Call::TexEnviv(t, p, v) => gl.TexEnviv(*t, *p, padded(v).as_ptr()),
                Call::TexEnvi(t, p, v) => gl.TexEnvi(*t, *p, *v),
                Call::TexEnvf(t, p, v) => gl.TexEnvf(*t, *p, *v),
                Call::LoadModelview(m) => {
                    gl.MatrixMode(raw::MODELVIEW);
                    gl.LoadMatrixf(m.as_ptr());
                }
                Call::LoadProjection(m) => {
                    gl.MatrixMode(raw::PROJECTION);
                    gl.LoadMatrixf(m.as_ptr());
                    gl.MatrixMode(raw::MODELVIEW);
                }
                Call::Fogf(p, v) => gl.Fogf(*p, *v),
                Call::Fogi(p, v) => gl.Fogi(*p, *v),
                Call::Fogfv(p, v) => gl.Fogfv(*p, padded(v).as_ptr()),
                Call::FogCoordf(v) => gl.FogCoordf(*v),
                Call::Hint(t, m) => gl.Hint(*t, *m),
                Call::AlphaFunc(f, r) => gl.AlphaFunc(*f, *r),
                Call::SecondaryColor3f([r, g, b]) => gl.SecondaryColor3f(*r, *g, *b),
                Call::Normal3f([x, y, z]) => gl.Normal3f(*x, *y, *z),
                Call::TexCoord4f([s, t, r, q]) => gl.TexCoord4f(*s, *t, *r, *q),
                Call::ClipPlane(p, e) => gl.ClipPlane(*p, e.as_ptr()),
                Call::PointParameterf(p, v) => gl.PointParameterf(*p, *v),
                Call::PointParameteri(p, v) => gl.PointParameteri(*p, *v),
                Call::PointParameterfv(p, v) => gl.PointParameterfv(*p, padded(v).as_ptr()),
                Call::PolygonMode(f, m) => gl.PolygonMode(*f, *m),
                Call::PolygonOffset(f, u) => gl.PolygonOffset(*f, *u),
                Call::EdgeFlag(f) => gl.EdgeFlag(*f),
                Call::LineStipple(f, p) => gl.LineStipple(*f, *p),
                Call::PolygonStipple(m) => gl.PolygonStipple(m.as_ptr()),
                Call::DepthRange(n, f) => gl.DepthRange(*n, *f),
                Call::StencilFunc(f, r, m) => gl.StencilFunc(*f, *r, *m),
                Call::StencilFuncSeparate(s, f, r, m) => gl.StencilFuncSeparate(*s, *f, *r, *m),
                Call::StencilOp(a, b, d) => gl.StencilOp(*a, *b, *d),
                Call::StencilOpSeparate(s, a, b, d) => gl.StencilOpSeparate(*s, *a, *b, *d),
                Call::StencilMask(m) => gl.StencilMask(*m),
                Call::StencilMaskSeparate(s, m) => gl.StencilMaskSeparate(*s, *m),
                Call::ClearStencil(s) => gl.ClearStencil(*s),
                Call::ColorMask([r, g, b, a]) => gl.ColorMask(*r, *g, *b, *a),
                Call::DepthMask(f) => gl.DepthMask(*f),
                Call::DepthFunc(f) => gl.DepthFunc(*f),
                Call::BlendFunc(s, d) => gl.BlendFunc(*s, *d),
                Call::BlendFuncSeparate([a, b, d, e]) => gl.BlendFuncSeparate(*a, *b, *d, *e),
                Call::BlendEquation(m) => gl.BlendEquation(*m),
                Call::BlendEquationSeparate(r, a) => gl.BlendEquationSeparate(*r, *a),
                Call::BlendColor([r, g, b, a]) => gl.BlendColor(*r, *g, *b, *a),
                Call::LogicOp(o) => gl.LogicOp(*o),
                Call::CullFace(m) => gl.CullFace(*m),
                Call::FrontFace(m) => gl.FrontFace(*m),
                Call::PointSize(s) => gl.PointSize(*s),
                Call::LineWidth(w) => gl.LineWidth(*w),
                Call::TexGeni(t, p, v) => gl.TexGeni(*t, *p, *v),
                Call::TexGenf(t, p, v) => gl.TexGenf(*t, *p, *v),
                Call::TexGend(t, p, v) => gl.TexGend(*t, *p, *v),
                Call::TexGeniv(t, p, v) => gl.TexGeniv(*t, *p, padded(v).as_ptr()),
                Call::TexGenfv(t, p, v) => gl.TexGenfv(*t, *p, padded(v).as_ptr()),
                Call::TexGendv(t, p, v) => gl.TexGendv(*t, *p, padded(v).as_ptr()),
                Call::ActiveTexture(t) => gl.ActiveTexture(*t),
                Call::MultiTexCoord4f(t, [s, tt, r, q]) => gl.MultiTexCoord4f(*t, *s, *tt, *r, *q),
                Call::MultiTexCoord2f(t, [s, tt]) => gl.MultiTexCoord2f(*t, *s, *tt),
                Call::MultiTexCoord4fv(t, v) => gl.MultiTexCoord4fv(*t, padded(v).as_ptr()),
                Call::LoadTextureMatrix(m) => {
                    gl.MatrixMode(raw::TEXTURE);
                    gl.LoadMatrixf(m.as_ptr());
                    gl.MatrixMode(raw::MODELVIEW);
                }
            }
        }
    }
    fn query(&mut self, query: Query) -> Vec<f64> {
        let gl = self.gl;
        let mut f = [UNWRITTEN as f32; 16];
        let mut i = [UNWRITTEN as i32; 16];
        let mut b = [0xAAu8; 16];
        let fs = |f: &[f32], n| f[..n].iter().map(|&v| v as f64).collect();
        let is = |i: &[i32], n| i[..n].iter().map(|&v| v as f64).collect();
        // SAFETY: the context is current; each buffer has room for 16 values.
        unsafe {
            match query {
                Query::GetLightfv(l, p, n) => (gl.GetLightfv(l, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetLightiv(l, p, n) => (gl.GetLightiv(l, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetMaterialfv(fc, p, n) => (gl.GetMaterialfv(fc, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetMaterialiv(fc, p, n) => (gl.GetMaterialiv(fc, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetFloatv(p, n) => (gl.GetFloatv(p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetIntegerv(p, n) => (gl.GetIntegerv(p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetBooleanv(p, n) => {
                    gl.GetBooleanv(p, b.as_mut_ptr());
                    booleans(&b[..n])
                }
                Query::GetTexEnvfv(t, p, n) => (gl.GetTexEnvfv(t, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetTexEnviv(t, p, n) => (gl.GetTexEnviv(t, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetTexGeniv(t, p, n) => (gl.GetTexGeniv(t, p, i.as_mut_ptr()), is(&i, n)).1,
                Query::GetTexGenfv(t, p, n) => (gl.GetTexGenfv(t, p, f.as_mut_ptr()), fs(&f, n)).1,
                Query::GetTexGendv(t, p, n) => {
                    let mut d = [UNWRITTEN; 16];
                    gl.GetTexGendv(t, p, d.as_mut_ptr());
                    d[..n].to_vec()
                }
                Query::GetClipPlane(p) => {
                    let mut d = [UNWRITTEN; 4];
                    gl.GetClipPlane(p, d.as_mut_ptr());
                    d.to_vec()
                }
                Query::GetPolygonStipple => {
                    let mut m = [0x5Au8; 128];
                    gl.GetPolygonStipple(m.as_mut_ptr());
                    m.map(f64::from).to_vec()
                }
                Query::IsEnabled(cap) => vec![gl.IsEnabled(cap) as f64],
            }
        }
    }
    fn error(&mut self) -> u32 {
        // SAFETY: the context is current.
        unsafe { self.gl.GetError() }
    }
    fn reset(&mut self) {
        let gl = self.gl;
        // SAFETY: the context is current. The attribute stack holds GL's initial lighting,
        // enable, current and texture state (pushed once, before any sequence ran); popping
        // and pushing again restores it for the next sequence.
        unsafe {
            gl.PopAttrib();
            gl.PushAttrib(raw::ALL_ATTRIB_BITS);
            for mode in [raw::PROJECTION, raw::MODELVIEW] {
                gl.MatrixMode(mode);
                gl.LoadIdentity();
            }
            // The texture matrices are in no attribute group: each unit's is set back by hand,
            // then unit 0 made active again as glPopAttrib left it.
            let mut units = 0;
            gl.GetIntegerv(MAX_TEXTURE_COORDS, &mut units);
            for unit in 0..units as u32 {
                gl.ActiveTexture(TEXTURE0 + unit);
                gl.MatrixMode(raw::TEXTURE);
                gl.LoadIdentity();
            }
            gl.ActiveTexture(TEXTURE0);
            gl.MatrixMode(raw::MODELVIEW);
            // Mesa 22.3's glPopAttrib(GL_FOG_BIT) leaves GL_FOG_COORD_SRC as it was: set GL's
            // initial value back by hand.
            gl.Fogi(raw::FOG_COORD_SRC, raw::FRAGMENT_DEPTH as i32);
            while gl.GetError() != raw::NO_ERROR {}
        }
    }
}

/// Differences from Mesa's GL that ffvk keeps, each where ffvk follows the GL 2.1
/// specification and Mesa 22.3 does not, or where the specification leaves the result
/// undefined and ffvk refuses the call with the error its documentation names; every one must
/// still be seen (the test fails when Mesa stops deviating, so that the list stays true).
const DEVIATIONS: [&str; 9] = [
    // Mesa's glLightf, glMaterialf, glLightModelf and glPointParameterf pass a multi-valued
    // name on to the vector version with the one value (glMaterialf's other three read from
    // its stack, glPointParameterf's two zeros).
    "2.14.2, 3.3: a non-vector Light, Material, LightModel or PointParameter call with a \
     multi-valued pname is INVALID_ENUM (\"If param corresponds to a multi-valued parameter, \
     the error INVALID_ENUM results\"; POINT_DISTANCE_ATTENUATION is set through the vector \
     forms); Mesa sets the parameter",
    // Mesa converts 2.0 to an integer as (int)(2.0 * 2147483647.0), which overflows to
    // -2147483648 on x86.
    "6.1.2: a color beyond [-1, 1] queried as an integer is the nearest representable value \
     (2147483647 for 2.0); Mesa's conversion overflows to -2147483648",
    // Mesa answers GetIntegerv of a matrix with the color mapping (1.0 as 2147483647).
    "6.1.2: GetIntegerv of a matrix rounds each element to the nearest integer (only colors, \
     depth range and normals map linearly); Mesa maps them as colors",
    // Mesa's glPointParameter checks the origin's value with INVALID_VALUE.
    "2.5: a PointParameter value that is not one of the enums POINT_SPRITE_COORD_ORIGIN takes \
     is INVALID_ENUM (an enum argument out of range); Mesa sets INVALID_VALUE",
    // Mesa's glGetLightiv and glGetMaterialiv cast floats to integers; its glGetIntegerv
    // rounds (IROUND), as ffvk does everywhere.
    "6.1.2: GetLightiv and GetMaterialiv round a float to the nearest integer (a spot direction's \
     0.5 is 1); Mesa truncates it toward zero (0)",
    // Mesa takes GL_SRC_ALPHA_SATURATE as a destination factor (GL 3.3's rule, with
    // ARB_blend_func_extended).
    "4.1.8, table 4.2: SRC_ALPHA_SATURATE is \"valid only for source RGB and alpha blending \
     functions\": as a BlendFunc or BlendFuncSeparate destination factor it is INVALID_ENUM; Mesa \
     sets it",
    // Mesa's glTexGen{i,f,d} pass the value on to glTexGenfv as (param, 0, 0, 0), whatever the
    // name.
    "2.11.4: TexGen{i,f,d} take a single-valued parameter (\"In the first form of the command, \
     param is a symbolic constant specifying a single-valued texture generation parameter\"): \
     OBJECT_PLANE or EYE_PLANE there is INVALID_ENUM; Mesa sets the plane from (param, 0, 0, 0)",
    // Mesa's glGetTexGeniv casts a plane's floats to integers.
    "6.1.2: GetTexGeniv rounds a plane's float to the nearest integer (0.75 is 1); Mesa truncates \
     it toward zero (0)",
    // Mesa's glMultiTexCoord takes the set from the target's low three bits, unchecked
    // (vbo_attrib_tmp.h: `(target & 0x7) + VBO_ATTRIB_TEX0`).
    "2.7: \"Specifying an invalid texture coordinate set for the target argument of MultiTexCoord \
     results in undefined behavior\": ffvk refuses a target that is no TEXTUREi below \
     MAX_TEXTURE_COORDS with INVALID_ENUM and changes nothing (its choice, documented in ffvk.h); \
     Mesa raises no error and sets the coordinates of set (target & 7)",
];

/// A glMultiTexCoord whose target is no `GL_TEXTUREi` below ffvk's `GL_MAX_TEXTURE_COORDS`
/// (nor the last unit's sentinel, which names one of each implementation's own).
fn invalid_coordinate_set(call: &Call) -> bool {
    match *call {
        Call::MultiTexCoord4f(t, _) | Call::MultiTexCoord2f(t, _) | Call::MultiTexCoord4fv(t, _) => {
            !(TEXTURE0..TEXTURE0 + 4).contains(&t) && t != UNIT_LAST
        }
        _ => false,
    }
}

/// A glTexGen{i,f,d} naming a plane, which has four values.
fn scalar_texgen_plane(call: &Call) -> bool {
    const OBJECT_PLANE: u32 = 0x2501;
    const EYE_PLANE: u32 = 0x2502;
    match *call {
        Call::TexGeni(_, p, _) | Call::TexGenf(_, p, _) | Call::TexGend(_, p, _) => {
            matches!(p, OBJECT_PLANE | EYE_PLANE)
        }
        _ => false,
    }
}

/// Whether `ours` is `theirs` rounded where Mesa truncated toward zero: each value equal, or
/// one step further from zero.
fn rounded_where_truncated(ours: &Answer, theirs: &Answer) -> bool {
    ours.error == theirs.error
        && ours.values.len() == theirs.values.len()
        && ours
            .values
            .iter()
            .zip(&theirs.values)
            .all(|(&a, &b)| a == b || (b == a - a.signum() && a != 0.0))
}

/// A glBlendFunc or glBlendFuncSeparate with `GL_SRC_ALPHA_SATURATE` as a destination factor.
fn destination_saturate(call: &Call) -> bool {
    const SATURATE: u32 = 0x0308;
    match *call {
        Call::BlendFunc(_, d) => d == SATURATE,
        Call::BlendFuncSeparate([_, d, _, da]) => d == SATURATE || da == SATURATE,
        _ => false,
    }
}

/// Scalar entry points naming a multi-valued parameter.
fn scalar_with_vector_name(call: &Call) -> bool {
    match *call {
        Call::Lightf(_, p, _) | Call::Lighti(_, p, _) => {
            matches!(p, AMBIENT | DIFFUSE | SPECULAR | POSITION | SPOT_DIRECTION)
        }
        Call::Materialf(_, p, _) | Call::Materiali(_, p, _) => p != SHININESS,
        Call::LightModelf(p, _) | Call::LightModeli(p, _) => p == LIGHT_MODEL_AMBIENT,
        Call::PointParameterf(p, _) | Call::PointParameteri(p, _) => p == 0x8129,
        _ => false,
    }
}

/// Which of [`DEVIATIONS`] explains a difference at `step` of `steps`, if one does.
fn deviation(steps: &[Step], step: &Step, ours: &Answer, theirs: &Answer) -> Option<usize> {
    let scalar_vector = steps
        .iter()
        .any(|s| matches!(s, Step::Call(c) | Step::Quiet(c) if scalar_with_vector_name(c)));
    let saturate = steps
        .iter()
        .any(|s| matches!(s, Step::Call(c) | Step::Quiet(c) if destination_saturate(c)));
    let texgen_plane = steps
        .iter()
        .any(|s| matches!(s, Step::Call(c) | Step::Quiet(c) if scalar_texgen_plane(c)));
    let coordinate_set = steps
        .iter()
        .any(|s| matches!(s, Step::Call(c) | Step::Quiet(c) if invalid_coordinate_set(c)));
    match step {
        Step::Call(c) if invalid_coordinate_set(c) && ours.error == 0x0500 && theirs.error == 0 => Some(8),
        Step::Query(_) if coordinate_set && ours.error == theirs.error => Some(8),
        Step::Call(c) if scalar_texgen_plane(c) && ours.error == 0x0500 && theirs.error == 0 => Some(6),
        Step::Query(_) if texgen_plane && ours.error == theirs.error => Some(6),
        Step::Query(Query::GetTexGeniv(..)) if rounded_where_truncated(ours, theirs) => Some(7),
        Step::Call(c) if scalar_with_vector_name(c) && ours.error == 0x0500 && theirs.error == 0 => Some(0),
        Step::Call(c) if destination_saturate(c) && ours.error == 0x0500 && theirs.error == 0 => Some(5),
        Step::Query(_) if saturate && ours.error == theirs.error => Some(5),
        Step::Call(Call::PointParameteri(0x8CA0, _) | Call::PointParameterf(0x8CA0, _))
            if ours.error == 0x0500 && theirs.error == 0x0501 =>
        {
            Some(3)
        }
        Step::Query(_) if scalar_vector && ours.error == theirs.error => Some(0),
        Step::Query(Query::GetIntegerv(MODELVIEW_MATRIX | PROJECTION_MATRIX | TEXTURE_MATRIX, _))
            if ours.error == theirs.error =>
        {
            Some(2)
        }
        Step::Query(Query::GetLightiv(..) | Query::GetMaterialiv(..))
            if rounded_where_truncated(ours, theirs) =>
        {
            Some(4)
        }
        Step::Query(Query::GetIntegerv(..) | Query::GetLightiv(..) | Query::GetMaterialiv(..))
            if ours.error == theirs.error && ours.values.len() == theirs.values.len() =>
        {
            let overflow_only = ours.values.iter().zip(&theirs.values).all(|(&a, &b)| {
                agree(
                    &Answer {
                        values: vec![a],
                        error: 0,
                    },
                    &Answer {
                        values: vec![b],
                        error: 0,
                    },
                ) || (a == i32::MAX as f64 && b == i32::MIN as f64)
            });
            overflow_only.then_some(1)
        }
        _ => None,
    }
}

/// Whether two answers agree: errors equal, values equal (floats within float rounding,
/// integers from colors within their float's precision).
fn agree(a: &Answer, b: &Answer) -> bool {
    a.error == b.error
        && a.values.len() == b.values.len()
        && a.values.iter().zip(&b.values).all(|(&x, &y)| {
            let tolerance = if x.abs().max(y.abs()) > (1 << 20) as f64 {
                x.abs().max(y.abs()) * 1e-6
            } else {
                1e-5 * x.abs().max(y.abs()).max(1.0)
            };
            (x - y).abs() <= tolerance
        })
}

/// The table: named sequences of calls and queries.
fn sequences() -> Vec<(String, Vec<Step>)> {
    use Call::*;
    use Query::*;
    let c = Step::Call;
    let q = Step::Query;
    let mut s: Vec<(String, Vec<Step>)> = Vec::new();
    type Row = (u32, usize, Vec<f32>, Option<Vec<f32>>);
    let light_values: &[Row] = &[
        // (pname, count, a valid value, an invalid value)
        (AMBIENT, 4, vec![0.25, -0.5, 2.0, 1.0], None),
        (DIFFUSE, 4, vec![0.5, 0.75, 0.125, 0.5], None),
        (SPECULAR, 4, vec![1.5, 0.0, 0.25, 1.0], None),
        (POSITION, 4, vec![1.0, 2.0, 3.0, 1.0], None),
        (SPOT_DIRECTION, 3, vec![0.0, -1.0, 0.5], None),
        (SPOT_EXPONENT, 1, vec![64.0], Some(vec![129.0])),
        (SPOT_CUTOFF, 1, vec![45.0], Some(vec![91.0])),
        (CONSTANT_ATTENUATION, 1, vec![2.0], Some(vec![-1.0])),
        (LINEAR_ATTENUATION, 1, vec![0.5], Some(vec![-0.25])),
        (QUADRATIC_ATTENUATION, 1, vec![0.125], Some(vec![-2.0])),
    ];
    for light in [LIGHT0, LIGHT0 + 1, LIGHT_LAST, LIGHT_PAST_MAX] {
        let name = |l: u32| match l {
            LIGHT_LAST => "GL_LIGHT(max-1)".to_string(),
            LIGHT_PAST_MAX => "GL_LIGHT(max)".to_string(),
            l => format!("GL_LIGHT{}", l - LIGHT0),
        };
        for (pname, n, valid, invalid) in light_values {
            let check = |steps: Vec<Step>| {
                let mut steps = steps;
                steps.push(q(GetLightfv(light, *pname, *n)));
                steps.push(q(GetLightiv(light, *pname, *n)));
                steps
            };
            s.push((
                format!("glLightfv({}, 0x{pname:04X}, valid)", name(light)),
                check(vec![c(Lightfv(light, *pname, valid.clone()))]),
            ));
            s.push((
                format!("glLightiv({}, 0x{pname:04X}, integers)", name(light)),
                check(vec![c(Lightiv(
                    light,
                    *pname,
                    valid
                        .iter()
                        .map(|&v| {
                            if *n == 4 && *pname != POSITION {
                                (v * 1e9) as i32
                            } else {
                                v as i32
                            }
                        })
                        .collect(),
                ))]),
            ));
            if let Some(invalid) = invalid {
                s.push((
                    format!("glLightfv({}, 0x{pname:04X}, out of range)", name(light)),
                    check(vec![c(Lightfv(light, *pname, invalid.clone()))]),
                ));
                s.push((
                    format!("glLightf({}, 0x{pname:04X}, out of range)", name(light)),
                    check(vec![c(Lightf(light, *pname, invalid[0]))]),
                ));
                s.push((
                    format!("glLighti({}, 0x{pname:04X}, valid)", name(light)),
                    check(vec![c(Lighti(light, *pname, valid[0] as i32))]),
                ));
                s.push((
                    format!("glLightf({}, 0x{pname:04X}, valid)", name(light)),
                    check(vec![c(Lightf(light, *pname, valid[0]))]),
                ));
            }
        }
    }
    // Positions and directions are transformed by the modelview at the call.
    let mut translate = [0.0f32; 16];
    for (i, v) in [
        1.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 3.0, -4.0, 5.0, 1.0,
    ]
    .iter()
    .enumerate()
    {
        translate[i] = *v;
    }
    for (what, pos) in [
        ("point", [1.0, 1.0, 1.0, 1.0]),
        ("directional", [0.0, 1.0, 0.0, 0.0]),
    ] {
        s.push((
            format!("a {what} light's position is stored in eye space"),
            vec![
                c(LoadModelview(translate)),
                c(Lightfv(LIGHT0 + 2, POSITION, pos.to_vec())),
                c(Lightfv(LIGHT0 + 2, SPOT_DIRECTION, vec![1.0, 1.0, 0.0])),
                c(LoadModelview(identity())),
                q(GetLightfv(LIGHT0 + 2, POSITION, 4)),
                q(GetLightfv(LIGHT0 + 2, SPOT_DIRECTION, 3)),
                q(GetFloatv(MODELVIEW_MATRIX, 16)),
            ],
        ));
    }
    // Scalar entry points with vector names, unknown names.
    for pname in [AMBIENT, POSITION, SPOT_DIRECTION, BOGUS] {
        s.push((
            format!("glLightf(GL_LIGHT0, 0x{pname:04X}) with a vector name"),
            vec![c(Lightf(LIGHT0, pname, 0.5)), q(GetLightfv(LIGHT0, AMBIENT, 4))],
        ));
    }
    s.push((
        "glLightfv with an unknown pname".into(),
        vec![
            c(Lightfv(LIGHT0, BOGUS, vec![1.0; 4])),
            q(GetLightfv(LIGHT0, BOGUS, 4)),
        ],
    ));
    s.push((
        "glLightfv with a light that is no GL_LIGHTi".into(),
        vec![
            c(Lightfv(BOGUS, AMBIENT, vec![1.0; 4])),
            q(GetLightfv(0x3FFF, AMBIENT, 4)),
        ],
    ));
    s.push((
        "a cutoff of 180 is accepted, 90.5 refused".into(),
        vec![
            c(Lightf(LIGHT0, SPOT_CUTOFF, 90.0)),
            c(Lightf(LIGHT0, SPOT_CUTOFF, 90.5)),
            q(GetLightfv(LIGHT0, SPOT_CUTOFF, 1)),
            c(Lightf(LIGHT0, SPOT_CUTOFF, 180.0)),
            q(GetLightfv(LIGHT0, SPOT_CUTOFF, 1)),
        ],
    ));

    // Materials.
    let material_values: &[(u32, usize, Vec<f32>)] = &[
        (AMBIENT, 4, vec![0.1, 0.2, 0.3, 0.4]),
        (DIFFUSE, 4, vec![0.5, -0.25, 1.5, 0.75]),
        (SPECULAR, 4, vec![1.0, 0.5, 0.25, 1.0]),
        (EMISSION, 4, vec![0.0, 0.125, 0.0, 1.0]),
        (SHININESS, 1, vec![76.0]),
        (COLOR_INDEXES, 3, vec![1.0, 2.0, 3.0]),
        (AMBIENT_AND_DIFFUSE, 4, vec![0.3, 0.6, 0.9, 1.0]),
    ];
    let readback = |steps: &mut Vec<Step>| {
        for face in [FRONT, BACK] {
            for (pname, n) in [
                (AMBIENT, 4),
                (DIFFUSE, 4),
                (SPECULAR, 4),
                (EMISSION, 4),
                (SHININESS, 1),
            ] {
                steps.push(q(GetMaterialfv(face, pname, n)));
            }
        }
        steps.push(q(GetMaterialiv(FRONT, SHININESS, 1)));
        steps.push(q(GetMaterialiv(BACK, DIFFUSE, 4)));
    };
    for face in [FRONT, BACK, FRONT_AND_BACK, BOGUS] {
        for (pname, _, value) in material_values {
            let mut steps = vec![c(Materialfv(face, *pname, value.clone()))];
            readback(&mut steps);
            s.push((format!("glMaterialfv(0x{face:04X}, 0x{pname:04X})"), steps));
            let mut steps = vec![c(Materialiv(
                face,
                *pname,
                value
                    .iter()
                    .map(|&v| {
                        if *pname == SHININESS || *pname == COLOR_INDEXES {
                            v as i32
                        } else {
                            (v * 1e9) as i32
                        }
                    })
                    .collect(),
            ))];
            readback(&mut steps);
            s.push((format!("glMaterialiv(0x{face:04X}, 0x{pname:04X})"), steps));
        }
    }
    for shininess in [-1.0, 0.0, 128.0, 128.5] {
        let mut steps = vec![c(Materialf(FRONT_AND_BACK, SHININESS, shininess))];
        readback(&mut steps);
        s.push((
            format!("glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, {shininess})"),
            steps,
        ));
    }
    s.push((
        "glMateriali(GL_FRONT, GL_SHININESS, 129)".into(),
        vec![
            c(Materiali(FRONT, SHININESS, 129)),
            q(GetMaterialfv(FRONT, SHININESS, 1)),
        ],
    ));
    s.push((
        "glMaterialf(GL_FRONT, GL_AMBIENT) with a vector name".into(),
        vec![
            c(Materialf(FRONT, AMBIENT, 0.5)),
            q(GetMaterialfv(FRONT, AMBIENT, 4)),
        ],
    ));
    s.push((
        "glGetMaterialfv(GL_FRONT_AND_BACK) is refused".into(),
        vec![q(GetMaterialfv(FRONT_AND_BACK, DIFFUSE, 4))],
    ));
    s.push((
        "glGetMaterialfv(GL_AMBIENT_AND_DIFFUSE) is refused".into(),
        vec![q(GetMaterialfv(FRONT, AMBIENT_AND_DIFFUSE, 4))],
    ));

    // Color material: tracking, write-back, glMaterial on tracked parameters.
    for face in [FRONT, BACK, FRONT_AND_BACK] {
        for mode in [EMISSION, AMBIENT, DIFFUSE, SPECULAR, AMBIENT_AND_DIFFUSE] {
            let mut steps = vec![
                c(ColorMaterial(face, mode)),
                c(Color4f([0.9, 0.1, 0.4, 0.6])),
                c(Enable(COLOR_MATERIAL)),
                c(Materialfv(BACK, mode, vec![0.2, 0.3, 0.4, 0.5])),
                c(Materialfv(FRONT, mode, vec![0.7, 0.7, 0.7, 0.7])),
                q(GetIntegerv(COLOR_MATERIAL_FACE, 1)),
                q(GetIntegerv(COLOR_MATERIAL_PARAMETER, 1)),
            ];
            // Read before and after the next glColor, which tracks the color again.
            readback(&mut steps);
            steps.push(c(Color3f([0.25, 0.5, 0.75])));
            readback(&mut steps);
            steps.push(c(Disable(COLOR_MATERIAL)));
            steps.push(c(Color4ub([255, 0, 128, 255])));
            readback(&mut steps);
            s.push((
                format!("glMaterial while COLOR_MATERIAL tracks 0x{face:04X} 0x{mode:04X}"),
                steps,
            ));
        }
    }
    s.push((
        "glColorMaterial with a bad face or mode".into(),
        vec![
            c(ColorMaterial(BOGUS, DIFFUSE)),
            c(ColorMaterial(FRONT, SHININESS)),
            q(GetIntegerv(COLOR_MATERIAL_FACE, 1)),
            q(GetIntegerv(COLOR_MATERIAL_PARAMETER, 1)),
        ],
    ));

    // Light model.
    for (name, call) in [
        (
            "ambient fv",
            LightModelfv(LIGHT_MODEL_AMBIENT, vec![0.4, 0.3, 0.2, 0.1]),
        ),
        (
            "ambient iv",
            LightModeliv(LIGHT_MODEL_AMBIENT, vec![1 << 30, 0, -(1 << 29), i32::MAX]),
        ),
        ("ambient f", LightModelf(LIGHT_MODEL_AMBIENT, 0.5)),
        ("local viewer i", LightModeli(LIGHT_MODEL_LOCAL_VIEWER, 1)),
        ("local viewer f", LightModelf(LIGHT_MODEL_LOCAL_VIEWER, 0.5)),
        ("two side i", LightModeli(LIGHT_MODEL_TWO_SIDE, 7)),
        ("two side fv", LightModelfv(LIGHT_MODEL_TWO_SIDE, vec![0.0])),
        (
            "color control separate",
            LightModeli(LIGHT_MODEL_COLOR_CONTROL, SEPARATE_SPECULAR_COLOR as i32),
        ),
        (
            "color control single f",
            LightModelf(LIGHT_MODEL_COLOR_CONTROL, SINGLE_COLOR as f32),
        ),
        (
            "color control bad",
            LightModeli(LIGHT_MODEL_COLOR_CONTROL, BOGUS as i32),
        ),
        ("unknown pname", LightModeli(BOGUS, 1)),
    ] {
        s.push((
            format!("glLightModel {name}"),
            vec![
                c(call),
                q(GetFloatv(LIGHT_MODEL_AMBIENT, 4)),
                q(GetIntegerv(LIGHT_MODEL_AMBIENT, 4)),
                q(GetBooleanv(LIGHT_MODEL_LOCAL_VIEWER, 1)),
                q(GetIntegerv(LIGHT_MODEL_TWO_SIDE, 1)),
                q(GetIntegerv(LIGHT_MODEL_COLOR_CONTROL, 1)),
                q(GetFloatv(LIGHT_MODEL_COLOR_CONTROL, 1)),
            ],
        ));
    }

    // Enable, disable, queries of the switches.
    for cap in [
        LIGHTING,
        LIGHT0,
        LIGHT0 + 3,
        LIGHT_LAST,
        LIGHT_PAST_MAX,
        COLOR_MATERIAL,
        NORMALIZE,
        RESCALE_NORMAL,
        TEXTURE_2D,
        BOGUS,
    ] {
        s.push((
            format!("glEnable/glDisable(0x{cap:04X})"),
            vec![
                q(IsEnabled(cap)),
                c(Enable(cap)),
                q(IsEnabled(cap)),
                q(GetBooleanv(cap, 1)),
                q(GetIntegerv(
                    if cap == LIGHT_LAST || cap == LIGHT_PAST_MAX {
                        LIGHTING
                    } else {
                        cap
                    },
                    1,
                )),
                c(Disable(cap)),
                q(IsEnabled(cap)),
                q(GetFloatv(
                    if cap == LIGHT_LAST || cap == LIGHT_PAST_MAX {
                        LIGHTING
                    } else {
                        cap
                    },
                    1,
                )),
            ],
        ));
    }

    // Current color and shading.
    for (name, call) in [
        ("glColor4f", Color4f([0.2, 0.4, 0.6, 0.8])),
        ("glColor3f", Color3f([1.5, -0.5, 0.25])),
        ("glColor4ub", Color4ub([0, 64, 128, 255])),
        ("glColor3ub", Color3ub([255, 1, 254])),
    ] {
        s.push((
            format!("{name} sets the current color"),
            vec![
                c(call),
                q(GetFloatv(CURRENT_COLOR, 4)),
                q(GetIntegerv(CURRENT_COLOR, 4)),
                q(GetBooleanv(CURRENT_COLOR, 4)),
            ],
        ));
    }
    for mode in [FLAT, SMOOTH, BOGUS, LIGHTING] {
        s.push((
            format!("glShadeModel(0x{mode:04X})"),
            vec![
                c(ShadeModel(FLAT)),
                c(ShadeModel(mode)),
                q(GetIntegerv(SHADE_MODEL, 1)),
            ],
        ));
    }

    // Texture environment.
    for mode in [MODULATE, DECAL, BLEND, REPLACE, ADD, BOGUS] {
        s.push((
            format!("glTexEnvi(GL_TEXTURE_ENV_MODE, 0x{mode:04X})"),
            vec![
                c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, mode as i32)),
                q(GetTexEnviv(TEXTURE_ENV, TEXTURE_ENV_MODE, 1)),
                c(TexEnvf(TEXTURE_ENV, TEXTURE_ENV_MODE, mode as f32)),
                q(GetTexEnvfv(TEXTURE_ENV, TEXTURE_ENV_MODE, 1)),
            ],
        ));
    }
    s.push((
        "glTexEnvfv(GL_TEXTURE_ENV_COLOR) clamps to [0, 1]".into(),
        vec![
            c(TexEnvfv(
                TEXTURE_ENV,
                TEXTURE_ENV_COLOR,
                vec![1.5, -0.5, 0.25, 0.75],
            )),
            q(GetTexEnvfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, 4)),
            q(GetTexEnviv(TEXTURE_ENV, TEXTURE_ENV_COLOR, 4)),
        ],
    ));
    s.push((
        "glTexEnv with a bad target".into(),
        vec![
            c(TexEnvi(BOGUS, TEXTURE_ENV_MODE, DECAL as i32)),
            q(GetTexEnviv(TEXTURE_ENV, TEXTURE_ENV_MODE, 1)),
            q(GetTexEnviv(BOGUS, TEXTURE_ENV_MODE, 1)),
        ],
    ));

    // GL's error rule: the first error sticks until read.
    s.push((
        "the first error sticks until glGetError reads it".into(),
        vec![
            Step::Quiet(Lightf(LIGHT0, SPOT_CUTOFF, 91.0)),
            Step::Quiet(Enable(BOGUS)),
            Step::Quiet(Materialf(FRONT, SHININESS, 200.0)),
            q(IsEnabled(LIGHTING)),
            q(IsEnabled(LIGHTING)),
        ],
    ));
    s.push((
        "matrices: modelview and projection as loaded".into(),
        vec![
            c(LoadModelview(translate)),
            c(LoadProjection(translate)),
            q(GetFloatv(MODELVIEW_MATRIX, 16)),
            q(GetFloatv(PROJECTION_MATRIX, 16)),
            q(GetIntegerv(PROJECTION_MATRIX, 16)),
        ],
    ));
    s.push((
        "queries of unknown names are refused and write nothing".into(),
        vec![
            q(GetFloatv(BOGUS, 4)),
            q(GetLightfv(LIGHT0, SHININESS, 4)),
            q(GetMaterialfv(FRONT, POSITION, 4)),
            q(GetTexEnvfv(TEXTURE_ENV, BOGUS, 4)),
        ],
    ));
    // The stages after texturing and the current values they read (issue 49), and the clip
    // planes: each call valid and invalid, each answered through every query form.
    const FOG: u32 = 0x0B60;
    const FOG_DENSITY: u32 = 0x0B62;
    const FOG_START: u32 = 0x0B63;
    const FOG_END: u32 = 0x0B64;
    const FOG_MODE: u32 = 0x0B65;
    const FOG_COLOR: u32 = 0x0B66;
    const FOG_COORD_SRC: u32 = 0x8450;
    const FOG_COORD: u32 = 0x8451;
    const CURRENT_FOG_COORD: u32 = 0x8453;
    const FOG_HINT: u32 = 0x0C54;
    const FASTEST: u32 = 0x1101;
    const NICEST: u32 = 0x1102;
    const EXP2: u32 = 0x0801;
    const LINEAR: u32 = 0x2601;
    const ALPHA_TEST: u32 = 0x0BC0;
    const ALPHA_TEST_FUNC: u32 = 0x0BC1;
    const ALPHA_TEST_REF: u32 = 0x0BC2;
    const LESS: u32 = 0x0201;
    const GEQUAL: u32 = 0x0206;
    const COLOR_SUM: u32 = 0x8458;
    const CURRENT_SECONDARY_COLOR: u32 = 0x8459;
    const CURRENT_NORMAL: u32 = 0x0B02;
    const CURRENT_TEXTURE_COORDS: u32 = 0x0B03;
    const CLIP_PLANE0: u32 = 0x3000;
    let answers = |pname: u32, n: usize| {
        vec![
            q(GetFloatv(pname, n)),
            q(GetIntegerv(pname, n)),
            q(GetBooleanv(pname, n)),
        ]
    };
    type StageCall = (&'static str, Vec<Step>, Vec<(u32, usize)>);
    let stage_calls: Vec<StageCall> = vec![
        (
            "glFogi(GL_FOG_MODE, GL_LINEAR)",
            vec![c(Fogi(FOG_MODE, LINEAR as i32))],
            vec![(FOG_MODE, 1)],
        ),
        (
            "glFogf(GL_FOG_MODE, GL_EXP2)",
            vec![c(Fogf(FOG_MODE, EXP2 as f32))],
            vec![(FOG_MODE, 1)],
        ),
        (
            "glFogi(GL_FOG_MODE, bad)",
            vec![c(Fogi(FOG_MODE, 0x1234))],
            vec![(FOG_MODE, 1)],
        ),
        (
            "glFogf(GL_FOG_DENSITY, 0.25)",
            vec![c(Fogf(FOG_DENSITY, 0.25))],
            vec![(FOG_DENSITY, 1)],
        ),
        (
            "glFogf(GL_FOG_DENSITY, -1)",
            vec![c(Fogf(FOG_DENSITY, -1.0))],
            vec![(FOG_DENSITY, 1)],
        ),
        (
            "glFogf(GL_FOG_START, -3), glFogf(GL_FOG_END, 7)",
            vec![c(Fogf(FOG_START, -3.0)), c(Fogf(FOG_END, 7.0))],
            vec![(FOG_START, 1), (FOG_END, 1)],
        ),
        (
            "glFogfv(GL_FOG_COLOR, beyond [0, 1])",
            vec![c(Fogfv(FOG_COLOR, vec![0.25, 1.5, -0.5, 0.75]))],
            vec![(FOG_COLOR, 4)],
        ),
        (
            "glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD)",
            vec![c(Fogi(FOG_COORD_SRC, FOG_COORD as i32))],
            vec![(FOG_COORD_SRC, 1)],
        ),
        (
            "glFogi(GL_FOG_COORD_SRC, bad)",
            vec![c(Fogi(FOG_COORD_SRC, LINEAR as i32))],
            vec![(FOG_COORD_SRC, 1)],
        ),
        (
            "glFogf(GL_FOG_INDEX, 3) (color-index fog: taken, no effect, and queried)",
            vec![c(Fogf(0x0B61, 3.0))],
            vec![(FOG_MODE, 1), (0x0B61, 1)],
        ),
        (
            "glFogf(bad pname)",
            vec![c(Fogf(0x0B67, 1.0))],
            vec![(FOG_MODE, 1)],
        ),
        (
            "glFogCoordf(-2)",
            vec![c(FogCoordf(-2.0))],
            vec![(CURRENT_FOG_COORD, 1)],
        ),
        (
            "glHint(GL_FOG_HINT, GL_FASTEST)",
            vec![c(Hint(FOG_HINT, FASTEST))],
            vec![(FOG_HINT, 1)],
        ),
        (
            "glHint(GL_FOG_HINT, GL_NICEST)",
            vec![c(Hint(FOG_HINT, NICEST))],
            vec![(FOG_HINT, 1)],
        ),
        (
            "glHint(GL_FOG_HINT, bad)",
            vec![c(Hint(FOG_HINT, 0x1234))],
            vec![(FOG_HINT, 1)],
        ),
        (
            "glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_NICEST) (GL 2.0's target, no effect)",
            vec![c(Hint(0x8B8B, NICEST))],
            vec![(FOG_HINT, 1)],
        ),
        (
            "glHint(bad target)",
            vec![c(Hint(0x1234, FASTEST))],
            vec![(FOG_HINT, 1)],
        ),
        (
            "glAlphaFunc(GL_LESS, 0.5)",
            vec![c(AlphaFunc(LESS, 0.5))],
            vec![(ALPHA_TEST_FUNC, 1), (ALPHA_TEST_REF, 1)],
        ),
        (
            "glAlphaFunc(GL_GEQUAL, 1.5) (clamped)",
            vec![c(AlphaFunc(GEQUAL, 1.5))],
            vec![(ALPHA_TEST_FUNC, 1), (ALPHA_TEST_REF, 1)],
        ),
        (
            "glAlphaFunc(GL_GEQUAL, -0.5) (clamped)",
            vec![c(AlphaFunc(GEQUAL, -0.5))],
            vec![(ALPHA_TEST_REF, 1)],
        ),
        (
            "glAlphaFunc(bad)",
            vec![c(AlphaFunc(0x0208, 0.5))],
            vec![(ALPHA_TEST_FUNC, 1), (ALPHA_TEST_REF, 1)],
        ),
        (
            "glSecondaryColor3f",
            vec![c(SecondaryColor3f([0.25, 0.5, 0.75]))],
            vec![(CURRENT_SECONDARY_COLOR, 4)],
        ),
        (
            "glNormal3f",
            vec![c(Normal3f([0.5, -2.0, 0.25]))],
            vec![(CURRENT_NORMAL, 3)],
        ),
        (
            "glTexCoord4f",
            vec![c(TexCoord4f([0.75, -2.0, 0.25, 2.0]))],
            vec![(CURRENT_TEXTURE_COORDS, 4)],
        ),
    ];
    for (name, mut steps, queries) in stage_calls {
        for (pname, n) in queries {
            steps.extend(answers(pname, n));
        }
        s.push((name.to_string(), steps));
    }
    for cap in [FOG, ALPHA_TEST, COLOR_SUM, CLIP_PLANE0, CLIP_PLANE0 + 5] {
        s.push((
            format!("glEnable(0x{cap:04X}), glDisable"),
            vec![
                c(Enable(cap)),
                q(IsEnabled(cap)),
                q(GetBooleanv(cap, 1)),
                c(Disable(cap)),
                q(IsEnabled(cap)),
            ],
        ));
    }
    // Clip planes: stored in eye space at the call (modelviews exact in floats), later
    // modelview changes do not move them; a plane past Mesa's 8 is refused by both.
    let mut identity = [0.0f32; 16];
    for i in 0..4 {
        identity[i * 5] = 1.0;
    }
    let translate = {
        let mut m = [0.0f32; 16];
        for i in 0..4 {
            m[i * 5] = if i == 3 { 1.0 } else { 2.0 };
        }
        m[12] = 0.5;
        m[13] = -1.0;
        m
    };
    s.push((
        "glClipPlane under a scale and translation".to_string(),
        vec![
            c(LoadModelview(translate)),
            c(ClipPlane(CLIP_PLANE0, [1.0, 0.5, 0.0, 0.25])),
            q(GetClipPlane(CLIP_PLANE0)),
            c(LoadModelview(identity)),
            q(GetClipPlane(CLIP_PLANE0)),
            c(ClipPlane(CLIP_PLANE0 + 5, [0.0, 0.0, 1.0, -2.0])),
            q(GetClipPlane(CLIP_PLANE0 + 5)),
        ],
    ));
    s.push((
        "glClipPlane(bad plane), glGetClipPlane(bad plane)".to_string(),
        vec![
            c(ClipPlane(CLIP_PLANE0 + 8, [1.0, 0.0, 0.0, 0.0])),
            q(GetClipPlane(CLIP_PLANE0 + 8)),
        ],
    ));
    // Points (issue 50): glPointParameter valid and invalid, GL_POINT_SPRITE, GL_COORD_REPLACE,
    // each answered through every query form.
    const POINT_SIZE_MIN: u32 = 0x8126;
    const POINT_SIZE_MAX: u32 = 0x8127;
    const POINT_FADE_THRESHOLD_SIZE: u32 = 0x8128;
    const POINT_DISTANCE_ATTENUATION: u32 = 0x8129;
    const POINT_SPRITE: u32 = 0x8861;
    const COORD_REPLACE: u32 = 0x8862;
    const POINT_SPRITE_COORD_ORIGIN: u32 = 0x8CA0;
    const LOWER_LEFT: u32 = 0x8CA1;
    let points = [
        POINT_SIZE_MIN,
        POINT_FADE_THRESHOLD_SIZE,
        POINT_SPRITE_COORD_ORIGIN,
    ];
    // (name, calls, the names queried and their value counts)
    type Case = (&'static str, Vec<Call>, Vec<(u32, usize)>);
    let point_cases: Vec<Case> = vec![
        (
            "glPointParameterf(GL_POINT_SIZE_MIN, 2.5)",
            vec![Call::PointParameterf(POINT_SIZE_MIN, 2.5)],
            vec![(POINT_SIZE_MIN, 1)],
        ),
        (
            "glPointParameterf(GL_POINT_SIZE_MIN, -1) (GL_INVALID_VALUE)",
            vec![Call::PointParameterf(POINT_SIZE_MIN, -1.0)],
            vec![(POINT_SIZE_MIN, 1)],
        ),
        (
            "glPointParameterf(GL_POINT_SIZE_MAX, 12)",
            vec![Call::PointParameterf(POINT_SIZE_MAX, 12.0)],
            vec![(POINT_SIZE_MAX, 1)],
        ),
        (
            "glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -0.5) (GL_INVALID_VALUE)",
            vec![Call::PointParameterf(POINT_FADE_THRESHOLD_SIZE, -0.5)],
            vec![(POINT_FADE_THRESHOLD_SIZE, 1)],
        ),
        (
            "glPointParameteri(GL_POINT_FADE_THRESHOLD_SIZE, 3)",
            vec![Call::PointParameteri(POINT_FADE_THRESHOLD_SIZE, 3)],
            vec![(POINT_FADE_THRESHOLD_SIZE, 1)],
        ),
        (
            "glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, (0.5, 0.25, 0.125))",
            vec![Call::PointParameterfv(
                POINT_DISTANCE_ATTENUATION,
                vec![0.5, 0.25, 0.125],
            )],
            vec![(POINT_DISTANCE_ATTENUATION, 3)],
        ),
        (
            "glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 1) (a vector name: GL_INVALID_ENUM)",
            vec![Call::PointParameterf(POINT_DISTANCE_ATTENUATION, 1.0)],
            vec![(POINT_DISTANCE_ATTENUATION, 3)],
        ),
        (
            "glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT)",
            vec![Call::PointParameteri(
                POINT_SPRITE_COORD_ORIGIN,
                LOWER_LEFT as i32,
            )],
            vec![(POINT_SPRITE_COORD_ORIGIN, 1)],
        ),
        (
            "glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, bad)",
            vec![Call::PointParameteri(POINT_SPRITE_COORD_ORIGIN, 0x1234)],
            vec![(POINT_SPRITE_COORD_ORIGIN, 1)],
        ),
        (
            "glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, 2) (neither GL_TRUE nor GL_FALSE)",
            vec![Call::TexEnvi(POINT_SPRITE, COORD_REPLACE, 2)],
            vec![(POINT_SPRITE, 1)],
        ),
        (
            "glPointParameterf(bad pname)",
            vec![Call::PointParameterf(0x812A, 1.0)],
            vec![(POINT_SIZE_MIN, 1)],
        ),
        (
            "glEnable(GL_POINT_SPRITE), glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE)",
            vec![
                Call::Enable(POINT_SPRITE),
                Call::TexEnvi(POINT_SPRITE, COORD_REPLACE, 1),
            ],
            vec![(POINT_SPRITE, 1)],
        ),
    ];
    for (name, calls, names) in point_cases {
        let mut steps: Vec<Step> = calls.into_iter().map(c).collect();
        for (pname, n) in names.into_iter().chain(points.map(|p| (p, 1))) {
            steps.push(q(GetFloatv(pname, n)));
            steps.push(q(GetIntegerv(pname, n)));
            steps.push(q(GetBooleanv(pname, n)));
        }
        steps.push(q(IsEnabled(POINT_SPRITE)));
        steps.push(q(GetTexEnviv(POINT_SPRITE, COORD_REPLACE, 1)));
        steps.push(q(GetTexEnvfv(POINT_SPRITE, 0x1234, 1)));
        s.push((name.to_string(), steps));
    }
    s.extend(raster::sequences());
    s.extend(texgen::sequences());
    s.extend(combine::sequences());
    s.extend(units::sequences());
    s
}

fn identity() -> [f32; 16] {
    let mut m = [0.0; 16];
    for i in 0..4 {
        m[i * 5] = 1.0;
    }
    m
}

#[test]
fn gl_call_sequences_set_the_same_errors_and_answer_the_same_queries_through_the_c_api_as_in_mesa_gl() {
    let table = sequences();
    assert!(
        table.len() >= 200,
        "the table has {} sequences: expected at least 200",
        table.len()
    );

    let mut ffvk = Ffvk {
        ctx: ffvk_c::gl::ffvkCreateContext(),
    };
    let ffvk_answers: Vec<Vec<Answer>> = table.iter().map(|(_, steps)| ffvk.run(steps)).collect();
    let mesa_answers = with_raw_gl(|gl| {
        // SAFETY: the context is current; the stack's bottom entry holds GL's initial state.
        unsafe { gl.PushAttrib(raw::ALL_ATTRIB_BITS) };
        let mut mesa = Mesa { gl };
        let answers: Vec<Vec<Answer>> = table.iter().map(|(_, steps)| mesa.run(steps)).collect();
        let max = mesa.max_lights();
        (answers, max, mesa.units())
    })
    .expect("Mesa's GL through EGL (make test installs it)");
    let (mesa_answers, mesa_max, mesa_units) = mesa_answers;
    assert!(
        mesa_max >= 8 && ffvk.max_lights() >= 8,
        "GL_MAX_LIGHTS must be at least 8"
    );
    // Each implementation answers its own unit limits (GL 2.1 table 6.44: at least 2), which the
    // sequences' unit sentinels stand for; ffvk's are 4 through every query form.
    assert_eq!(
        ffvk.units(),
        Units {
            units: 4,
            coords: 4,
            active: 4
        }
    );
    for pname in [MAX_TEXTURE_UNITS, MAX_TEXTURE_COORDS] {
        for query in [
            Query::GetFloatv(pname, 1),
            Query::GetIntegerv(pname, 1),
            Query::GetBooleanv(pname, 1),
        ] {
            let expected = if matches!(query, Query::GetBooleanv(..)) {
                1.0
            } else {
                4.0
            };
            assert_eq!(ffvk.query(query), [expected], "{query:?}");
            assert_eq!(ffvk.error(), 0);
        }
    }
    assert!(
        mesa_units.units >= 2
            && mesa_units.coords >= mesa_units.units
            && mesa_units.active >= mesa_units.coords,
        "Mesa's unit limits {mesa_units:?}"
    );
    eprintln!("texture units: ffvk {:?}, Mesa {mesa_units:?}", ffvk.units());

    let mut unexplained = Vec::new();
    let mut seen = [0usize; DEVIATIONS.len()];
    let mut compared = 0;
    for (((name, steps), ours), theirs) in table.iter().zip(&ffvk_answers).zip(&mesa_answers) {
        for ((step, a), b) in steps.iter().zip(ours).zip(theirs) {
            compared += 1;
            if !agree(a, b) {
                match deviation(steps, step, a, b) {
                    Some(d) => seen[d] += 1,
                    None => unexplained.push(format!("{name}: after {step:?}: ffvk {a:?}, Mesa {b:?}")),
                }
            }
        }
    }
    for (d, count) in DEVIATIONS.iter().zip(seen) {
        eprintln!("{count:>3} steps: {d}");
    }
    eprintln!(
        "{} sequences, {compared} steps compared (errors and values)",
        table.len()
    );
    assert!(
        unexplained.is_empty(),
        "{} differences from Mesa's GL:\n{}",
        unexplained.len(),
        unexplained.join("\n")
    );
    let unseen: Vec<_> = DEVIATIONS
        .iter()
        .zip(seen)
        .filter(|(_, n)| *n == 0)
        .map(|(d, _)| *d)
        .collect();
    assert!(
        unseen.is_empty(),
        "listed as Mesa deviations but not seen any more: {unseen:?}"
    );
}
