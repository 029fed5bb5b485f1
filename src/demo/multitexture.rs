//! The demo's sheet of the texturing modes that came with several texture units (issue 51):
//! the environment a chrome teapot reflects, as a sphere map; the teapot reflecting it by
//! `GL_SPHERE_MAP` texgen and by `GL_REFLECTION_MAP` on a cube map of the same surroundings; a
//! room corner lit by light maps on a second unit (`GL_COMBINE`'s `MODULATE` scaled by 2); and
//! DOT3 bump mapping (`GL_DOT3_RGB` of a normal map and the light's direction, in the constant
//! color and then per vertex in the primary color, a second unit modulating the base texture
//! by it). Every texture is made here, procedurally; only the library's public API draws.

use glam::{Mat4, Vec3, Vec4};

use ffvk::gl::state::{
    Cap, ColorControl, Face, GlState, LightModelParam, LightParam, LightingMode, MaterialParam, TexEnvParam,
};
use ffvk::gl::texture::{TexEnvMode, TexGenMode, Wrap};
use ffvk::mesh::teapot;
use ffvk::{Draw, Renderer};

mod bumps;
mod common;
mod environment;
mod room;

use super::Panel;
use crate::Result;
use common::{flat_view, plane, projection, render, trilinear};
use environment::{cube_map, eye_to_world, sphere_map, SUN};

/// The teapot panels' camera, the main sheet's.
fn teapot_view() -> Mat4 {
    Mat4::look_at_rh(Vec3::new(0.0, 1.2, 3.0), Vec3::new(0.0, -0.05, 0.0), Vec3::Y)
}

/// The chrome teapot's lighting: a white metal lit per fragment by one white directional light
/// from the sun's direction, the reflection modulated by the diffuse shading (`GL_MODULATE`),
/// the highlight added after texturing (`GL_SEPARATE_SPECULAR_COLOR`).
fn chrome(view: Mat4) -> Result<GlState> {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting)?;
    gl.enable(Cap::Light(0))?;
    gl.lighting_mode(LightingMode::Fragment);
    gl.light_model(LightModelParam::Ambient(Vec4::new(0.1, 0.1, 0.1, 1.0)))?;
    gl.light_model(LightModelParam::ColorControl(ColorControl::SeparateSpecularColor))?;
    gl.material(Face::FrontAndBack, MaterialParam::Ambient(Vec4::ONE))?;
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Diffuse(Vec4::new(0.75, 0.75, 0.75, 1.0)),
    )?;
    gl.material(Face::FrontAndBack, MaterialParam::Specular(Vec4::ONE))?;
    gl.material(Face::FrontAndBack, MaterialParam::Shininess(60.0))?;
    gl.light(0, LightParam::Ambient(Vec4::new(0.35, 0.35, 0.35, 1.0)))?;
    gl.load_modelview(view)?;
    gl.light(0, LightParam::Position(SUN.extend(0.0)))?;
    gl.enable(Cap::Texture2D)?;
    gl.tex_env(TexEnvParam::Mode(TexEnvMode::Modulate))?;
    Ok(gl)
}

/// Coordinates 0..`count` of the active unit generated in `mode`.
fn generate(gl: &mut GlState, count: usize, mode: TexGenMode) -> Result<()> {
    for coord in 0..count {
        gl.tex_gen_mode(coord, mode)?;
        gl.enable(Cap::TextureGen(coord))?;
    }
    Ok(())
}

/// The sheet's panels, `size` pixels square.
pub fn multitexture_panels(renderer: &mut Renderer, size: u32) -> Result<Vec<Panel>> {
    let mut panels = Vec::new();
    let mut add = |name: &str, label: &str, image: image::RgbaImage| {
        panels.push(Panel {
            name: format!("multitexture_{name}"),
            label: label.to_owned(),
            image,
        });
    };
    let teapot = renderer.upload(&teapot::teapot(12)?)?;
    let square = renderer.upload(&plane(0.9, 1, |_| Vec4::ONE))?;
    let (view, p) = (teapot_view(), projection());

    // The environment as the sphere map holds it, drawn flat (GL_REPLACE, unlit).
    let sphere = renderer.upload_texture(&sphere_map(256, view), &trilinear(Wrap::ClampToEdge))?;
    let mut flat = GlState::new();
    flat.enable(Cap::Texture2D)?;
    flat.tex_env(TexEnvParam::Mode(TexEnvMode::Replace))?;
    let draw = Draw::new(&square, flat_view(), p, flat.lighting).with_texture(Some(&sphere));
    add(
        "sphere_map_image",
        "(a) the sphere map texture",
        render(renderer, size, vec![draw])?,
    );

    // The chrome teapot by GL_SPHERE_MAP on S and T.
    let mut gl = chrome(view)?;
    generate(&mut gl, 2, TexGenMode::SphereMap)?;
    let draw = Draw::new(&teapot, view, p, gl.lighting).with_texture(Some(&sphere));
    add(
        "sphere_map",
        "(b) GL_SPHERE_MAP chrome",
        render(renderer, size, vec![draw])?,
    );

    // The same by GL_REFLECTION_MAP on S, T and R into a cube map of the surroundings; the
    // texture matrix turns the eye-space reflection into the world, where the cube's faces are.
    let cube = renderer.upload_cube_map(&cube_map(128), &trilinear(Wrap::ClampToEdge))?;
    let mut gl = chrome(view)?;
    gl.disable(Cap::Texture2D)?;
    gl.enable(Cap::TextureCubeMap)?;
    generate(&mut gl, 3, TexGenMode::ReflectionMap)?;
    gl.load_texture_matrix(Mat4::from_mat3(eye_to_world(view)))?;
    let mut draw = Draw::new(&teapot, view, p, gl.lighting);
    draw.cube_maps[0] = Some(&cube);
    add(
        "reflection_map",
        "(c) GL_REFLECTION_MAP cube",
        render(renderer, size, vec![draw])?,
    );

    add(
        "lightmap",
        "(d) light maps, COMBINE 2×",
        room::lightmapped_corner(renderer, size)?,
    );

    // DOT3: the light from the upper left front in GL_CONSTANT, then from a point light at
    // the lower right, near the plane, per vertex in the primary color.
    let bumps = bumps::Bumps::upload(renderer)?;
    let light = Vec3::new(-0.55, 0.6, 0.6).normalize();
    let image = bumps.draw(renderer, size, bumps::LightIn::Constant(light))?;
    add("dot3_constant", "(e) DOT3, light in CONSTANT", image);
    let lamp = Vec3::new(0.55, -0.45, 0.8);
    let image = bumps.draw(renderer, size, bumps::LightIn::PrimaryColor(lamp))?;
    add("dot3_primary", "(f) DOT3, light per vertex", image);
    Ok(panels)
}
