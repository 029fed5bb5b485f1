//! The demo: the emerald teapot under one directional light, term by term, and the same
//! teapot in each lighting mode at a coarse tessellation, as separate PNGs and one labelled
//! contact sheet; the white teapot textured in each texture environment mode, with and without
//! separate specular color; then the glTF files of `assets/gltf` drawn directly, on a sheet of
//! their own.

use std::path::Path;

use glam::{Mat4, Vec3, Vec4};

use crate::gl::presets;
use crate::gl::state::{
    Cap, ColorControl, Face, GlState, LightModelParam, LightParam, LightingMode, MaterialParam, TexEnvParam,
};
use crate::gl::texture::{MagFilter, MinFilter, Sampling, TexEnvMode, TextureImage, Wrap};
use crate::images::save_png;
use crate::mesh::teapot;
use crate::renderer::{Draw, Frame, Renderer, RendererOptions};
use crate::tools::sheet::contact_sheet;
use crate::tools::Result;

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
    mesh: &crate::Mesh,
    gl: &GlState,
    size: u32,
) -> Result<image::RgbaImage> {
    render_textured(renderer, mesh, gl, None, size)
}

fn render_textured(
    renderer: &mut Renderer,
    mesh: &crate::Mesh,
    gl: &GlState,
    texture: Option<&crate::Texture>,
    size: u32,
) -> Result<image::RgbaImage> {
    let mut frame = Frame::new(size, size);
    frame.clear_color = Vec4::new(0.08, 0.08, 0.1, 1.0);
    frame.draws.push(Draw {
        texture,
        ..Draw::new(mesh, view(), projection(), gl.lighting)
    });
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
    let sampling = Sampling {
        min_filter: MinFilter::LinearMipmapLinear,
        mag_filter: MagFilter::Linear,
        wrap_s: Wrap::Repeat,
        wrap_t: Wrap::Repeat,
    };
    let texture = renderer.upload_texture(&demo_texture(), &sampling)?;
    let mut panels = Vec::new();
    for control in [ColorControl::SingleColor, ColorControl::SeparateSpecularColor] {
        for env in TexEnvMode::ALL {
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
    println!(
        "wrote {} and {} panels in {}",
        path.display(),
        labelled.len(),
        out.display()
    );
    let textured = texture_panels(&mut renderer, 256)?;
    for (name, image) in &textured {
        let file = name.replace(", separate specular", "_separate");
        save_png(image, &out.join("texture").join(format!("{file}.png")))?;
    }
    let sheet = contact_sheet(&textured, 5)?;
    let path = out.join("texture_sheet.png");
    save_png(&sheet, &path)?;
    println!("wrote {} (the texture environment modes)", path.display());
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
    println!(
        "wrote {} ({} glTF files drawn directly)",
        path.display(),
        gltf.len()
    );
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
        .map_err(|source| crate::tools::Error::Read {
            path: folder.to_path_buf(),
            source,
        })?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| crate::scene::direct::is_gltf(p))
        .collect();
    files.sort();
    let options = crate::scene::direct::DirectOptions {
        size: Some((size, size)),
        ..Default::default()
    };
    let mut panels = Vec::new();
    for file in files {
        let made =
            crate::scene::direct::from_gltf(&file, &file.to_string_lossy(), &Default::default(), &options)?;
        let image = crate::scene::render_scene(renderer, &made.scene, Some(LightingMode::Fragment))?;
        let name = file
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        panels.push((name, image));
    }
    Ok(panels)
}
