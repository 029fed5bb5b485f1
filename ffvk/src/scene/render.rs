//! Drawing a [`Scene`] with a [`Renderer`](crate::Renderer): its meshes in file order, each
//! with its state, raster state and texture units, into one frame.

use super::{MeshTexture, Scene};
use crate::gl::state::LightingMode;
use crate::gl::texture::MAX_TEXTURE_UNITS;

/// Draws a scene with `renderer`; `mode` overrides the file's lighting mode when given.
pub fn render_scene(
    renderer: &mut crate::Renderer,
    scene: &Scene,
    mode: Option<LightingMode>,
) -> crate::Result<image::RgbaImage> {
    render_scene_with(renderer, scene, mode, None)
}

/// [`render_scene`], `path` overriding the scene's [`Scene::fragment_path`] when given.
pub fn render_scene_with(
    renderer: &mut crate::Renderer,
    scene: &Scene,
    mode: Option<LightingMode>,
    path: Option<crate::FragmentPath>,
) -> crate::Result<image::RgbaImage> {
    let (width, height) = (scene.width, scene.height);
    let uploaded = scene
        .meshes
        .iter()
        .map(|m| renderer.upload(&m.data))
        .collect::<crate::Result<Vec<_>>>()?;
    // Each image once, however many meshes share it (by image and sampling, as a GL program
    // keeps one texture object per image and parameters).
    let mut textures: Vec<(&MeshTexture, crate::Texture)> = Vec::new();
    for t in scene.meshes.iter().flat_map(|m| m.textures.iter().flatten()) {
        if t.cube_map.is_some() {
            continue;
        }
        if !textures
            .iter()
            .any(|(u, _)| std::sync::Arc::ptr_eq(&u.image, &t.image) && u.sampling == t.sampling)
        {
            textures.push((t, renderer.upload_texture(&t.image, &t.sampling)?));
        }
    }
    // Each cube map once likewise; a unit with one samples it (GL's precedence), never its
    // 2D texture.
    let mut cubes: Vec<(&MeshTexture, crate::Texture)> = Vec::new();
    for t in scene.meshes.iter().flat_map(|m| m.textures.iter().flatten()) {
        let Some(cube) = &t.cube_map else { continue };
        if !cubes
            .iter()
            .any(|(u, _)| same_cube(u, cube) && u.sampling == t.sampling)
        {
            cubes.push((t, renderer.upload_cube_map(cube, &t.sampling)?));
        }
    }
    let cube_of = |t: &MeshTexture| {
        let cube = t.cube_map.as_ref()?;
        cubes
            .iter()
            .find(|(u, _)| same_cube(u, cube) && u.sampling == t.sampling)
            .map(|(_, gpu)| gpu)
    };
    let texture_of = |t: &MeshTexture| {
        textures
            .iter()
            .find(|(u, _)| std::sync::Arc::ptr_eq(&u.image, &t.image) && u.sampling == t.sampling)
            .map(|(_, gpu)| gpu)
    };
    let mut frame = crate::Frame::new(width, height);
    frame.clear_color = scene.clear_color;
    frame.depth_test = scene.depth_test;
    frame.clear_stencil = scene.clear_stencil;
    frame.fragment_path = path.unwrap_or(scene.fragment_path);
    // In file order: what one mesh leaves in the stencil and depth buffers is what the next
    // one is tested against.
    for (mesh, gpu) in scene.meshes.iter().zip(&uploaded) {
        let raster = &mesh.raster;
        let mut state = scene.draw_state(mesh);
        if let Some(mode) = mode {
            state.mode = mode;
        }
        frame.draws.push(crate::Draw {
            mesh: gpu,
            modelview: scene.modelview(mesh),
            projection: scene.projection,
            state,
            cull_face: scene.cull_face(mesh),
            front_face: raster.front_face,
            textures: {
                let mut textures = [None; MAX_TEXTURE_UNITS];
                for (gpu, t) in textures.iter_mut().zip(&mesh.textures) {
                    *gpu = t.as_ref().and_then(texture_of);
                }
                textures
            },
            cube_maps: {
                let mut cubes = [None; MAX_TEXTURE_UNITS];
                for (gpu, t) in cubes.iter_mut().zip(&mesh.textures) {
                    *gpu = t.as_ref().and_then(cube_of);
                }
                cubes
            },
            mesh_texcoords: mesh.mesh_texcoords(),
            second_texcoords: mesh.second_texcoords(),
            topology: gpu.topology(),
            // glPointSize draws points only: other meshes keep GL's 1 (their pipelines are
            // not split by it).
            point_size: if gpu.topology() == crate::Topology::PointList {
                scene.point_size
            } else {
                1.0
            },
            line_width: 1.0,
            polygon_offset: raster.polygon_offset,
            color_mask: raster.color_mask,
            blend: raster.blend,
            blend_color: raster.blend_color,
            polygon_mode: raster.polygon_mode,
            stencil: raster.stencil,
            logic_op: raster.logic_op,
            line_stipple: raster.line_stipple,
            depth_range: raster.depth_range,
            depth_write: raster.depth_write,
            polygon_stipple: raster.polygon_stipple,
        });
    }
    Ok(renderer.render(&frame)?.into())
}

/// Whether `u`'s cube map is `cube` (the same shared image).
fn same_cube(u: &MeshTexture, cube: &std::sync::Arc<crate::gl::texture::CubeImage>) -> bool {
    u.cube_map
        .as_ref()
        .is_some_and(|c| std::sync::Arc::ptr_eq(c, cube))
}
