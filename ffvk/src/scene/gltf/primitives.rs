//! Mesh primitives: their accessors checked and read, and turned into counter-clockwise
//! triangle lists ([`MeshData`]) as documented on [`load`](super::load).

use super::accessors::read_checked;
use super::{quantized, Context, LoadError, LoadErrorKind};
use crate::alloc::try_vec;
use crate::mesh::{MeshData, Vertex};
use crate::scene::MeshBudget;
use glam::{Vec3, Vec4};
use gltf::accessor::{DataType, Dimensions};
use gltf::json::Value;
use gltf::mesh::Mode;
use gltf::Semantic;

/// Checks in the raw JSON that every primitive names a POSITION accessor that exists, before
/// the `gltf` crate's validator (which indexes the accessors with it unchecked) and for a
/// better message than the validator's.
pub(super) fn check_positions(cx: &Context) -> Result<(), LoadError> {
    let raw = cx.raw;
    if let Some(meshes) = raw.get("meshes").and_then(Value::as_array) {
        for (m, mesh) in meshes.iter().enumerate() {
            let primitives = mesh.get("primitives").and_then(Value::as_array);
            for (p, primitive) in primitives.into_iter().flatten().enumerate() {
                let Some(position) = primitive.get("attributes").and_then(|a| a.get("POSITION")) else {
                    return Err(cx.error(LoadErrorKind::MissingAttribute {
                        primitive: cx.primitive_label(m, p),
                        attribute: "POSITION",
                    }));
                };
                // The gltf crate's validator indexes the accessors with this unchecked.
                let accessor_count = raw.get("accessors").and_then(Value::as_array).map_or(0, Vec::len);
                if position.as_u64().is_none_or(|i| i >= accessor_count as u64) {
                    return Err(cx.error(LoadErrorKind::PositionAccessor {
                        primitive: cx.primitive_label(m, p),
                        accessor: position.to_string(),
                        accessor_count,
                    }));
                }
            }
        }
    }
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

/// Whether a primitive of `mode` is made of triangles (the others are points and lines).
pub(super) fn draws_triangles(mode: Mode) -> bool {
    matches!(mode, Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan)
}

/// The first element of `values` with a NaN or infinite component is an error: GL would
/// drop its triangles (positions) or light them with NaN (normals, colors) without a word.
fn check_finite<const N: usize>(
    cx: &Context,
    primitive: &str,
    attribute: &'static str,
    accessor: &gltf::Accessor,
    values: &[[f32; N]],
) -> Result<(), LoadError> {
    match values.iter().position(|v| !v.iter().all(|x| x.is_finite())) {
        None => Ok(()),
        Some(element) => Err(cx.error(LoadErrorKind::NotFinite {
            primitive: primitive.to_owned(),
            attribute,
            accessor: accessor.index(),
            element,
            value: values[element].to_vec(),
        })),
    }
}

/// Reads one primitive of mesh `mesh` (see [`load`](super::load)): triangles of every mode as
/// a triangle list, `mirrored` swapping each triangle's first two vertices; points and lines
/// as their own topology (GL_LINE_LOOP as a line list), with their vertices as given. With
/// `second_set`, its TEXCOORD_1 (which it has) becomes the mesh's second texture coordinates.
pub(super) fn read_primitive(
    cx: &Context,
    buffers: &[gltf::buffer::Data],
    mesh: usize,
    primitive: &gltf::Primitive,
    (mirrored, second_set): (bool, bool),
    budget: &mut MeshBudget,
    warnings: &mut Vec<String>,
) -> Result<MeshData, LoadError> {
    let label = cx.primitive_label(mesh, primitive.index());
    let mode = primitive.mode();
    // What the mesh will take, charged before anything is read.
    let vertex_count = primitive.get(&Semantic::Positions).map_or(0, |a| a.count());
    let sequence_len = primitive.indices().map_or(vertex_count, |a| a.count());
    let triangle_count = match mode {
        Mode::Triangles => sequence_len / 3,
        Mode::TriangleStrip | Mode::TriangleFan => sequence_len.saturating_sub(2),
        Mode::Points | Mode::Lines | Mode::LineStrip | Mode::LineLoop => 0,
    };
    let (kept_vertices, kept_indices) = match mode {
        Mode::Points | Mode::Lines | Mode::LineStrip => (vertex_count, sequence_len),
        Mode::LineLoop => (vertex_count, sequence_len.saturating_mul(2)),
        _ if primitive.get(&Semantic::Normals).is_some() => (vertex_count, triangle_count.saturating_mul(3)),
        _ => (triangle_count.saturating_mul(3), triangle_count.saturating_mul(3)),
    };
    let second_bytes = if second_set { 8 } else { 0 };
    budget
        .charge_sized(kept_vertices, second_bytes, kept_indices)
        .map_err(|source| {
            cx.error(LoadErrorKind::OverBudget {
                primitive: label.clone(),
                source,
            })
        })?;
    let alloc_error = |source| {
        cx.error(LoadErrorKind::Alloc {
            primitive: label.clone(),
            source,
        })
    };
    let reader = primitive.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
    let format_error = |attribute: &str, accessor: &gltf::Accessor, expected: &'static str| {
        cx.error(LoadErrorKind::AttributeFormat {
            primitive: label.clone(),
            attribute: attribute.to_owned(),
            accessor: accessor.index(),
            found: type_name(accessor),
            expected,
        })
    };
    let count_error = |attribute: &str, accessor: &gltf::Accessor, expected: usize| {
        cx.error(LoadErrorKind::AttributeCount {
            primitive: label.clone(),
            attribute: attribute.to_owned(),
            accessor: accessor.index(),
            count: accessor.count(),
            expected,
        })
    };

    let Some(position_accessor) = primitive.get(&Semantic::Positions) else {
        return Err(cx.error(LoadErrorKind::MissingAttribute {
            primitive: label,
            attribute: "POSITION",
        }));
    };
    // KHR_mesh_quantization widens the types of POSITION, NORMAL and TEXCOORD_0.
    let quantization = quantized::declared(cx);
    let accepts = |accessor: &gltf::Accessor, core: quantized::Accepted, extended: quantized::Accepted| {
        let accepted = if quantization { extended } else { core };
        accepted.allows(accessor.data_type(), accessor.normalized())
    };
    if position_accessor.dimensions() != Dimensions::Vec3
        || !accepts(&position_accessor, quantized::FLOAT, quantized::POSITION)
    {
        return Err(format_error(
            "POSITION",
            &position_accessor,
            if quantization {
                "FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT (KHR_mesh_quantization) VEC3"
            } else {
                "FLOAT VEC3 (integer positions need KHR_mesh_quantization in extensionsUsed)"
            },
        ));
    }
    let positions = quantized::read_vectors::<3>(cx, &label, &position_accessor, buffers)?;
    check_finite(cx, &label, "POSITION", &position_accessor, &positions)?;
    let vertex_count = positions.len();

    let normals = match primitive.get(&Semantic::Normals) {
        None => None,
        Some(accessor) => {
            if accessor.dimensions() != Dimensions::Vec3
                || !accepts(&accessor, quantized::FLOAT, quantized::NORMAL)
            {
                return Err(format_error(
                    "NORMAL",
                    &accessor,
                    if quantization {
                        "FLOAT, or normalized BYTE or SHORT (KHR_mesh_quantization), VEC3"
                    } else {
                        "FLOAT VEC3 (integer normals need KHR_mesh_quantization in extensionsUsed)"
                    },
                ));
            }
            if accessor.count() != vertex_count {
                return Err(count_error("NORMAL", &accessor, vertex_count));
            }
            let normals = quantized::read_vectors::<3>(cx, &label, &accessor, buffers)?;
            check_finite(cx, &label, "NORMAL", &accessor, &normals)?;
            Some(normals)
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
            let iter = || reader.read_colors(0).map(|c| c.into_rgba_f32());
            let colors = read_checked(cx, &label, &accessor, buffers, iter)?;
            check_finite(cx, &label, "COLOR_0", &accessor, &colors)?;
            Some(colors)
        }
    };

    // Texture coordinates in every type glTF allows: FLOAT, or normalized UNSIGNED_BYTE or
    // UNSIGNED_SHORT (divided by 255 or 65535), VEC2.
    let read_texcoords = |set: u32| -> Result<Option<Vec<[f32; 2]>>, LoadError> {
        let Some(accessor) = primitive.get(&Semantic::TexCoords(set)) else {
            return Ok(None);
        };
        let name = format!("TEXCOORD_{set}");
        // glTF's core: UNSIGNED_BYTE and UNSIGNED_SHORT are read as normalized whatever the
        // accessor says, as before the extension; with it, its flag decides.
        let supported = if quantization {
            accepts(&accessor, quantized::FLOAT, quantized::TEXCOORD)
        } else {
            matches!(accessor.data_type(), DataType::F32 | DataType::U8 | DataType::U16)
        };
        if !supported || accessor.dimensions() != Dimensions::Vec2 {
            return Err(format_error(
                &name,
                &accessor,
                if quantization {
                    "FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT (KHR_mesh_quantization), VEC2"
                } else {
                    "FLOAT, normalized UNSIGNED_BYTE or normalized UNSIGNED_SHORT, VEC2"
                },
            ));
        }
        if accessor.count() != vertex_count {
            return Err(count_error(&name, &accessor, vertex_count));
        }
        let st = if quantization {
            quantized::read_vectors::<2>(cx, &label, &accessor, buffers)?
        } else {
            let iter = || reader.read_tex_coords(set).map(|t| t.into_f32());
            read_checked(cx, &label, &accessor, buffers, iter)?
        };
        let what = if set == 0 { "TEXCOORD_0" } else { "TEXCOORD_1" };
        check_finite(cx, &label, what, &accessor, &st)?;
        Ok(Some(st))
    };
    let texcoords = read_texcoords(0)?;
    let second = if second_set { read_texcoords(1)? } else { None };
    let texcoord_of = |i: u32| {
        texcoords
            .as_ref()
            .map_or(glam::Vec2::ZERO, |t| glam::Vec2::from_array(t[i as usize]))
    };

    let sequence: Vec<u32> = match primitive.indices() {
        None => {
            let mut sequence = try_vec(vertex_count, "mesh indices").map_err(alloc_error)?;
            sequence.extend(0..vertex_count as u32);
            sequence
        }
        Some(accessor) => {
            let unsigned = matches!(accessor.data_type(), DataType::U8 | DataType::U16 | DataType::U32);
            if !(unsigned && accessor.dimensions() == Dimensions::Scalar) {
                return Err(format_error(
                    "indices",
                    &accessor,
                    "UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT SCALAR",
                ));
            }
            let iter = || reader.read_indices().map(|i| i.into_u32());
            let indices = read_checked(cx, &label, &accessor, buffers, iter)?;
            if let Some((element, &value)) = indices
                .iter()
                .enumerate()
                .find(|(_, &i)| i as usize >= vertex_count)
            {
                return Err(cx.error(LoadErrorKind::IndexOutOfRange {
                    primitive: label,
                    accessor: accessor.index(),
                    element,
                    value,
                    vertex_count,
                }));
            }
            indices
        }
    };

    // The second set of the `count` vertices that `sources` name (one vertex each), when read.
    let second_of =
        |count: usize, sources: &mut dyn Iterator<Item = u32>| -> Result<Vec<[f32; 2]>, LoadError> {
            let Some(second) = &second else {
                return Ok(Vec::new());
            };
            let mut out = try_vec(count, "mesh texture coordinates").map_err(alloc_error)?;
            out.extend(sources.map(|i| second[i as usize]));
            Ok(out)
        };

    if !draws_triangles(mode) {
        let data = points_and_lines(cx, &label, mode, &sequence, vertex_count, alloc_error, |i| {
            let normal = normals
                .as_ref()
                .map_or(Vec3::Z, |n| Vec3::from_array(n[i as usize]));
            let color = colors
                .as_ref()
                .map_or(Vec4::ONE, |c| Vec4::from_array(c[i as usize]));
            Vertex::new(Vec3::from_array(positions[i as usize]), normal, color).with_texcoord(texcoord_of(i))
        })?;
        let second = second_of(vertex_count, &mut (0..vertex_count as u32))?;
        return Ok(data.with_second_texcoords(second));
    }

    let mut triangles: Vec<[u32; 3]> = try_vec(triangle_count, "mesh triangles").map_err(alloc_error)?;
    match mode {
        Mode::Triangles => {
            if !sequence.len().is_multiple_of(3) {
                return Err(cx.error(LoadErrorKind::PartialTriangle {
                    primitive: label,
                    what: if primitive.indices().is_some() {
                        "indices"
                    } else {
                        "vertices"
                    },
                    count: sequence.len(),
                }));
            }
            triangles.extend(sequence.chunks_exact(3).map(|t| [t[0], t[1], t[2]]));
        }
        // GL's order: triangle i is (i, i+1, i+2) for even i and (i+1, i, i+2) for odd i,
        // glTF's {i, i+2, i+1} up to rotation; the provoking vertex i+2 comes last.
        Mode::TriangleStrip => triangles.extend(sequence.windows(3).enumerate().map(|(i, w)| {
            if i % 2 == 0 {
                [w[0], w[1], w[2]]
            } else {
                [w[1], w[0], w[2]]
            }
        })),
        // GL's (0, i+1, i+2), glTF's {i+1, i+2, 0} up to rotation; provoking vertex last.
        Mode::TriangleFan => triangles.extend(sequence.windows(2).skip(1).map(|w| [sequence[0], w[0], w[1]])),
        // Returned above.
        Mode::Points | Mode::Lines | Mode::LineLoop | Mode::LineStrip => {}
    }

    let color_of = |i: u32| {
        colors
            .as_ref()
            .map_or(Vec4::ONE, |c| Vec4::from_array(c[i as usize]))
    };
    let position_of = |i: u32| Vec3::from_array(positions[i as usize]);
    let mut data = MeshData::default();
    match &normals {
        Some(normals) => {
            data.vertices = try_vec(vertex_count, "mesh vertices").map_err(alloc_error)?;
            data.vertices.extend((0..vertex_count as u32).map(|i| {
                Vertex::new(position_of(i), Vec3::from_array(normals[i as usize]), color_of(i))
                    .with_texcoord(texcoord_of(i))
            }));
            data.second_texcoords = second_of(vertex_count, &mut (0..vertex_count as u32))?;
        }
        None => {
            // Flat normals: every triangle gets its own three vertices.
            let mut flat = try_vec(triangles.len() * 3, "mesh vertices").map_err(alloc_error)?;
            data.second_texcoords = second_of(triangles.len() * 3, &mut triangles.iter().flatten().copied())?;
            for t in &mut triangles {
                let [a, b, c] = t.map(position_of);
                let normal = (b - a).cross(c - a).normalize_or(Vec3::Z);
                let base = flat.len() as u32;
                flat.extend(t.iter().map(|&i| {
                    Vertex::new(position_of(i), normal, color_of(i)).with_texcoord(texcoord_of(i))
                }));
                *t = [base, base + 1, base + 2];
            }
            data.vertices = flat;
        }
    }
    if mirrored {
        triangles.iter_mut().for_each(|t| t.swap(0, 1));
    }
    data.indices = try_vec(triangles.len() * 3, "mesh indices").map_err(alloc_error)?;
    data.indices.extend(triangles.into_iter().flatten());
    Ok(data)
}

/// A primitive of points or lines as a mesh of that topology: every vertex as `vertex` makes
/// it, the indices as given (GL_LINE_LOOP closed into a line list, GL's way). GL_LINES needs
/// an even count, as glTF says.
fn points_and_lines(
    cx: &Context,
    label: &str,
    mode: Mode,
    sequence: &[u32],
    vertex_count: usize,
    alloc_error: impl Fn(crate::alloc::AllocError) -> LoadError,
    vertex: impl Fn(u32) -> Vertex,
) -> Result<MeshData, LoadError> {
    use crate::Topology;
    if mode == Mode::Lines && !sequence.len().is_multiple_of(2) {
        return Err(cx.error(LoadErrorKind::InvalidValue {
            object: label.to_owned(),
            field: "count",
            value: format!("{} indices or vertices", sequence.len()),
            expected: "an even number for LINES (two a line)",
        }));
    }
    let (topology, indices) = match mode {
        Mode::Points => (Topology::PointList, sequence.to_vec()),
        Mode::Lines => (Topology::LineList, sequence.to_vec()),
        Mode::LineStrip => (Topology::LineStrip, sequence.to_vec()),
        _ => (
            Topology::LineList,
            crate::draw::gl_primitives::line_loop(sequence),
        ),
    };
    let mut vertices = try_vec(vertex_count, "mesh vertices").map_err(alloc_error)?;
    vertices.extend((0..vertex_count as u32).map(vertex));
    Ok(MeshData::new(vertices, indices).with_topology(topology))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::gltf::load;
    use crate::scene::gltf::testing::{message, one_mesh_body, scratch_dir, Asset, QUAD};

    fn face_normal(mesh: &MeshData, t: usize) -> Vec3 {
        let [a, b, c] =
            [0, 1, 2].map(|k| Vec3::from_array(mesh.vertices[mesh.indices[3 * t + k] as usize].position));
        (b - a).cross(c - a)
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
            e.kind,
            LoadErrorKind::IndexOutOfRange {
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
    fn points_and_lines_load_as_their_own_topology_unlit_without_normals() {
        use crate::Topology;
        let dir = scratch_dir("modes");
        // Modes 0-3 over three vertices (a LINES primitive takes two of them, by indices).
        let cases = [
            (0, "POINTS", Topology::PointList, vec![0, 1, 2]),
            (1, "LINES", Topology::LineList, vec![0, 1]),
            (2, "LINE_LOOP", Topology::LineList, vec![0, 1, 1, 2, 2, 0]),
            (3, "LINE_STRIP", Topology::LineStrip, vec![0, 1, 2]),
        ];
        for (mode, name, topology, indices) in cases {
            let mut a = Asset::default();
            let pos = a.positions(&QUAD[..3]);
            let idx = if mode == 1 {
                format!(r#", "indices": {}"#, a.u16s(&[0, 1]))
            } else {
                String::new()
            };
            let body = one_mesh_body(&format!(
                r#"{{ "attributes": {{ "POSITION": {pos} }}, "mode": {mode}{idx} }},
                   {{ "attributes": {{ "POSITION": {pos} }} }}"#
            ));
            let loaded = load(&a.write_gltf(&dir, name, &body)).unwrap();
            assert_eq!(loaded.meshes.len(), 2, "{name} and the triangle beside it");
            let m = &loaded.meshes[0];
            assert_eq!(m.data.topology, topology, "{name}");
            assert_eq!(m.data.indices, indices, "{name}");
            assert_eq!(m.data.vertices.len(), 3, "{name}: the vertices as given");
            assert!(!m.lit, "{name} without normals is unlit");
            assert!(loaded.meshes[1].lit);
            assert_eq!(loaded.meshes[1].data.topology, Topology::TriangleList);
        }
        // An odd LINES count is an error naming the primitive and what glTF asks.
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "mode": 1 }}"#
        ));
        let e = message(load(&a.write_gltf(&dir, "odd", &body)).unwrap_err());
        assert!(
            e.contains("primitive 0") && e.contains("an even number for LINES"),
            "{e}"
        );
    }

    #[test]
    fn nan_or_infinite_positions_normals_and_colors_are_errors() {
        let dir = scratch_dir("not_finite");
        let floats =
            |v: &[[f32; 3]]| -> Vec<u8> { v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect() };
        let bounds = r#", "min": [0, 0, 0], "max": [1, 1, 0]"#;
        for (case, bad) in [("nan", f32::NAN), ("inf", f32::INFINITY)] {
            let mut a = Asset::default();
            let pos = a.accessor(
                &floats(&[[0.0; 3], [1.0, 0.0, 0.0], [bad, 1.0, 0.0]]),
                5126,
                3,
                "VEC3",
                bounds,
            );
            let body = one_mesh_body(&format!(r#"{{ "attributes": {{ "POSITION": {pos} }} }}"#));
            let e = message(load(&a.write_gltf(&dir, &format!("position_{case}"), &body)).unwrap_err());
            assert!(
                e.contains("mesh 0 (\"thing\") primitive 0: POSITION (accessor 0) element 2")
                    && e.contains(&format!("[{bad:?}, 1.0, 0.0]"))
                    && e.contains("expected finite numbers"),
                "{e}"
            );
        }
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let nrm = a.vec3s(&[[0.0, 0.0, 1.0], [f32::NAN, 0.0, 1.0], [0.0, 0.0, 1.0]]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "NORMAL": {nrm} }} }}"#
        ));
        let e = message(load(&a.write_gltf(&dir, "normal_nan", &body)).unwrap_err());
        assert!(
            e.contains("NORMAL (accessor 1) element 1 is [NaN, 0.0, 1.0]"),
            "{e}"
        );

        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let col = a.vec3s(&[[1.0; 3], [1.0; 3], [0.0, f32::NEG_INFINITY, 0.0]]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "COLOR_0": {col} }} }}"#
        ));
        let e = message(load(&a.write_gltf(&dir, "color_inf", &body)).unwrap_err());
        assert!(
            e.contains("COLOR_0 (accessor 1) element 2 is [0.0, -inf, 0.0, 1.0]"),
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
}
