//! glTF 2.0 scenes (`.gltf` with embedded data-URI or external `.bin` buffers, and `.glb`)
//! turned into ffvk geometry, PBR factors and punctual lights, plus the documented mappings
//! of those onto GL's fixed-function material ([`gl_material`]) and light ([`gl_light`]).
//!
//! [`load`] walks the default scene (or the first scene; or, in a file with no scene, every
//! root node) applying node transforms (world = parent × local), and returns one
//! [`LoadedMesh`] per mesh primitive per node that instances it, the KHR_lights_punctual
//! lights attached to nodes, and warnings about what it ignored. Every error names the file,
//! the object (mesh, primitive, accessor, buffer, node), the offending value and what was
//! expected.
//!
//! Textures, skins, morph targets, cameras and texture coordinates are ignored (with a
//! warning where the file uses them).

pub mod write;

use crate::gl::state::{Light, Material};
use crate::mesh::{MeshData, Vertex};
use glam::{Mat4, Vec3, Vec4};
use gltf::accessor::{DataType, Dimensions};
use gltf::json::Value;
use gltf::mesh::Mode;
use gltf::Semantic;
use std::path::{Path, PathBuf};

/// The glTF extensions ffvk understands; a file that requires any other is rejected.
pub const SUPPORTED_EXTENSIONS: &[&str] = &["KHR_lights_punctual", "KHR_materials_emissive_strength"];

/// The factors of a glTF metallic-roughness material (textures are not read).
#[derive(Debug, Clone, PartialEq)]
pub struct PbrMaterial {
    /// The material's index in the file (`None` for glTF's default material).
    pub index: Option<usize>,
    pub name: Option<String>,
    /// baseColorFactor, linear RGBA.
    pub base_color_factor: Vec4,
    /// metallicFactor in [0, 1].
    pub metallic_factor: f32,
    /// roughnessFactor in [0, 1].
    pub roughness_factor: f32,
    /// emissiveFactor, linear RGB.
    pub emissive_factor: Vec3,
    /// KHR_materials_emissive_strength's emissiveStrength (1 without the extension).
    pub emissive_strength: f32,
    pub double_sided: bool,
}

impl Default for PbrMaterial {
    /// glTF's default material: white, fully metallic, fully rough, no emission.
    fn default() -> Self {
        PbrMaterial {
            index: None,
            name: None,
            base_color_factor: Vec4::ONE,
            metallic_factor: 1.0,
            roughness_factor: 1.0,
            emissive_factor: Vec3::ZERO,
            emissive_strength: 1.0,
            double_sided: false,
        }
    }
}

/// One mesh primitive as placed by one node.
#[derive(Debug, Clone, PartialEq)]
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
}

/// A KHR_lights_punctual light type. Cone angles are in radians from the spot axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LightKind {
    Directional,
    Point,
    Spot { inner_cone: f32, outer_cone: f32 },
}

/// A KHR_lights_punctual light as placed by one node.
#[derive(Debug, Clone, PartialEq)]
pub struct PunctualLight {
    /// The light's name (or `light N`).
    pub name: String,
    pub kind: LightKind,
    /// Linear RGB.
    pub color: Vec3,
    /// Lux for directional lights, candela for point and spot lights.
    pub intensity: f32,
    pub range: Option<f32>,
    /// The node's world transform; the light sits at its origin and shines along its -Z.
    pub world_transform: Mat4,
}

/// What [`load`] found.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Loaded {
    pub meshes: Vec<LoadedMesh>,
    pub lights: Vec<PunctualLight>,
    /// Things the file uses that ffvk ignores, one sentence each.
    pub warnings: Vec<String>,
}

/// Why a file could not be loaded. Every message starts with the file's path.
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    #[error("{}: cannot read the file: {source}", .path.display())]
    Io { path: PathBuf, source: std::io::Error },

    #[error("{}: not a glTF 2.0 file (.gltf JSON or .glb): {message}", .path.display())]
    Parse { path: PathBuf, message: String },

    #[error(
        "{}: extensionsRequired names {extension}, which ffvk does not support: expected only {}",
        .path.display(),
        SUPPORTED_EXTENSIONS.join(", ")
    )]
    UnsupportedExtension { path: PathBuf, extension: String },

    #[error("{}: invalid glTF: {problems}", .path.display())]
    Invalid { path: PathBuf, problems: String },

    #[error("{}: buffer {buffer}: {message}", .path.display())]
    Buffer {
        path: PathBuf,
        buffer: usize,
        message: String,
    },

    #[error("{}: {primitive}: the required attribute {attribute} is missing", .path.display())]
    MissingAttribute {
        path: PathBuf,
        primitive: String,
        attribute: &'static str,
    },

    #[error(
        "{}: {primitive}: {attribute} (accessor {accessor}) is {found}: expected {expected}",
        .path.display()
    )]
    AttributeFormat {
        path: PathBuf,
        primitive: String,
        attribute: String,
        accessor: usize,
        found: String,
        expected: &'static str,
    },

    #[error(
        "{}: {primitive}: {attribute} (accessor {accessor}) has {count} elements: expected {expected} \
         (the POSITION count)",
        .path.display()
    )]
    AttributeCount {
        path: PathBuf,
        primitive: String,
        attribute: String,
        accessor: usize,
        count: usize,
        expected: usize,
    },

    #[error("{}: {primitive}: accessor {accessor}: {message}", .path.display())]
    AccessorData {
        path: PathBuf,
        primitive: String,
        accessor: usize,
        message: String,
    },

    #[error(
        "{}: {primitive}: mode {mode} is not supported: expected TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN",
        .path.display()
    )]
    UnsupportedMode {
        path: PathBuf,
        primitive: String,
        mode: &'static str,
    },

    #[error(
        "{}: {primitive}: index accessor {accessor} holds {value} at element {element}: expected a value \
         < {vertex_count} (the POSITION count)",
        .path.display()
    )]
    IndexOutOfRange {
        path: PathBuf,
        primitive: String,
        accessor: usize,
        element: usize,
        value: u32,
        vertex_count: usize,
    },

    #[error(
        "{}: {primitive}: {count} {what} do not make whole TRIANGLES: expected a multiple of 3",
        .path.display()
    )]
    PartialTriangle {
        path: PathBuf,
        primitive: String,
        /// "indices" or "vertices".
        what: &'static str,
        count: usize,
    },

    #[error("{}: node {node} is its own ancestor: expected the node hierarchy to be a forest", .path.display())]
    NodeCycle { path: PathBuf, node: usize },
}

/// GL's fixed-function material for a glTF metallic-roughness material.
///
/// With c = baseColorFactor.rgb, a = baseColorFactor.a, m = metallicFactor and
/// r = roughnessFactor (both clamped to [0, 1]):
///
/// * ambient = diffuse = (c, a);
/// * specular = (F0 · (1 − r), a) with F0 = mix(0.04, c, m), the Fresnel reflectance at
///   normal incidence of the metallic-roughness model (0.04 for dielectrics, the base color
///   for metals). The (1 − r) factor fades the highlight out as the lobe widens: at r = 1
///   GL's shininess is 0 and (n·h)^0 = 1 would otherwise add F0 uniformly to every lit point;
/// * shininess = clamp(2/α² − 2, 0, 128) with α = r², the Blinn-Phong exponent whose lobe
///   matches a GGX/Beckmann lobe of roughness α (r = 0.5 → 30, r ≤ 0.35 → 128, r = 1 → 0);
/// * emission = (emissiveFactor · emissiveStrength, a).
///
/// Every alpha is a; GL takes the lit alpha from the diffuse alpha alone. Textures are not
/// sampled. The result satisfies [`Material::validate`] for finite inputs.
pub fn gl_material(pbr: &PbrMaterial) -> Material {
    let c = pbr.base_color_factor.truncate();
    let a = pbr.base_color_factor.w;
    let metallic = pbr.metallic_factor.clamp(0.0, 1.0);
    let roughness = pbr.roughness_factor.clamp(0.0, 1.0);
    let f0 = Vec3::splat(0.04).lerp(c, metallic);
    let alpha = roughness * roughness;
    let shininess = if alpha * alpha <= 2.0 / 130.0 {
        128.0
    } else {
        (2.0 / (alpha * alpha) - 2.0).clamp(0.0, 128.0)
    };
    Material {
        ambient: c.extend(a),
        diffuse: c.extend(a),
        specular: (f0 * (1.0 - roughness)).extend(a),
        emission: (pbr.emissive_factor * pbr.emissive_strength).extend(a),
        shininess,
    }
}

/// The GL spot exponent that makes GL's spot factor (cos θ)^e fall to one half halfway (in
/// cosine) between a glTF spot light's inner and outer cone, where glTF's own falloff,
/// linear in cos θ from 1 at the inner cone to 0 at the outer, is one half:
/// e = ln ½ / ln((cos inner + cos outer) / 2), clamped to [0, 128].
pub fn spot_exponent(inner_cone: f32, outer_cone: f32) -> f32 {
    let outer = outer_cone.clamp(0.0, std::f32::consts::FRAC_PI_2);
    let inner = inner_cone.clamp(0.0, outer);
    let half = (inner.cos() + outer.cos()) / 2.0;
    if half >= 1.0 - 1e-7 {
        return 128.0;
    }
    if half <= 0.0 {
        return 0.0;
    }
    (0.5f32.ln() / half.ln()).clamp(0.0, 128.0)
}

/// GL's fixed-function light for a KHR_lights_punctual light, in WORLD coordinates: GL keeps
/// light positions and spot directions in eye space, so the caller transforms `position` and
/// `spot_direction` by its view matrix (e.g. by setting them through `GlState::light` with
/// the view as the modelview).
///
/// * enabled; ambient black; diffuse = specular = (color · intensity, 1). Intensity is taken
///   as-is, one GL unit per lux (directional) or per candela (point, spot: with the
///   attenuation below this is lux at distance ≫ 1); physically scaled files need an
///   exposure scale by the caller;
/// * directional: position = (d, 0) with d the unit direction *toward* the light, the node's
///   +Z axis (the light shines along its -Z); no attenuation;
/// * point: position = (node origin, 1); attenuation k0 = 1, k1 = 0, k2 = 1, i.e.
///   1 / (1 + d²): glTF's inverse square law, kept finite at the light (within 1 % of 1/d²
///   beyond d = 10). `range` is ignored: GL has no cutoff distance;
/// * spot: as point, plus spot direction = the node's -Z axis (unit), cutoff = the outer
///   cone in degrees (clamped to [0, 90]) and the exponent of [`spot_exponent`].
pub fn gl_light(light: &PunctualLight) -> Light {
    let w = light.world_transform;
    let color = (light.color * light.intensity).extend(1.0);
    let mut gl = Light::gl_default(1);
    gl.enabled = true;
    gl.ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
    gl.diffuse = color;
    gl.specular = color;
    match light.kind {
        LightKind::Directional => {
            let toward = w.transform_vector3(Vec3::Z).normalize_or(Vec3::Z);
            gl.position = toward.extend(0.0);
        }
        LightKind::Point | LightKind::Spot { .. } => {
            gl.position = w.transform_point3(Vec3::ZERO).extend(1.0);
            gl.constant_attenuation = 1.0;
            gl.linear_attenuation = 0.0;
            gl.quadratic_attenuation = 1.0;
        }
    }
    if let LightKind::Spot {
        inner_cone,
        outer_cone,
    } = light.kind
    {
        gl.spot_direction = w.transform_vector3(Vec3::NEG_Z).normalize_or(Vec3::NEG_Z);
        gl.spot_cutoff = outer_cone.to_degrees().clamp(0.0, 90.0);
        gl.spot_exponent = spot_exponent(inner_cone, outer_cone);
    }
    gl
}

/// What every error needs: the file and the raw JSON (for names, which the `gltf` crate
/// only parses with its `names` feature).
struct Context<'a> {
    path: &'a Path,
    raw: &'a Value,
}

impl Context<'_> {
    fn path(&self) -> PathBuf {
        self.path.to_path_buf()
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
            Some(name) => format!("mesh {mesh} ({name:?}) primitive {primitive}"),
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
    let bytes = std::fs::read(path).map_err(|source| LoadError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let parse_error = |message: String| LoadError::Parse {
        path: path.to_path_buf(),
        message,
    };
    let raw: Value = if bytes.starts_with(b"glTF") {
        let glb = gltf::Glb::from_slice(&bytes).map_err(|e| parse_error(e.to_string()))?;
        gltf::json::deserialize::from_slice(&glb.json).map_err(|e| parse_error(e.to_string()))?
    } else {
        gltf::json::deserialize::from_slice(&bytes).map_err(|e| parse_error(e.to_string()))?
    };
    let gltf::Gltf { document, blob } =
        gltf::Gltf::from_slice_without_validation(&bytes).map_err(|e| parse_error(e.to_string()))?;
    let cx = Context { path, raw: &raw };
    let mut warnings = Vec::new();

    for extension in document.extensions_required() {
        if !SUPPORTED_EXTENSIONS.contains(&extension) {
            return Err(LoadError::UnsupportedExtension {
                path: cx.path(),
                extension: extension.to_owned(),
            });
        }
    }
    for extension in document.extensions_used() {
        if !SUPPORTED_EXTENSIONS.contains(&extension) {
            warnings.push(format!(
                "extension {extension} is used but not supported by ffvk: ignored"
            ));
        }
    }

    // POSITION first, for a better message than the validator's.
    if let Some(meshes) = raw.get("meshes").and_then(Value::as_array) {
        for (m, mesh) in meshes.iter().enumerate() {
            let primitives = mesh.get("primitives").and_then(Value::as_array);
            for (p, primitive) in primitives.into_iter().flatten().enumerate() {
                let Some(position) = primitive.get("attributes").and_then(|a| a.get("POSITION")) else {
                    return Err(LoadError::MissingAttribute {
                        path: cx.path(),
                        primitive: cx.primitive_label(m, p),
                        attribute: "POSITION",
                    });
                };
                // The gltf crate's validator indexes the accessors with this unchecked.
                let accessor_count = raw.get("accessors").and_then(Value::as_array).map_or(0, Vec::len);
                if position.as_u64().is_none_or(|i| i >= accessor_count as u64) {
                    return Err(LoadError::Invalid {
                        path: cx.path(),
                        problems: format!(
                            "{}: POSITION names accessor {position}: expected an accessor index < {accessor_count}",
                            cx.primitive_label(m, p)
                        ),
                    });
                }
            }
        }
    }

    validate(&cx, &document)?;
    let buffers = read_buffers(&cx, &document, blob)?;

    let mut roots: Vec<gltf::Node> = Vec::new();
    if let Some(scene) = document.default_scene().or_else(|| document.scenes().next()) {
        roots.extend(scene.nodes());
    } else if document.nodes().len() > 0 {
        let mut is_child = vec![false; document.nodes().len()];
        for node in document.nodes() {
            node.children().for_each(|c| is_child[c.index()] = true);
        }
        roots.extend(document.nodes().filter(|n| !is_child[n.index()]));
        warnings.push("the file has no scene: loaded every root node".to_owned());
    }

    let mut out = Loaded {
        warnings,
        ..Loaded::default()
    };
    let mut on_path = vec![false; document.nodes().len()];
    for root in roots {
        visit(
            &cx,
            &buffers,
            root,
            Mat4::IDENTITY,
            &mut on_path,
            &mut Vec::new(),
            &mut out,
        )?;
    }
    for material in document.materials() {
        let pbr = material.pbr_metallic_roughness();
        let textured = pbr.base_color_texture().is_some()
            || pbr.metallic_roughness_texture().is_some()
            || material.normal_texture().is_some()
            || material.occlusion_texture().is_some()
            || material.emissive_texture().is_some();
        if textured {
            let index = material.index().unwrap_or_default();
            out.warnings.push(format!(
                "material {index}{}: textures are ignored; ffvk uses the material's factors",
                cx.name("materials", index)
                    .map(|n| format!(" ({n:?})"))
                    .unwrap_or_default()
            ));
        }
    }
    Ok(out)
}

fn validate(cx: &Context, document: &gltf::Document) -> Result<(), LoadError> {
    use gltf::json::validation::Validate;
    let root = document.as_json();
    let mut problems = Vec::new();
    root.validate(root, gltf::json::Path::new, &mut |path, error| {
        problems.push(format!("{}: {error}", path()));
    });
    if problems.is_empty() {
        return Ok(());
    }
    let shown = problems.len().min(8);
    let mut text = problems[..shown].join("; ");
    if problems.len() > shown {
        text.push_str(&format!("; and {} more", problems.len() - shown));
    }
    Err(LoadError::Invalid {
        path: cx.path(),
        problems: text,
    })
}

fn read_buffers(
    cx: &Context,
    document: &gltf::Document,
    mut blob: Option<Vec<u8>>,
) -> Result<Vec<gltf::buffer::Data>, LoadError> {
    let base = cx.path.parent().unwrap_or(Path::new(""));
    let mut buffers = Vec::new();
    for buffer in document.buffers() {
        let index = buffer.index();
        let error = |message: String| LoadError::Buffer {
            path: cx.path(),
            buffer: index,
            message,
        };
        let data = gltf::buffer::Data::from_source_and_blob(buffer.source(), Some(base), &mut blob).map_err(
            |e| match (buffer.source(), e) {
                (gltf::buffer::Source::Uri(uri), gltf::Error::Io(io)) => {
                    error(format!("cannot read {}: {io}", base.join(uri).display()))
                }
                (gltf::buffer::Source::Bin, gltf::Error::MissingBlob) => {
                    error("refers to the GLB binary chunk, which is missing".to_owned())
                }
                (gltf::buffer::Source::Uri(uri), e) if uri.starts_with("data:") => {
                    error(format!("bad data URI: {e}"))
                }
                (gltf::buffer::Source::Uri(uri), e) => error(format!("cannot load {uri:?}: {e}")),
                (gltf::buffer::Source::Bin, e) => error(e.to_string()),
            },
        )?;
        if data.len() < buffer.length() {
            return Err(error(format!(
                "holds {} bytes: expected at least {} (its byteLength)",
                data.len(),
                buffer.length()
            )));
        }
        buffers.push(data);
    }
    Ok(buffers)
}

fn visit(
    cx: &Context,
    buffers: &[gltf::buffer::Data],
    node: gltf::Node,
    parent: Mat4,
    on_path: &mut [bool],
    names: &mut Vec<String>,
    out: &mut Loaded,
) -> Result<(), LoadError> {
    let index = node.index();
    if on_path[index] {
        return Err(LoadError::NodeCycle {
            path: cx.path(),
            node: index,
        });
    }
    on_path[index] = true;
    names.push(cx.name("nodes", index).unwrap_or_else(|| format!("node {index}")));
    let world = parent * Mat4::from_cols_array_2d(&node.transform().matrix());

    if let Some(mesh) = node.mesh() {
        let m = mesh.index();
        let base_name = cx.name("meshes", m).unwrap_or_else(|| format!("mesh {m}"));
        let several = mesh.primitives().len() > 1;
        let mirrored = world.determinant() < 0.0;
        for primitive in mesh.primitives() {
            let p = primitive.index();
            if primitive.morph_targets().len() > 0 {
                out.warnings
                    .push(format!("{}: morph targets are ignored", cx.primitive_label(m, p)));
            }
            let data = read_primitive(cx, buffers, m, &primitive, mirrored, &mut out.warnings)?;
            let material = primitive.material();
            let material = material.index().map(|i| PbrMaterial {
                index: Some(i),
                name: cx.name("materials", i),
                base_color_factor: Vec4::from_array(material.pbr_metallic_roughness().base_color_factor()),
                metallic_factor: material.pbr_metallic_roughness().metallic_factor(),
                roughness_factor: material.pbr_metallic_roughness().roughness_factor(),
                emissive_factor: Vec3::from_array(material.emissive_factor()),
                emissive_strength: material.emissive_strength().unwrap_or(1.0),
                double_sided: material.double_sided(),
            });
            out.meshes.push(LoadedMesh {
                name: if several {
                    format!("{base_name}[{p}]")
                } else {
                    base_name.clone()
                },
                data,
                transform: world,
                node_path: names.clone(),
                material,
            });
        }
    }
    if node.skin().is_some() {
        out.warnings.push(format!("node {index}: skinning is ignored"));
    }
    if let Some(light) = node.light() {
        let l = light.index();
        let kind = match light.kind() {
            gltf::khr_lights_punctual::Kind::Directional => LightKind::Directional,
            gltf::khr_lights_punctual::Kind::Point => LightKind::Point,
            gltf::khr_lights_punctual::Kind::Spot {
                inner_cone_angle,
                outer_cone_angle,
            } => LightKind::Spot {
                inner_cone: inner_cone_angle,
                outer_cone: outer_cone_angle,
            },
        };
        out.lights.push(PunctualLight {
            name: cx.light_name(l).unwrap_or_else(|| format!("light {l}")),
            kind,
            color: Vec3::from_array(light.color()),
            intensity: light.intensity(),
            range: light.range(),
            world_transform: world,
        });
    }
    for child in node.children() {
        visit(cx, buffers, child, world, on_path, names, out)?;
    }
    names.pop();
    on_path[index] = false;
    Ok(())
}

fn type_name(accessor: &gltf::Accessor) -> String {
    let component = match accessor.data_type() {
        DataType::I8 => "BYTE",
        DataType::U8 => "UNSIGNED_BYTE",
        DataType::I16 => "SHORT",
        DataType::U16 => "UNSIGNED_SHORT",
        DataType::U32 => "UNSIGNED_INT",
        DataType::F32 => "FLOAT",
    };
    let dims = match accessor.dimensions() {
        Dimensions::Scalar => "SCALAR",
        Dimensions::Vec2 => "VEC2",
        Dimensions::Vec3 => "VEC3",
        Dimensions::Vec4 => "VEC4",
        Dimensions::Mat2 => "MAT2",
        Dimensions::Mat3 => "MAT3",
        Dimensions::Mat4 => "MAT4",
    };
    format!("{component} {dims}")
}

fn mode_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Points => "POINTS",
        Mode::Lines => "LINES",
        Mode::LineLoop => "LINE_LOOP",
        Mode::LineStrip => "LINE_STRIP",
        Mode::Triangles => "TRIANGLES",
        Mode::TriangleStrip => "TRIANGLE_STRIP",
        Mode::TriangleFan => "TRIANGLE_FAN",
    }
}

/// Checks that an accessor's elements lie inside its buffer view and buffer, so the `gltf`
/// crate's reader neither panics nor silently stops short.
fn check_accessor_bounds(accessor: &gltf::Accessor, buffers: &[gltf::buffer::Data]) -> Result<(), String> {
    let count = accessor.count();
    if count == 0 {
        return Err("count is 0: expected at least 1".to_owned());
    }
    let element = accessor.size();
    let view_fits = |view: gltf::buffer::View, offset: usize, count: usize, element: usize, what: &str| {
        let stride = view.stride().unwrap_or(element);
        if stride < element {
            return Err(format!(
                "{what}buffer view {} has byteStride {stride}: expected at least {element} (the element size)",
                view.index()
            ));
        }
        let end = stride
            .checked_mul(count - 1)
            .and_then(|x| x.checked_add(offset))
            .and_then(|x| x.checked_add(element));
        match end {
            Some(end) if end <= view.length() => {}
            _ => {
                return Err(format!(
                    "{what}{count} elements of {element} bytes from byte {offset} overrun buffer view {} \
                     ({} bytes)",
                    view.index(),
                    view.length()
                ))
            }
        }
        let buffer = view.buffer().index();
        let available = buffers.get(buffer).map_or(0, |b| b.len());
        if view
            .offset()
            .checked_add(view.length())
            .is_none_or(|end| end > available)
        {
            return Err(format!(
                "{what}buffer view {} (bytes {}..+{}) overruns buffer {buffer} ({available} bytes)",
                view.index(),
                view.offset(),
                view.length()
            ));
        }
        Ok(())
    };
    if let Some(view) = accessor.view() {
        view_fits(view, accessor.offset(), count, element, "")?;
    }
    if let Some(sparse) = accessor.sparse() {
        let n = sparse.count();
        if n == 0 || n > count {
            return Err(format!(
                "sparse count is {n}: expected 1..={count} (the accessor count)"
            ));
        }
        let indices = sparse.indices();
        view_fits(
            indices.view(),
            indices.offset(),
            n,
            indices.index_type().size(),
            "sparse indices: ",
        )?;
        let values = sparse.values();
        view_fits(values.view(), values.offset(), n, element, "sparse values: ")?;
    }
    Ok(())
}

/// Reads one attribute or index accessor after its bounds check, as `T`.
fn read_checked<T, I>(
    cx: &Context,
    primitive: &str,
    accessor: &gltf::Accessor,
    buffers: &[gltf::buffer::Data],
    iter: Option<I>,
) -> Result<Vec<T>, LoadError>
where
    I: Iterator<Item = T>,
{
    let data_error = |message: String| LoadError::AccessorData {
        path: cx.path(),
        primitive: primitive.to_owned(),
        accessor: accessor.index(),
        message,
    };
    check_accessor_bounds(accessor, buffers).map_err(data_error)?;
    let values: Vec<T> = iter
        .ok_or_else(|| data_error("its data could not be read from its buffer view".to_owned()))?
        .collect();
    if values.len() != accessor.count() {
        return Err(data_error(format!(
            "read {} elements: expected {} (its count)",
            values.len(),
            accessor.count()
        )));
    }
    Ok(values)
}

fn read_primitive(
    cx: &Context,
    buffers: &[gltf::buffer::Data],
    mesh: usize,
    primitive: &gltf::Primitive,
    mirrored: bool,
    warnings: &mut Vec<String>,
) -> Result<MeshData, LoadError> {
    let label = cx.primitive_label(mesh, primitive.index());
    let mode = primitive.mode();
    if !matches!(mode, Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan) {
        return Err(LoadError::UnsupportedMode {
            path: cx.path(),
            primitive: label,
            mode: mode_name(mode),
        });
    }
    let reader = primitive.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
    let format_error =
        |attribute: &str, accessor: &gltf::Accessor, expected: &'static str| LoadError::AttributeFormat {
            path: cx.path(),
            primitive: label.clone(),
            attribute: attribute.to_owned(),
            accessor: accessor.index(),
            found: type_name(accessor),
            expected,
        };
    let count_error =
        |attribute: &str, accessor: &gltf::Accessor, expected: usize| LoadError::AttributeCount {
            path: cx.path(),
            primitive: label.clone(),
            attribute: attribute.to_owned(),
            accessor: accessor.index(),
            count: accessor.count(),
            expected,
        };

    let Some(position_accessor) = primitive.get(&Semantic::Positions) else {
        return Err(LoadError::MissingAttribute {
            path: cx.path(),
            primitive: label,
            attribute: "POSITION",
        });
    };
    if (position_accessor.data_type(), position_accessor.dimensions()) != (DataType::F32, Dimensions::Vec3) {
        return Err(format_error("POSITION", &position_accessor, "FLOAT VEC3"));
    }
    let positions = read_checked(cx, &label, &position_accessor, buffers, reader.read_positions())?;
    let vertex_count = positions.len();

    let normals = match primitive.get(&Semantic::Normals) {
        None => None,
        Some(accessor) => {
            if (accessor.data_type(), accessor.dimensions()) != (DataType::F32, Dimensions::Vec3) {
                return Err(format_error("NORMAL", &accessor, "FLOAT VEC3"));
            }
            if accessor.count() != vertex_count {
                return Err(count_error("NORMAL", &accessor, vertex_count));
            }
            Some(read_checked(
                cx,
                &label,
                &accessor,
                buffers,
                reader.read_normals(),
            )?)
        }
    };

    let colors = match primitive.get(&Semantic::Colors(0)) {
        None => None,
        Some(accessor) => {
            let supported_type = matches!(accessor.data_type(), DataType::F32 | DataType::U8 | DataType::U16);
            let supported_dims = matches!(accessor.dimensions(), Dimensions::Vec3 | Dimensions::Vec4);
            if !(supported_type && supported_dims) {
                return Err(format_error(
                    "COLOR_0",
                    &accessor,
                    "FLOAT, normalized UNSIGNED_BYTE or normalized UNSIGNED_SHORT, VEC3 or VEC4",
                ));
            }
            if accessor.data_type() != DataType::F32 && !accessor.normalized() {
                warnings.push(format!(
                    "{label}: COLOR_0 (accessor {}) is {} without normalized: true; read as normalized",
                    accessor.index(),
                    type_name(&accessor)
                ));
            }
            if accessor.count() != vertex_count {
                return Err(count_error("COLOR_0", &accessor, vertex_count));
            }
            let iter = reader.read_colors(0).map(|c| c.into_rgba_f32());
            Some(read_checked(cx, &label, &accessor, buffers, iter)?)
        }
    };

    let sequence: Vec<u32> = match primitive.indices() {
        None => (0..vertex_count as u32).collect(),
        Some(accessor) => {
            let unsigned = matches!(accessor.data_type(), DataType::U8 | DataType::U16 | DataType::U32);
            if !(unsigned && accessor.dimensions() == Dimensions::Scalar) {
                return Err(format_error(
                    "indices",
                    &accessor,
                    "UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT SCALAR",
                ));
            }
            let iter = reader.read_indices().map(|i| i.into_u32());
            let indices = read_checked(cx, &label, &accessor, buffers, iter)?;
            if let Some((element, &value)) = indices
                .iter()
                .enumerate()
                .find(|(_, &i)| i as usize >= vertex_count)
            {
                return Err(LoadError::IndexOutOfRange {
                    path: cx.path(),
                    primitive: label,
                    accessor: accessor.index(),
                    element,
                    value,
                    vertex_count,
                });
            }
            indices
        }
    };

    let mut triangles: Vec<[u32; 3]> = match mode {
        Mode::Triangles => {
            if sequence.len() % 3 != 0 {
                return Err(LoadError::PartialTriangle {
                    path: cx.path(),
                    primitive: label,
                    what: if primitive.indices().is_some() {
                        "indices"
                    } else {
                        "vertices"
                    },
                    count: sequence.len(),
                });
            }
            sequence.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect()
        }
        // GL's order: triangle i is (i, i+1, i+2) for even i and (i+1, i, i+2) for odd i,
        // glTF's {i, i+2, i+1} up to rotation; the provoking vertex i+2 comes last.
        Mode::TriangleStrip => sequence
            .windows(3)
            .enumerate()
            .map(|(i, w)| {
                if i % 2 == 0 {
                    [w[0], w[1], w[2]]
                } else {
                    [w[1], w[0], w[2]]
                }
            })
            .collect(),
        // GL's (0, i+1, i+2), glTF's {i+1, i+2, 0} up to rotation; provoking vertex last.
        Mode::TriangleFan => sequence
            .windows(2)
            .skip(1)
            .map(|w| [sequence[0], w[0], w[1]])
            .collect(),
        _ => unreachable!("checked above"),
    };

    let color_of = |i: u32| {
        colors
            .as_ref()
            .map_or(Vec4::ONE, |c| Vec4::from_array(c[i as usize]))
    };
    let position_of = |i: u32| Vec3::from_array(positions[i as usize]);
    let mut data = MeshData::default();
    match &normals {
        Some(normals) => {
            data.vertices = (0..vertex_count as u32)
                .map(|i| Vertex::new(position_of(i), Vec3::from_array(normals[i as usize]), color_of(i)))
                .collect();
        }
        None => {
            // Flat normals: every triangle gets its own three vertices.
            let mut flat = Vec::with_capacity(triangles.len() * 3);
            for t in &mut triangles {
                let [a, b, c] = t.map(position_of);
                let normal = (b - a).cross(c - a).normalize_or(Vec3::Z);
                let base = flat.len() as u32;
                flat.extend(
                    t.iter()
                        .map(|&i| Vertex::new(position_of(i), normal, color_of(i))),
                );
                *t = [base, base + 1, base + 2];
            }
            data.vertices = flat;
        }
    }
    if mirrored {
        triangles.iter_mut().for_each(|t| t.swap(0, 1));
    }
    data.indices = triangles.into_iter().flatten().collect();
    Ok(data)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_8};

    fn scratch_dir(test: &str) -> PathBuf {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("target")
            .join("ffvk-test-gltf_load")
            .join(test);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// A binary buffer under construction plus the bufferViews and accessors into it.
    #[derive(Default)]
    struct Asset {
        bin: Vec<u8>,
        views: Vec<String>,
        accessors: Vec<String>,
    }

    impl Asset {
        fn view(&mut self, bytes: &[u8]) -> usize {
            while self.bin.len() % 4 != 0 {
                self.bin.push(0);
            }
            self.views.push(format!(
                r#"{{ "buffer": 0, "byteOffset": {}, "byteLength": {} }}"#,
                self.bin.len(),
                bytes.len()
            ));
            self.bin.extend_from_slice(bytes);
            self.views.len() - 1
        }

        /// An accessor over `bytes`; `extra` is more JSON members (with a leading comma).
        fn accessor(&mut self, bytes: &[u8], component: u32, count: usize, ty: &str, extra: &str) -> usize {
            let view = self.view(bytes);
            self.accessors.push(format!(
                r#"{{ "bufferView": {view}, "componentType": {component}, "count": {count}, "type": "{ty}"{extra} }}"#
            ));
            self.accessors.len() - 1
        }

        fn positions(&mut self, p: &[[f32; 3]]) -> usize {
            let mut lo = [f32::INFINITY; 3];
            let mut hi = [f32::NEG_INFINITY; 3];
            for v in p {
                for k in 0..3 {
                    lo[k] = lo[k].min(v[k]);
                    hi[k] = hi[k].max(v[k]);
                }
            }
            let bytes: Vec<u8> = p.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
            let extra = format!(r#", "min": {lo:?}, "max": {hi:?}"#);
            self.accessor(&bytes, 5126, p.len(), "VEC3", &extra)
        }

        fn vec3s(&mut self, v: &[[f32; 3]]) -> usize {
            let bytes: Vec<u8> = v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
            self.accessor(&bytes, 5126, v.len(), "VEC3", "")
        }

        fn u8s(&mut self, v: &[u8]) -> usize {
            self.accessor(v, 5121, v.len(), "SCALAR", "")
        }

        fn u16s(&mut self, v: &[u16]) -> usize {
            let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
            self.accessor(&bytes, 5123, v.len(), "SCALAR", "")
        }

        fn u32s(&mut self, v: &[u32]) -> usize {
            let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
            self.accessor(&bytes, 5125, v.len(), "SCALAR", "")
        }

        /// The document: `body` holds the remaining top-level members (meshes, nodes, ...,
        /// each followed by a comma); the buffer has `uri` or none (GLB).
        fn json(&self, body: &str, uri: Option<&str>) -> String {
            let uri = uri.map(|u| format!(r#", "uri": "{u}""#)).unwrap_or_default();
            format!(
                r#"{{ "asset": {{ "version": "2.0" }}, {body}
                   "accessors": [{}], "bufferViews": [{}],
                   "buffers": [ {{ "byteLength": {}{uri} }} ] }}"#,
                self.accessors.join(", "),
                self.views.join(", "),
                self.bin.len()
            )
        }

        /// `NAME.gltf` with its buffer in `NAME.bin` beside it.
        fn write_gltf(&self, dir: &Path, name: &str, body: &str) -> PathBuf {
            std::fs::write(dir.join(format!("{name}.bin")), &self.bin).unwrap();
            let path = dir.join(format!("{name}.gltf"));
            std::fs::write(&path, self.json(body, Some(&format!("{name}.bin")))).unwrap();
            path
        }

        /// `NAME.glb`: a JSON chunk and a BIN chunk.
        fn write_glb(&self, dir: &Path, name: &str, body: &str) -> PathBuf {
            let mut json = self.json(body, None).into_bytes();
            while json.len() % 4 != 0 {
                json.push(b' ');
            }
            let mut bin = self.bin.clone();
            while bin.len() % 4 != 0 {
                bin.push(0);
            }
            let total = 12 + 8 + json.len() + 8 + bin.len();
            let mut out = Vec::with_capacity(total);
            out.extend_from_slice(b"glTF");
            out.extend_from_slice(&2u32.to_le_bytes());
            out.extend_from_slice(&(total as u32).to_le_bytes());
            out.extend_from_slice(&(json.len() as u32).to_le_bytes());
            out.extend_from_slice(&0x4E4F_534Au32.to_le_bytes());
            out.extend_from_slice(&json);
            out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
            out.extend_from_slice(&0x004E_4942u32.to_le_bytes());
            out.extend_from_slice(&bin);
            let path = dir.join(format!("{name}.glb"));
            std::fs::write(&path, out).unwrap();
            path
        }
    }

    /// One node holding mesh 0, in scene 0.
    fn one_mesh_body(primitive: &str) -> String {
        format!(
            r#""scene": 0, "scenes": [ {{ "nodes": [0] }} ], "nodes": [ {{ "mesh": 0 }} ],
               "meshes": [ {{ "name": "thing", "primitives": [ {primitive} ] }} ],"#
        )
    }

    const QUAD: [[f32; 3]; 4] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];

    fn face_normal(mesh: &MeshData, t: usize) -> Vec3 {
        let [a, b, c] =
            [0, 1, 2].map(|k| Vec3::from_array(mesh.vertices[mesh.indices[3 * t + k] as usize].position));
        (b - a).cross(c - a)
    }

    fn message(e: LoadError) -> String {
        e.to_string()
    }

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
    fn external_bin_u8_indices_missing_normals_give_flat_unshared_vertices() {
        let dir = scratch_dir("flat");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD);
        let colors: Vec<u8> = vec![255, 0, 0, 0, 255, 0, 0, 0, 255, 51, 102, 153];
        let col = a.accessor(&colors, 5121, 4, "VEC3", r#", "normalized": true"#);
        let idx = a.u8s(&[0, 1, 2, 0, 2, 3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "COLOR_0": {col} }}, "indices": {idx} }}"#
        ));
        let path = a.write_gltf(&dir, "flat", &body);
        let loaded = load(&path).unwrap();
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        let m = &loaded.meshes[0];
        assert_eq!(m.name, "thing");
        assert!(m.material.is_none());
        assert_eq!(m.data.vertices.len(), 6, "every triangle has its own vertices");
        assert_eq!(m.data.indices, vec![0, 1, 2, 3, 4, 5]);
        for v in &m.data.vertices {
            assert_eq!(v.normal, [0.0, 0.0, 1.0]);
        }
        assert_eq!(m.data.vertices[0].color, [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(m.data.vertices[2].color, [0.0, 0.0, 1.0, 1.0]);
        assert!(Vec4::from_array(m.data.vertices[5].color).abs_diff_eq(Vec4::new(0.2, 0.4, 0.6, 1.0), 1e-6));
        assert_eq!(m.data.vertices[5].position, [0.0, 1.0, 0.0]);
    }

    #[test]
    fn triangle_strip_alternates_and_keeps_counter_clockwise_winding() {
        let dir = scratch_dir("strip");
        let mut a = Asset::default();
        // A zig-zag strip along x: 0 (0,0) 1 (0,1)? No: glTF/GL strips list bottom, top pairs
        // such that the first triangle (0, 1, 2) is counter-clockwise.
        let p = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 2.0, 0.0],
        ];
        let pos = a.positions(&p);
        let nrm = a.vec3s(&[[0.0, 0.0, 1.0]; 5]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "NORMAL": {nrm} }}, "mode": 5 }}"#
        ));
        let m = load(&a.write_gltf(&dir, "strip", &body))
            .unwrap()
            .meshes
            .remove(0);
        assert_eq!(m.data.vertices.len(), 5, "normals given: vertices are shared");
        assert_eq!(m.data.indices, vec![0, 1, 2, 2, 1, 3, 2, 3, 4]);
        for t in 0..3 {
            assert!(
                face_normal(&m.data, t).z > 0.0,
                "triangle {t} is counter-clockwise"
            );
        }
    }

    #[test]
    fn triangle_fan_and_u32_indices() {
        let dir = scratch_dir("fan");
        let mut a = Asset::default();
        let p = [
            [0.0, 0.0, 0.0],
            [1.0, -1.0, 0.0],
            [1.0, 1.0, 0.0],
            [-1.0, 1.0, 0.0],
            [-1.0, -1.0, 0.0],
        ];
        let pos = a.positions(&p);
        let idx = a.u32s(&[0, 1, 2, 3, 4]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "indices": {idx}, "mode": 6 }}"#
        ));
        let m = load(&a.write_gltf(&dir, "fan", &body)).unwrap().meshes.remove(0);
        assert_eq!(m.data.triangle_count(), 3);
        for t in 0..3 {
            assert!(
                face_normal(&m.data, t).z > 0.0,
                "triangle {t} is counter-clockwise"
            );
            let first = m.data.vertices[m.data.indices[3 * t] as usize].position;
            assert_eq!(first, [0.0, 0.0, 0.0], "the fan center leads each triangle");
            assert_eq!(
                m.data.vertices[m.data.indices[3 * t] as usize].normal,
                [0.0, 0.0, 1.0]
            );
        }
    }

    #[test]
    fn u16_indices_u16_rgba_colors_and_given_normals_share_vertices() {
        let dir = scratch_dir("u16");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD);
        let nrm = a.vec3s(&[[0.0, 0.0, 1.0]; 4]);
        let rgba: Vec<u8> = [
            65535u16, 0, 0, 65535, 0, 65535, 0, 32768, 0, 0, 65535, 0, 65535, 65535, 65535, 65535,
        ]
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
        let col = a.accessor(&rgba, 5123, 4, "VEC4", r#", "normalized": true"#);
        let idx = a.u16s(&[0, 1, 2, 0, 2, 3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "NORMAL": {nrm}, "COLOR_0": {col} }}, "indices": {idx} }}"#
        ));
        let m = load(&a.write_gltf(&dir, "u16", &body)).unwrap().meshes.remove(0);
        assert_eq!(m.data.vertices.len(), 4);
        assert_eq!(m.data.indices, vec![0, 1, 2, 0, 2, 3]);
        assert_eq!(m.data.vertices[0].color, [1.0, 0.0, 0.0, 1.0]);
        assert!((m.data.vertices[1].color[3] - 32768.0 / 65535.0).abs() < 1e-6);
        assert_eq!(m.data.vertices[2].color, [0.0, 0.0, 1.0, 0.0]);
        assert_eq!(m.data.vertices[3].color, [1.0; 4]);
        assert_eq!(m.data.vertices[3].normal, [0.0, 0.0, 1.0]);
    }

    #[test]
    fn unnormalized_integer_colors_warn_and_float_rgb_colors_get_alpha_one() {
        let dir = scratch_dir("colors");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let col = a.accessor(&[255, 0, 0, 255, 0, 0, 255, 0, 0, 0, 0, 0], 5121, 3, "VEC4", "");
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "COLOR_0": {col} }} }}"#
        ));
        let loaded = load(&a.write_gltf(&dir, "u8_unnormalized", &body)).unwrap();
        assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
        assert!(loaded.warnings[0].contains("COLOR_0") && loaded.warnings[0].contains("normalized"));
        assert_eq!(loaded.meshes[0].data.vertices[0].color, [1.0, 0.0, 0.0, 1.0]);

        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let col = a.vec3s(&[[0.5, 0.25, 1.0]; 3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "COLOR_0": {col} }} }}"#
        ));
        let loaded = load(&a.write_gltf(&dir, "f32_rgb", &body)).unwrap();
        assert!(loaded.warnings.is_empty());
        assert_eq!(loaded.meshes[0].data.vertices[2].color, [0.5, 0.25, 1.0, 1.0]);
    }

    #[test]
    fn glb_with_bin_chunk_loads() {
        let dir = scratch_dir("glb");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD);
        let idx = a.u16s(&[0, 1, 2, 0, 2, 3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "indices": {idx}, "material": 0 }}"#
        )) + r#""materials": [ { "name": "red", "pbrMetallicRoughness": { "baseColorFactor": [1, 0, 0, 0.5],
                "metallicFactor": 0.25, "roughnessFactor": 0.75 }, "emissiveFactor": [0, 1, 0],
                "doubleSided": true } ],"#;
        let loaded = load(&a.write_glb(&dir, "quad", &body)).unwrap();
        let m = &loaded.meshes[0];
        assert_eq!(m.data.triangle_count(), 2);
        assert_eq!(m.data.vertices.len(), 6);
        let material = m.material.as_ref().unwrap();
        assert_eq!(material.name.as_deref(), Some("red"));
        assert_eq!(material.base_color_factor, Vec4::new(1.0, 0.0, 0.0, 0.5));
        assert_eq!(
            (material.metallic_factor, material.roughness_factor),
            (0.25, 0.75)
        );
        assert_eq!(material.emissive_factor, Vec3::Y);
        assert!(material.double_sided);
    }

    #[test]
    fn node_hierarchy_composes_parent_times_local_in_the_default_scene() {
        let dir = scratch_dir("hierarchy");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let s = std::f32::consts::FRAC_1_SQRT_2;
        let body = format!(
            r#""scene": 1,
               "scenes": [ {{ "nodes": [3] }}, {{ "nodes": [0] }} ],
               "nodes": [
                 {{ "name": "parent", "translation": [1, 2, 3], "children": [1] }},
                 {{ "name": "child", "scale": [2, 2, 2], "rotation": [0, {s}, 0, {s}], "children": [2], "mesh": 0 }},
                 {{ "name": "grandchild", "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1], "mesh": 1 }},
                 {{ "name": "other scene", "mesh": 0 }}
               ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }}, {{ "attributes": {{ "POSITION": {pos} }} }} ] }},
                           {{ "name": "leaf", "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],"#
        );
        let loaded = load(&a.write_gltf(&dir, "hierarchy", &body)).unwrap();
        let names: Vec<&str> = loaded.meshes.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["mesh 0[0]", "mesh 0[1]", "leaf"]);
        let parent = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0));
        let child = Mat4::from_scale_rotation_translation(
            Vec3::splat(2.0),
            glam::Quat::from_xyzw(0.0, s, 0.0, s),
            Vec3::ZERO,
        );
        let grandchild = Mat4::from_translation(Vec3::new(0.0, 0.0, 5.0));
        assert!(loaded.meshes[0].transform.abs_diff_eq(parent * child, 1e-6));
        assert!(loaded.meshes[2]
            .transform
            .abs_diff_eq(parent * child * grandchild, 1e-5));
        // (0,0,5) in the child's frame: rotated +90° about y to (5,0,0), scaled by 2, moved.
        let origin = loaded.meshes[2].transform.transform_point3(Vec3::ZERO);
        assert!(origin.abs_diff_eq(Vec3::new(11.0, 2.0, 3.0), 1e-4), "{origin}");
    }

    #[test]
    fn a_file_without_scenes_loads_its_root_nodes_with_a_warning() {
        let dir = scratch_dir("no_scene");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = format!(
            r#""nodes": [ {{ "children": [1] }}, {{ "mesh": 0, "translation": [0, 1, 0] }}, {{ "mesh": 0 }} ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],"#
        );
        let loaded = load(&a.write_gltf(&dir, "no_scene", &body)).unwrap();
        assert_eq!(
            loaded.meshes.len(),
            2,
            "node 1 once, as node 0's child, and node 2"
        );
        assert!(
            loaded.warnings.iter().any(|w| w.contains("no scene")),
            "{:?}",
            loaded.warnings
        );
    }

    #[test]
    fn mirrored_nodes_swap_winding() {
        let dir = scratch_dir("mirror");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = format!(
            r#""scene": 0, "scenes": [ {{ "nodes": [0, 1] }} ],
               "nodes": [ {{ "mesh": 0 }}, {{ "mesh": 0, "scale": [-1, 1, 1] }} ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],"#
        );
        let loaded = load(&a.write_gltf(&dir, "mirror", &body)).unwrap();
        let (plain, mirrored) = (&loaded.meshes[0], &loaded.meshes[1]);
        assert_eq!(plain.data.indices, vec![0, 1, 2]);
        assert_eq!(mirrored.data.indices, vec![1, 0, 2]);
        // The normal is the object-space face normal either way (the normal matrix mirrors it).
        assert_eq!(mirrored.data.vertices[0].normal, [0.0, 0.0, 1.0]);
        // Drawn with its transform, the mirrored triangle is counter-clockwise again.
        let w: Vec<Vec3> = mirrored
            .data
            .indices
            .iter()
            .map(|&i| {
                mirrored
                    .transform
                    .transform_point3(Vec3::from_array(mirrored.data.vertices[i as usize].position))
            })
            .collect();
        assert!((w[1] - w[0]).cross(w[2] - w[0]).z > 0.0);
    }

    #[test]
    fn missing_position_names_mesh_primitive_and_attribute() {
        let dir = scratch_dir("missing_position");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let nrm = a.vec3s(&[[0.0, 0.0, 1.0]; 3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }} }}, {{ "attributes": {{ "NORMAL": {nrm} }} }}"#
        ));
        let path = a.write_gltf(&dir, "missing_position", &body);
        let e = message(load(&path).unwrap_err());
        assert!(e.contains("missing_position.gltf"), "{e}");
        assert!(e.contains("mesh 0 (\"thing\") primitive 1"), "{e}");
        assert!(e.contains("POSITION") && e.contains("missing"), "{e}");
    }

    #[test]
    fn index_out_of_range_names_accessor_and_value() {
        let dir = scratch_dir("bad_index");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let idx = a.u8s(&[0, 1, 7]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "indices": {idx} }}"#
        ));
        let e = load(&a.write_gltf(&dir, "bad_index", &body)).unwrap_err();
        assert!(matches!(
            e,
            LoadError::IndexOutOfRange {
                accessor: 1,
                element: 2,
                value: 7,
                vertex_count: 3,
                ..
            }
        ));
        let e = message(e);
        assert!(
            e.contains("bad_index.gltf") && e.contains("accessor 1") && e.contains("holds 7"),
            "{e}"
        );
        assert!(e.contains("< 3"), "{e}");
    }

    #[test]
    fn points_and_lines_are_rejected_by_name() {
        let dir = scratch_dir("modes");
        for (mode, name) in [(0, "POINTS"), (1, "LINES"), (2, "LINE_LOOP"), (3, "LINE_STRIP")] {
            let mut a = Asset::default();
            let pos = a.positions(&QUAD[..3]);
            let body = one_mesh_body(&format!(
                r#"{{ "attributes": {{ "POSITION": {pos} }}, "mode": {mode} }}"#
            ));
            let e = message(load(&a.write_gltf(&dir, name, &body)).unwrap_err());
            assert!(e.contains(&format!("mode {name} is not supported")), "{e}");
            assert!(
                e.contains("mesh 0") && e.contains("primitive 0") && e.contains("TRIANGLES"),
                "{e}"
            );
        }
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

        let body = format!(
            r#""extensionsUsed": ["EXT_fancy_thing", "KHR_materials_emissive_strength"],
               "extensionsRequired": ["KHR_materials_emissive_strength"], {mesh}"#
        );
        let loaded = load(&a.write_gltf(&dir, "used", &body)).unwrap();
        assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
        assert!(loaded.warnings[0].contains("EXT_fancy_thing"));
    }

    #[test]
    fn file_buffer_and_json_errors_name_the_file() {
        let dir = scratch_dir("io");
        let e = message(load(&dir.join("nope.gltf")).unwrap_err());
        assert!(e.contains("nope.gltf") && e.contains("cannot read"), "{e}");

        let bad = dir.join("bad.gltf");
        std::fs::write(&bad, "{ not json").unwrap();
        let e = message(load(&bad).unwrap_err());
        assert!(e.contains("bad.gltf") && e.contains("not a glTF 2.0 file"), "{e}");

        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = one_mesh_body(&format!(r#"{{ "attributes": {{ "POSITION": {pos} }} }}"#));
        let path = a.write_gltf(&dir, "lost_bin", &body);
        std::fs::remove_file(dir.join("lost_bin.bin")).unwrap();
        let e = load(&path).unwrap_err();
        assert!(matches!(e, LoadError::Buffer { buffer: 0, .. }));
        let e = message(e);
        assert!(
            e.contains("lost_bin.gltf: buffer 0: cannot read") && e.contains("lost_bin.bin"),
            "{e}"
        );

        // A buffer shorter than its byteLength.
        let short = dir.join("short.gltf");
        std::fs::write(dir.join("short.bin"), [0u8; 8]).unwrap();
        std::fs::write(&short, a.json(&body, Some("short.bin"))).unwrap();
        let e = message(load(&short).unwrap_err());
        assert!(e.contains("buffer 0: holds 8 bytes: expected at least 36"), "{e}");

        // Schema problems go through the gltf crate's validator.
        let invalid = dir.join("invalid.gltf");
        let body = one_mesh_body(r#"{ "attributes": { "POSITION": 9 } }"#);
        std::fs::write(&invalid, a.json(&body, Some("lost_bin.bin"))).unwrap();
        let e = message(load(&invalid).unwrap_err());
        assert!(
            e.contains("invalid.gltf: invalid glTF") && e.contains("POSITION names accessor 9"),
            "{e}"
        );
        let body = one_mesh_body(r#"{ "attributes": { "POSITION": 0, "NORMAL": 9 } }"#);
        std::fs::write(&invalid, a.json(&body, Some("lost_bin.bin"))).unwrap();
        let e = message(load(&invalid).unwrap_err());
        assert!(
            e.contains("invalid.gltf: invalid glTF") && e.contains("NORMAL"),
            "{e}"
        );
    }

    #[test]
    fn attribute_format_count_and_data_errors() {
        let dir = scratch_dir("attributes");
        // POSITION as UNSIGNED_SHORT VEC3.
        let mut a = Asset::default();
        let p16: Vec<u8> = [0u16, 0, 0, 1, 0, 0, 0, 1, 0]
            .iter()
            .flat_map(|x| x.to_le_bytes())
            .collect();
        let pos = a.accessor(&p16, 5123, 3, "VEC3", r#", "min": [0, 0, 0], "max": [1, 1, 0]"#);
        let body = one_mesh_body(&format!(r#"{{ "attributes": {{ "POSITION": {pos} }} }}"#));
        let e = message(load(&a.write_gltf(&dir, "u16_position", &body)).unwrap_err());
        assert!(
            e.contains("POSITION (accessor 0) is UNSIGNED_SHORT VEC3: expected FLOAT VEC3"),
            "{e}"
        );

        // NORMAL with the wrong count.
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let nrm = a.vec3s(&[[0.0, 0.0, 1.0]; 2]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "NORMAL": {nrm} }} }}"#
        ));
        let e = message(load(&a.write_gltf(&dir, "normal_count", &body)).unwrap_err());
        assert!(
            e.contains("NORMAL (accessor 1) has 2 elements: expected 3"),
            "{e}"
        );

        // COLOR_0 as FLOAT VEC2.
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let c: Vec<u8> = [0.0f32; 6].iter().flat_map(|x| x.to_le_bytes()).collect();
        let col = a.accessor(&c, 5126, 3, "VEC2", "");
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "COLOR_0": {col} }} }}"#
        ));
        let e = message(load(&a.write_gltf(&dir, "color_vec2", &body)).unwrap_err());
        assert!(
            e.contains("COLOR_0 (accessor 1) is FLOAT VEC2: expected FLOAT, normalized"),
            "{e}"
        );

        // An accessor claiming more elements than its view holds.
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let idx = a.u16s(&[0, 1, 2]);
        a.accessors[idx] = a.accessors[idx].replace("\"count\": 3", "\"count\": 6");
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "indices": {idx} }}"#
        ));
        let e = message(load(&a.write_gltf(&dir, "overrun", &body)).unwrap_err());
        assert!(
            e.contains("accessor 1: 6 elements of 2 bytes") && e.contains("overrun buffer view 1"),
            "{e}"
        );

        // TRIANGLES with 4 indices.
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let idx = a.u16s(&[0, 1, 2, 0]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "indices": {idx} }}"#
        ));
        let e = message(load(&a.write_gltf(&dir, "partial", &body)).unwrap_err());
        assert!(
            e.contains("4 indices do not make whole TRIANGLES: expected a multiple of 3"),
            "{e}"
        );
    }

    #[test]
    fn node_cycles_are_an_error() {
        let dir = scratch_dir("cycle");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = format!(
            r#""scene": 0, "scenes": [ {{ "nodes": [0] }} ],
               "nodes": [ {{ "children": [1] }}, {{ "children": [0], "mesh": 0 }} ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],"#
        );
        let e = message(load(&a.write_gltf(&dir, "cycle", &body)).unwrap_err());
        assert!(
            e.contains("cycle.gltf") && e.contains("node 0 is its own ancestor"),
            "{e}"
        );
    }

    #[test]
    fn textures_are_reported_as_ignored() {
        let dir = scratch_dir("textures");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "material": 0 }}"#
        )) + r#""materials": [ { "name": "wood", "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } } ],
                 "textures": [ { "source": 0 } ], "images": [ { "uri": "wood.png" } ],"#;
        let loaded = load(&a.write_gltf(&dir, "textured", &body)).unwrap();
        assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
        assert!(
            loaded.warnings[0].contains("material 0 (\"wood\")") && loaded.warnings[0].contains("textures")
        );
        let pbr = loaded.meshes[0].material.clone().unwrap();
        assert_eq!(
            (pbr.base_color_factor, pbr.metallic_factor, pbr.roughness_factor),
            (Vec4::ONE, 1.0, 1.0)
        );
    }

    #[test]
    fn punctual_lights_are_placed_by_their_nodes() {
        let dir = scratch_dir("lights");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        // Nodes 1 and 3 turn -Z (the shine direction) to -Y: -90° about x.
        let s = std::f32::consts::FRAC_1_SQRT_2;
        let body = format!(
            r#""extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
               "extensions": {{ "KHR_lights_punctual": {{ "lights": [
                 {{ "name": "sun", "type": "directional", "color": [1, 0.5, 0.25], "intensity": 2 }},
                 {{ "type": "point", "intensity": 10, "range": 4 }},
                 {{ "name": "torch", "type": "spot", "spot": {{ "innerConeAngle": {FRAC_PI_8}, "outerConeAngle": {FRAC_PI_4} }} }}
               ] }} }},
               "scene": 0, "scenes": [ {{ "nodes": [0, 1, 2] }} ],
               "nodes": [
                 {{ "mesh": 0 }},
                 {{ "rotation": [-{s}, 0, 0, {s}], "extensions": {{ "KHR_lights_punctual": {{ "light": 0 }} }} }},
                 {{ "translation": [0, 3, 0], "children": [3], "extensions": {{ "KHR_lights_punctual": {{ "light": 1 }} }} }},
                 {{ "translation": [1, 0, 0], "rotation": [-{s}, 0, 0, {s}], "extensions": {{ "KHR_lights_punctual": {{ "light": 2 }} }} }}
               ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }}, "material": 0 }} ] }} ],
               "materials": [ {{ "emissiveFactor": [1, 0.5, 0], "extensions": {{ "KHR_materials_emissive_strength": {{ "emissiveStrength": 4 }} }} }} ],"#
        );
        let loaded = load(&a.write_gltf(&dir, "lights", &body)).unwrap();
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        assert_eq!(loaded.meshes[0].material.as_ref().unwrap().emissive_strength, 4.0);
        let [sun, bulb, torch] = [0, 1, 2].map(|k| loaded.lights[k].clone());
        assert_eq!((sun.name.as_str(), sun.kind), ("sun", LightKind::Directional));
        assert_eq!(
            (sun.color, sun.intensity, sun.range),
            (Vec3::new(1.0, 0.5, 0.25), 2.0, None)
        );
        assert_eq!(
            (bulb.name.as_str(), bulb.kind, bulb.range),
            ("light 1", LightKind::Point, Some(4.0))
        );
        assert_eq!((bulb.color, bulb.intensity), (Vec3::ONE, 10.0));
        assert_eq!(
            torch.kind,
            LightKind::Spot {
                inner_cone: FRAC_PI_8,
                outer_cone: FRAC_PI_4
            }
        );
        assert_eq!(torch.intensity, 1.0);

        let gl = gl_light(&sun);
        assert!(gl.enabled);
        assert!(
            gl.position.abs_diff_eq(Vec4::new(0.0, 1.0, 0.0, 0.0), 1e-6),
            "toward the light: {}",
            gl.position
        );
        assert_eq!(gl.diffuse, Vec4::new(2.0, 1.0, 0.5, 1.0));
        assert_eq!(gl.specular, gl.diffuse);
        assert_eq!(gl.ambient, Vec4::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(
            (gl.constant_attenuation, gl.quadratic_attenuation, gl.spot_cutoff),
            (1.0, 0.0, 180.0)
        );

        let gl = gl_light(&bulb);
        assert_eq!(gl.position, Vec4::new(0.0, 3.0, 0.0, 1.0));
        assert_eq!(gl.diffuse, Vec4::new(10.0, 10.0, 10.0, 1.0));
        assert_eq!(
            (
                gl.constant_attenuation,
                gl.linear_attenuation,
                gl.quadratic_attenuation
            ),
            (1.0, 0.0, 1.0)
        );
        assert_eq!(gl.spot_cutoff, 180.0);

        let gl = gl_light(&torch);
        assert!(
            gl.position.abs_diff_eq(Vec4::new(1.0, 3.0, 0.0, 1.0), 1e-6),
            "{}",
            gl.position
        );
        assert!(
            gl.spot_direction.abs_diff_eq(Vec3::NEG_Y, 1e-6),
            "{}",
            gl.spot_direction
        );
        assert!((gl.spot_cutoff - 45.0).abs() < 1e-4);
        assert!((gl.spot_exponent - spot_exponent(FRAC_PI_8, FRAC_PI_4)).abs() < 1e-6);
        for l in [&sun, &bulb, &torch] {
            let mut state = crate::gl::state::LightingState::default();
            state.lights[0] = gl_light(l);
            state.validate().unwrap();
        }
    }

    #[test]
    fn spot_exponent_halves_the_spot_factor_midway_between_the_cones() {
        for (inner, outer) in [
            (0.0, FRAC_PI_4),
            (FRAC_PI_8, FRAC_PI_4),
            (0.2, 1.2),
            (0.0, FRAC_PI_2),
        ] {
            let e = spot_exponent(inner, outer);
            let half_cos = (f32::cos(inner) + f32::cos(outer)) / 2.0;
            assert!(
                (half_cos.powf(e) - 0.5).abs() < 1e-4,
                "inner {inner} outer {outer}: e = {e}"
            );
            assert!((0.0..=128.0).contains(&e));
        }
        assert_eq!(spot_exponent(0.0, 0.0), 128.0);
        assert_eq!(spot_exponent(0.01, 0.01), 128.0, "clamped");
    }

    #[test]
    fn gl_material_follows_the_documented_rule() {
        let dielectric = PbrMaterial {
            base_color_factor: Vec4::new(0.8, 0.2, 0.1, 0.5),
            metallic_factor: 0.0,
            roughness_factor: 0.5,
            emissive_factor: Vec3::new(0.1, 0.2, 0.3),
            emissive_strength: 2.0,
            ..PbrMaterial::default()
        };
        let m = gl_material(&dielectric);
        assert_eq!(m.ambient, Vec4::new(0.8, 0.2, 0.1, 0.5));
        assert_eq!(m.diffuse, m.ambient);
        assert!(
            m.specular.abs_diff_eq(Vec4::new(0.02, 0.02, 0.02, 0.5), 1e-6),
            "{}",
            m.specular
        );
        assert!((m.shininess - 30.0).abs() < 1e-3, "{}", m.shininess);
        assert!(m.emission.abs_diff_eq(Vec4::new(0.2, 0.4, 0.6, 0.5), 1e-6));
        m.validate().unwrap();

        let polished_gold = PbrMaterial {
            base_color_factor: Vec4::new(1.0, 0.8, 0.3, 1.0),
            metallic_factor: 1.0,
            roughness_factor: 0.0,
            ..PbrMaterial::default()
        };
        let m = gl_material(&polished_gold);
        assert_eq!(m.specular, Vec4::new(1.0, 0.8, 0.3, 1.0));
        assert_eq!(m.shininess, 128.0);
        assert_eq!(m.emission, Vec4::new(0.0, 0.0, 0.0, 1.0));

        let m = gl_material(&PbrMaterial::default());
        assert_eq!(
            m.specular,
            Vec4::new(0.0, 0.0, 0.0, 1.0),
            "fully rough: no highlight"
        );
        assert_eq!(m.shininess, 0.0);

        for r in 0..=20 {
            let pbr = PbrMaterial {
                roughness_factor: r as f32 / 20.0,
                metallic_factor: 0.5,
                ..PbrMaterial::default()
            };
            gl_material(&pbr).validate().unwrap();
        }
        // Out-of-range factors are clamped, not propagated.
        let wild = PbrMaterial {
            metallic_factor: 3.0,
            roughness_factor: -1.0,
            ..PbrMaterial::default()
        };
        gl_material(&wild).validate().unwrap();
    }
}
