//! The demo: the emerald teapot under one directional light, term by term, and the same
//! teapot in each lighting mode at a coarse tessellation, as separate PNGs and one labelled
//! contact sheet; the white teapot textured in each texture environment mode, with and without
//! separate specular color; then the glTF files of `assets/gltf` drawn directly, on a sheet of
//! their own; a sheet of ffvk's lighting variants: Blinn's (GL's) against Phong's specular
//! term, and hard against soft spot edges; a sheet of the stages around lighting
//! ([`stages`]); a sheet of the raster state a draw carries ([`raster`]); and a sheet of the
//! texturing modes of several units: sphere and cube environment maps, light maps, DOT3
//! bumps ([`multitexture`]).

pub mod multitexture;
pub mod raster;
pub mod stages;

use std::path::Path;

use glam::{Mat4, Vec3, Vec4};

use crate::sheet::contact_sheet;
use crate::Result;
use ffvk::gl::presets;
use ffvk::gl::state::{
    Cap, ColorControl, Face, GlState, LightModelParam, LightParam, LightingMode, MaterialParam,
    SpecularModel, SpotEdge, TexEnvParam,
};
use ffvk::gl::texture::{MagFilter, MinFilter, Sampling, TexEnvMode, TextureImage, Wrap};
use ffvk::images::save_png;
use ffvk::mesh::{teapot, MeshData, Vertex};
use ffvk::renderer::{Draw, Frame, Renderer, RendererOptions};

const PANEL: u32 = 320;

/// Which of the light's terms a panel shows.
struct Terms {
    name: &'static str,
    label: &'static str,
    ambient: bool,
    diffuse: bool,
    specular: bool,
}

const PANELS: [Terms; 5] = [
    Terms {
        name: "a_ambient",
        label: "(a) ambient",
        ambient: true,
        diffuse: false,
        specular: false,
    },
    Terms {
        name: "b_diffuse",
        label: "(b) diffuse",
        ambient: false,
        diffuse: true,
        specular: false,
    },
    Terms {
        name: "c_specular",
        label: "(c) specular",
        ambient: false,
        diffuse: false,
        specular: true,
    },
    Terms {
        name: "d_diffuse_specular",
        label: "(d) diffuse + specular",
        ambient: false,
        diffuse: true,
        specular: true,
    },
    Terms {
        name: "e_all",
        label: "(e) ambient + diffuse + specular",
        ambient: true,
        diffuse: true,
        specular: true,
    },
];

/// The demo's camera: looking at the teapot from above and in front.
fn view() -> Mat4 {
    Mat4::look_at_rh(Vec3::new(0.0, 1.2, 3.0), Vec3::new(0.0, -0.05, 0.0), Vec3::Y)
}

fn projection() -> Mat4 {
    Mat4::perspective_rh_gl(40f32.to_radians(), 1.0, 0.5, 10.0)
}

/// The lighting state of one panel: emerald, one white directional light from the upper
/// right front, given in world space under the view matrix as glLight would be.
fn state(terms: &Terms, mode: LightingMode) -> Result<GlState> {
    let mut gl = GlState::new();
    let emerald = presets::preset("emerald").expect("the preset table has emerald");
    gl.lighting.front = emerald;
    gl.lighting.back = emerald;
    gl.enable(Cap::Lighting)?;
    gl.enable(Cap::Light(0))?;
    gl.lighting_mode(mode);
    // Scene ambient off so that "ambient" is the light's own a_cli term.
    let on = |b: bool| {
        if b {
            Vec4::ONE
        } else {
            Vec4::new(0.0, 0.0, 0.0, 1.0)
        }
    };
    let scene_ambient = if terms.ambient && terms.diffuse {
        Vec4::new(0.2, 0.2, 0.2, 1.0)
    } else {
        Vec4::ZERO
    };
    gl.light_model(LightModelParam::Ambient(scene_ambient))?;
    gl.light(0, LightParam::Ambient(on(terms.ambient)))?;
    gl.light(0, LightParam::Diffuse(on(terms.diffuse)))?;
    gl.light(0, LightParam::Specular(on(terms.specular)))?;
    gl.load_modelview(view())?;
    gl.light(0, LightParam::Position(Vec4::new(1.0, 1.5, 1.2, 0.0)))?;
    gl.material(Face::FrontAndBack, MaterialParam::Shininess(emerald.shininess))?;
    Ok(gl)
}

fn render_teapot(
    renderer: &mut Renderer,
    mesh: &ffvk::Mesh,
    gl: &GlState,
    size: u32,
) -> Result<image::RgbaImage> {
    render_textured(renderer, mesh, gl, None, size)
}

fn render_textured(
    renderer: &mut Renderer,
    mesh: &ffvk::Mesh,
    gl: &GlState,
    texture: Option<&ffvk::Texture>,
    size: u32,
) -> Result<image::RgbaImage> {
    let mut frame = Frame::new(size, size);
    frame.clear_color = Vec4::new(0.08, 0.08, 0.1, 1.0);
    let mut draw = Draw::new(mesh, view(), projection(), gl.lighting);
    draw.textures[0] = texture;
    frame.draws.push(draw);
    Ok(renderer.render(&frame)?.into())
}

/// The texture of the texturing panels: a 64² checker of 8 cells, warm white opaque cells and
/// blue cells of alpha 0.4 (so that DECAL, which blends by the texel's alpha, shows them).
fn demo_texture() -> TextureImage {
    TextureImage::checker(64, 8, [250, 236, 210, 255], [30, 80, 200, 102])
        .expect("a 64x64 checker is a valid texture")
        .with_mipmaps()
}

/// The white teapot with [`demo_texture`] in each environment mode (GL_BLEND's color orange),
/// per fragment, first with GL_SINGLE_COLOR, then GL_SEPARATE_SPECULAR_COLOR, whose highlight
/// the texture does not touch.
pub fn texture_panels(renderer: &mut Renderer, size: u32) -> Result<Vec<(String, image::RgbaImage)>> {
    let mesh = renderer.upload(&teapot::teapot(12)?)?;
    let mut sampling = Sampling::default();
    sampling.min_filter = MinFilter::LinearMipmapLinear;
    sampling.mag_filter = MagFilter::Linear;
    sampling.wrap_s = Wrap::Repeat;
    sampling.wrap_t = Wrap::Repeat;
    let texture = renderer.upload_texture(&demo_texture(), &sampling)?;
    let mut panels = Vec::new();
    for control in [ColorControl::SingleColor, ColorControl::SeparateSpecularColor] {
        for &env in TexEnvMode::ALL {
            let mut gl = state(&PANELS[4], LightingMode::Fragment)?;
            let white = presets::preset("white_plastic").expect("the preset table has white_plastic");
            gl.lighting.front = white;
            gl.lighting.back = white;
            gl.material(
                Face::FrontAndBack,
                MaterialParam::Specular(Vec4::new(0.9, 0.9, 0.9, 1.0)),
            )?;
            gl.material(Face::FrontAndBack, MaterialParam::Shininess(40.0))?;
            gl.light_model(LightModelParam::ColorControl(control))?;
            gl.enable(Cap::Texture2D)?;
            gl.tex_env(TexEnvParam::Mode(env))?;
            gl.tex_env(TexEnvParam::Color(Vec4::new(1.0, 0.55, 0.1, 1.0)))?;
            let image = render_textured(renderer, &mesh, &gl, Some(&texture), size)?;
            let label = match control {
                ColorControl::SingleColor => env.name().to_string(),
                ColorControl::SeparateSpecularColor => format!("{}, separate specular", env.name()),
            };
            panels.push((label, image));
        }
    }
    Ok(panels)
}

/// One demo panel: file name, label, image.
pub struct Panel {
    pub name: String,
    pub label: String,
    pub image: image::RgbaImage,
}

/// Renders the demo's panels: the five term-by-term panels, then the three modes.
pub fn panels(renderer: &mut Renderer, size: u32) -> Result<Vec<Panel>> {
    let fine = renderer.upload(&teapot::teapot(12)?)?;
    let coarse = renderer.upload(&teapot::teapot(3)?)?;
    let mut panels = Vec::new();
    for terms in &PANELS {
        let image = render_teapot(renderer, &fine, &state(terms, LightingMode::Fragment)?, size)?;
        panels.push(Panel {
            name: terms.name.to_string(),
            label: terms.label.to_string(),
            image,
        });
    }
    for mode in LightingMode::ALL {
        let image = render_teapot(renderer, &coarse, &state(&PANELS[4], mode)?, size)?;
        panels.push(Panel {
            name: format!("mode_{}", mode.name()),
            label: format!("{} (coarse mesh)", mode.name()),
            image,
        });
    }
    Ok(panels)
}

/// The specular exponents the model sheet compares Blinn's and Phong's terms at.
const MODEL_EXPONENTS: [f32; 4] = [4.0, 16.0, 64.0, 128.0];

/// A floor of `n` × `n` quads in the plane y = `y`, 4 wide, facing up: dense enough for
/// per-vertex lighting to show a spot's edge.
fn floor(n: u32, y: f32) -> MeshData {
    let mut mesh = MeshData::default();
    for j in 0..=n {
        for i in 0..=n {
            let (x, z) = (4.0 * i as f32 / n as f32 - 2.0, 4.0 * j as f32 / n as f32 - 2.0);
            mesh.vertices
                .push(Vertex::new(Vec3::new(x, y, z), Vec3::Y, Vec4::ONE));
        }
    }
    let at = |i: u32, j: u32| j * (n + 1) + i;
    for j in 0..n {
        for i in 0..n {
            // Counter-clockwise seen from above.
            mesh.indices.extend([
                at(i, j),
                at(i, j + 1),
                at(i + 1, j + 1),
                at(i, j),
                at(i + 1, j + 1),
                at(i + 1, j),
            ]);
        }
    }
    mesh
}

/// The model sheet's panels: the emerald teapot with GL's halfway specular term (Blinn)
/// against Phong's reflection term at the same exponents, then a spotlight on the teapot and
/// a floor with GL's hard edge, GL's exponent, a linear and a smoothstep edge between 9° and
/// 18° (ffvk's lighting variants), per fragment.
pub fn model_panels(renderer: &mut Renderer, size: u32) -> Result<Vec<Panel>> {
    let teapot = renderer.upload(&teapot::teapot(12)?)?;
    let ground = renderer.upload(&floor(48, -0.55))?;
    let mut panels = Vec::new();
    for (model, tag) in [
        (SpecularModel::BlinnHalfway, "blinn"),
        (SpecularModel::PhongReflect, "phong"),
    ] {
        for s in MODEL_EXPONENTS {
            let mut gl = state(&PANELS[3], LightingMode::Fragment)?;
            gl.light_model(LightModelParam::SpecularModel(model))?;
            gl.material(Face::FrontAndBack, MaterialParam::Shininess(s))?;
            let image = render_meshes(renderer, &[&teapot], &gl, size)?;
            let label = match model {
                SpecularModel::BlinnHalfway => format!("Blinn (GL's n·h), s = {s}"),
                SpecularModel::PhongReflect => format!("Phong (r·v), s = {s}"),
                other => format!("{other:?}, s = {s}"),
            };
            panels.push(Panel {
                name: format!("{tag}_{s}"),
                label,
                image,
            });
        }
    }
    let edges = [
        (
            "spot_gl_hard",
            "GL cutoff 18°, exponent 0",
            SpotEdge::GlExponent,
            0.0,
        ),
        (
            "spot_gl_exponent",
            "GL cutoff 18°, exponent 20",
            SpotEdge::GlExponent,
            20.0,
        ),
        (
            "spot_linear",
            "linear 9° to 18°",
            SpotEdge::LinearInnerOuter { inner_degrees: 9.0 },
            0.0,
        ),
        (
            "spot_smoothstep",
            "smoothstep 9° to 18°",
            SpotEdge::SmoothstepInnerOuter { inner_degrees: 9.0 },
            0.0,
        ),
    ];
    for (name, label, edge, exponent) in edges {
        let mut gl = state(&PANELS[4], LightingMode::Fragment)?;
        // Light 0 off: the spot alone.
        gl.disable(Cap::Light(0))?;
        gl.light_model(LightModelParam::Ambient(Vec4::new(0.05, 0.05, 0.05, 1.0)))?;
        gl.enable(Cap::Light(1))?;
        // The view is the modelview: the spot is placed in world space.
        gl.light(1, LightParam::Position(Vec4::new(0.4, 2.4, 0.6, 1.0)))?;
        gl.light(1, LightParam::SpotDirection(Vec3::new(-0.15, -1.0, -0.25)))?;
        gl.light(1, LightParam::Diffuse(Vec4::new(1.0, 0.95, 0.85, 1.0)))?;
        gl.light(1, LightParam::Specular(Vec4::ONE))?;
        gl.light(1, LightParam::SpotCutoff(18.0))?;
        gl.light(1, LightParam::SpotExponent(exponent))?;
        gl.light(1, LightParam::SpotEdge(edge))?;
        let image = render_meshes(renderer, &[&ground, &teapot], &gl, size)?;
        panels.push(Panel {
            name: name.to_string(),
            label: label.to_string(),
            image,
        });
    }
    Ok(panels)
}

/// Draws `meshes` with one state into one image.
fn render_meshes(
    renderer: &mut Renderer,
    meshes: &[&ffvk::Mesh],
    gl: &GlState,
    size: u32,
) -> Result<image::RgbaImage> {
    let mut frame = Frame::new(size, size);
    frame.clear_color = Vec4::new(0.08, 0.08, 0.1, 1.0);
    for mesh in meshes {
        frame
            .draws
            .push(Draw::new(mesh, view(), projection(), gl.lighting));
    }
    Ok(renderer.render(&frame)?.into())
}

/// Renders every panel into `out` and writes `contact_sheet.png` there.
pub fn run(options: &RendererOptions, out: &Path) -> Result<()> {
    let mut renderer = Renderer::new(options)?;
    let panels = panels(&mut renderer, PANEL)?;
    for p in &panels {
        save_png(&p.image, &out.join(format!("{}.png", p.name)))?;
    }
    let labelled: Vec<(String, image::RgbaImage)> = panels.into_iter().map(|p| (p.label, p.image)).collect();
    let sheet = contact_sheet(&labelled, 5)?;
    let path = out.join("contact_sheet.png");
    save_png(&sheet, &path)?;
    crate::outln!(
        "wrote {} and {} panels in {}",
        path.display(),
        labelled.len(),
        out.display()
    )?;
    let textured = texture_panels(&mut renderer, 256)?;
    for (name, image) in &textured {
        let file = name.replace(", separate specular", "_separate");
        save_png(image, &out.join("texture").join(format!("{file}.png")))?;
    }
    let sheet = contact_sheet(&textured, 5)?;
    let path = out.join("texture_sheet.png");
    save_png(&sheet, &path)?;
    crate::outln!("wrote {} (the texture environment modes)", path.display())?;
    let models = model_panels(&mut renderer, 256)?;
    for p in &models {
        save_png(&p.image, &out.join("models").join(format!("{}.png", p.name)))?;
    }
    let labelled: Vec<(String, image::RgbaImage)> = models.into_iter().map(|p| (p.label, p.image)).collect();
    let sheet = contact_sheet(&labelled, 4)?;
    let path = out.join("models_sheet.png");
    save_png(&sheet, &path)?;
    crate::outln!(
        "wrote {} (Blinn against Phong, hard against soft spot edges)",
        path.display()
    )?;
    let stages = stages::stage_panels(&mut renderer, 256)?;
    for p in &stages {
        save_png(&p.image, &out.join("stages").join(format!("{}.png", p.name)))?;
    }
    let labelled: Vec<(String, image::RgbaImage)> = stages.into_iter().map(|p| (p.label, p.image)).collect();
    let sheet = contact_sheet(&labelled, 4)?;
    let path = out.join("stages_sheet.png");
    save_png(&sheet, &path)?;
    crate::outln!(
        "wrote {} (fog, the alpha test, clip planes and the color sum)",
        path.display()
    )?;
    let raster = raster::raster_panels(&mut renderer, 256)?;
    for p in &raster {
        save_png(&p.image, &out.join("raster").join(format!("{}.png", p.name)))?;
    }
    let labelled: Vec<(String, image::RgbaImage)> = raster.into_iter().map(|p| (p.label, p.image)).collect();
    let sheet = contact_sheet(&labelled, 4)?;
    let path = out.join("raster_sheet.png");
    save_png(&sheet, &path)?;
    crate::outln!(
        "wrote {} (polygon modes and offsets, the stencil test, logic ops, stipple, depth range)",
        path.display()
    )?;
    let multi = multitexture::multitexture_panels(&mut renderer, 256)?;
    for p in &multi {
        save_png(
            &p.image,
            &out.join("multitexture").join(format!("{}.png", p.name)),
        )?;
    }
    let labelled: Vec<(String, image::RgbaImage)> = multi.into_iter().map(|p| (p.label, p.image)).collect();
    let sheet = contact_sheet(&labelled, 3)?;
    let path = out.join("multitexture_sheet.png");
    save_png(&sheet, &path)?;
    crate::outln!(
        "wrote {} (sphere and cube environment maps, light maps, DOT3 bump mapping)",
        path.display()
    )?;
    let gltf = gltf_panels(
        &mut renderer,
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/gltf"),
        256,
    )?;
    for (name, image) in &gltf {
        save_png(image, &out.join("gltf").join(format!("{name}.png")))?;
    }
    let sheet = contact_sheet(&gltf, 3)?;
    let path = out.join("gltf_sheet.png");
    save_png(&sheet, &path)?;
    crate::outln!(
        "wrote {} ({} glTF files drawn directly)",
        path.display(),
        gltf.len()
    )?;
    Ok(())
}

/// Each `.gltf`/`.glb` file in `folder`, in name order, drawn as `ffvk render FILE` draws it
/// (per-fragment lighting), `size` pixels square, named by its file name.
pub fn gltf_panels(
    renderer: &mut Renderer,
    folder: &Path,
    size: u32,
) -> Result<Vec<(String, image::RgbaImage)>> {
    let mut files: Vec<std::path::PathBuf> = std::fs::read_dir(folder)
        .map_err(|source| crate::Error::Read {
            path: folder.to_path_buf(),
            source,
        })?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| ffvk::scene::direct::is_gltf(p))
        .collect();
    files.sort();
    let mut options = ffvk::scene::direct::DirectOptions::default();
    options.size = Some((size, size));
    let mut panels = Vec::new();
    for file in files {
        let made =
            ffvk::scene::direct::from_gltf(&file, &file.to_string_lossy(), &Default::default(), &options)?;
        let image = ffvk::scene::render_scene(renderer, &made.scene, Some(LightingMode::Fragment))?;
        let name = file
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        panels.push((name, image));
    }
    Ok(panels)
}
