//! The fixed-function stages after texturing that a draw's state carries
//! ([`FragmentStages`]): the color sum (GL 2.1 §3.9) and the alpha test (§4.1.4), in GL's
//! order; fog (§3.10) joins them between the two.

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
    /// The alpha test.
    pub alpha_test: AlphaTest,
}
