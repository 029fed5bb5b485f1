//! The stages sweep's texturing rows: one texture unit as most textured programs draw
//! (`GL_MODULATE` of a 2D texture), and all four units at once with what each kind of program
//! adds (a light map through `GL_COMBINE`, a sphere-mapped 2D texture and a reflection-mapped
//! cube map by texgen): the state a GL program sets, and the textures it binds.

use ffvk::gl::state::{Cap, GlState, TexEnvParam};
use ffvk::gl::texture::{
    CombineFunc, CubeImage, MagFilter, MinFilter, Sampling, TexEnvMode, TexGenMode, TextureImage,
    MAX_TEXTURE_UNITS,
};

use super::sweep::Stage;
use crate::gl_reference::GlDraw;
use crate::Result;
use ffvk::renderer::{Draw, Renderer, Texture};

/// What a texturing stage binds: each unit's 2D texture and cube map with its sampling, and
/// the units 1-3 whose coordinates are the mesh's (a bit each).
pub struct StageTextures {
    textures: [Option<(TextureImage, Sampling)>; MAX_TEXTURE_UNITS],
    cube_maps: [Option<(CubeImage, Sampling)>; MAX_TEXTURE_UNITS],
    mesh_texcoords: u32,
}

/// A stage's textures on the device ([`StageTextures::upload`]).
pub struct UploadedTextures {
    textures: [Option<Texture>; MAX_TEXTURE_UNITS],
    cube_maps: [Option<Texture>; MAX_TEXTURE_UNITS],
    mesh_texcoords: u32,
}

impl UploadedTextures {
    /// `draw` with these textures bound.
    pub fn bind<'a>(&'a self, draw: Draw<'a>) -> Draw<'a> {
        draw.with_textures(std::array::from_fn(|i| self.textures[i].as_ref()))
            .with_cube_maps(std::array::from_fn(|i| self.cube_maps[i].as_ref()))
            .with_mesh_texcoords(self.mesh_texcoords)
    }
}

impl StageTextures {
    /// The textures `stage` binds (none for the stages that do not texture).
    pub fn of(stage: Stage) -> Result<StageTextures> {
        let mut out = StageTextures {
            textures: [None, None, None, None],
            cube_maps: [None, None, None, None],
            mesh_texcoords: 0,
        };
        let checker = || TextureImage::checker(64, 8, [235, 235, 235, 255], [40, 90, 160, 255]);
        let bad = |e: ffvk::gl::texture::TextureError| crate::Error::Bench(format!("a bench texture: {e}"));
        match stage {
            Stage::Texture => out.textures[0] = Some((checker().map_err(bad)?, linear())),
            Stage::Units4 => {
                out.textures[0] = Some((checker().map_err(bad)?, linear()));
                out.textures[1] = Some((TextureImage::lightmap(64).map_err(bad)?, linear()));
                out.textures[2] = Some((checker().map_err(bad)?, linear()));
                let faces = [
                    [230, 60, 50, 255],
                    [60, 200, 200, 255],
                    [240, 220, 60, 255],
                    [120, 60, 180, 255],
                    [60, 80, 230, 255],
                    [60, 190, 80, 255],
                ];
                out.cube_maps[3] = Some((CubeImage::solid(16, faces).map_err(bad)?, linear()));
                out.mesh_texcoords = 1 << 1;
            }
            _ => {}
        }
        Ok(out)
    }

    /// Uploads them to `renderer`'s device.
    pub fn upload(&self, renderer: &Renderer) -> Result<UploadedTextures> {
        let mut textures = [None, None, None, None];
        let mut cube_maps = [None, None, None, None];
        for i in 0..MAX_TEXTURE_UNITS {
            if let Some((image, sampling)) = &self.textures[i] {
                textures[i] = Some(renderer.upload_texture(image, sampling)?);
            }
            if let Some((cube, sampling)) = &self.cube_maps[i] {
                cube_maps[i] = Some(renderer.upload_cube_map(cube, sampling)?);
            }
        }
        Ok(UploadedTextures {
            textures,
            cube_maps,
            mesh_texcoords: self.mesh_texcoords,
        })
    }

    /// The GL reference's `draw` with these textures bound.
    pub fn bind_gl<'a>(&'a self, draw: GlDraw<'a>) -> GlDraw<'a> {
        GlDraw {
            textures: std::array::from_fn(|i| self.textures[i].as_ref().map(|(t, s)| (t, *s))),
            cube_maps: std::array::from_fn(|i| self.cube_maps[i].as_ref().map(|(c, s)| (c, *s))),
            mesh_texcoords: self.mesh_texcoords,
            ..draw
        }
    }
}

/// Linear filtering without mipmaps: what these rows sample with.
fn linear() -> Sampling {
    Sampling::default()
        .with_min_filter(MinFilter::Linear)
        .with_mag_filter(MagFilter::Linear)
}

/// Sets the units `stage` textures with, as a GL program would: `GL_TEXTURE_2D` (or
/// `GL_TEXTURE_CUBE_MAP`) on, the environment, and texgen where the unit generates.
pub(super) fn set_texture_stage(gl: &mut GlState, stage: Stage) -> Result<()> {
    match stage {
        Stage::Texture => {
            gl.active_texture(0)?;
            gl.enable(Cap::Texture2D)?;
        }
        Stage::Units4 => {
            // Unit 0: the base texture, GL_MODULATE (GL's default environment).
            gl.active_texture(0)?;
            gl.enable(Cap::Texture2D)?;
            // Unit 1: a light map, GL_COMBINE's MODULATE of GL_TEXTURE and GL_PREVIOUS, × 2.
            gl.active_texture(1)?;
            gl.enable(Cap::Texture2D)?;
            gl.tex_env(TexEnvParam::Mode(TexEnvMode::Combine))?;
            gl.tex_env(TexEnvParam::CombineRgb(CombineFunc::Modulate))?;
            gl.tex_env(TexEnvParam::RgbScale(2.0))?;
            // Unit 2: a sphere map on S and T, modulated.
            gl.active_texture(2)?;
            gl.enable(Cap::Texture2D)?;
            for coord in 0..2 {
                gl.tex_gen_mode(coord, TexGenMode::SphereMap)?;
                gl.enable(Cap::TextureGen(coord))?;
            }
            // Unit 3: a cube map by GL_REFLECTION_MAP on S, T and R, added.
            gl.active_texture(3)?;
            gl.enable(Cap::TextureCubeMap)?;
            gl.tex_env(TexEnvParam::Mode(TexEnvMode::Add))?;
            for coord in 0..3 {
                gl.tex_gen_mode(coord, TexGenMode::ReflectionMap)?;
                gl.enable(Cap::TextureGen(coord))?;
            }
            gl.active_texture(0)?;
        }
        _ => {}
    }
    Ok(())
}
