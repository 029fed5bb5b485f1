//! Scene files (TOML): every piece of GL lighting state with GL's names and defaults, a camera,
//! the image, and meshes from glTF files or built-in shapes. See the README for the format.
//!
//! Light positions and spot directions are given in world space; they are set through
//! [`GlState::light`] with the view matrix loaded, exactly as glLight would store them.

mod builtin;
pub mod direct;
mod file;
pub mod gltf;
mod meaning;
mod texture;

use std::path::{Path, PathBuf};

use glam::{EulerRot, Mat4, Quat, Vec3, Vec4};

use self::file::{
    CameraSpec, ColorMaterialSpec, LightModelSpec, LightSpec, MaterialSpec, MeshSpec, SceneFile,
};
use self::gltf::{GltfLights, LoadError, PunctualLight};
pub use self::meaning::{auto_exposure, GltfMeaning};
pub use self::texture::MeshTexture;
use crate::gl::presets;
use crate::gl::state::{
    Attenuation, Cap, ColorControl, ColorMaterialMode, Face, GlState, LightModelParam, LightParam,
    LightingMode, LightingState, Material, SpecularModel, SpotEdge, StateError, MAX_LIGHTS,
};
use crate::mesh::MeshData;

/// The largest image side a scene may ask for (the renderer also checks its device's limit).
pub const MAX_SIZE: u32 = 16384;

/// The largest scene file read, in bytes (16 MiB): a scene is a short TOML file; anything
/// larger is refused before it is read.
pub const MAX_SCENE_BYTES: u64 = 16 << 20;

/// The host memory a scene's meshes may take by default: 1 GiB, about 22 million vertices
/// (48 bytes each, shared between triangles) or 6.9 million triangles with vertices of their
/// own. [`Limits::mesh_bytes`] (`ffvk --max-mesh-mib`) raises it.
pub const DEFAULT_MESH_BYTES: u64 = 1 << 30;

/// What a scene file may make ffvk allocate and read.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Limits {
    /// Folders a glTF buffer URI may reach besides the glTF file's own (`ffvk --allow-root`):
    /// by default none, so that an untrusted asset reads nothing outside its folder.
    pub asset_roots: Vec<PathBuf>,
    /// The bytes all the scene's meshes may take on the host, counted as ffvk stores them
    /// (a [`Vertex`](crate::mesh::Vertex) is 48 bytes, an index 4), each glTF primitive
    /// before it is read and once per node that places it. The device holds the same
    /// amount.
    pub mesh_bytes: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            asset_roots: Vec::new(),
            mesh_bytes: DEFAULT_MESH_BYTES,
        }
    }
}

with_fields!(Limits {
    /// Sets [`asset_roots`](Limits::asset_roots).
    with_asset_roots => asset_roots: Vec<PathBuf>,
    /// Sets [`mesh_bytes`](Limits::mesh_bytes).
    with_mesh_bytes => mesh_bytes: u64,
});

/// The mesh memory left to a scene as it loads.
#[derive(Debug, Clone)]
pub struct MeshBudget {
    limit: u64,
    used: u64,
}

impl MeshBudget {
    /// A budget of `limit` bytes, none used.
    pub fn new(limit: u64) -> Self {
        MeshBudget { limit, used: 0 }
    }

    /// Takes the memory of a mesh of `vertices` vertices and `indices` indices, or says why
    /// it does not fit.
    pub fn charge(&mut self, vertices: usize, indices: usize) -> Result<(), OverBudget> {
        let vertex_size = std::mem::size_of::<crate::mesh::Vertex>() as u64;
        let bytes = (vertices as u64)
            .saturating_mul(vertex_size)
            .saturating_add((indices as u64).saturating_mul(4));
        let total = self.used.saturating_add(bytes);
        if total > self.limit {
            return Err(OverBudget {
                vertices,
                indices,
                bytes,
                used: self.used,
                limit: self.limit,
            });
        }
        self.used = total;
        Ok(())
    }
}

/// A mesh that would take the scene past its mesh memory limit ([`Limits::mesh_bytes`]).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "{vertices} vertices and {indices} indices take {bytes} bytes, which with the {used} bytes of \
     the meshes before them passes the scene's mesh memory limit of {limit} bytes: expected \
     smaller meshes, or a higher limit (ffvk --max-mesh-mib)"
)]
#[non_exhaustive]
pub struct OverBudget {
    /// Vertices of the mesh refused.
    pub vertices: usize,
    /// Indices of the mesh refused.
    pub indices: usize,
    /// What it would take.
    pub bytes: u64,
    /// What the meshes before it took.
    pub used: u64,
    /// The limit.
    pub limit: u64,
}

/// The longest value echoed whole in a message, in characters.
const MAX_ECHO: usize = 120;

/// `text` as a message shows it: whole up to [`MAX_ECHO`] characters, else its start and how
/// long it was, so that a megabyte-long value in a file cannot flood a terminal or a log.
pub(crate) fn shorten(text: &str) -> String {
    shorten_to(text, MAX_ECHO)
}

fn shorten_to(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        return text.to_owned();
    }
    let start: String = text.chars().take(max * 2 / 3).collect();
    format!("{start}… ({} bytes in all)", text.len())
}

/// A TOML parser message with every long line (it quotes the offending line) shortened; the
/// limit leaves room for the parser's own lists of expected field names.
fn shorten_lines(text: &str) -> String {
    text.trim_end()
        .lines()
        .map(|line| shorten_to(line, 3 * MAX_ECHO))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Why a scene could not be loaded: the scene file, and what was wrong with it. The message
/// is the path followed by the kind's message.
#[derive(Debug, thiserror::Error)]
#[error("{}", scene_error_text(self))]
#[non_exhaustive]
pub struct SceneError {
    /// The scene file (for errors in a glTF file it names, the kind names that file).
    pub path: PathBuf,
    /// What was wrong; also the error's `source()`, so that the error beneath it (I/O, TOML,
    /// GL state, glTF) stays reachable.
    #[source]
    pub kind: SceneErrorKind,
}

/// `data`'s index list drawn as GL's primitive mode `name` (see the scene file's `primitive`):
/// Vulkan's topologies as they are, GL's others through [`crate::draw::gl_primitives`]; an
/// incomplete last line is dropped, as GL drops it.
fn as_primitive(mut data: MeshData, name: &str) -> Result<MeshData, String> {
    use crate::draw::gl_primitives;
    use crate::Topology;
    if data.topology != Topology::TriangleList {
        return Err(format!(
            "{:?} for a mesh of {}: expected a triangle mesh to redraw",
            shorten(name),
            data.topology.gl_name()
        ));
    }
    let indices = std::mem::take(&mut data.indices);
    let (topology, indices) = match name {
        "points" => (Topology::PointList, indices),
        "lines" => {
            let whole = indices.len() / 2 * 2;
            (Topology::LineList, indices[..whole].to_vec())
        }
        "line_strip" => (Topology::LineStrip, indices),
        "line_loop" => (Topology::LineList, gl_primitives::line_loop(&indices)),
        "triangles" => (Topology::TriangleList, indices),
        "triangle_strip" => (Topology::TriangleStrip, indices),
        "triangle_fan" => (Topology::TriangleFan, indices),
        "quads" => (Topology::TriangleList, gl_primitives::quads(&indices)),
        "quad_strip" => (Topology::TriangleList, gl_primitives::quad_strip(&indices)),
        "polygon" => (Topology::TriangleList, gl_primitives::polygon(&indices)),
        _ => {
            return Err(format!(
                "{:?}: expected points, lines, line_strip, line_loop, triangles, triangle_strip, \
                 triangle_fan, quads, quad_strip or polygon",
                shorten(name)
            ))
        }
    };
    data.indices = indices;
    Ok(data.with_topology(topology))
}

/// A [`SceneError`]'s message: the path, then the kind's message; a glTF file drawn directly
/// (the scene's path is the glTF file's) is named once, not as the scene and again as its file.
fn scene_error_text(error: &SceneError) -> String {
    match &error.kind {
        SceneErrorKind::Gltf { field, source } if field == "gltf" && source.path == error.path => {
            source.to_string()
        }
        kind => format!("{}: {kind}", error.path.display()),
    }
}

/// What was wrong with a scene file. Every message names the field, the value and what was
/// expected.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SceneErrorKind {
    /// The file could not be read.
    #[error("cannot read the scene: {source}")]
    Io {
        /// The I/O error from opening or reading the scene file.
        source: std::io::Error,
    },

    /// Not TOML, or not a scene's tables: an unknown field, a value of the wrong type. The
    /// message is the TOML parser's, which shows the line.
    #[error("{}", shorten_lines(&.source.to_string()))]
    Toml {
        /// The TOML parser's error, with the offending line and column.
        source: toml::de::Error,
    },

    /// A value outside what the field allows, or fields that do not go together.
    #[error("{field}: {message}")]
    Field {
        /// Where in the scene, as a TOML path: `camera.fovy`, `lights[0].index`, `meshes[2]`.
        field: String,
        /// The offending value and what was expected.
        message: String,
    },

    /// A value GL's own checks reject (what glLight, glMaterial, ... would flag).
    #[error("{field}: {source}")]
    State {
        /// The scene field whose value GL rejected, as a TOML path (`light_model.color_control`).
        field: String,
        /// GL's error: the GL parameter, the rejected value and what is valid.
        source: StateError,
    },

    /// A built-in mesh past the scene's mesh memory limit.
    #[error("{field}: {source}")]
    OverBudget {
        /// The `[[meshes]]` table of the refused mesh (`meshes[2]`).
        field: String,
        /// The mesh's size, the bytes already used and the limit.
        source: OverBudget,
    },

    /// A glTF file named by a `[[meshes]]` table that could not be loaded.
    #[error("{field}: {source}")]
    Gltf {
        /// The field naming the glTF file (`meshes[2].gltf`; `gltf` for a file drawn directly).
        field: String,
        /// Boxed: glTF errors are large.
        source: Box<LoadError>,
    },
}

/// One mesh placed in the scene, with the materials it is drawn with.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct SceneMesh {
    /// The built-in shape's name, or the glTF mesh's (see [`gltf::LoadedMesh::name`]).
    pub name: String,
    /// Object-space geometry.
    pub data: MeshData,
    /// Object to world.
    pub model: Mat4,
    /// The front material: the mesh's `material`, else the scene's, else its glTF material
    /// through [`gltf::gl_material`], else GL's default.
    pub front: Material,
    /// The back material: the mesh's `back_material`, else its `material`, else the scene's
    /// `back_material`, else `front`.
    pub back: Material,
    /// What glTF asks of this mesh where the scene follows glTF's meaning (`gltf_defaults`);
    /// `None` for built-in shapes and in scenes that keep GL's defaults.
    pub gltf: Option<GltfMeaning>,
    /// The texture it is drawn with: the mesh's `texture`, else the scene's `[texture]`, else
    /// (under glTF's meaning) its glTF base color texture; `None` draws it untextured.
    pub texture: Option<MeshTexture>,
    /// Whether lighting applies: false for glTF points and lines without normals, which are
    /// drawn unlit (glTF 2.0: lighting needs normals).
    pub lit: bool,
}

/// A scene ready to draw: GL state already in eye space, matrices in GL conventions.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Scene {
    /// The scene file it was loaded from (or the path given to [`Scene::parse`]).
    pub path: PathBuf,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// RGBA the image is cleared to.
    pub clear_color: Vec4,
    /// Whether the depth test is on (GL_DEPTH_TEST with GL_LESS).
    pub depth_test: bool,
    /// World to eye.
    pub view: Mat4,
    /// Eye to clip, GL conventions (z in [-w, w]).
    pub projection: Mat4,
    /// Lights, light model, color material, normal handling, mode; materials per mesh.
    pub state: LightingState,
    /// What is drawn, in file order.
    pub meshes: Vec<SceneMesh>,
    /// Things ignored while loading (from glTF files), one sentence each.
    pub warnings: Vec<String>,
    /// What the scene chose where its files left it open (glTF's meaning, the light exposure),
    /// one sentence each; `ffvk explain` prints them.
    pub notes: Vec<String>,
}

impl Scene {
    /// The lighting state `mesh` is drawn with.
    pub fn draw_state(&self, mesh: &SceneMesh) -> LightingState {
        let mut state = self.state;
        state.front = mesh.front;
        state.back = mesh.back;
        if let Some(meaning) = &mesh.gltf {
            meaning.apply(&mut state);
        }
        if let Some(texture) = &mesh.texture {
            state.texture = texture.unit;
        }
        state.lighting &= mesh.lit;
        state
    }

    /// The faces `mesh` is drawn without (GL_CULL_FACE with glCullFace): back faces of
    /// single-sided glTF materials where the scene follows glTF's meaning, else none.
    pub fn cull_face(&self, mesh: &SceneMesh) -> Option<Face> {
        mesh.gltf.and_then(|m| m.cull_face())
    }

    /// The modelview matrix `mesh` is drawn with: view × model.
    pub fn modelview(&self, mesh: &SceneMesh) -> Mat4 {
        self.view * mesh.model
    }

    /// Changes the image size, keeping the vertical field of view (x is rescaled in clip
    /// space for the new aspect ratio).
    pub fn set_size(&mut self, width: u32, height: u32) {
        let old = self.width as f32 / self.height as f32;
        let new = width as f32 / height.max(1) as f32;
        self.projection = Mat4::from_scale(Vec3::new(old / new, 1.0, 1.0)) * self.projection;
        self.width = width;
        self.height = height;
    }

    /// Reads and checks a scene file within the default [`Limits`].
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        Scene::load_with(path, &Limits::default())
    }

    /// Reads and checks a scene file within `limits`.
    pub fn load_with(path: &Path, limits: &Limits) -> Result<Scene, SceneError> {
        let io = |source| SceneError {
            path: path.to_path_buf(),
            kind: SceneErrorKind::Io { source },
        };
        let bytes = crate::files::read_regular(path, MAX_SCENE_BYTES).map_err(io)?;
        let text = String::from_utf8(bytes).map_err(|e| {
            io(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!("not UTF-8 text: {e}"),
            ))
        })?;
        Scene::parse_with(&text, path, limits)
    }

    /// Parses scene text within the default [`Limits`]; `path` names it in errors and
    /// anchors relative glTF paths.
    pub fn parse(text: &str, path: &Path) -> Result<Scene, SceneError> {
        Scene::parse_with(text, path, &Limits::default())
    }

    /// [`Scene::parse`] within `limits`.
    pub fn parse_with(text: &str, path: &Path, limits: &Limits) -> Result<Scene, SceneError> {
        Scene::parse_into(text, path, limits, MeshBudget::new(limits.mesh_bytes), None)
    }

    /// [`Scene::parse_with`] with the glTF file at `gltf_path` already loaded (its meshes
    /// charged to `budget`): a `[[meshes]]` table naming that file takes `loaded` instead of
    /// reading it again.
    pub(crate) fn parse_preloaded(
        text: &str,
        path: &Path,
        limits: &Limits,
        budget: MeshBudget,
        gltf_path: PathBuf,
        loaded: self::gltf::Loaded,
    ) -> Result<Scene, SceneError> {
        Scene::parse_into(text, path, limits, budget, Some((gltf_path, loaded)))
    }

    fn parse_into(
        text: &str,
        path: &Path,
        limits: &Limits,
        budget: MeshBudget,
        preloaded: Option<(PathBuf, self::gltf::Loaded)>,
    ) -> Result<Scene, SceneError> {
        let file: SceneFile = toml::from_str(text).map_err(|source| SceneError {
            path: path.to_path_buf(),
            kind: SceneErrorKind::Toml { source },
        })?;
        Builder {
            path,
            limits,
            budget: std::cell::RefCell::new(budget),
            preloaded: std::cell::RefCell::new(preloaded),
        }
        .build(file)
    }
}

/// One glTF primitive or built-in shape placed by a `[[meshes]]` table.
struct Placed {
    name: String,
    data: MeshData,
    /// Object to world.
    model: Mat4,
    /// The glTF material (glTF's default for primitives without one); `None` for built-ins.
    material: Option<self::gltf::PbrMaterial>,
    /// Whether the primitive has COLOR_0.
    vertex_colors: bool,
    /// Whether it is lit (see [`SceneMesh::lit`]).
    lit: bool,
}

struct Builder<'a> {
    path: &'a Path,
    limits: &'a Limits,
    /// What the meshes built so far took.
    budget: std::cell::RefCell<MeshBudget>,
    /// A glTF file loaded before the scene was built, and its path (see
    /// [`Scene::parse_preloaded`]).
    preloaded: std::cell::RefCell<Option<(PathBuf, self::gltf::Loaded)>>,
}

impl Builder<'_> {
    /// An error about this scene file.
    fn error(&self, kind: SceneErrorKind) -> SceneError {
        SceneError {
            path: self.path.to_path_buf(),
            kind,
        }
    }

    fn field(&self, field: impl Into<String>, message: impl Into<String>) -> SceneError {
        self.error(SceneErrorKind::Field {
            field: field.into(),
            message: message.into(),
        })
    }

    fn state(&self, field: impl Into<String>) -> impl FnOnce(StateError) -> SceneError + '_ {
        let field = field.into();
        move |source| self.error(SceneErrorKind::State { field, source })
    }

    /// A color of 3 (alpha 1) or 4 finite numbers.
    fn color(&self, field: &str, v: &[f32]) -> Result<Vec4, SceneError> {
        let c = match *v {
            [r, g, b] => Vec4::new(r, g, b, 1.0),
            [r, g, b, a] => Vec4::new(r, g, b, a),
            _ => {
                return Err(self.field(
                    field,
                    format!("{v:?} has {} numbers: expected 3 (RGB) or 4 (RGBA)", v.len()),
                ))
            }
        };
        if !c.is_finite() {
            return Err(self.field(field, format!("{v:?}: expected finite numbers")));
        }
        Ok(c)
    }

    fn finite(&self, field: &str, v: &[f32]) -> Result<(), SceneError> {
        match v.iter().find(|x| !x.is_finite()) {
            Some(x) => Err(self.field(field, format!("{x} is not finite: expected finite numbers"))),
            None => Ok(()),
        }
    }

    fn build(&self, file: SceneFile) -> Result<Scene, SceneError> {
        let [width, height] = file.image.size.unwrap_or([512, 512]);
        if width == 0 || height == 0 || width > MAX_SIZE || height > MAX_SIZE {
            return Err(self.field(
                "image.size",
                format!("[{width}, {height}]: expected each side in 1..={MAX_SIZE}"),
            ));
        }
        let clear_color = match &file.image.clear_color {
            Some(c) => self.color("image.clear_color", c)?,
            None => Vec4::new(0.0, 0.0, 0.0, 1.0),
        };
        let mode = match &file.image.lighting_mode {
            Some(m) => m.parse::<LightingMode>().map_err(|_| {
                self.field(
                    "image.lighting_mode",
                    format!("{:?}: expected \"vertex\", \"fragment\" or \"flat\"", shorten(m)),
                )
            })?,
            None => LightingMode::Vertex,
        };
        let (view, projection) = self.camera(&file.camera, width as f32 / height as f32)?;

        let mut gl = GlState::new();
        gl.set_enabled(Cap::Lighting, file.lighting.unwrap_or(true))
            .map_err(self.state("lighting"))?;
        gl.lighting_mode(mode);
        let gltf_meaning = file.gltf_defaults.unwrap_or(false);
        let mut notes = Vec::new();
        gl.set_enabled(Cap::Normalize, file.normalize.unwrap_or(gltf_meaning))
            .map_err(self.state("normalize"))?;
        gl.set_enabled(Cap::RescaleNormal, file.rescale_normal)
            .map_err(self.state("rescale_normal"))?;
        self.light_model(&mut gl, &file.light_model)?;
        if gltf_meaning {
            if file.normalize.is_none() {
                notes.push(
                    "glTF: normals renormalized (GL_NORMALIZE), as glTF's scaled nodes need".to_owned(),
                );
            }
            if file.light_model.color_control.is_none() {
                gl.light_model(LightModelParam::ColorControl(ColorControl::SeparateSpecularColor))
                    .map_err(self.state("light_model.color_control"))?;
                notes.push("glTF: separate specular color (GL_SEPARATE_SPECULAR_COLOR)".to_owned());
            }
        }
        if let Some(cm) = &file.color_material {
            self.color_material(&mut gl, cm)?;
        }

        // Lights are specified in world space with the view loaded, as glLight after
        // glLoadMatrix(view).
        gl.load_modelview(view).map_err(self.state("camera.view"))?;
        let mut light_of_index: Vec<(usize, usize)> = Vec::new();
        for (i, spec) in file.lights.iter().enumerate() {
            let index = match spec.index {
                None => i,
                Some(index) => usize::try_from(index)
                    .ok()
                    .filter(|&index| index < MAX_LIGHTS)
                    .ok_or_else(|| {
                        self.field(
                            format!("lights[{i}].index"),
                            format!(
                                "{index}: expected 0..{MAX_LIGHTS} (GL_LIGHT0 to GL_LIGHT{}, GL_MAX_LIGHTS = {MAX_LIGHTS})",
                                MAX_LIGHTS - 1
                            ),
                        )
                    })?,
            };
            // A second table for one GL light would silently replace the first.
            if let Some(&(_, first)) = light_of_index.iter().find(|(gl_index, _)| *gl_index == index) {
                return Err(self.field(
                    format!("lights[{i}].index"),
                    format!("GL_LIGHT{index} is already lights[{first}]: expected each light index once"),
                ));
            }
            light_of_index.push((index, i));
            self.light(&mut gl, &format!("lights[{i}]"), index, spec)?;
        }

        let scene_front = match &file.material {
            Some(m) => Some(self.material("material", m)?),
            None => None,
        };
        let scene_back = match &file.back_material {
            Some(m) => Some(self.material("back_material", m)?),
            None => None,
        };

        let exposure_spec = self.exposure_spec(&file, gltf_meaning)?;
        let mut meshes = Vec::new();
        let mut warnings = Vec::new();
        let scene_texture = match &file.texture {
            Some(t) => self.texture("texture", t, &mut warnings)?,
            None => None,
        };
        let mut gltf_lights: Vec<(String, PunctualLight, Mat4)> = Vec::new();
        let textures = if gltf_meaning {
            self::gltf::Textures::Means
        } else {
            self::gltf::Textures::Ignore
        };
        for (i, spec) in file.meshes.iter().enumerate() {
            let field = format!("meshes[{i}]");
            let placed = self.mesh(&field, spec, textures, &mut warnings, &mut gltf_lights)?;
            for p in placed {
                let pbr = match (&p.material, gltf_meaning) {
                    (Some(m), true) => Some(m.with_texture_means()),
                    (m, _) => m.clone(),
                };
                // Material precedence: the mesh's own, the scene's, the glTF's, GL's default.
                let front = match (&spec.material, scene_front, &pbr) {
                    (Some(m), _, _) => self.material(&format!("{field}.material"), m)?,
                    (None, Some(m), _) => m,
                    (None, None, Some(p)) => self::gltf::gl_material(p),
                    (None, None, None) => Material::default(),
                };
                let back = match (&spec.back_material, &spec.material, scene_back) {
                    (Some(m), _, _) => self.material(&format!("{field}.back_material"), m)?,
                    (None, Some(_), _) => front,
                    (None, None, Some(m)) => m,
                    (None, None, None) => front,
                };
                let own_material = spec.material.is_none() && scene_front.is_none();
                let mut data = p.data;
                if let Some(name) = &spec.primitive {
                    data =
                        as_primitive(data, name).map_err(|m| self.field(format!("{field}.primitive"), m))?;
                }
                let meaning = match &pbr {
                    Some(pbr) if gltf_meaning => {
                        let color_material = own_material && p.vertex_colors;
                        if color_material {
                            self::meaning::multiply_colors(&mut data, pbr.base_color_factor);
                        }
                        Some(GltfMeaning {
                            double_sided: pbr.double_sided,
                            color_material,
                        })
                    }
                    _ => None,
                };
                // Texture precedence: the mesh's own, the scene's, the glTF base color texture
                // (under glTF's meaning, through GL_MODULATE), none.
                let texture = match (&spec.texture, &scene_texture, &pbr) {
                    (Some(t), _, _) => self.texture(&format!("{field}.texture"), t, &mut warnings)?,
                    (None, Some(t), _) => Some(t.clone()),
                    (None, None, Some(pbr)) if gltf_meaning => {
                        pbr.base_color_sampled.as_ref().map(|s| MeshTexture {
                            image: s.image.clone(),
                            sampling: s.sampling,
                            unit: crate::gl::texture::TextureUnit {
                                enabled: true,
                                matrix: s.matrix,
                                ..Default::default()
                            },
                            source: format!("glTF image {} (base color, GL_MODULATE)", s.image_index),
                        })
                    }
                    _ => None,
                };
                meshes.push(SceneMesh {
                    name: p.name,
                    data,
                    model: p.model,
                    front,
                    back,
                    gltf: meaning,
                    texture,
                    lit: p.lit,
                });
            }
        }
        let mapping = self.gltf_lights(&file)?;
        if !gltf_lights.is_empty() && mapping != GltfLights::Off {
            let exposure = Builder::exposure(exposure_spec, &gltf_lights, &meshes, mapping, &mut notes);
            for (f, light, model) in &gltf_lights {
                let mut gl_light = match mapping {
                    GltfLights::Exact => self::gltf::exact_light(light),
                    _ => self::gltf::gl_light(light),
                };
                gl_light.diffuse = (gl_light.diffuse.truncate() * exposure).extend(1.0);
                gl_light.specular = gl_light.diffuse;
                // World-space light under the scene's model transform.
                gl_light.position = *model * gl_light.position;
                gl_light.spot_direction = glam::Mat3::from_mat4(*model) * gl_light.spot_direction;
                // The next disabled light takes it.
                let index = (0..MAX_LIGHTS)
                    .find(|&i| !gl.lighting.lights[i].enabled)
                    .ok_or_else(|| {
                        self.field(
                            f,
                            format!("no free light: expected at most {MAX_LIGHTS} enabled lights in all"),
                        )
                    })?;
                crate::gl::state::validate_light(&gl_light).map_err(self.state(f))?;
                gl.lighting.lights[index] = gl_light;
                let (position, direction) = (gl_light.position, gl_light.spot_direction);
                gl.light(index, LightParam::Position(position))
                    .map_err(self.state(f))?;
                gl.light(index, LightParam::SpotDirection(direction))
                    .map_err(self.state(f))?;
            }
        }
        if meshes.is_empty() {
            return Err(self.field("meshes", "no meshes: expected at least one [[meshes]] table"));
        }
        self.check_drawable(&gl.lighting, &light_of_index, view, projection, &meshes)?;
        gl.load_modelview(Mat4::IDENTITY)
            .map_err(self.state("camera.view"))?;

        Ok(Scene {
            path: self.path.to_path_buf(),
            width,
            height,
            clear_color,
            depth_test: file.image.depth_test.unwrap_or(true),
            view,
            projection,
            state: gl.lighting,
            meshes,
            warnings,
            notes,
        })
    }

    /// `gltf_lights` checked: GL's mapping unless the file says otherwise.
    fn gltf_lights(&self, file: &SceneFile) -> Result<GltfLights, SceneError> {
        use self::file::GltfLightsSpec;
        match &file.gltf_lights {
            None => Ok(GltfLights::Gl),
            Some(GltfLightsSpec::Bool(true)) => Ok(GltfLights::Gl),
            Some(GltfLightsSpec::Bool(false)) => Ok(GltfLights::Off),
            Some(GltfLightsSpec::Word(w)) => w.parse::<GltfLights>().map_err(|_| {
                self.field(
                    "gltf_lights",
                    format!(
                        "{:?}: expected \"off\", \"gl\" (GL's light for each glTF light, the default) or \"exact\" (glTF's falloff and cones), or true/false",
                        shorten(w)
                    ),
                )
            }),
        }
    }

    /// `gltf_exposure` checked: `Some(scale)`, or `None` for "auto" (the default under glTF's
    /// meaning; 1 without it). Checked whether or not the files have lights, so that a bad
    /// value is never passed over.
    fn exposure_spec(&self, file: &SceneFile, gltf_meaning: bool) -> Result<Option<f32>, SceneError> {
        use self::file::ExposureSpec;
        match &file.gltf_exposure {
            None if gltf_meaning => Ok(None),
            None => Ok(Some(1.0)),
            Some(ExposureSpec::Word(w)) if w == "auto" => Ok(None),
            Some(ExposureSpec::Scale(x)) if *x > 0.0 && x.is_finite() && (*x as f32).is_normal() => {
                Ok(Some(*x as f32))
            }
            Some(other) => {
                let value = match other {
                    ExposureSpec::Scale(x) => x.to_string(),
                    ExposureSpec::Word(w) => format!("{:?}", shorten(w)),
                };
                Err(self.field(
                    "gltf_exposure",
                    format!("{value}: expected \"auto\" or a number > 0 (GL light color per lux or candela)"),
                ))
            }
        }
    }

    /// The scale from glTF light units to GL light colors: `spec` (from
    /// [`Builder::exposure_spec`]), "auto" computed by [`auto_exposure`] over the lights and
    /// the meshes' bounds with the falloff `mapping` draws; the choice goes into `notes`.
    fn exposure(
        spec: Option<f32>,
        lights: &[(String, PunctualLight, Mat4)],
        meshes: &[SceneMesh],
        mapping: GltfLights,
        notes: &mut Vec<String>,
    ) -> f32 {
        let (scale, how) = match spec {
            Some(scale) => (scale, "as given, or GL's 1"),
            None => {
                let placed: Vec<(PunctualLight, Mat4)> =
                    lights.iter().map(|(_, l, m)| (l.clone(), *m)).collect();
                let bounds = self::meaning::world_bounds(meshes.iter().map(|m| (&m.data, m.model)));
                (self::meaning::auto_exposure_for(&placed, bounds, mapping), "auto")
            }
        };
        notes.push(format!(
            "glTF lights: {} from the files (gltf_lights \"{}\"), GL color = color × intensity × {scale} (gltf_exposure {how})",
            lights.len(),
            mapping.name()
        ));
        scale
    }

    /// What drawing would refuse (see [`DrawBlock::new`]), found here so that the error names
    /// the scene's field rather than surfacing at render time without it: a positional light
    /// with all three attenuations 0, and a mesh whose modelview has no inverse (its normals
    /// would be NaN).
    ///
    /// [`DrawBlock::new`]: crate::gpu::layout::DrawBlock::new
    fn check_drawable(
        &self,
        state: &LightingState,
        light_of_index: &[(usize, usize)],
        view: Mat4,
        projection: Mat4,
        meshes: &[SceneMesh],
    ) -> Result<(), SceneError> {
        if !state.lighting {
            return Ok(());
        }
        for (index, light) in state.lights.iter().enumerate() {
            let sum = light.constant_attenuation + light.linear_attenuation + light.quadratic_attenuation;
            // glTF's falloff does not read k0, k1, k2.
            let gl_falloff = light.attenuation == Attenuation::GlK012;
            if light.enabled && light.position.w != 0.0 && gl_falloff && sum == 0.0 {
                let field = match light_of_index.iter().find(|(gl_index, _)| *gl_index == index) {
                    Some((_, i)) => format!("lights[{i}]"),
                    None => format!("GL_LIGHT{index}"),
                };
                return Err(self.field(
                    field,
                    "constant_attenuation + linear_attenuation + quadratic_attenuation = 0 for a \
                     positional light: expected a sum > 0 (GL's att_i would be 1/0)",
                ));
            }
        }
        for mesh in meshes {
            let det = glam::Mat3::from_mat4(view * mesh.model).determinant();
            if det == 0.0 || !det.is_finite() {
                let model_det = glam::Mat3::from_mat4(mesh.model).determinant();
                let field = if model_det == 0.0 || !model_det.is_finite() {
                    format!("meshes (mesh {:?})", shorten(&mesh.name))
                } else {
                    "camera.view".to_owned()
                };
                return Err(self.field(
                    field,
                    format!(
                        "the modelview's upper 3x3 has determinant {det} for mesh {:?}: expected an \
                         invertible matrix (a scale of 0 flattens the mesh and leaves GL's normal \
                         matrix undefined)",
                        shorten(&mesh.name)
                    ),
                ));
            }
            let mut draw = *state;
            draw.front = mesh.front;
            draw.back = mesh.back;
            crate::gpu::layout::DrawBlock::new(&draw, view * mesh.model, projection)
                .map_err(self.state(format!("meshes (mesh {:?})", shorten(&mesh.name))))?;
        }
        Ok(())
    }

    fn camera(&self, c: &CameraSpec, aspect: f32) -> Result<(Mat4, Mat4), SceneError> {
        let view = match c.view {
            Some(m) => {
                self.finite("camera.view", &m)?;
                Mat4::from_cols_array(&m)
            }
            None => {
                let eye = Vec3::from(c.eye.unwrap_or([0.0, 0.0, 3.0]));
                let target = Vec3::from(c.target.unwrap_or([0.0, 0.0, 0.0]));
                let up = Vec3::from(c.up.unwrap_or([0.0, 1.0, 0.0]));
                self.finite("camera.eye", &eye.to_array())?;
                self.finite("camera.target", &target.to_array())?;
                self.finite("camera.up", &up.to_array())?;
                if (target - eye).length() == 0.0 || (target - eye).cross(up).length() == 0.0 {
                    return Err(self.field(
                        "camera",
                        format!("eye {eye} and target {target} with up {up}: expected distinct points and an up not along the view"),
                    ));
                }
                Mat4::look_at_rh(eye, target, up)
            }
        };
        let projection = match c.projection {
            Some(m) => {
                self.finite("camera.projection", &m)?;
                let projection = Mat4::from_cols_array(&m);
                // A singular projection maps the scene onto a plane or a point: nothing is drawn.
                if projection.determinant() == 0.0 {
                    return Err(self.field(
                        "camera.projection",
                        "has determinant 0 (e.g. all zeros): expected an invertible projection",
                    ));
                }
                projection
            }
            None => {
                let fovy = c.fovy.unwrap_or(45.0);
                if !(fovy > 0.0 && fovy < 180.0) {
                    return Err(self.field("camera.fovy", format!("{fovy}: expected degrees in (0, 180)")));
                }
                let near = c.near.unwrap_or(0.1);
                let far = c.far.unwrap_or(100.0);
                if !(near > 0.0 && far > near && far.is_finite()) {
                    return Err(self.field(
                        "camera.near",
                        format!("near {near}, far {far}: expected 0 < near < far"),
                    ));
                }
                Mat4::perspective_rh_gl(fovy.to_radians(), aspect, near, far)
            }
        };
        Ok((view, projection))
    }

    fn light_model(&self, gl: &mut GlState, m: &LightModelSpec) -> Result<(), SceneError> {
        if let Some(a) = &m.ambient {
            let a = self.color("light_model.ambient", a)?;
            gl.light_model(LightModelParam::Ambient(a))
                .map_err(self.state("light_model.ambient"))?;
        }
        if let Some(b) = m.local_viewer {
            gl.light_model(LightModelParam::LocalViewer(b))
                .map_err(self.state("light_model.local_viewer"))?;
        }
        if let Some(b) = m.two_side {
            gl.light_model(LightModelParam::TwoSide(b))
                .map_err(self.state("light_model.two_side"))?;
        }
        if let Some(c) = &m.color_control {
            let control = match c.as_str() {
                "single_color" => ColorControl::SingleColor,
                "separate_specular_color" => ColorControl::SeparateSpecularColor,
                other => {
                    return Err(self.field(
                        "light_model.color_control",
                        format!(
                            "{:?}: expected \"single_color\" or \"separate_specular_color\"",
                            shorten(other)
                        ),
                    ))
                }
            };
            gl.light_model(LightModelParam::ColorControl(control))
                .map_err(self.state("light_model.color_control"))?;
        }
        if let Some(m) = &m.specular_model {
            let model = match m.as_str() {
                "blinn_halfway" => SpecularModel::BlinnHalfway,
                "phong_reflect" => SpecularModel::PhongReflect,
                other => {
                    return Err(self.field(
                        "light_model.specular_model",
                        format!(
                            "{:?}: expected \"blinn_halfway\" (GL's) or \"phong_reflect\"",
                            shorten(other)
                        ),
                    ))
                }
            };
            gl.light_model(LightModelParam::SpecularModel(model))
                .map_err(self.state("light_model.specular_model"))?;
        }
        Ok(())
    }

    /// The spot edge and attenuation of a `[[lights]]` table (ffvk's extensions), checked
    /// against each other and against the light's cone.
    fn light_variants(
        &self,
        gl: &mut GlState,
        field: &str,
        index: usize,
        l: &LightSpec,
    ) -> Result<(), SceneError> {
        let f = |name: &str| format!("{field}.{name}");
        let inner = l.spot_inner_cutoff;
        let edge = match (l.spot_edge.as_deref(), inner) {
            (None | Some("gl_exponent"), None) => None,
            (None | Some("gl_exponent"), Some(v)) => {
                return Err(self.field(
                    f("spot_inner_cutoff"),
                    format!("{v}: a soft spot edge's inner angle, but the light has GL's edge: expected spot_edge = \"linear_inner_outer\" or \"smoothstep_inner_outer\" with it"),
                ))
            }
            (Some(kind @ ("linear_inner_outer" | "smoothstep_inner_outer")), None) => {
                return Err(self.field(
                    f("spot_inner_cutoff"),
                    format!("missing: spot_edge = \"{kind}\" needs the inner cone's half-angle in degrees, in [0, spot_cutoff]"),
                ))
            }
            (Some("linear_inner_outer"), Some(v)) => Some(SpotEdge::LinearInnerOuter { inner_degrees: v }),
            (Some("smoothstep_inner_outer"), Some(v)) => Some(SpotEdge::SmoothstepInnerOuter { inner_degrees: v }),
            (Some(other), _) => {
                return Err(self.field(
                    f("spot_edge"),
                    format!(
                        "{:?}: expected \"gl_exponent\" (GL's), \"linear_inner_outer\" or \"smoothstep_inner_outer\"",
                        shorten(other)
                    ),
                ))
            }
        };
        if let Some(edge) = edge {
            gl.light(index, LightParam::SpotEdge(edge))
                .map_err(self.state(f("spot_inner_cutoff")))?;
            let outer = gl.lighting.lights[index].spot_cutoff;
            if let Some(inner) = edge.inner_degrees().filter(|&i| outer != 180.0 && i > outer) {
                return Err(self.field(
                    f("spot_inner_cutoff"),
                    format!("{inner}: wider than the outer cone, spot_cutoff = {outer}: expected an inner angle <= {outer}"),
                ));
            }
        }
        let attenuation = match (l.attenuation.as_deref(), l.range) {
            (None | Some("gl_k012"), None) => None,
            (None | Some("gl_k012"), Some(r)) => {
                return Err(self.field(
                    f("range"),
                    format!("{r}: glTF's range, but the light has GL's attenuation: expected attenuation = \"gltf_inverse_square\" with it"),
                ))
            }
            (Some("gltf_inverse_square"), range) => Some(Attenuation::GltfInverseSquare { range }),
            (Some(other), _) => {
                return Err(self.field(
                    f("attenuation"),
                    format!(
                        "{:?}: expected \"gl_k012\" (GL's) or \"gltf_inverse_square\"",
                        shorten(other)
                    ),
                ))
            }
        };
        if let Some(a) = attenuation {
            gl.light(index, LightParam::Attenuation(a))
                .map_err(self.state(f("range")))?;
        }
        Ok(())
    }

    fn color_material(&self, gl: &mut GlState, cm: &ColorMaterialSpec) -> Result<(), SceneError> {
        let face = match cm.face.as_deref().unwrap_or("front_and_back") {
            "front" => Face::Front,
            "back" => Face::Back,
            "front_and_back" => Face::FrontAndBack,
            other => {
                return Err(self.field(
                    "color_material.face",
                    format!(
                        "{:?}: expected \"front\", \"back\" or \"front_and_back\"",
                        shorten(other)
                    ),
                ))
            }
        };
        let mode = match cm.mode.as_deref().unwrap_or("ambient_and_diffuse") {
            "emission" => ColorMaterialMode::Emission,
            "ambient" => ColorMaterialMode::Ambient,
            "diffuse" => ColorMaterialMode::Diffuse,
            "specular" => ColorMaterialMode::Specular,
            "ambient_and_diffuse" => ColorMaterialMode::AmbientAndDiffuse,
            other => {
                return Err(self.field(
                    "color_material.mode",
                    format!("{:?}: expected \"emission\", \"ambient\", \"diffuse\", \"specular\" or \"ambient_and_diffuse\"", shorten(other)),
                ))
            }
        };
        gl.color_material(face, mode);
        // A [color_material] table enables it unless it says otherwise.
        gl.set_enabled(Cap::ColorMaterial, cm.enabled.unwrap_or(true))
            .map_err(self.state("color_material.enabled"))
    }

    fn light(&self, gl: &mut GlState, field: &str, index: usize, l: &LightSpec) -> Result<(), SceneError> {
        let f = |name: &str| format!("{field}.{name}");
        let idx_field = f("index");
        gl.set_enabled(Cap::Light(index), l.enabled.unwrap_or(true))
            .map_err(self.state(idx_field))?;
        let colors = [
            (
                "ambient",
                &l.ambient,
                LightParam::Ambient as fn(Vec4) -> LightParam,
            ),
            ("diffuse", &l.diffuse, LightParam::Diffuse),
            ("specular", &l.specular, LightParam::Specular),
        ];
        for (name, value, param) in colors {
            if let Some(c) = value {
                let c = self.color(&f(name), c)?;
                gl.light(index, param(c)).map_err(self.state(f(name)))?;
            }
        }
        if let Some(p) = l.position {
            gl.light(index, LightParam::Position(Vec4::from(p)))
                .map_err(self.state(f("position")))?;
        }
        if let Some(d) = l.spot_direction {
            gl.light(index, LightParam::SpotDirection(Vec3::from(d)))
                .map_err(self.state(f("spot_direction")))?;
        }
        let scalars = [
            (
                "spot_exponent",
                l.spot_exponent,
                LightParam::SpotExponent as fn(f32) -> LightParam,
            ),
            ("spot_cutoff", l.spot_cutoff, LightParam::SpotCutoff),
            (
                "constant_attenuation",
                l.constant_attenuation,
                LightParam::ConstantAttenuation,
            ),
            (
                "linear_attenuation",
                l.linear_attenuation,
                LightParam::LinearAttenuation,
            ),
            (
                "quadratic_attenuation",
                l.quadratic_attenuation,
                LightParam::QuadraticAttenuation,
            ),
        ];
        for (name, value, param) in scalars {
            if let Some(v) = value {
                gl.light(index, param(v)).map_err(self.state(f(name)))?;
            }
        }
        self.light_variants(gl, field, index, l)
    }

    fn material(&self, field: &str, m: &MaterialSpec) -> Result<Material, SceneError> {
        let mut material = match &m.preset {
            Some(name) => presets::preset(name).ok_or_else(|| {
                self.field(
                    format!("{field}.preset"),
                    format!(
                        "{:?} is not a preset: expected one of {}",
                        shorten(name),
                        presets::PRESET_NAMES.join(", ")
                    ),
                )
            })?,
            None => Material::default(),
        };
        let f = |name: &str| format!("{field}.{name}");
        if let Some(c) = &m.ambient {
            material.ambient = self.color(&f("ambient"), c)?;
        }
        if let Some(c) = &m.diffuse {
            material.diffuse = self.color(&f("diffuse"), c)?;
        }
        if let Some(c) = &m.specular {
            material.specular = self.color(&f("specular"), c)?;
        }
        if let Some(c) = &m.emission {
            material.emission = self.color(&f("emission"), c)?;
        }
        if let Some(s) = m.shininess {
            material.shininess = s;
        }
        material.validate().map_err(self.state(field))?;
        Ok(material)
    }

    fn model_matrix(&self, field: &str, m: &MeshSpec) -> Result<Mat4, SceneError> {
        if let Some(matrix) = m.matrix {
            if m.translate.is_some() || m.rotate.is_some() || m.scale.is_some() {
                return Err(self.field(
                    format!("{field}.matrix"),
                    "given with translate/rotate/scale: expected either a matrix or those",
                ));
            }
            self.finite(&format!("{field}.matrix"), &matrix)?;
            return Ok(Mat4::from_cols_array(&matrix));
        }
        let t = m.translate.unwrap_or([0.0; 3]);
        let r = m.rotate.unwrap_or([0.0; 3]);
        let s = m.scale.unwrap_or([1.0; 3]);
        for (name, v) in [("translate", t), ("rotate", r), ("scale", s)] {
            self.finite(&format!("{field}.{name}"), &v)?;
        }
        let rotation = Quat::from_euler(
            EulerRot::ZYX,
            r[2].to_radians(),
            r[1].to_radians(),
            r[0].to_radians(),
        );
        Ok(Mat4::from_scale_rotation_translation(
            Vec3::from(s),
            rotation,
            Vec3::from(t),
        ))
    }

    /// The placed primitives of one [[meshes]] entry; its glTF file's lights are added to
    /// `lights` (with the field that names them and the entry's model matrix).
    fn mesh(
        &self,
        field: &str,
        spec: &MeshSpec,
        textures: self::gltf::Textures,
        warnings: &mut Vec<String>,
        lights: &mut Vec<(String, PunctualLight, Mat4)>,
    ) -> Result<Vec<Placed>, SceneError> {
        let model = self.model_matrix(field, spec)?;
        match (&spec.gltf, &spec.builtin) {
            (Some(_), Some(_)) => Err(self.field(field, "has both gltf and builtin: expected one of them")),
            (None, None) => Err(self.field(field, "has neither gltf nor builtin: expected one of them")),
            (None, Some(name)) => {
                if spec.node.is_some() || spec.mesh.is_some() {
                    return Err(self.field(
                        field,
                        "node and mesh select within a glTF file: expected them with gltf",
                    ));
                }
                let data = self.builtin(field, name, spec)?;
                self.budget
                    .borrow_mut()
                    .charge(data.vertices.len(), data.indices.len())
                    .map_err(|source| {
                        self.error(SceneErrorKind::OverBudget {
                            field: field.to_owned(),
                            source,
                        })
                    })?;
                Ok(vec![Placed {
                    name: name.clone(),
                    data,
                    model,
                    material: None,
                    vertex_colors: true,
                    lit: true,
                }])
            }
            (Some(_), None) if spec.level.is_some() || spec.color.is_some() => {
                let name = if spec.level.is_some() { "level" } else { "color" };
                Err(self.field(
                    format!("{field}.{name}"),
                    "applies to built-in shapes only: expected it with builtin, not with gltf",
                ))
            }
            (Some(file), None) => {
                let base = self.path.parent().unwrap_or(Path::new("."));
                let gltf_path = base.join(file);
                let preloaded = self
                    .preloaded
                    .borrow_mut()
                    .take_if(|(path, _)| *path == gltf_path)
                    .map(|(_, loaded)| loaded);
                let loaded = match preloaded {
                    Some(loaded) => loaded,
                    None => self::gltf::load_with(
                        &gltf_path,
                        self.limits,
                        &mut self.budget.borrow_mut(),
                        textures,
                    )
                    .map_err(|source| {
                        self.error(SceneErrorKind::Gltf {
                            field: format!("{field}.gltf"),
                            source: Box::new(source),
                        })
                    })?,
                };
                warnings.extend(
                    loaded
                        .warnings
                        .iter()
                        .map(|w| format!("{}: {w}", gltf_path.display())),
                );
                for light in &loaded.lights {
                    let f = format!("{field}: glTF light {:?}", shorten(&light.name));
                    lights.push((f, light.clone(), model));
                }
                let mut placed = Vec::new();
                for m in loaded.meshes {
                    let base_name = m.name.split('[').next().unwrap_or("").to_string();
                    if spec.mesh.as_ref().is_some_and(|want| *want != base_name) {
                        continue;
                    }
                    // A node selects itself and its descendants.
                    if spec.node.as_ref().is_some_and(|want| !m.node_path.contains(want)) {
                        continue;
                    }
                    placed.push(Placed {
                        name: m.name,
                        data: m.data,
                        model: model * m.transform,
                        material: m.material.or(Some(Default::default())),
                        vertex_colors: m.vertex_colors,
                        lit: m.lit,
                    });
                }
                if placed.is_empty() {
                    let what = match (&spec.mesh, &spec.node) {
                        (Some(m), _) => format!("no mesh named {:?}", shorten(m)),
                        (None, Some(n)) => format!("no node named {:?}", shorten(n)),
                        _ => "no meshes".to_string(),
                    };
                    return Err(self.field(
                        format!("{field}.gltf"),
                        format!("{}: {what}", gltf_path.display()),
                    ));
                }
                Ok(placed)
            }
        }
    }
}

/// Draws a scene with `renderer`; `mode` overrides the file's lighting mode when given.
pub fn render_scene(
    renderer: &mut crate::Renderer,
    scene: &Scene,
    mode: Option<LightingMode>,
) -> crate::Result<image::RgbaImage> {
    let (width, height) = (scene.width, scene.height);
    let uploaded = scene
        .meshes
        .iter()
        .map(|m| renderer.upload(&m.data))
        .collect::<crate::Result<Vec<_>>>()?;
    // Each image once, however many meshes share it (by image and sampling, as a GL program
    // keeps one texture object per image and parameters).
    let mut textures: Vec<(&MeshTexture, crate::Texture)> = Vec::new();
    for t in scene.meshes.iter().filter_map(|m| m.texture.as_ref()) {
        if !textures
            .iter()
            .any(|(u, _)| std::sync::Arc::ptr_eq(&u.image, &t.image) && u.sampling == t.sampling)
        {
            textures.push((t, renderer.upload_texture(&t.image, &t.sampling)?));
        }
    }
    let texture_of = |t: &MeshTexture| {
        textures
            .iter()
            .find(|(u, _)| std::sync::Arc::ptr_eq(&u.image, &t.image) && u.sampling == t.sampling)
            .map(|(_, gpu)| gpu)
    };
    let mut frame = crate::Frame::new(width, height);
    frame.clear_color = scene.clear_color;
    frame.depth_test = scene.depth_test;
    for (mesh, gpu) in scene.meshes.iter().zip(&uploaded) {
        let mut state = scene.draw_state(mesh);
        if let Some(mode) = mode {
            state.mode = mode;
        }
        frame.draws.push(crate::Draw {
            mesh: gpu,
            modelview: scene.modelview(mesh),
            projection: scene.projection,
            state,
            cull_face: scene.cull_face(mesh),
            texture: mesh.texture.as_ref().and_then(texture_of),
            topology: gpu.topology(),
            point_size: 1.0,
            line_width: 1.0,
        });
    }
    Ok(renderer.render(&frame)?.into())
}
