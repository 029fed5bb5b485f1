//! The scene file's meshes: built-in shapes and glTF primitives, placed by their model
//! matrices.

use super::super::*;
use super::{Builder, Placed};

impl Builder<'_> {
    pub(super) fn model_matrix(&self, field: &str, m: &MeshSpec) -> Result<Mat4, SceneError> {
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
    pub(super) fn mesh(
        &self,
        field: &str,
        spec: &MeshSpec,
        textures: super::super::gltf::Textures,
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
                    None => super::super::gltf::load_with(
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
