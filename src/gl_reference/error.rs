//! Why the GL reference could not render.

/// The Debian packages that give EGL and Mesa's GL at run time (the README, docs/conformance.md
/// and `scripts/setup-deps.sh --test` name the same).
const DEBIAN_PACKAGES: &str = "libegl1 libegl-mesa0 libgl1-mesa-dri";

/// An error of the GL reference renderer ([`super::render_gl`] and the others).
#[derive(Debug, thiserror::Error)]
pub enum GlError {
    /// No usable GL on this machine: no EGL library, or no EGL display that gives a desktop
    /// OpenGL compatibility context.
    #[error("no GL driver: {0}")]
    NoDriver(#[from] NoDriver),

    /// GL works, but on no device that [`super::GlOptions`] asks for.
    #[error("GL reference: no EGL device matches {wanted}; tried: {}", .tried.join("; "))]
    NoMatchingDevice { wanted: String, tried: Vec<String> },

    /// An EGL call that failed on the display and context already chosen.
    #[error("GL reference: {call} failed: {error}")]
    Egl {
        call: &'static str,
        error: khronos_egl::Error,
    },

    /// Error flags GL raised (`glGetError`), and when.
    #[error("GL reference: GL error {} {when}", hex_codes(.codes))]
    Gl { codes: Vec<u32>, when: String },

    /// A framebuffer size of zero, or more than GL_MAX_RENDERBUFFER_SIZE or memory allow.
    #[error("GL reference: a {width}x{height} framebuffer is {problem}")]
    Size {
        width: u32,
        height: u32,
        problem: String,
    },

    /// A context without framebuffer objects.
    #[error(
        "GL reference: GL {version} has no framebuffer objects (expected GL 3.0, \
         GL_ARB_framebuffer_object or GL_EXT_framebuffer_object)"
    )]
    NoFramebufferObjects { version: String },

    /// glCheckFramebufferStatus said other than GL_FRAMEBUFFER_COMPLETE.
    #[error("GL reference: the RGBA8 + DEPTH24 framebuffer object is incomplete (status 0x{status:04X})")]
    IncompleteFramebuffer { status: u32 },

    /// glGetString returned NULL.
    #[error("GL reference: glGetString(0x{0:04X}) returned NULL")]
    NullString(u32),

    /// One draw of the scene could not be made.
    #[error("GL reference: draw {index}: {problem}")]
    Draw { index: usize, problem: DrawError },

    /// [`super::time_frames`] with no warm-up frame.
    #[error("GL reference: time_frames needs at least one warm-up frame")]
    NoWarmup,
}

/// Why there is no usable GL driver.
#[derive(Debug, thiserror::Error)]
pub enum NoDriver {
    /// The EGL library could not be opened (or lacks EGL 1.4's entry points).
    #[error(
        "cannot load the EGL library {library}: {source} (on Debian: apt-get install {DEBIAN_PACKAGES})"
    )]
    Library {
        library: String,
        source: khronos_egl::LoadError<libloading::Error>,
    },

    /// EGL without client extensions: glvnd's libEGL with no vendor library (Mesa's
    /// libEGL_mesa.so.0, NVIDIA's) installed or loadable.
    #[error(
        "{library} has no EGL driver (no client extensions; glvnd finds its vendor libraries \
         through /usr/share/glvnd/egl_vendor.d; on Debian: apt-get install {DEBIAN_PACKAGES})"
    )]
    NoVendor { library: String },

    /// EGL without either platform this renderer can open without a window system.
    #[error(
        "EGL offers neither EGL_EXT_platform_device nor EGL_MESA_platform_surfaceless \
         (client extensions: {extensions:?}; on Debian: apt-get install {DEBIAN_PACKAGES})"
    )]
    NoPlatform { extensions: String },

    /// Every display that was tried failed; each entry says which and why.
    #[error(
        "no EGL display gave a desktop OpenGL compatibility context: {} \
         (on Debian: apt-get install {DEBIAN_PACKAGES})",
        .tried.join("; ")
    )]
    NoContext { tried: Vec<String> },
}

/// Why one draw could not be made.
#[derive(Debug, thiserror::Error)]
pub enum DrawError {
    /// An enabled light at an index GL does not have.
    #[error("light {index} is enabled but this GL has GL_MAX_LIGHTS = {max_lights}")]
    TooManyLights { index: usize, max_lights: usize },

    /// An index past the mesh's vertices.
    #[error("index {index} is out of range for a mesh of {vertices} vertices")]
    IndexOutOfRange { index: u32, vertices: usize },

    /// An edge flag array whose length is not the mesh's vertex count.
    #[error("{flags} edge flags for a mesh of {vertices} vertices: expected one per vertex")]
    EdgeFlagCount { flags: usize, vertices: usize },

    /// A draw reading the mesh's second texture coordinates where it has not one per vertex.
    #[error("{count} second texture coordinates for a mesh of {vertices} vertices: expected one per vertex")]
    SecondTexcoordCount { count: usize, vertices: usize },

    /// A timed draw reading the mesh's second texture coordinates (the timed frames draw from
    /// buffer objects of the interleaved vertices alone).
    #[error("the timed frames draw the interleaved vertices alone: expected no second_texcoords")]
    SecondTexcoordsTimed,

    /// More indices than one glDrawElements takes.
    #[error("{0} indices are too many for one draw")]
    TooManyIndices(usize),

    /// More bytes than a buffer object takes.
    #[error("{0} bytes are too many for a buffer")]
    TooManyBytes(usize),

    /// A texture level whose bytes are not width × height × 4 (glTexImage2D would read past
    /// them), or whose size does not fit GL's.
    #[error("texture level {level} is {width}x{height} with {bytes} bytes: expected width × height × 4 bytes and sides that fit a GLsizei")]
    TextureLevel {
        level: usize,
        width: u32,
        height: u32,
        bytes: usize,
    },

    /// GL raised errors for this draw's calls.
    #[error("GL error {} {when}", hex_codes(.codes))]
    Gl { codes: Vec<u32>, when: &'static str },
}

fn hex_codes(codes: &[u32]) -> String {
    codes
        .iter()
        .map(|c| format!("0x{c:04X}"))
        .collect::<Vec<_>>()
        .join(", ")
}
