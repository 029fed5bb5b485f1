//! The fixed-function stages after texturing that a draw's state carries
//! ([`FragmentStages`]), in GL's order: the color sum (GL 2.1 §3.9), fog (§3.10) and the alpha
//! test (§4.1.4).

/// A comparison function of GL's (`glAlphaFunc`, and later `glDepthFunc` and `glStencilFunc`):
/// the test passes when `value func reference`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum CompareFunc {
    /// `GL_NEVER`.
    Never,
    /// `GL_LESS`.
    Less,
    /// `GL_EQUAL`.
    Equal,
    /// `GL_LEQUAL`.
    LessOrEqual,
    /// `GL_GREATER`.
    Greater,
    /// `GL_NOTEQUAL`.
    NotEqual,
    /// `GL_GEQUAL`.
    GreaterOrEqual,
    /// `GL_ALWAYS` (the alpha test's default).
    #[default]
    Always,
}

impl CompareFunc {
    /// The eight, in GL's enum order (`GL_NEVER` = 0x0200 .. `GL_ALWAYS` = 0x0207).
    pub const ALL: [CompareFunc; 8] = [
        CompareFunc::Never,
        CompareFunc::Less,
        CompareFunc::Equal,
        CompareFunc::LessOrEqual,
        CompareFunc::Greater,
        CompareFunc::NotEqual,
        CompareFunc::GreaterOrEqual,
        CompareFunc::Always,
    ];

    /// Its place in GL's enum order, 0 (`GL_NEVER`) to 7 (`GL_ALWAYS`): GL's value is 0x0200
    /// plus this, and the shaders' `SPEC_ALPHA_FUNC` takes it.
    pub fn code(self) -> u32 {
        self as u32
    }

    /// GL's name.
    pub fn gl_name(self) -> &'static str {
        match self {
            CompareFunc::Never => "GL_NEVER",
            CompareFunc::Less => "GL_LESS",
            CompareFunc::Equal => "GL_EQUAL",
            CompareFunc::LessOrEqual => "GL_LEQUAL",
            CompareFunc::Greater => "GL_GREATER",
            CompareFunc::NotEqual => "GL_NOTEQUAL",
            CompareFunc::GreaterOrEqual => "GL_GEQUAL",
            CompareFunc::Always => "GL_ALWAYS",
        }
    }

    /// Whether `value func reference` holds.
    pub fn passes<T: PartialOrd>(self, value: T, reference: T) -> bool {
        match self {
            CompareFunc::Never => false,
            CompareFunc::Less => value < reference,
            CompareFunc::Equal => value == reference,
            CompareFunc::LessOrEqual => value <= reference,
            CompareFunc::Greater => value > reference,
            CompareFunc::NotEqual => value != reference,
            CompareFunc::GreaterOrEqual => value >= reference,
            CompareFunc::Always => true,
        }
    }
}

/// `GL_ALPHA_TEST` and `glAlphaFunc` (§4.1.4): a fragment is kept when its final alpha (after
/// texturing and the color sum) compares with the reference as `func` says. GL compares both
/// at the color buffer's fixed-point precision: on an 8-bit UNORM target, round(a × 255)
/// against round(ref × 255).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct AlphaTest {
    /// `GL_ALPHA_TEST`; off by default.
    pub enabled: bool,
    /// `GL_ALPHA_TEST_FUNC`; `GL_ALWAYS` by default.
    pub func: CompareFunc,
    /// `GL_ALPHA_TEST_REF`, clamped to [0, 1] when set (GL's rule); 0 by default.
    pub reference: f32,
}

impl Default for AlphaTest {
    fn default() -> Self {
        AlphaTest {
            enabled: false,
            func: CompareFunc::Always,
            reference: 0.0,
        }
    }
}

impl AlphaTest {
    /// The function the pipeline applies: `Always` while the test is disabled, so that a
    /// disabled test and `GL_ALWAYS` share a pipeline.
    pub fn effective_func(&self) -> CompareFunc {
        if self.enabled {
            self.func
        } else {
            CompareFunc::Always
        }
    }
}

/// The fragment stages after texturing a draw's state carries, in GL's order.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub struct FragmentStages {
    /// `GL_COLOR_SUM` (EXT_secondary_color, §3.9); off by default. With lighting off, it adds
    /// the secondary color (the layout's array or the current secondary color) to the primary
    /// after texturing; with lighting on GL always sums (the separate specular color).
    pub color_sum: bool,
    /// Fog, after the color sum.
    pub fog: Fog,
    /// The alpha test, last.
    pub alpha_test: AlphaTest,
}

/// `GL_FOG_MODE` (§3.10): how the fog factor f falls with the distance c.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum FogMode {
    /// `GL_LINEAR`: f = (end − c) / (end − start).
    Linear,
    /// `GL_EXP` (GL's default): f = exp(−density · c).
    #[default]
    Exp,
    /// `GL_EXP2`: f = exp(−(density · c)²).
    Exp2,
}

impl FogMode {
    /// The shaders' `SPEC_FOG_MODE` for this mode with fog on: 1 linear, 2 exp, 3 exp2 (0 is
    /// fog off).
    pub fn code(self) -> u32 {
        match self {
            FogMode::Linear => 1,
            FogMode::Exp => 2,
            FogMode::Exp2 => 3,
        }
    }

    /// GL's name.
    pub fn gl_name(self) -> &'static str {
        match self {
            FogMode::Linear => "GL_LINEAR",
            FogMode::Exp => "GL_EXP",
            FogMode::Exp2 => "GL_EXP2",
        }
    }
}

/// `GL_FOG_COORD_SRC` (EXT_fog_coord): where the fog's distance c comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum FogSource {
    /// `GL_FRAGMENT_DEPTH` (the default): the eye-space distance, taken as |z_e| (the
    /// approximation GL 2.1 allows and Mesa uses).
    #[default]
    FragmentDepth,
    /// `GL_FOG_COORD`: the fog coordinate (a layout's array or the current one,
    /// `glFogCoord`), as it is: GL 2.1 takes no absolute value (Mesa does).
    FogCoord,
}

/// `GL_FOG_HINT`: where ffvk computes f. `GL_FASTEST` per vertex, interpolated (GL 2.1
/// allows it; Mesa ignores the hint); the others per fragment from the interpolated c.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum FogHint {
    /// `GL_DONT_CARE` (the default): per fragment.
    #[default]
    DontCare,
    /// `GL_FASTEST`: per vertex.
    Fastest,
    /// `GL_NICEST`: per fragment.
    Nicest,
}

impl FogHint {
    /// Whether f is computed per vertex.
    pub fn per_vertex(self) -> bool {
        self == FogHint::Fastest
    }
}

/// Fog (§3.10): after texturing and the color sum, each fragment's RGB becomes
/// f · rgb + (1 − f) · color.rgb, f clamped to [0, 1]; alpha is untouched.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Fog {
    /// `GL_FOG`; off by default.
    pub enabled: bool,
    /// `GL_FOG_MODE`; `GL_EXP` by default.
    pub mode: FogMode,
    /// `GL_FOG_DENSITY`, ≥ 0; 1 by default.
    pub density: f32,
    /// `GL_FOG_START`; 0 by default.
    pub start: f32,
    /// `GL_FOG_END`; 1 by default.
    pub end: f32,
    /// `GL_FOG_COLOR`, clamped to [0, 1] when set; (0, 0, 0, 0) by default.
    pub color: glam::Vec4,
    /// `GL_FOG_COORD_SRC`.
    pub source: FogSource,
    /// `GL_FOG_HINT`.
    pub hint: FogHint,
}

impl Default for Fog {
    fn default() -> Self {
        Fog {
            enabled: false,
            mode: FogMode::Exp,
            density: 1.0,
            start: 0.0,
            end: 1.0,
            color: glam::Vec4::ZERO,
            source: FogSource::FragmentDepth,
            hint: FogHint::DontCare,
        }
    }
}

impl Fog {
    /// The shaders' `SPEC_FOG_MODE`: 0 with fog off, else [`FogMode::code`].
    pub fn mode_code(&self) -> u32 {
        if self.enabled {
            self.mode.code()
        } else {
            0
        }
    }

    /// GL 2.1's fog factor for distance `c`, clamped to [0, 1] (`GL_LINEAR` with end = start,
    /// which GL leaves undefined, gives 1: no fog, as Mesa's scale of 1 with no divide does
    /// for c = start), in double precision (the CPU reference's).
    pub fn factor(&self, c: f64) -> f64 {
        let (start, end, density) = (
            f64::from(self.start),
            f64::from(self.end),
            f64::from(self.density),
        );
        let f = match self.mode {
            FogMode::Linear if end == start => 1.0,
            FogMode::Linear => (end - c) / (end - start),
            FogMode::Exp => (-density * c).exp(),
            FogMode::Exp2 => (-(density * c) * (density * c)).exp(),
        };
        f.clamp(0.0, 1.0)
    }
}

/// Parameters of glFog.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum FogParam {
    /// `GL_FOG_MODE`.
    Mode(FogMode),
    /// `GL_FOG_DENSITY`: a negative value is GL's `GL_INVALID_VALUE`.
    Density(f32),
    /// `GL_FOG_START`.
    Start(f32),
    /// `GL_FOG_END`.
    End(f32),
    /// `GL_FOG_COLOR`: clamped to [0, 1] as GL does.
    Color(glam::Vec4),
    /// `GL_FOG_COORD_SRC`.
    CoordSrc(FogSource),
}
