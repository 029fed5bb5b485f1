//! What a sweep measures: its configuration and what a point is (modes, densities, image
//! sizes, light counts and kinds, pipeline variants); the points themselves and the scene
//! of each are in `points.rs`.

use serde::{Deserialize, Serialize};

use crate::{Error, Result};
use ffvk::gl::state::LightingMode;

/// A sweep: which points, how many frames each.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepConfig {
    /// The sweep's name ("quick", "standard", "full", "tiny").
    pub name: String,
    /// Unmeasured frames first (at least one: it compiles what the point needs).
    pub warmup: u32,
    /// Measured frames per point (at least one).
    pub frames: u32,
    /// Densities of the density sweep, as sphere stacks (slices = 2 × stacks;
    /// (2s + 1)(s + 1) vertices).
    pub stacks: Vec<u32>,
    /// Image sides of the size sweep (square images).
    pub sizes: Vec<u32>,
    /// Light counts of the light-count sweep (directional lights).
    pub light_counts: Vec<usize>,
    /// Light kinds of the light-kind sweep, each with an infinite and a local viewer.
    pub kinds: Vec<LightKind>,
    /// Lights in the light-kind sweep.
    pub kind_lights: usize,
    /// Directional lights in the density and size sweeps.
    pub base_lights: usize,
    /// The mesh of the light-count and light-kind sweeps.
    pub base_stacks: u32,
    /// The mesh of the size sweep: dense enough that per-vertex and per-fragment lighting
    /// cross over within its image sizes.
    pub size_stacks: u32,
    /// The image side of every sweep but the size sweep.
    pub base_size: u32,
    /// Run the density and size sweeps with the uber-shader too (the light sweeps always
    /// run both variants).
    pub variants_everywhere: bool,
    /// Draw the OpenGL anchor points (left out, with a note, when no GL driver is found).
    pub gl: bool,
    /// Whether the process keeps freed heap memory (`--malloc-no-trim`). [`run`](super::run)
    /// sets the allocator up, process-wide; [`run_sweep`](super::run_sweep) only records this.
    pub malloc_no_trim: bool,
    /// Draws per frame of the recording-cost measurement, each with its own state.
    pub record_draws: usize,
    /// Draws of the point's sphere per frame, each a little nearer than the last so that
    /// every one passes the depth test and is lit in full: work enough per frame that a
    /// GPU's fixed cost per frame does not hide the lighting.
    pub draws: u32,
    /// Time the measured frames of a point in one submission ([`Renderer::measure_frames`]),
    /// and GL's with GL_TIME_ELAPSED queries where the driver has them: GPU time without
    /// submission and waiting, which on a GPU are larger than a frame's work.
    ///
    /// [`Renderer::measure_frames`]: ffvk::Renderer::measure_frames
    pub batch: bool,
    /// New specialization keys whose pipeline creation is timed (at most 16).
    pub new_keys: usize,
    /// Draws per frame of the draws sweep ([`super::draws`]), each with its own material; empty
    /// leaves the sweep out.
    pub draw_counts: Vec<u32>,
    /// The fragment sweep's mesh (sphere stacks): per-fragment lighting against per-vertex
    /// lighting and the unlit floor on a dense mesh, issue 37's baseline.
    pub fragment_stacks: u32,
    /// Directional lights in the fragment sweep.
    pub fragment_lights: usize,
    /// Image sides of the fragment sweep; empty leaves it out.
    pub fragment_sizes: Vec<u32>,
    /// The paths sweep ([`Group::Paths`]): the fragment mode forward and deferred on the
    /// sphere with these stacks, …
    pub path_stacks: Vec<u32>,
    /// … at these image sides …
    pub path_sizes: Vec<u32>,
    /// … under these directional light counts; any of the three empty leaves it out.
    pub path_lights: Vec<usize>,
    /// Whether the primitives group runs.
    pub primitives: bool,
    /// Whether the stages group runs ([`Group::Stages`]): what fog, the alpha test, the color
    /// sum and user clip planes cost in each lighting mode.
    pub stages: bool,
    /// ffvk's own executable, which times the zink anchor in a process of its own
    /// ([`super::zink`]); `None` leaves zink out.
    #[serde(skip)]
    pub zink: Option<std::path::PathBuf>,
}

impl SweepConfig {
    /// About a minute on 2 cores.
    pub fn quick() -> Self {
        SweepConfig {
            name: "quick".into(),
            warmup: 2,
            frames: 5,
            stacks: vec![8, 32, 128, 512, 768],
            sizes: vec![128, 256, 512, 1024],
            light_counts: vec![1, 4, 8],
            kinds: LightKind::ALL.to_vec(),
            kind_lights: 4,
            base_lights: 4,
            base_stacks: 128,
            size_stacks: 256,
            base_size: 512,
            variants_everywhere: false,
            gl: true,
            malloc_no_trim: false,
            record_draws: 10_000,
            new_keys: 8,
            draw_counts: DRAW_COUNTS.to_vec(),
            draws: 1,
            batch: false,
            fragment_stacks: 512,
            fragment_lights: 8,
            fragment_sizes: vec![1024],
            path_stacks: Vec::new(),
            path_sizes: Vec::new(),
            path_lights: Vec::new(),
            primitives: true,
            stages: true,
            zink: None,
        }
    }

    /// The default: about 4 minutes on 2 cores, from 153 to 2.1 million vertices and from
    /// 64² to 2048².
    pub fn standard() -> Self {
        SweepConfig {
            name: "standard".into(),
            warmup: 3,
            frames: 11,
            stacks: vec![8, 16, 32, 64, 128, 256, 512, 768, 1024],
            sizes: vec![64, 128, 256, 512, 1024, 2048],
            light_counts: vec![1, 2, 4, 8, 16],
            base_stacks: 256,
            size_stacks: 512,
            fragment_sizes: vec![1024, 2048],
            ..SweepConfig::quick()
        }
    }

    /// More of everything: about 25 minutes on 2 cores.
    pub fn full() -> Self {
        SweepConfig {
            name: "full".into(),
            warmup: 4,
            frames: 17,
            stacks: vec![8, 16, 32, 64, 128, 256, 384, 512, 768, 1024],
            sizes: vec![64, 96, 128, 192, 256, 384, 512, 768, 1024, 1536, 2048],
            light_counts: vec![1, 2, 3, 4, 6, 8, 12, 16],
            variants_everywhere: true,
            path_stacks: SweepConfig::PATH_STACKS.to_vec(),
            path_sizes: SweepConfig::PATH_SIZES.to_vec(),
            path_lights: SweepConfig::PATH_LIGHTS.to_vec(),
            ..SweepConfig::standard()
        }
    }

    const PATH_STACKS: [u32; 5] = [32, 64, 128, 256, 512];
    const PATH_SIZES: [u32; 4] = [256, 512, 1024, 2048];
    const PATH_LIGHTS: [usize; 4] = [1, 2, 4, 8];

    /// The paths sweep alone (about 3 minutes on 2 cores): where the fragment mode's
    /// deferred path beats the forward one, over 2,145 to 525,825 vertices, 256² to 2048²
    /// and 1, 2, 4 and 8 lights; the constants of [`FragmentPath::Auto`](ffvk::FragmentPath::Auto)
    /// come from it. On a GPU (`gpu`) the frames draw the sphere 16 times and are timed in
    /// batches, as in [`SweepConfig::gpu`].
    pub fn paths(gpu: bool) -> Self {
        let base = SweepConfig {
            name: "paths".into(),
            warmup: 2,
            frames: 7,
            stacks: Vec::new(),
            sizes: Vec::new(),
            light_counts: Vec::new(),
            kinds: Vec::new(),
            gl: false,
            record_draws: 200,
            new_keys: 1,
            draw_counts: Vec::new(),
            fragment_sizes: Vec::new(),
            path_stacks: SweepConfig::PATH_STACKS.to_vec(),
            path_sizes: SweepConfig::PATH_SIZES.to_vec(),
            path_lights: SweepConfig::PATH_LIGHTS.to_vec(),
            primitives: false,
            stages: false,
            ..SweepConfig::quick()
        };
        match gpu {
            true => SweepConfig {
                warmup: 10,
                frames: 21,
                draws: 16,
                batch: true,
                ..base
            },
            false => base,
        }
    }

    /// The draws sweep alone (about 2 minutes on 2 cores): the many-draws frames of
    /// [`super::draws`] with their anchors, at the standard sweep's frames, and nothing else.
    pub fn draws_only() -> Self {
        SweepConfig {
            name: "draws".into(),
            stacks: Vec::new(),
            sizes: Vec::new(),
            light_counts: Vec::new(),
            kinds: Vec::new(),
            record_draws: 0,
            fragment_sizes: Vec::new(),
            primitives: false,
            stages: false,
            ..SweepConfig::standard()
        }
    }

    /// The stages sweep alone (about 2 minutes on 2 cores): what fog, the alpha test, the color
    /// sum and clip planes cost in each mode, at the standard sweep's frames.
    pub fn stages_only() -> Self {
        SweepConfig {
            name: "stages".into(),
            primitives: false,
            stages: true,
            draw_counts: Vec::new(),
            ..SweepConfig::draws_only()
        }
    }

    /// A few tiny points, one or two frames each: proves the harness works (tests).
    pub fn tiny() -> Self {
        SweepConfig {
            name: "tiny".into(),
            warmup: 1,
            frames: 2,
            stacks: vec![4, 8],
            sizes: vec![16, 32],
            light_counts: vec![1, 2],
            kinds: vec![LightKind::Directional, LightKind::Spot, LightKind::SpotSmoothstep],
            kind_lights: 2,
            base_lights: 1,
            base_stacks: 6,
            size_stacks: 5,
            base_size: 24,
            variants_everywhere: false,
            gl: true,
            malloc_no_trim: false,
            record_draws: 200,
            new_keys: 1,
            draw_counts: vec![1, 16],
            draws: 1,
            batch: false,
            fragment_stacks: 6,
            fragment_lights: 2,
            fragment_sizes: vec![16, 24],
            path_stacks: vec![4, 8],
            path_sizes: vec![16],
            path_lights: vec![1, 2],
            primitives: true,
            stages: true,
            zink: None,
        }
    }

    /// The sweep for GPUs (chosen for discrete, integrated and virtual GPUs): 16 draws per
    /// frame, frames timed in batches, images up to 4096², up to 16 lights, 2.1 million
    /// vertices per draw. A GPU runs the standard sweep's frames in tens of microseconds,
    /// where the fixed cost of a frame is as large as its lighting.
    pub fn gpu() -> Self {
        SweepConfig {
            name: "gpu".into(),
            warmup: 20,
            frames: 51,
            stacks: vec![8, 16, 32, 64, 128, 256, 512, 1024],
            sizes: vec![256, 512, 1024, 2048, 4096],
            light_counts: vec![1, 2, 4, 8, 12, 16],
            base_stacks: 128,
            size_stacks: 128,
            base_size: 1024,
            draws: 16,
            batch: true,
            ..SweepConfig::standard()
        }
    }

    /// [`SweepConfig::tiny`] the way the GPU sweep runs it: several draws per frame, frames
    /// timed in batches (tests).
    pub fn tiny_batched() -> Self {
        SweepConfig {
            name: "tiny-batched".into(),
            draws: 3,
            batch: true,
            ..SweepConfig::tiny()
        }
    }
    pub(super) fn validate(&self) -> Result<()> {
        let bad = |what: String| Err(Error::Bench(what));
        if !(1..=MAX_DRAWS).contains(&self.draws) {
            return bad(format!(
                "{} draws per frame: expected 1..={MAX_DRAWS}",
                self.draws
            ));
        }
        if self.batch && self.frames > ffvk::renderer::MAX_REPEAT {
            return bad(format!(
                "{} frames in one batch: expected at most {}",
                self.frames,
                ffvk::renderer::MAX_REPEAT
            ));
        }
        if let Some(n) = self
            .draw_counts
            .iter()
            .find(|&&n| !(1..=MAX_DRAW_COUNT).contains(&n))
        {
            return bad(format!(
                "{n} draws in the draws sweep: expected 1..={}",
                MAX_DRAW_COUNT
            ));
        }
        if self.warmup == 0 || self.frames == 0 {
            return bad(format!(
                "warm-up {} and frames {}: expected at least 1 of each",
                self.warmup, self.frames
            ));
        }
        let max_lights = ffvk::gl::state::MAX_LIGHTS;
        if let Some(n) = self
            .light_counts
            .iter()
            .chain([&self.kind_lights, &self.base_lights, &self.fragment_lights])
            .chain(&self.path_lights)
            .find(|&&n| n == 0 || n > max_lights)
        {
            return bad(format!("{n} lights: expected 1..={max_lights}"));
        }
        if let Some(s) = self
            .sizes
            .iter()
            .chain(&self.fragment_sizes)
            .chain(&self.path_sizes)
            .chain([&self.base_size])
            .find(|&&s| s == 0 || s > ffvk::scene::MAX_SIZE)
        {
            return bad(format!("image size {s}: expected 1..={}", ffvk::scene::MAX_SIZE));
        }
        if let Some(s) = self
            .stacks
            .iter()
            .chain([&self.base_stacks, &self.size_stacks, &self.fragment_stacks])
            .chain(&self.path_stacks)
            .find(|&&s| !(2..=2048).contains(&s))
        {
            return bad(format!("{s} sphere stacks: expected 2..=2048"));
        }
        Ok(())
    }
}

/// The draw counts of the draws sweep in every sweep but the tiny ones: an emulation layer's
/// frames, from one object to ten thousand.
pub const DRAW_COUNTS: [u32; 5] = [1, 10, 100, 1_000, 10_000];

/// The most draws a frame of the sweep may have.
pub const MAX_DRAW_COUNT: u32 = 100_000;

/// The most draws per frame a sweep may ask for.
pub const MAX_DRAWS: u32 = 256;

/// Which sweep a point belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Group {
    /// Mesh density: time against vertices.
    Density,
    /// Image size: time against pixels.
    Size,
    /// Light count: time against directional lights.
    Lights,
    /// Light kind: directional, point or spot lights, infinite or local viewer.
    Kind,
    /// Primitives: the sphere as triangles, as the lines of its triangles' edges, as points.
    Primitives,
    /// Fragment lighting's cost on a dense mesh: fragment, vertex and unlit at a few image
    /// sizes, with the pixels the sphere covers (issue 37's baseline).
    Fragment,
    /// The fragment mode's two paths, forward and deferred, over density, size and lights:
    /// where each wins, and what [`FragmentPath::Auto`](ffvk::FragmentPath::Auto) picks.
    Paths,
    /// The stages around lighting ([`Stage`]), each alone and all together, in every mode.
    Stages,
}

/// The fixed-function stages around lighting a point turns on (the stages sweep).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    /// None: the pipeline of a frame without them.
    #[default]
    Off,
    /// `GL_FOG` `GL_LINEAR` from the eye-space depth, per fragment.
    FogLinear,
    /// `GL_FOG` `GL_EXP2`, per fragment.
    FogExp2,
    /// `GL_FOG` `GL_EXP2` under `GL_FOG_HINT` `GL_FASTEST`: f per vertex.
    FogExp2PerVertex,
    /// `GL_ALPHA_TEST` `GL_GREATER` 0 (every fragment passes: the test's cost, not a saving).
    AlphaTest,
    /// `GL_COLOR_SUM` with a current secondary color (lit draws always sum: no change there).
    ColorSum,
    /// One user clip plane that cuts nothing (the distance's cost, not a saving).
    ClipPlane,
    /// All six user clip planes, cutting nothing.
    ClipPlanes6,
    /// Linear fog, the alpha test, the color sum and six clip planes together.
    All,
    /// One texture unit: a 2D texture, linear, `GL_MODULATE`d.
    Texture,
    /// Four texture units: the 2D texture modulated, a light map through `GL_COMBINE`
    /// (`MODULATE` × 2), a sphere map and a reflection-mapped cube map added.
    Units4,
}

impl Stage {
    /// Every stage setting, in table order.
    pub const ALL: [Stage; 11] = [
        Stage::Off,
        Stage::FogLinear,
        Stage::FogExp2,
        Stage::FogExp2PerVertex,
        Stage::AlphaTest,
        Stage::ColorSum,
        Stage::ClipPlane,
        Stage::ClipPlanes6,
        Stage::All,
        Stage::Texture,
        Stage::Units4,
    ];

    /// How tables name it.
    pub fn label(self) -> &'static str {
        match self {
            Stage::Off => "none",
            Stage::FogLinear => "fog GL_LINEAR",
            Stage::FogExp2 => "fog GL_EXP2",
            Stage::FogExp2PerVertex => "fog GL_EXP2, GL_FASTEST (per vertex)",
            Stage::AlphaTest => "alpha test GL_GREATER 0",
            Stage::ColorSum => "GL_COLOR_SUM",
            Stage::ClipPlane => "1 clip plane",
            Stage::ClipPlanes6 => "6 clip planes",
            Stage::All => "all of them",
            Stage::Texture => "1 texture unit, GL_MODULATE",
            Stage::Units4 => "4 units: + GL_COMBINE, sphere map, cube map",
        }
    }
}

/// What the sphere is drawn as.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Primitive {
    /// Its triangles (`GL_TRIANGLES`).
    #[default]
    Triangles,
    /// Each triangle's three edges (`GL_LINES`): a wireframe, as CAD viewers draw.
    Lines,
    /// Each vertex once (`GL_POINTS`).
    Points,
}

impl Primitive {
    /// Every primitive, in table order.
    pub const ALL: [Primitive; 3] = [Primitive::Triangles, Primitive::Lines, Primitive::Points];

    /// GL's name of the mode.
    pub fn gl_name(self) -> &'static str {
        match self {
            Primitive::Triangles => "GL_TRIANGLES",
            Primitive::Lines => "GL_LINES",
            Primitive::Points => "GL_POINTS",
        }
    }

    /// The sphere `triangles` drawn as this primitive.
    pub fn mesh(self, triangles: &ffvk::mesh::MeshData) -> ffvk::mesh::MeshData {
        use ffvk::Topology;
        match self {
            Primitive::Triangles => triangles.clone(),
            Primitive::Lines => {
                let edges = triangles
                    .indices
                    .chunks_exact(3)
                    .flat_map(|t| [t[0], t[1], t[1], t[2], t[2], t[0]])
                    .collect();
                ffvk::mesh::MeshData::new(triangles.vertices.clone(), edges).with_topology(Topology::LineList)
            }
            Primitive::Points => {
                let all = (0..triangles.vertices.len() as u32).collect();
                ffvk::mesh::MeshData::new(triangles.vertices.clone(), all).with_topology(Topology::PointList)
            }
        }
    }
}

/// Who draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Engine {
    /// ffvk on Vulkan.
    Ffvk,
    /// Fixed-function OpenGL through EGL (the GL reference renderer).
    Gl,
    /// Mesa's GL on Vulkan (zink) on the same Vulkan driver, in a process of its own: the
    /// peer that draws fixed-function GL on Vulkan by another road.
    Zink,
}

impl Engine {
    /// How tables and labels name it.
    pub fn name(self) -> &'static str {
        match self {
            Engine::Ffvk => "ffvk",
            Engine::Gl => "GL",
            Engine::Zink => "zink",
        }
    }
}

/// Where the equation is evaluated, or nowhere.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BenchMode {
    /// Lit at each vertex, colors interpolated (GL's SMOOTH).
    Vertex,
    /// Lit at each fragment.
    Fragment,
    /// Lit at each vertex, each triangle in its last vertex's color (GL's FLAT).
    Flat,
    /// The same geometry with lighting off: the vertex color passes through (the floor).
    Unlit,
}

impl BenchMode {
    /// Every mode, in the order of the tables.
    pub const ALL: [BenchMode; 4] = [
        BenchMode::Vertex,
        BenchMode::Fragment,
        BenchMode::Flat,
        BenchMode::Unlit,
    ];

    /// The mode's name in tables, plots and CSV.
    pub fn name(self) -> &'static str {
        match self {
            BenchMode::Vertex => "vertex",
            BenchMode::Fragment => "fragment",
            BenchMode::Flat => "flat",
            BenchMode::Unlit => "unlit",
        }
    }

    pub(super) fn lighting_mode(self) -> LightingMode {
        match self {
            BenchMode::Fragment => LightingMode::Fragment,
            BenchMode::Flat => LightingMode::Flat,
            BenchMode::Vertex | BenchMode::Unlit => LightingMode::Vertex,
        }
    }
}

/// Which pipelines drew the point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Variant {
    /// ffvk's pipelines specialized for the state ([`Specialize::Always`](ffvk::Specialize::Always)).
    Specialized,
    /// ffvk's uber-shader ([`Specialize::Never`](ffvk::Specialize::Never)).
    Uber,
    /// GL's own fixed-function pipeline.
    FixedFunction,
    /// ffvk's specialized pipelines on the fragment mode's deferred path
    /// ([`FragmentPath::Deferred`](ffvk::FragmentPath::Deferred)).
    Deferred,
    /// The deferred path with the uber-shader's pipelines: its lighting pass reads every
    /// state value from the state block, as one lighting pass over draws of several lighting
    /// states would have to.
    DeferredUber,
}

impl Variant {
    /// The variant's name in tables, plots and CSV.
    pub fn name(self) -> &'static str {
        match self {
            Variant::Specialized => "specialized",
            Variant::Uber => "uber",
            Variant::FixedFunction => "fixed_function",
            Variant::Deferred => "deferred",
            Variant::DeferredUber => "deferred_uber",
        }
    }
}

/// The kind of every light of a point: GL's three, and ffvk's lighting variants on them
/// (what each variant costs is its time against its GL form's).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LightKind {
    /// w = 0.
    Directional,
    /// w = 1, attenuated.
    Point,
    /// A point light with a 35° cone, exponent 8.
    Spot,
    /// Directional lights with Phong's (r_i ⊙ v)^s_rm specular term.
    DirectionalPhong,
    /// Point lights with glTF's inverse-square falloff and a range.
    PointGltf,
    /// The spot with a linear edge from 20° to 35° instead of the exponent.
    SpotLinear,
    /// The spot with a smoothstep edge from 20° to 35°.
    SpotSmoothstep,
}

impl LightKind {
    /// Every kind, in the order of the tables.
    pub const ALL: [LightKind; 7] = [
        LightKind::Directional,
        LightKind::Point,
        LightKind::Spot,
        LightKind::DirectionalPhong,
        LightKind::PointGltf,
        LightKind::SpotLinear,
        LightKind::SpotSmoothstep,
    ];

    /// The kind's name in tables and CSV.
    pub fn name(self) -> &'static str {
        match self {
            LightKind::Directional => "directional",
            LightKind::Point => "point",
            LightKind::Spot => "spot",
            LightKind::DirectionalPhong => "directional_phong",
            LightKind::PointGltf => "point_gltf",
            LightKind::SpotLinear => "spot_linear",
            LightKind::SpotSmoothstep => "spot_smoothstep",
        }
    }

    /// The GL kind a variant kind changes, `None` for GL's own (which GL draws too).
    pub fn gl_form(self) -> Option<LightKind> {
        match self {
            LightKind::Directional | LightKind::Point | LightKind::Spot => None,
            LightKind::DirectionalPhong => Some(LightKind::Directional),
            LightKind::PointGltf => Some(LightKind::Point),
            LightKind::SpotLinear | LightKind::SpotSmoothstep => Some(LightKind::Spot),
        }
    }
}

/// One measured configuration.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Point {
    /// The sweep it belongs to.
    pub group: Group,
    /// Who draws it.
    pub engine: Engine,
    /// Where the equation is evaluated.
    pub mode: BenchMode,
    /// Which pipelines draw it.
    pub variant: Variant,
    /// Sphere stacks (slices are twice as many).
    pub stacks: u32,
    /// The sphere's vertices.
    pub vertices: u64,
    /// The sphere's triangles.
    pub triangles: u64,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// width × height.
    pub pixels: u64,
    /// Enabled lights (0 when unlit).
    pub lights: usize,
    /// The kind of every light.
    pub light_kind: LightKind,
    /// GL_LIGHT_MODEL_LOCAL_VIEWER.
    pub local_viewer: bool,
    /// Draws of the sphere per frame ([`SweepConfig::draws`]).
    pub draws: u32,
    /// What the sphere is drawn as.
    pub primitive: Primitive,
    /// The stages around lighting that are on.
    pub stage: Stage,
}

impl Point {
    pub(super) fn label(&self) -> String {
        format!(
            "{:?} {} {} {} {}v{} {}x{} {}×{}{}{}{}",
            self.group,
            self.engine.name(),
            self.mode.name(),
            self.variant.name(),
            self.vertices,
            if self.draws > 1 {
                format!(" ×{}", self.draws)
            } else {
                String::new()
            },
            self.width,
            self.height,
            self.lights,
            self.light_kind.name(),
            if self.local_viewer { " local" } else { "" },
            match self.primitive {
                Primitive::Triangles => String::new(),
                p => format!(" {}", p.gl_name()),
            },
            match self.stage {
                Stage::Off => String::new(),
                s => format!(", {}", s.label()),
            }
        )
    }
}
