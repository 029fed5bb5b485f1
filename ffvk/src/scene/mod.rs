//! Scene files (TOML): every piece of GL lighting state with GL's names and defaults, a camera,
//! the image, and meshes from glTF files or built-in shapes. See docs/scene-files.md for the format.
//!
//! Light positions and spot directions are given in world space; they are set through
//! [`GlState::light`] with the view matrix loaded, exactly as glLight would store them.

mod build;
mod builtin;
mod combine;
mod cube;
pub mod direct;
mod file;
pub mod gltf;
mod inputs;
mod meaning;
mod open;
mod raster;
mod render;
mod texture;

pub use inputs::inputs;
pub use open::{open, OpenNote};
pub use render::{render_scene, render_scene_with};

use std::path::{Path, PathBuf};

use glam::{EulerRot, Mat4, Quat, Vec3, Vec4};

use self::build::Builder;
use self::file::{
    CameraSpec, ColorMaterialSpec, LightModelSpec, LightSpec, MaterialSpec, MeshSpec, SceneFile,
};
use self::gltf::{GltfLights, LoadError, PunctualLight};
pub use self::meaning::{auto_exposure, GltfMeaning};
pub use self::raster::MeshRaster;
pub use self::texture::{MeshTexture, TexCoords};
use crate::gl::presets;
use crate::gl::state::{
    Attenuation, Cap, ColorControl, ColorMaterialMode, DrawValues, Face, FixedFunctionState, GlState,
    LightModelParam, LightParam, LightingMode, Material, SpecularModel, SpotEdge, StateError, MAX_LIGHTS,
};
use crate::gl::texture::MAX_TEXTURE_UNITS;
use crate::mesh::MeshData;

/// The largest image side a scene may ask for (the renderer also checks its device's limit).
pub const MAX_SIZE: u32 = 16384;

/// The largest scene file read, in bytes (16 MiB): a scene is a short TOML file; anything
/// larger is refused before it is read.
pub const MAX_SCENE_BYTES: u64 = 16 << 20;

/// The deepest nesting of arrays and inline tables a scene file may have. Checked before the
/// TOML parser runs, whose recursion would otherwise take stack in proportion to the depth.
pub const MAX_SCENE_NESTING: usize = 32;

/// How deep arrays and inline tables nest in TOML `text`: brackets and braces counted outside
/// strings and comments (a table header `[[meshes]]` counts 2).
pub(crate) fn nesting_depth(text: &str) -> usize {
    let bytes = text.as_bytes();
    let (mut depth, mut deepest, mut i) = (0usize, 0usize, 0usize);
    while i < bytes.len() {
        match bytes[i] {
            b'#' => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
            }
            quote @ (b'"' | b'\'') => {
                let triple = bytes[i..].starts_with(if quote == b'"' { b"\"\"\"" } else { b"'''" });
                i += if triple { 3 } else { 1 };
                while i < bytes.len() {
                    if quote == b'"' && bytes[i] == b'\\' {
                        i += 2;
                        continue;
                    }
                    if bytes[i] == quote && (!triple || bytes[i..].starts_with(&[quote; 3])) {
                        // A closing run of more than three quotes keeps the first ones as text.
                        while triple && bytes.get(i + 3) == Some(&quote) {
                            i += 1;
                        }
                        i += if triple { 2 } else { 0 };
                        break;
                    }
                    if !triple && bytes[i] == b'\n' {
                        break;
                    }
                    i += 1;
                }
            }
            b'[' | b'{' => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            b']' | b'}' => depth = depth.saturating_sub(1),
            _ => {}
        }
        i += 1;
    }
    deepest
}

/// The host memory a scene's meshes may take by default: 1 GiB, about 22 million vertices
/// (48 bytes each, shared between triangles) or 6.9 million triangles with vertices of their
/// own. [`Limits::mesh_bytes`] (`ffvk --max-mesh-mib`) raises it.
pub const DEFAULT_MESH_BYTES: u64 = 1 << 30;

/// The decoded textures a scene may take on the host by default: 1 GiB, twelve 4096²
/// textures (each 64 MiB as RGBA8, 85 MiB with its mipmaps) or about 190 of 1024².
/// [`Limits::texture_bytes`] (`ffvk --max-texture-mib`) raises it.
pub const DEFAULT_TEXTURE_BYTES: u64 = 1 << 30;

/// The bytes a glTF file's buffers may take together on the host by default: 1 GiB, what one
/// buffer file may hold ([`gltf::MAX_FILE_BYTES`]). [`Limits::buffer_bytes`]
/// (`ffvk --max-buffer-mib`) raises it.
pub const DEFAULT_BUFFER_BYTES: u64 = 1 << 30;

/// The mesh placements (one glTF primitive placed by one node, counted by the nodes on its
/// path) a scene may hold by default: 4,194,304, e.g. a million primitives placed three nodes
/// deep. [`Limits::placements`] (`ffvk --max-placements`) raises it.
pub const DEFAULT_PLACEMENTS: u64 = 1 << 22;

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
    /// The bytes all the scene's decoded textures may take on the host: RGBA8 with its
    /// mipmaps (a 4096² image takes 85 MiB), each image charged from its header's size
    /// before it is decoded: once however many glTF images name the same file or bytes, and
    /// once per use for a scene file's `image` and cube map `faces` (each decoded on its own).
    pub texture_bytes: u64,
    /// The bytes one glTF file's buffers may take together on the host: external files,
    /// data URIs, the GLB binary chunk and meshopt fallback buffers, each charged before it
    /// is read or allocated.
    pub buffer_bytes: u64,
    /// The mesh placements (one glTF primitive placed by one node) all the scene's glTF files
    /// may make together, each counted by the nodes on its path (1 for a root node's, 10 for a
    /// node 10 deep), whose names it keeps: so that a deep chain of nodes that each place a
    /// mesh, whose paths grow as the square of its depth, is bounded too.
    pub placements: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            asset_roots: Vec::new(),
            mesh_bytes: DEFAULT_MESH_BYTES,
            texture_bytes: DEFAULT_TEXTURE_BYTES,
            buffer_bytes: DEFAULT_BUFFER_BYTES,
            placements: DEFAULT_PLACEMENTS,
        }
    }
}

with_fields!(Limits {
    /// Sets [`asset_roots`](Limits::asset_roots).
    with_asset_roots => asset_roots: Vec<PathBuf>,
    /// Sets [`mesh_bytes`](Limits::mesh_bytes).
    with_mesh_bytes => mesh_bytes: u64,
    /// Sets [`texture_bytes`](Limits::texture_bytes).
    with_texture_bytes => texture_bytes: u64,
    /// Sets [`buffer_bytes`](Limits::buffer_bytes).
    with_buffer_bytes => buffer_bytes: u64,
    /// Sets [`placements`](Limits::placements).
    with_placements => placements: u64,
});

/// The mesh memory left to a scene as it loads, and what its glTF files took of the other
/// per-scene limits ([`Limits::texture_bytes`], [`Limits::placements`]), whose values the
/// loader is given with the [`Limits`].
#[derive(Debug, Clone)]
pub struct MeshBudget {
    limit: u64,
    used: u64,
    texture_used: u64,
    placements: u64,
}

impl MeshBudget {
    /// A budget of `limit` bytes, none used.
    pub fn new(limit: u64) -> Self {
        MeshBudget {
            limit,
            used: 0,
            texture_used: 0,
            placements: 0,
        }
    }

    /// Takes `bytes` of decoded texture memory within `limit` ([`Limits::texture_bytes`]);
    /// on `Err`, the bytes the textures before took.
    pub(crate) fn charge_texture(&mut self, bytes: u64, limit: u64) -> Result<(), u64> {
        let total = self.texture_used.saturating_add(bytes);
        if total > limit {
            return Err(self.texture_used);
        }
        self.texture_used = total;
        Ok(())
    }

    /// Takes one mesh placement `depth` nodes deep within `limit` ([`Limits::placements`]);
    /// on `Err`, what the placements before counted.
    pub(crate) fn charge_placement(&mut self, depth: u64, limit: u64) -> Result<(), u64> {
        let total = self.placements.saturating_add(depth);
        if total > limit {
            return Err(self.placements);
        }
        self.placements = total;
        Ok(())
    }

    /// Takes the memory of a mesh of `vertices` vertices and `indices` indices, or says why
    /// it does not fit.
    pub fn charge(&mut self, vertices: usize, indices: usize) -> Result<(), OverBudget> {
        self.charge_sized(vertices, 0, indices)
    }

    /// [`MeshBudget::charge`] for vertices that carry `extra` bytes each beside their
    /// [`Vertex`](crate::mesh::Vertex) (a second set of texture coordinates: 8).
    pub(crate) fn charge_sized(
        &mut self,
        vertices: usize,
        extra: u64,
        indices: usize,
    ) -> Result<(), OverBudget> {
        let vertex_size = std::mem::size_of::<crate::mesh::Vertex>() as u64 + extra;
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
/// incomplete last line is dropped, as GL drops it. Quads, quad strips and polygons of a mesh
/// drawn as lines or points (`outlined`) keep their edge flags
/// ([`Topology::EdgeFlaggedTriangles`](crate::Topology::EdgeFlaggedTriangles)): GL draws
/// their sides, not ffvk's inner triangle edges.
fn as_primitive(mut data: MeshData, name: &str, outlined: bool) -> Result<MeshData, String> {
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
        "quads" | "quad_strip" | "polygon" if outlined => {
            let all = |_| true;
            let flagged = match name {
                "quads" => gl_primitives::quads_edge_flagged(&indices, all),
                "quad_strip" => gl_primitives::quad_strip_edge_flagged(&indices),
                _ => gl_primitives::polygon_edge_flagged(&indices, all),
            };
            (Topology::EdgeFlaggedTriangles, flagged)
        }
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
    /// The textures its units are drawn with, `GL_TEXTURE0` first: the mesh's `texture_units`,
    /// else its `texture` (unit 0), else the scene's `[texture]`, else (under glTF's meaning)
    /// its glTF base color texture (unit 0) and occlusion texture (unit 1); `None` leaves a
    /// unit off (all `None`: untextured).
    pub textures: [Option<MeshTexture>; MAX_TEXTURE_UNITS],
    /// Whether lighting applies: false for glTF points and lines without normals, which are
    /// drawn unlit (glTF 2.0: lighting needs normals).
    pub lit: bool,
    /// The raster state it is drawn with: the `[[meshes]]` table's `polygon_mode`,
    /// `polygon_offset`, `color_mask`, `stencil`, `logic_op`, `line_stipple`, `blend`,
    /// `cull_face`, `depth_range`; GL's defaults for those left out.
    pub raster: MeshRaster,
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
    /// glClearStencil: what the stencil buffer of a scene with a stencil-tested mesh is
    /// cleared to (`[image] clear_stencil`), 0 by default.
    pub clear_stencil: u32,
    /// glPointSize of the meshes drawn as points (`[points] size`); 1 by default.
    pub point_size: f32,
    /// How the fragment mode is drawn (`[image] fragment_path`): forward (the default),
    /// deferred where the frame allows it, or auto.
    pub fragment_path: crate::FragmentPath,
    /// World to eye.
    pub view: Mat4,
    /// Eye to clip, GL conventions (z in [-w, w]).
    pub projection: Mat4,
    /// Lights, light model, color material, normal handling, mode; materials per mesh.
    pub state: FixedFunctionState,
    /// What is drawn, in file order.
    pub meshes: Vec<SceneMesh>,
    /// Things ignored while loading (from glTF files), one sentence each.
    pub warnings: Vec<String>,
    /// What the scene chose where its files left it open (glTF's meaning, the light exposure),
    /// one sentence each; `ffvk explain` prints them.
    pub notes: Vec<String>,
}

impl SceneMesh {
    /// Unit 0's texture (see [`SceneMesh::textures`]).
    pub fn texture(&self) -> Option<&MeshTexture> {
        self.textures[0].as_ref()
    }

    /// The mesh's textures as the CPU reference reads them: each unit's 2D texture, its cube
    /// map, and the units whose coordinates are the mesh's.
    pub fn draw_textures(&self) -> crate::reference::units::DrawTextures<'_> {
        crate::reference::units::DrawTextures {
            textures: std::array::from_fn(|i| self.textures[i].as_ref().map(|t| (&*t.image, &t.sampling))),
            cube_maps: std::array::from_fn(|i| {
                let t = self.textures[i].as_ref()?;
                Some((&**t.cube_map.as_ref()?, &t.sampling))
            }),
            mesh_texcoords: self.mesh_texcoords(),
            second_texcoords: self.second_texcoords(),
            triangle_second: [[0.0; 2]; 3],
        }
    }

    /// The units 1-3 whose texture coordinates are the mesh's ([`TexCoords::Mesh`]), a bit
    /// each, as [`Draw::mesh_texcoords`](crate::Draw::mesh_texcoords) takes them.
    pub fn mesh_texcoords(&self) -> u32 {
        (1..MAX_TEXTURE_UNITS)
            .filter(|&i| {
                self.textures[i]
                    .as_ref()
                    .is_some_and(|t| t.coords == TexCoords::Mesh)
            })
            .fold(0, |bits, i| bits | 1 << i)
    }

    /// The units 1-3 whose texture coordinates are the mesh's second set
    /// ([`TexCoords::MeshSecond`]), a bit each, as
    /// [`Draw::second_texcoords`](crate::Draw::second_texcoords) takes them.
    pub fn second_texcoords(&self) -> u32 {
        (1..MAX_TEXTURE_UNITS)
            .filter(|&i| {
                self.textures[i]
                    .as_ref()
                    .is_some_and(|t| t.coords == TexCoords::MeshSecond)
            })
            .fold(0, |bits, i| bits | 1 << i)
    }
}

impl Scene {
    /// The lighting state `mesh` is drawn with: its materials, its texture units and their
    /// current texture coordinates.
    pub fn draw_state(&self, mesh: &SceneMesh) -> FixedFunctionState {
        let mut state = self.state;
        state.front = mesh.front;
        state.back = mesh.back;
        if let Some(meaning) = &mesh.gltf {
            meaning.apply(&mut state);
        }
        for (i, texture) in mesh.textures.iter().enumerate() {
            let Some(texture) = texture else { continue };
            state.texture_units[i] = texture.unit;
            if let TexCoords::Current(c) = texture.coords {
                state.current_texcoords[i] = c;
            }
        }
        state.lighting &= mesh.lit;
        state
    }

    /// The faces `mesh` is drawn without (GL_CULL_FACE with glCullFace): the mesh's
    /// `cull_face`, else back faces of single-sided glTF materials where the scene follows
    /// glTF's meaning, else none.
    pub fn cull_face(&self, mesh: &SceneMesh) -> Option<Face> {
        mesh.raster
            .cull_face
            .or_else(|| mesh.gltf.and_then(|m| m.cull_face()))
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

    /// The scene of the TOML values `table` (a scene file's tables as values, not text), with
    /// the glTF file at `gltf_path` already loaded (its meshes charged to `budget`): a
    /// `[[meshes]]` table naming that file takes `loaded` instead of reading it again.
    pub(crate) fn from_table_preloaded(
        table: toml::Table,
        path: &Path,
        limits: &Limits,
        budget: MeshBudget,
        gltf_path: PathBuf,
        loaded: self::gltf::Loaded,
    ) -> Result<Scene, SceneError> {
        let file: SceneFile = toml::Value::Table(table)
            .try_into()
            .map_err(|source| SceneError {
                path: path.to_path_buf(),
                kind: SceneErrorKind::Toml { source },
            })?;
        Scene::build(file, path, limits, budget, Some((gltf_path, loaded)))
    }

    fn parse_into(
        text: &str,
        path: &Path,
        limits: &Limits,
        budget: MeshBudget,
        preloaded: Option<(PathBuf, self::gltf::Loaded)>,
    ) -> Result<Scene, SceneError> {
        let depth = nesting_depth(text);
        if depth > MAX_SCENE_NESTING {
            return Err(SceneError {
                path: path.to_path_buf(),
                kind: SceneErrorKind::Field {
                    field: "the file".into(),
                    message: format!(
                        "arrays and inline tables nest {depth} deep: expected at most {MAX_SCENE_NESTING} (a scene file's values nest 2 deep at most)"
                    ),
                },
            });
        }
        let file: SceneFile = toml::from_str(text).map_err(|source| SceneError {
            path: path.to_path_buf(),
            kind: SceneErrorKind::Toml { source },
        })?;
        Scene::build(file, path, limits, budget, preloaded)
    }

    fn build(
        file: SceneFile,
        path: &Path,
        limits: &Limits,
        budget: MeshBudget,
        preloaded: Option<(PathBuf, self::gltf::Loaded)>,
    ) -> Result<Scene, SceneError> {
        Builder {
            path,
            limits,
            budget: std::cell::RefCell::new(budget),
            preloaded: std::cell::RefCell::new(preloaded),
        }
        .build(file)
    }
}
