//! The points of a sweep, in a stable order, and the scene each point draws: its lighting
//! state and its matrices.

use glam::{Mat4, Vec3, Vec4};

use super::sweep::{BenchMode, Engine, Group, LightKind, Point, Primitive, Stage, SweepConfig, Variant};
use crate::Result;
use ffvk::gl::state::{
    Attenuation, Cap, CompareFunc, Face, FixedFunctionState, FogHint, FogMode, FogParam, GlState,
    LightModelParam, LightParam, MaterialParam, SpecularModel, SpotEdge,
};

pub(super) fn sphere_counts(stacks: u32) -> (u64, u64) {
    let (slices, stacks) = (2 * stacks as u64, stacks as u64);
    ((slices + 1) * (stacks + 1), slices * (2 * stacks - 2))
}

/// The modes of GL's points in the density and size sweeps (smooth, flat, unlit).
pub(super) const GL_MODES: [BenchMode; 3] = [BenchMode::Vertex, BenchMode::Flat, BenchMode::Unlit];

/// The points of `config`, in a stable order: density, size, lights, kind; GL after ffvk.
pub fn points(config: &SweepConfig) -> Vec<Point> {
    let mut out = Vec::new();
    let base = |group, engine, mode, variant| {
        let (vertices, triangles) = sphere_counts(config.base_stacks);
        Point {
            group,
            engine,
            mode,
            variant,
            stacks: config.base_stacks,
            vertices,
            triangles,
            width: config.base_size,
            height: config.base_size,
            pixels: config.base_size as u64 * config.base_size as u64,
            lights: if mode == BenchMode::Unlit {
                0
            } else {
                config.base_lights
            },
            light_kind: LightKind::Directional,
            local_viewer: false,
            draws: config.draws,
            primitive: Primitive::Triangles,
            stage: Stage::Off,
        }
    };
    let some_variants = |everywhere: bool| {
        if everywhere {
            vec![Variant::Specialized, Variant::Uber]
        } else {
            vec![Variant::Specialized]
        }
    };

    for &stacks in &config.stacks {
        let (vertices, triangles) = sphere_counts(stacks);
        for mode in BenchMode::ALL {
            for variant in some_variants(config.variants_everywhere) {
                out.push(Point {
                    stacks,
                    vertices,
                    triangles,
                    ..base(Group::Density, Engine::Ffvk, mode, variant)
                });
            }
        }
        if config.gl {
            for mode in GL_MODES {
                out.push(Point {
                    stacks,
                    vertices,
                    triangles,
                    ..base(Group::Density, Engine::Gl, mode, Variant::FixedFunction)
                });
            }
        }
    }
    for &size in &config.sizes {
        let (vertices, triangles) = sphere_counts(config.size_stacks);
        let sized = |p: Point| Point {
            stacks: config.size_stacks,
            vertices,
            triangles,
            width: size,
            height: size,
            pixels: size as u64 * size as u64,
            ..p
        };
        for mode in BenchMode::ALL {
            for variant in some_variants(config.variants_everywhere) {
                out.push(sized(base(Group::Size, Engine::Ffvk, mode, variant)));
            }
        }
        if config.gl {
            for mode in GL_MODES {
                out.push(sized(base(Group::Size, Engine::Gl, mode, Variant::FixedFunction)));
            }
        }
    }
    for &lights in &config.light_counts {
        for mode in [BenchMode::Vertex, BenchMode::Fragment] {
            for variant in [Variant::Specialized, Variant::Uber] {
                out.push(Point {
                    lights,
                    ..base(Group::Lights, Engine::Ffvk, mode, variant)
                });
            }
        }
        if config.gl {
            out.push(Point {
                lights,
                ..base(
                    Group::Lights,
                    Engine::Gl,
                    BenchMode::Vertex,
                    Variant::FixedFunction,
                )
            });
        }
    }
    for &kind in &config.kinds {
        for local_viewer in [false, true] {
            let with_kind = |p: Point| Point {
                lights: config.kind_lights,
                light_kind: kind,
                local_viewer,
                ..p
            };
            for mode in [BenchMode::Vertex, BenchMode::Fragment] {
                for variant in [Variant::Specialized, Variant::Uber] {
                    out.push(with_kind(base(Group::Kind, Engine::Ffvk, mode, variant)));
                }
            }
            // GL has no lighting variants to draw.
            if config.gl && kind.gl_form().is_none() {
                out.push(with_kind(base(
                    Group::Kind,
                    Engine::Gl,
                    BenchMode::Vertex,
                    Variant::FixedFunction,
                )));
            }
        }
    }
    // The light sweeps' sphere as triangles, lines and points, lit at the vertices (smooth and
    // flat) and unlit, by ffvk and GL.
    for primitive in Primitive::ALL.into_iter().filter(|_| config.primitives) {
        for mode in [BenchMode::Vertex, BenchMode::Flat, BenchMode::Unlit] {
            let with_primitive = |p: Point| Point { primitive, ..p };
            out.push(with_primitive(base(
                Group::Primitives,
                Engine::Ffvk,
                mode,
                Variant::Specialized,
            )));
            if config.gl {
                out.push(with_primitive(base(
                    Group::Primitives,
                    Engine::Gl,
                    mode,
                    Variant::FixedFunction,
                )));
            }
        }
    }
    // The stages around lighting on the light sweeps' sphere, each alone and all together, in
    // every mode, specialized and uber, and GL's.
    for stage in Stage::ALL.into_iter().filter(|_| config.stages) {
        let with_stage = |p: Point| Point { stage, ..p };
        for mode in BenchMode::ALL {
            for variant in [Variant::Specialized, Variant::Uber] {
                out.push(with_stage(base(Group::Stages, Engine::Ffvk, mode, variant)));
            }
        }
        if config.gl {
            for mode in GL_MODES {
                out.push(with_stage(base(
                    Group::Stages,
                    Engine::Gl,
                    mode,
                    Variant::FixedFunction,
                )));
            }
        }
    }
    // Fragment lighting's cost on the dense mesh, ffvk's modes only (GL has no fragment mode).
    let (vertices, triangles) = sphere_counts(config.fragment_stacks);
    for &size in &config.fragment_sizes {
        let paths = [
            (BenchMode::Vertex, Variant::Specialized),
            (BenchMode::Fragment, Variant::Specialized),
            (BenchMode::Fragment, Variant::Deferred),
            (BenchMode::Fragment, Variant::DeferredUber),
            (BenchMode::Unlit, Variant::Specialized),
        ];
        for (mode, variant) in paths {
            let mut point = base(Group::Fragment, Engine::Ffvk, mode, variant);
            point.stacks = config.fragment_stacks;
            (point.vertices, point.triangles) = (vertices, triangles);
            (point.width, point.height, point.pixels) = (size, size, size as u64 * size as u64);
            if mode != BenchMode::Unlit {
                point.lights = config.fragment_lights;
            }
            out.push(point);
        }
    }
    for &stacks in &config.path_stacks {
        let (vertices, triangles) = sphere_counts(stacks);
        for &size in &config.path_sizes {
            for &lights in &config.path_lights {
                for variant in [Variant::Specialized, Variant::Deferred] {
                    out.push(Point {
                        stacks,
                        vertices,
                        triangles,
                        width: size,
                        height: size,
                        pixels: size as u64 * size as u64,
                        lights,
                        ..base(Group::Paths, Engine::Ffvk, BenchMode::Fragment, variant)
                    });
                }
            }
        }
    }
    out
}

/// The lighting state of a point: `lights` lights of one kind around the view axis, white
/// light split between them, a shiny material on both faces.
pub fn point_state(point: &Point) -> Result<FixedFunctionState> {
    let mut gl = GlState::new();
    gl.lighting_mode(point.mode.lighting_mode());
    set_stage(&mut gl, point.stage)?;
    if point.mode == BenchMode::Unlit {
        return Ok(gl.lighting);
    }
    gl.enable(Cap::Lighting)?;
    gl.light_model(LightModelParam::LocalViewer(point.local_viewer))?;
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Diffuse(Vec4::new(0.8, 0.7, 0.6, 1.0)),
    )?;
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Specular(Vec4::new(0.6, 0.6, 0.6, 1.0)),
    )?;
    gl.material(Face::FrontAndBack, MaterialParam::Shininess(32.0))?;
    let n = point.lights.max(1);
    let share = 1.0 / n as f32;
    for i in 0..point.lights {
        let a = std::f32::consts::TAU * i as f32 / n as f32;
        let (s, c) = a.sin_cos();
        gl.enable(Cap::Light(i))?;
        gl.light(i, LightParam::Diffuse(Vec4::new(share, share, share, 1.0)))?;
        gl.light(i, LightParam::Specular(Vec4::new(share, share, share, 1.0)))?;
        // Eye space (the modelview is the identity here): the sphere's center is at z = -2.6.
        let local = Vec3::new(1.6 * c, 1.6 * s, -1.0);
        let kind = point.light_kind.gl_form().unwrap_or(point.light_kind);
        match kind {
            LightKind::Directional => {
                gl.light(i, LightParam::Position(Vec4::new(0.6 * c, 0.6 * s, 1.0, 0.0)))?;
            }
            _ => {
                gl.light(i, LightParam::Position(local.extend(1.0)))?;
                gl.light(i, LightParam::ConstantAttenuation(1.0))?;
                gl.light(i, LightParam::LinearAttenuation(0.05))?;
                gl.light(i, LightParam::QuadraticAttenuation(0.02))?;
            }
        }
        if kind == LightKind::Spot {
            gl.light(i, LightParam::SpotDirection(Vec3::new(0.0, 0.0, -2.6) - local))?;
            gl.light(i, LightParam::SpotCutoff(35.0))?;
            gl.light(i, LightParam::SpotExponent(8.0))?;
        }
        match point.light_kind {
            LightKind::DirectionalPhong => {
                gl.light_model(LightModelParam::SpecularModel(SpecularModel::PhongReflect))?;
            }
            LightKind::PointGltf => gl.light(
                i,
                LightParam::Attenuation(Attenuation::GltfInverseSquare { range: Some(6.0) }),
            )?,
            LightKind::SpotLinear => gl.light(
                i,
                LightParam::SpotEdge(SpotEdge::LinearInnerOuter { inner_degrees: 20.0 }),
            )?,
            LightKind::SpotSmoothstep => gl.light(
                i,
                LightParam::SpotEdge(SpotEdge::SmoothstepInnerOuter { inner_degrees: 20.0 }),
            )?,
            _ => {}
        }
    }
    Ok(gl.lighting)
}

/// Turns on the stages of `stage` as a GL program would, with the identity modelview (the
/// sphere's center is at z_e = -2.6, its radius 1): fog over the sphere's depth, an alpha
/// test and clip planes every fragment passes, so that a point costs the stage's work and
/// draws the same pixels.
fn set_stage(gl: &mut GlState, stage: Stage) -> Result<()> {
    let fog = |gl: &mut GlState, mode: FogMode, hint: FogHint| -> Result<()> {
        gl.enable(Cap::Fog)?;
        gl.fog(FogParam::Mode(mode))?;
        gl.fog(FogParam::Start(1.5))?;
        gl.fog(FogParam::End(4.0))?;
        gl.fog(FogParam::Density(0.3))?;
        gl.fog(FogParam::Color(Vec4::new(0.5, 0.55, 0.6, 1.0)))?;
        gl.fog_hint(hint);
        Ok(())
    };
    let alpha = |gl: &mut GlState| -> Result<()> {
        gl.enable(Cap::AlphaTest)?;
        gl.alpha_func(CompareFunc::Greater, 0.0)?;
        Ok(())
    };
    let color_sum = |gl: &mut GlState| -> Result<()> {
        gl.enable(Cap::ColorSum)?;
        gl.secondary_color(Vec3::new(0.1, 0.05, 0.0))?;
        Ok(())
    };
    let planes = |gl: &mut GlState, n: usize| -> Result<()> {
        // Planes facing the eye from 50 units behind it: every vertex is kept.
        for i in 0..n {
            let a = std::f64::consts::TAU * i as f64 / 6.0;
            gl.clip_plane(i, glam::DVec4::new(0.1 * a.cos(), 0.1 * a.sin(), -1.0, 50.0))?;
            gl.enable(Cap::ClipPlane(i))?;
        }
        Ok(())
    };
    match stage {
        Stage::Off => {}
        Stage::FogLinear => fog(gl, FogMode::Linear, FogHint::DontCare)?,
        Stage::FogExp2 => fog(gl, FogMode::Exp2, FogHint::DontCare)?,
        Stage::FogExp2PerVertex => fog(gl, FogMode::Exp2, FogHint::Fastest)?,
        Stage::AlphaTest => alpha(gl)?,
        Stage::ColorSum => color_sum(gl)?,
        Stage::ClipPlane => planes(gl, 1)?,
        Stage::ClipPlanes6 => planes(gl, 6)?,
        Stage::All => {
            fog(gl, FogMode::Linear, FogHint::DontCare)?;
            alpha(gl)?;
            color_sum(gl)?;
            planes(gl, 6)?;
        }
        Stage::Texture | Stage::Units4 => super::stage_textures::set_texture_stage(gl, stage)?,
    }
    Ok(())
}

/// The modelview of each of the point's draws and the GL projection (square image). Draw
/// `i` sits `i` × 1/1024 nearer than the first: drawn back to front, each passes GL_LESS and
/// is lit in full, while the image stays the one sphere's.
pub(super) fn matrices(point: &Point) -> (Vec<Mat4>, Mat4) {
    let aspect = point.width as f32 / point.height as f32;
    let modelviews = (0..point.draws.max(1))
        .map(|i| Mat4::from_translation(Vec3::new(0.0, 0.0, -2.6 + i as f32 / 1024.0)))
        .collect();
    (
        modelviews,
        Mat4::perspective_rh_gl(45f32.to_radians(), aspect, 0.5, 10.0),
    )
}

pub(super) const CLEAR: Vec4 = Vec4::new(0.1, 0.1, 0.12, 1.0);
