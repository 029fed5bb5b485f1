//! Building a [`Scene`] from a parsed scene file: its GL state, camera, glTF lights and
//! exposure here; the lights, light model and materials in `state.rs`; the meshes in
//! `meshes.rs`.

use super::*;

mod gltf_units;
mod meshes;
mod stages;
mod state;

/// One glTF primitive or built-in shape placed by a `[[meshes]]` table.
pub(super) struct Placed {
    name: String,
    data: MeshData,
    /// Object to world.
    model: Mat4,
    /// The glTF material (glTF's default for primitives without one); `None` for built-ins.
    material: Option<super::gltf::PbrMaterial>,
    /// Whether the primitive has COLOR_0.
    vertex_colors: bool,
    /// Whether it is lit (see [`SceneMesh::lit`]).
    lit: bool,
}

pub(super) struct Builder<'a> {
    pub(super) path: &'a Path,
    pub(super) limits: &'a Limits,
    /// What the meshes built so far took.
    pub(super) budget: std::cell::RefCell<MeshBudget>,
    /// A glTF file loaded before the scene was built, and its path (see
    /// [`Scene::from_table_preloaded`]).
    pub(super) preloaded: std::cell::RefCell<Option<(PathBuf, super::gltf::Loaded)>>,
}

impl Builder<'_> {
    /// An error about this scene file.
    pub(super) fn error(&self, kind: SceneErrorKind) -> SceneError {
        SceneError {
            path: self.path.to_path_buf(),
            kind,
        }
    }

    pub(super) fn field(&self, field: impl Into<String>, message: impl Into<String>) -> SceneError {
        self.error(SceneErrorKind::Field {
            field: field.into(),
            message: message.into(),
        })
    }

    pub(super) fn state(&self, field: impl Into<String>) -> impl FnOnce(StateError) -> SceneError + '_ {
        let field = field.into();
        move |source| self.error(SceneErrorKind::State { field, source })
    }

    /// A color of 3 (alpha 1) or 4 finite numbers.
    pub(super) fn color(&self, field: &str, v: &[f32]) -> Result<Vec4, SceneError> {
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

    pub(super) fn finite(&self, field: &str, v: &[f32]) -> Result<(), SceneError> {
        match v.iter().find(|x| !x.is_finite()) {
            Some(x) => Err(self.field(field, format!("{x} is not finite: expected finite numbers"))),
            None => Ok(()),
        }
    }

    pub(super) fn build(&self, file: SceneFile) -> Result<Scene, SceneError> {
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
        let fragment_path = match file.image.fragment_path.as_deref() {
            None | Some("forward") => crate::FragmentPath::Forward,
            Some("deferred") => crate::FragmentPath::Deferred,
            Some("auto") => crate::FragmentPath::Auto,
            Some(other) => {
                return Err(self.field(
                    "image.fragment_path",
                    format!(
                        "{:?}: expected \"forward\", \"deferred\" or \"auto\"",
                        shorten(other)
                    ),
                ))
            }
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
        let point_size = self.points(&mut gl, file.points.as_ref())?;
        self.fragment_stages(
            &mut gl,
            file.color_sum,
            file.secondary_color.as_deref(),
            file.fog.as_ref(),
            file.alpha_test.as_ref(),
        )?;

        // Lights and clip planes are specified in world space with the view loaded, as glLight
        // and glClipPlane after glLoadMatrix(view).
        gl.load_modelview(view).map_err(self.state("camera.view"))?;
        self.clip_planes(&mut gl, &file.clip_planes)?;
        let mut light_of_index: Vec<(usize, usize)> = Vec::new();
        let mut warnings = Vec::new();
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
            self.light(&mut gl, &format!("lights[{i}]"), index, spec, &mut warnings)?;
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
        let scene_texture = match &file.texture {
            Some(t) => self.texture("texture", t, (0, 1), view, &mut warnings)?,
            None => None,
        };
        let mut gltf_lights: Vec<(String, PunctualLight, Mat4)> = Vec::new();
        let textures = if gltf_meaning {
            super::gltf::Textures::Means
        } else {
            super::gltf::Textures::Ignore
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
                    (None, None, Some(p)) => super::gltf::gl_material(p),
                    (None, None, None) => Material::default(),
                };
                let back = match (&spec.back_material, &spec.material, scene_back) {
                    (Some(m), _, _) => self.material(&format!("{field}.back_material"), m)?,
                    (None, Some(_), _) => front,
                    (None, None, Some(m)) => m,
                    (None, None, None) => front,
                };
                let own_material = spec.material.is_none() && scene_front.is_none();
                let raster = self.mesh_raster(&field, spec)?;
                let mut data = p.data;
                if let Some(name) = &spec.primitive {
                    let outlined = raster.polygon_mode != crate::PolygonModes::FILL;
                    data = as_primitive(data, name, outlined)
                        .map_err(|m| self.field(format!("{field}.primitive"), m))?;
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
                // Texture precedence: the mesh's own units (or its one), the scene's, the glTF
                // base color and occlusion textures (under glTF's meaning, on units 0 and 1
                // through GL_MODULATE), none.
                let mut textures: [Option<MeshTexture>; MAX_TEXTURE_UNITS] = Default::default();
                match (&spec.texture_units, &spec.texture, &scene_texture, &pbr) {
                    (Some(_), Some(_), _, _) => {
                        return Err(self.field(
                            format!("{field}.texture_units"),
                            format!(
                                "is given with {field}.texture: expected either texture (unit 0 alone) or texture_units"
                            ),
                        ))
                    }
                    (Some(units), None, _, _) => {
                        let at = format!("{field}.texture_units");
                        textures = self.texture_units(&at, units, view, &mut warnings)?;
                    }
                    (None, Some(t), _, _) => {
                        let at = format!("{field}.texture");
                        textures[0] = self.texture(&at, t, (0, 1), view, &mut warnings)?;
                    }
                    (None, None, Some(t), _) => textures[0] = Some(t.clone()),
                    (None, None, None, Some(pbr)) if gltf_meaning => {
                        textures = self::gltf_units::gltf_units(pbr, &mut notes);
                    }
                    _ => {}
                }
                meshes.push(SceneMesh {
                    name: p.name,
                    data,
                    model: p.model,
                    front,
                    back,
                    gltf: meaning,
                    textures,
                    lit: p.lit,
                    raster,
                });
            }
        }
        let mapping = self.gltf_lights(&file)?;
        if !gltf_lights.is_empty() && mapping != GltfLights::Off {
            let exposure = Builder::exposure(exposure_spec, &gltf_lights, &meshes, mapping, &mut notes);
            for (f, light, model) in &gltf_lights {
                let mut gl_light = match mapping {
                    GltfLights::Exact => super::gltf::exact_light(light),
                    _ => super::gltf::gl_light(light),
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
        self.check_drawable(&gl.lighting, &light_of_index, view, &meshes)?;
        gl.load_modelview(Mat4::IDENTITY)
            .map_err(self.state("camera.view"))?;

        Ok(Scene {
            path: self.path.to_path_buf(),
            width,
            height,
            clear_color,
            depth_test: file.image.depth_test.unwrap_or(true),
            clear_stencil: self.clear_stencil(file.image.clear_stencil)?,
            point_size,
            fragment_path,
            view,
            projection,
            state: gl.lighting,
            meshes,
            warnings,
            notes,
        })
    }

    /// `gltf_lights` checked: GL's mapping unless the file says otherwise.
    pub(super) fn gltf_lights(&self, file: &SceneFile) -> Result<GltfLights, SceneError> {
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
    pub(super) fn exposure_spec(
        &self,
        file: &SceneFile,
        gltf_meaning: bool,
    ) -> Result<Option<f32>, SceneError> {
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
    pub(super) fn exposure(
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

    /// What drawing would refuse, by the GL state's own rules
    /// ([`FixedFunctionState::check_drawable`], [`FixedFunctionState::check_draw`]), found here so that
    /// the error names the scene's field rather than surfacing at render time without it: a
    /// positional light with all three attenuations 0, a mesh whose modelview has no inverse
    /// (its normals would be NaN).
    pub(super) fn check_drawable(
        &self,
        state: &FixedFunctionState,
        light_of_index: &[(usize, usize)],
        view: Mat4,
        meshes: &[SceneMesh],
    ) -> Result<(), SceneError> {
        match state.check_drawable() {
            Ok(()) => {}
            Err(StateError::ZeroAttenuation { light }) => {
                let field = match light_of_index.iter().find(|(gl_index, _)| *gl_index == light) {
                    Some((_, i)) => format!("lights[{i}]"),
                    None => format!("GL_LIGHT{light}"),
                };
                return Err(self.field(
                    field,
                    "constant_attenuation + linear_attenuation + quadratic_attenuation = 0 for a \
                     positional light: expected a sum > 0 (GL's att_i would be 1/0)",
                ));
            }
            Err(e) => return Err(self.state("lights".to_owned())(e)),
        }
        for mesh in meshes {
            let modelview = view * mesh.model;
            match state.check_draw(
                &DrawValues::new(mesh.front, mesh.back, state.current_color),
                modelview,
            ) {
                Ok(()) => {}
                Err(StateError::SingularModelview { determinant }) => {
                    let model_det = glam::Mat3::from_mat4(mesh.model).determinant();
                    let field = if model_det == 0.0 || !model_det.is_finite() {
                        format!("meshes (mesh {:?})", shorten(&mesh.name))
                    } else {
                        "camera.view".to_owned()
                    };
                    return Err(self.field(
                        field,
                        format!(
                            "the modelview's upper 3x3 has determinant {determinant} for mesh {:?}: expected \
                             an invertible matrix (a scale of 0 flattens the mesh and leaves GL's normal \
                             matrix undefined)",
                            shorten(&mesh.name)
                        ),
                    ));
                }
                Err(e) => return Err(self.state(format!("meshes (mesh {:?})", shorten(&mesh.name)))(e)),
            }
        }
        Ok(())
    }

    pub(super) fn camera(&self, c: &CameraSpec, aspect: f32) -> Result<(Mat4, Mat4), SceneError> {
        // A matrix replaces the values it is made from: both given, one would be ignored.
        let look_at = [
            ("eye", c.eye.is_some()),
            ("target", c.target.is_some()),
            ("up", c.up.is_some()),
        ];
        let perspective = [
            ("fovy", c.fovy.is_some()),
            ("near", c.near.is_some()),
            ("far", c.far.is_some()),
        ];
        for (matrix, given, parts) in [
            ("view", c.view.is_some(), look_at),
            ("projection", c.projection.is_some(), perspective),
        ] {
            let named: Vec<&str> = parts.iter().filter(|(_, g)| *g).map(|(n, _)| *n).collect();
            if given && !named.is_empty() {
                return Err(self.field(
                    format!("camera.{matrix}"),
                    format!(
                        "is given with camera.{}, which it replaces: expected either the matrix or {}",
                        named.join(", camera."),
                        parts.iter().map(|(n, _)| *n).collect::<Vec<_>>().join("/")
                    ),
                ));
            }
        }
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
}
