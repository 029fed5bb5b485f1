//! glTF 2.0 scenes (`.gltf` with embedded data-URI or external `.bin` buffers, and `.glb`)
//! turned into ffvk geometry, PBR factors and punctual lights, plus the documented mappings
//! of those onto GL's fixed-function material ([`gl_material`]) and light ([`gl_light`]).
//!
//! [`load`] walks the default scene (or the first scene; or, in a file with no scene, every
//! root node) applying node transforms (world = parent × local), and returns one
//! [`LoadedMesh`] per mesh primitive per node that instances it, the KHR_lights_punctual
//! lights and the cameras attached to nodes, and warnings about what it ignored. Every error
//! names the file, the object (mesh, primitive, accessor, buffer, node), the offending value
//! and what was expected.
//!
//! Textures are read under [`Textures::Means`]: the base color texture is sampled (unit 0),
//! the occlusion texture too (unit 1, as `GL_LUMINANCE`, from `TEXCOORD_0` or `TEXCOORD_1`),
//! the emissive texture enters as its mean texel; skins and morph targets are ignored (with a
//! warning where the file uses them). Geometry that exists only compressed (Draco, meshopt)
//! is refused with the extension's name.

mod accessors;
mod cameras;
mod compressed;
mod external;
mod lights;
mod materials;
mod meshopt;
mod occlusion;
mod primitives;
mod quantized;
mod read;
mod rules;
mod sampler;
#[cfg(test)]
mod testing;
mod textures;
mod uris;
mod values;
pub mod write;

pub use accessors::{AccessorPart, AccessorProblem};
pub use cameras::{CameraProjection, PlacedCamera};
pub use external::external_files;
pub use lights::{exact_light, gl_light, spot_exponent, GltfLights, LightKind, PunctualLight};
pub use materials::{gl_material, PbrMaterial};
pub use occlusion::OcclusionTexture;
pub use sampler::SampledTexture;
pub(in crate::scene) use textures::mipmapped_bytes;
pub use textures::{TextureMean, Textures};

use crate::mesh::MeshData;
use crate::scene::{Limits, MeshBudget, OverBudget};
use glam::Mat4;
use gltf::json::Value;
use std::path::{Path, PathBuf};

/// The glTF extensions ffvk understands; a file that requires any other is rejected.
pub const SUPPORTED_EXTENSIONS: &[&str] = &[
    "KHR_lights_punctual",
    "KHR_materials_emissive_strength",
    "KHR_mesh_quantization",
    "KHR_texture_transform",
    "EXT_meshopt_compression",
    "KHR_meshopt_compression",
];

/// Extensions that change only how textures are read. ffvk samples PNG and JPEG base color
/// textures, so a file that requires one of these still renders (with a warning), the
/// texture in question left out.
pub const TEXTURE_EXTENSIONS: &[&str] = &[
    "KHR_texture_basisu",
    "EXT_texture_webp",
    "EXT_texture_avif",
    "MSFT_texture_dds",
];

/// The largest glTF, GLB or buffer file read, in bytes (1 GiB): beyond it a file is refused
/// before it is read.
pub const MAX_FILE_BYTES: u64 = 1 << 30;

/// One mesh primitive as placed by one node.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct LoadedMesh {
    /// The mesh's name (or `mesh N`), with `[P]` appended when the mesh has several
    /// primitives (P = primitive index).
    pub name: String,
    /// Object-space geometry: a counter-clockwise-front triangle list (see [`load`]).
    pub data: MeshData,
    /// The node's world transform (object to world).
    pub transform: Mat4,
    /// The names (or `node N`) of the node that places it and of its ancestors, root first.
    pub node_path: Vec<String>,
    /// The primitive's material; `None` when it uses glTF's default material
    /// ([`PbrMaterial::default`]).
    pub material: Option<PbrMaterial>,
    /// Whether the primitive has COLOR_0 (else every vertex color is white).
    pub vertex_colors: bool,
    /// Whether the primitive has TEXCOORD_0 (else every texture coordinate is (0, 0)).
    pub texcoords: bool,
    /// Whether it is lit: false for points and lines without normals, which glTF draws
    /// unlit (their vertex colors, or the material's base color, as they are).
    pub lit: bool,
}

/// What [`load`] found.
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct Loaded {
    /// One per mesh primitive per node that places it, in node order (depth first).
    pub meshes: Vec<LoadedMesh>,
    /// One per node that places a light, in node order.
    pub lights: Vec<PunctualLight>,
    /// One per node that places a usable camera, in node order.
    pub cameras: Vec<PlacedCamera>,
    /// Things the file uses that ffvk ignores, one sentence each.
    pub warnings: Vec<String>,
}

/// Why a file could not be loaded: the file, and what was wrong with it. The message is
/// the path followed by the kind's message.
#[derive(Debug, thiserror::Error)]
#[error("{}: {kind}", .path.display())]
#[non_exhaustive]
pub struct LoadError {
    /// The `.gltf` or `.glb` file.
    pub path: PathBuf,
    /// What was wrong with it; also the error's `source()`, so that an I/O error beneath it
    /// stays reachable.
    #[source]
    pub kind: LoadErrorKind,
}

/// What was wrong with a glTF file. Every message names the object (mesh, primitive,
/// accessor, buffer, node), the offending value and what was expected.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LoadErrorKind {
    /// The file itself could not be read.
    #[error("cannot read the file: {source}")]
    Io {
        /// The I/O error from opening or reading the `.gltf` or `.glb` file.
        source: std::io::Error,
    },

    /// Neither glTF JSON nor GLB; `message` is the parser's.
    #[error("not a glTF 2.0 file (.gltf JSON or .glb): {message}")]
    Parse {
        /// The GLB header check's, the GLB reader's or the JSON parser's message.
        message: String,
    },

    /// extensionsRequired names extensions outside [`SUPPORTED_EXTENSIONS`] (and
    /// [`TEXTURE_EXTENSIONS`]); every one is named.
    #[error(
        "extensionsRequired names {}, which ffvk does not support: expected only {}",
        extensions.join(", "),
        SUPPORTED_EXTENSIONS.join(", ")
    )]
    UnsupportedExtension {
        /// The required extensions ffvk neither supports nor may ignore, in the file's order.
        extensions: Vec<String>,
    },

    /// What the `gltf` crate's validator found, one entry per problem; the message shows the
    /// first eight.
    #[error("invalid glTF: {}", problem_list(.problems))]
    Invalid {
        /// One `JSON path: problem` entry per problem, in the validator's order.
        problems: Vec<String>,
    },

    /// A primitive's POSITION (`accessor`, as written in the JSON) is not an accessor index.
    #[error(
        "invalid glTF: {primitive}: POSITION names accessor {accessor}: expected an accessor index \
         < {accessor_count}"
    )]
    PositionAccessor {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The POSITION value as JSON text (a number out of range, a string, a float...).
        accessor: String,
        /// How many accessors the file has: valid indices are below it.
        accessor_count: usize,
    },

    /// A buffer's external file could not be read.
    #[error("buffer {buffer}: cannot read {}: {source}", crate::scene::shorten(&.file.display().to_string()))]
    BufferFile {
        /// The buffer's index in `buffers`.
        buffer: usize,
        /// The file its URI leads to, resolved against the glTF file's folder.
        file: PathBuf,
        /// The I/O error from opening or reading it.
        source: std::io::Error,
    },

    /// A buffer URI that leaves the glTF file's folder (an absolute path, a `file:` URI, `..`
    /// past the folder, or a link out of it): an asset may only read `data:` URIs and files
    /// inside its own folder.
    #[error(
        "buffer {buffer}: the URI {uri:?} leaves the asset's folder: expected a data: URI or a \
         relative path inside {} (ffvk --allow-root DIR widens that)",
        .folder.display()
    )]
    BufferOutside {
        /// The buffer's index in `buffers`.
        buffer: usize,
        /// The buffer's URI as written, shortened past 120 characters.
        uri: String,
        /// The glTF file's folder, which the URI had to stay inside.
        folder: PathBuf,
    },

    /// A buffer that refers to the GLB binary chunk, in a file without one.
    #[error("buffer {buffer}: refers to the GLB binary chunk, which is missing")]
    MissingBinChunk {
        /// The buffer's index in `buffers`.
        buffer: usize,
    },

    /// A buffer that holds fewer bytes than its byteLength.
    #[error("buffer {buffer}: holds {len} bytes: expected at least {byte_length} (its byteLength)")]
    BufferLength {
        /// The buffer's index in `buffers`.
        buffer: usize,
        /// The bytes it holds (an external file's padded with zeros to a multiple of 4).
        len: usize,
        /// The byteLength the JSON declares for it.
        byte_length: usize,
    },

    /// A buffer that could not be loaded otherwise (a bad data URI, an unsupported URI);
    /// `message` is the `gltf` crate's.
    #[error("buffer {buffer}: {message}")]
    Buffer {
        /// The buffer's index in `buffers`.
        buffer: usize,
        /// What was wrong with its URI or data.
        message: String,
    },

    /// A primitive whose attribute or indices exist only compressed by an extension ffvk
    /// cannot decode (see `compressed.rs` for why).
    #[error(
        "{primitive}: {attribute} (accessor {accessor}) {detail}, and ffvk cannot decode \
         {extension}: expected uncompressed geometry (export the file without mesh compression)"
    )]
    Compressed {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The attribute's semantic (`POSITION`, `NORMAL`, ...) or `indices`.
        attribute: String,
        /// The index of the accessor it names.
        accessor: u64,
        /// The extension its data is compressed with: `KHR_draco_mesh_compression`.
        extension: &'static str,
        /// Why the accessor holds no data (it has no bufferView).
        detail: &'static str,
    },

    /// A meshopt-compressed bufferView (EXT_meshopt_compression or KHR_meshopt_compression)
    /// whose extension object is wrong or whose bytes do not decode.
    #[error("bufferViews[{view}].extensions.{extension}: {problem}")]
    Meshopt {
        /// The bufferView's index.
        view: usize,
        /// The extension's name.
        extension: &'static str,
        /// The field, its value and what was expected, or why the bytes did not decode.
        problem: String,
    },

    /// A primitive without an attribute ffvk needs (POSITION).
    #[error("{primitive}: the required attribute {attribute} is missing")]
    MissingAttribute {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The missing attribute's semantic.
        attribute: &'static str,
    },

    /// An attribute (or the indices) of a component type or element type ffvk cannot read;
    /// `found` is the accessor's, e.g. `UNSIGNED_SHORT VEC3`.
    #[error("{primitive}: {attribute} (accessor {accessor}) is {found}: expected {expected}")]
    AttributeFormat {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The attribute's semantic (`POSITION`, `NORMAL`, `COLOR_0`, `TEXCOORD_0`, `TEXCOORD_1`)
        /// or `indices`.
        attribute: String,
        /// The accessor's index.
        accessor: usize,
        /// The accessor's component and element type.
        found: String,
        /// The types ffvk reads for this attribute, e.g. `FLOAT VEC3`.
        expected: &'static str,
    },

    /// An attribute with another number of elements than POSITION.
    #[error(
        "{primitive}: {attribute} (accessor {accessor}) has {count} elements: expected {expected} \
         (the POSITION count)"
    )]
    AttributeCount {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The attribute's semantic (`NORMAL`, `COLOR_0`, `TEXCOORD_0`, `TEXCOORD_1`).
        attribute: String,
        /// The accessor's index.
        accessor: usize,
        /// The accessor's element count.
        count: usize,
        /// The POSITION accessor's element count.
        expected: usize,
    },

    /// An accessor whose data is not where it says, or could not be read.
    #[error("{primitive}: accessor {accessor}: {problem}")]
    AccessorData {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The accessor's index.
        accessor: usize,
        /// What is out of bounds or could not be read.
        problem: Box<AccessorProblem>,
    },

    /// An index (element `element` of the index accessor) that names no vertex.
    #[error(
        "{primitive}: index accessor {accessor} holds {value} at element {element}: expected a value \
         < {vertex_count} (the POSITION count)"
    )]
    IndexOutOfRange {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The index accessor's index.
        accessor: usize,
        /// The position of the first offending index in the accessor.
        element: usize,
        /// The offending index.
        value: u32,
        /// The POSITION element count: indices must be below it.
        vertex_count: usize,
    },

    /// A TRIANGLES primitive whose index or vertex count is not a multiple of 3.
    #[error("{primitive}: {count} {what} do not make whole TRIANGLES: expected a multiple of 3")]
    PartialTriangle {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// "indices" or "vertices".
        what: &'static str,
        /// How many indices (or, unindexed, vertices) the primitive has.
        count: usize,
    },

    /// A value outside what the glTF specification (or an extension's schema) allows.
    #[error("{object}: {field} = {value}: expected {expected}")]
    InvalidValue {
        /// E.g. `material 2 ("paint")` or `KHR_lights_punctual light 0`.
        object: String,
        /// The property, as named in the JSON (dotted below the object).
        field: &'static str,
        /// The value as found (shortened when long).
        value: String,
        /// What the specification allows, e.g. `a number in [0, 1]`.
        expected: &'static str,
    },

    /// A POSITION, NORMAL or COLOR_0 element that is NaN or infinite.
    #[error(
        "{primitive}: {attribute} (accessor {accessor}) element {element} is {value:?}: expected \
         finite numbers"
    )]
    NotFinite {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// `POSITION`, `NORMAL`, `COLOR_0`, `TEXCOORD_0` or `TEXCOORD_1`.
        attribute: &'static str,
        /// The accessor's index.
        accessor: usize,
        /// The position of the first offending element in the accessor.
        element: usize,
        /// That element's components, as read.
        value: Vec<f32>,
    },

    /// A primitive past the scene's mesh memory limit.
    #[error("{primitive}: {source}")]
    OverBudget {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The primitive's size, the bytes already used and the limit.
        source: OverBudget,
    },

    /// A host allocation for a primitive's data failed.
    #[error("{primitive}: {source}")]
    Alloc {
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// What was being allocated, and how many bytes.
        source: crate::alloc::AllocError,
    },

    /// A placement past the scene's limit on mesh placements ([`Limits::placements`]), each
    /// counted by the nodes on its path.
    #[error(
        "nodes[{node}] places {primitive} {depth} node(s) deep, which with the {made} placements \
         before it (each counted by the nodes on its path, whose names it keeps) passes the \
         scene's placement limit of {limit}: expected fewer or shallower placements, or a higher \
         limit (ffvk --max-placements)"
    )]
    Placements {
        /// The node placing the primitive.
        node: usize,
        /// `mesh M ("name") primitive P`.
        primitive: String,
        /// The nodes on its path, root to `node`: what it counts.
        depth: u64,
        /// What the placements before it counted, in this file and the scene's earlier ones.
        made: u64,
        /// The limit.
        limit: u64,
    },

    /// An image whose decoded texels would pass the scene's texture memory limit
    /// ([`Limits::texture_bytes`]), judged from its header before it is decoded.
    #[error(
        "images[{image}]: {width}x{height} texels take {bytes} bytes decoded (RGBA8 with \
         mipmaps), which with the {used} bytes of the textures before it passes the scene's \
         texture memory limit of {limit} bytes: expected fewer or smaller textures, or a higher \
         limit (ffvk --max-texture-mib)"
    )]
    TextureBudget {
        /// The image's index in `images`.
        image: usize,
        /// Its width, from its header.
        width: u32,
        /// Its height, from its header.
        height: u32,
        /// What it would take decoded.
        bytes: u64,
        /// What the textures decoded before it took.
        used: u64,
        /// The limit.
        limit: u64,
    },

    /// A buffer that would take the file's buffers past [`Limits::buffer_bytes`], or whose
    /// memory could not be allocated; judged before it is read or allocated.
    #[error(
        "buffers[{buffer}]: {what} of {bytes} bytes, with the {used} bytes of the buffers before \
         it, passes the limit of {limit} bytes on a file's buffers: expected smaller buffers, or \
         a higher limit (ffvk --max-buffer-mib)"
    )]
    BufferBudget {
        /// The buffer's index in `buffers`.
        buffer: usize,
        /// What it is: `its file`, `its data URI`, `the GLB binary chunk`, `a meshopt fallback buffer`.
        what: &'static str,
        /// Its size.
        bytes: u64,
        /// What the buffers before it took.
        used: u64,
        /// The limit.
        limit: u64,
    },

    /// A host allocation for a buffer's data failed.
    #[error("buffers[{buffer}]: {source}")]
    BufferAlloc {
        /// The buffer's index in `buffers`.
        buffer: usize,
        /// What was being allocated, and how many bytes.
        source: crate::alloc::AllocError,
    },

    /// A node hierarchy with a cycle through node `node`.
    #[error("node {node} is its own ancestor: expected the node hierarchy to be a forest")]
    NodeCycle {
        /// The index of a node on the cycle: the first one found to be its own ancestor.
        node: usize,
    },
}

/// The validator's first eight problems, and how many more there are.
fn problem_list(problems: &[String]) -> String {
    let shown = problems.len().min(8);
    let mut text = problems[..shown].join("; ");
    if problems.len() > shown {
        text.push_str(&format!("; and {} more", problems.len() - shown));
    }
    text
}

/// What every error needs: the file and the raw JSON (for names, which the `gltf` crate
/// only parses with its `names` feature).
struct Context<'a> {
    path: &'a Path,
    raw: &'a Value,
}

impl Context<'_> {
    /// An error about this file.
    fn error(&self, kind: LoadErrorKind) -> LoadError {
        LoadError {
            path: self.path.to_path_buf(),
            kind,
        }
    }

    fn name(&self, array: &str, index: usize) -> Option<String> {
        self.raw
            .get(array)?
            .get(index)?
            .get("name")?
            .as_str()
            .map(str::to_owned)
    }

    fn light_name(&self, index: usize) -> Option<String> {
        let lights = self
            .raw
            .get("extensions")?
            .get("KHR_lights_punctual")?
            .get("lights")?;
        lights.get(index)?.get("name")?.as_str().map(str::to_owned)
    }

    fn primitive_label(&self, mesh: usize, primitive: usize) -> String {
        match self.name("meshes", mesh) {
            Some(name) => format!(
                "mesh {mesh} ({:?}) primitive {primitive}",
                crate::scene::shorten(&name)
            ),
            None => format!("mesh {mesh} primitive {primitive}"),
        }
    }
}

/// Loads a `.gltf` or `.glb` file (see the module docs).
///
/// Geometry: POSITION (float VEC3) is required; NORMAL (float VEC3) is optional, and without
/// it every triangle gets its flat face normal and its own three vertices, as glTF requires;
/// COLOR_0 may be float, normalized unsigned byte or unsigned short, RGB (alpha 1) or RGBA,
/// and defaults to white; indices may be unsigned byte, short or int, or absent (vertices in
/// order). TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN become triangle lists with the
/// primitive's winding, each triangle ordered so its last vertex is GL's provoking vertex
/// for that mode (what flat shading uses). Where a node's world transform has a negative
/// determinant (a mirror) each triangle's first two vertices are swapped, so that drawn with
/// `transform` the front faces are counter-clockwise on screen as glTF intends.
pub fn load(path: &Path) -> Result<Loaded, LoadError> {
    let limits = Limits::default();
    load_with(
        path,
        &limits,
        &mut MeshBudget::new(limits.mesh_bytes),
        Textures::Ignore,
    )
}

/// [`load`] with buffer URIs also allowed into `limits.asset_roots`, each primitive charged to
/// `budget` before it is read (once per node that places it), and textures read as `textures`
/// says (see [`TextureMean`]).
pub fn load_with(
    path: &Path,
    limits: &Limits,
    budget: &mut MeshBudget,
    textures: Textures,
) -> Result<Loaded, LoadError> {
    let read::Parsed {
        raw,
        document,
        blob,
        mut warnings,
    } = read::parse(path)?;
    let cx = Context { path, raw: &raw };

    let unsupported: Vec<String> = document
        .extensions_required()
        .filter(|e| !SUPPORTED_EXTENSIONS.contains(e) && !TEXTURE_EXTENSIONS.contains(e))
        .map(crate::scene::shorten)
        .collect();
    if !unsupported.is_empty() {
        return Err(cx.error(LoadErrorKind::UnsupportedExtension {
            extensions: unsupported,
        }));
    }
    for extension in document.extensions_used() {
        if TEXTURE_EXTENSIONS.contains(&extension) {
            warnings.push(format!(
                "extension {extension} changes only textures (ffvk reads PNG and JPEG): ignored"
            ));
        } else if !SUPPORTED_EXTENSIONS.contains(&extension) {
            warnings.push(format!(
                "extension {} is used but not supported by ffvk: ignored",
                crate::scene::shorten(extension)
            ));
        }
    }

    primitives::check_positions(&cx)?;
    compressed::check(&cx)?;
    read::validate(&cx, &document, &mut warnings)?;
    values::check(&cx, &document)?;
    let mut buffers = read::read_buffers(&cx, &document, blob, limits)?;
    meshopt::decode(&cx, &mut buffers)?;

    let mut out = Loaded {
        warnings,
        ..Loaded::default()
    };
    read::walk(&cx, &document, &buffers, (limits, textures), budget, &mut out)?;
    out.warnings
        .extend(materials::texture_warnings(&cx, &document, textures));
    let table = textures::material_textures(
        &cx,
        &document,
        &buffers,
        (limits, budget),
        textures,
        &mut out.warnings,
    )?;
    for material in out.meshes.iter_mut().filter_map(|m| m.material.as_mut()) {
        if let Some(t) = material.index.and_then(|i| table.get(i)) {
            material.base_color_texture = t.base_color;
            material.emissive_texture = t.emissive;
            material.base_color_sampled = t.base_color_sampled.clone();
            material.occlusion_sampled = t.occlusion.clone();
        }
    }
    occlusion::drop_unmapped(&mut out.meshes, &cx, &mut out.warnings);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::gltf::testing::{message, one_mesh_body, scratch_dir, Asset, QUAD};
    use glam::Vec4;

    #[test]
    fn teapot_written_by_write_gltf_loads_back_identically() {
        let dir = scratch_dir("teapot");
        let teapot = crate::mesh::teapot::teapot(4).unwrap();
        let path = dir.join("teapot.gltf");
        crate::scene::gltf::write::write_gltf(&teapot, &path).unwrap();
        let loaded = load(&path).unwrap();
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        assert!(loaded.lights.is_empty());
        assert_eq!(loaded.meshes.len(), 1);
        let mesh = &loaded.meshes[0];
        assert_eq!(mesh.name, "teapot");
        assert_eq!(mesh.data, teapot);
        assert_eq!(mesh.transform, Mat4::IDENTITY);
        let material = mesh.material.as_ref().unwrap();
        assert_eq!(material.index, Some(0));
        assert_eq!(material.name.as_deref(), Some("default"));
        assert_eq!(material.base_color_factor, Vec4::ONE);
        assert_eq!((material.metallic_factor, material.roughness_factor), (0.0, 0.5));
        assert_eq!(material.emissive_strength, 1.0);
    }

    #[test]
    fn required_unknown_extension_is_an_error_and_used_one_a_warning() {
        let dir = scratch_dir("extensions");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let mesh = one_mesh_body(&format!(r#"{{ "attributes": {{ "POSITION": {pos} }} }}"#));
        let body = format!(
            r#""extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"], {mesh}"#
        );
        let e = load(&a.write_gltf(&dir, "required", &body)).unwrap_err();
        let text = message(e);
        assert!(
            text.contains("required.gltf") && text.contains("KHR_draco_mesh_compression"),
            "{text}"
        );
        assert!(
            text.contains("KHR_lights_punctual, KHR_materials_emissive_strength"),
            "{text}"
        );

        // Every unsupported required extension is named, not only the first.
        let body = format!(
            r#""extensionsUsed": ["KHR_draco_mesh_compression", "EXT_mesh_gpu_instancing"],
               "extensionsRequired": ["KHR_draco_mesh_compression", "EXT_mesh_gpu_instancing"], {mesh}"#
        );
        let text = message(load(&a.write_gltf(&dir, "two", &body)).unwrap_err());
        assert!(
            text.contains("names KHR_draco_mesh_compression, EXT_mesh_gpu_instancing, which"),
            "{text}"
        );

        // An extension that changes only how textures are read is a warning, even when
        // required; KHR_texture_transform is supported.
        let body = format!(
            r#""extensionsUsed": ["KHR_texture_transform", "EXT_texture_webp"],
               "extensionsRequired": ["KHR_texture_transform", "EXT_texture_webp"], {mesh}"#
        );
        let loaded = load(&a.write_gltf(&dir, "texture", &body)).unwrap();
        assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
        assert!(
            loaded.warnings[0].contains("EXT_texture_webp changes only textures"),
            "{:?}",
            loaded.warnings
        );

        let body = format!(
            r#""extensionsUsed": ["EXT_fancy_thing", "KHR_materials_emissive_strength"],
               "extensionsRequired": ["KHR_materials_emissive_strength"], {mesh}"#
        );
        let loaded = load(&a.write_gltf(&dir, "used", &body)).unwrap();
        assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
        assert!(loaded.warnings[0].contains("EXT_fancy_thing"));
    }
}
