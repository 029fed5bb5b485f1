//! The embedding API: GL lighting recorded into a caller's own device and command buffers
//! (`ffvk::Lighting`), and the offscreen renderer built on it.

#[path = "../../ffvk/examples/embed.rs"]
#[allow(dead_code)]
pub(crate) mod embed;

use ffvk::gl::state::{Cap, Face, GlState, LightingMode, MaterialParam};
use ffvk::{Draw, Frame};
use glam::{DVec3, DVec4, Mat4, Vec4};

use crate::support::*;

/// Cell (i, j) of a grid of 2×2-pixel quads facing the viewer at the eye is lit as the CPU
/// reference lights `gl`'s front material there (within 1/255).
fn assert_cell_lit(image: &image::RgbaImage, (i, j): (u32, u32), gl: &GlState, what: &str) {
    let lit = ffvk::reference::light(
        &gl.lighting,
        DVec4::new(0.0, 0.0, 0.0, 1.0),
        DVec3::Z,
        &gl.lighting.front,
    );
    assert_pixel(image, 2 * i, 2 * j, lit.color(), 1.0, what);
}

/// Fails with the first pixel where the Renderer's image and the caller's differ, saving both.
pub(crate) fn assert_same_bytes(renderer: &ffvk::Pixels, caller: &[u8], what: &str) {
    let first_difference = renderer
        .rgba()
        .chunks(4)
        .zip(caller.chunks(4))
        .position(|(a, b)| a != b);
    if let Some(i) = first_difference {
        let (x, y) = (i as u32 % renderer.width(), i as u32 / renderer.width());
        let renderer_path = save_for_inspection(
            &renderer.clone().into_rgba_image(),
            &format!("embed_renderer_{what}"),
        );
        let caller_image =
            image::RgbaImage::from_raw(renderer.width(), renderer.height(), caller.to_vec()).unwrap();
        let caller_path = save_for_inspection(&caller_image, &format!("embed_caller_{what}"));
        panic!(
            "{what}: pixel ({x}, {y}) is {:?} through the Renderer but {:?} through the caller's device; images {} and {}",
            &renderer.rgba()[i * 4..i * 4 + 4],
            &caller[i * 4..i * 4 + 4],
            renderer_path.display(),
            caller_path.display()
        );
    }
    assert_eq!(renderer.rgba().len(), caller.len(), "{what}: image sizes");
}

/// The teapot frame of the embedding example, drawn through the Renderer.
fn renderer_frame(
    r: &mut ffvk::Renderer,
    mesh: &ffvk::Mesh,
    state: &ffvk::gl::state::FixedFunctionState,
) -> ffvk::Pixels {
    let mut frame = Frame::new(embed::SIZE, embed::SIZE);
    frame.clear_color = Vec4::from_array(embed::CLEAR);
    frame
        .draws
        .push(Draw::new(mesh, embed::view(), embed::projection(), *state));
    r.render(&frame).unwrap()
}

#[test]
fn a_callers_device_draws_the_same_bytes_as_the_renderer_in_every_mode() {
    let embedded = embed::render_modes(None, true).expect("the embedding example renders with validation on");
    assert_eq!(embedded.len(), 3);
    let mut r = renderer();
    let mesh = r.upload(&embed::teapot().unwrap()).unwrap();
    for (mode, bytes) in embedded {
        let gl = embed::gl_state(mode).unwrap();
        let pixels = renderer_frame(&mut r, &mesh, &gl.lighting);
        assert_same_bytes(&pixels, &bytes, mode.name());
        // Not a blank image: the teapot covers the center.
        let clear = embed::CLEAR.map(|c| (c * 255.0).round() as u8);
        assert_ne!(
            pixels.pixel(128, 128),
            Some(clear),
            "{} mode draws the teapot",
            mode.name()
        );
    }
    finish(r);
}

/// An emulation layer's frame: many objects under one shared state, each draw carrying only its
/// modelview and its own materials (`LitDraw::with_values`), recorded as one run (where draws
/// of one mesh become instances of one command) on the caller's device, against the Renderer
/// drawing the same objects each with a whole state of its own, one draw command each.
#[test]
fn a_run_of_draws_sharing_one_state_with_values_of_their_own_draws_what_a_state_per_draw_draws() {
    let mut r = renderer();
    let mesh = r.upload(&embed::teapot().unwrap()).unwrap();
    // A mesh per object on the Renderer's side: nothing merges there.
    let meshes: Vec<ffvk::Mesh> = (0..36)
        .map(|_| r.upload(&embed::teapot().unwrap()).unwrap())
        .collect();
    for mode in LightingMode::ALL {
        let mut gl = embed::gl_state(mode).unwrap();
        gl.enable(Cap::Normalize).unwrap();
        let state = gl.lighting;
        let frames = [embed::EmbedFrame {
            state,
            color_array: true,
            grid: 6,
            topology: ffvk::Topology::TriangleList,
        }];
        let embedded = embed::render_frames(None, true, embed::SIZE, &frames)
            .expect("the run renders with validation on");
        for (merged, meshes) in [(true, std::slice::from_ref(&mesh)), (false, meshes.as_slice())] {
            let mut frame = Frame::new(embed::SIZE, embed::SIZE);
            frame.clear_color = Vec4::from_array(embed::CLEAR);
            for ((modelview, values), mesh) in embed::grid_objects(&state, 6)
                .into_iter()
                .zip(meshes.iter().cycle())
            {
                let mut own = state;
                (own.front, own.back, own.current_color) = (values.front, values.back, values.current_color);
                frame
                    .draws
                    .push(Draw::new(mesh, modelview, embed::projection(), own));
            }
            let pixels = r.render(&frame).unwrap();
            let what = format!(
                "{}_grid_{}",
                mode.name(),
                if merged { "one_mesh" } else { "a_mesh_each" }
            );
            assert_same_bytes(&pixels, &embedded[0], &what);
        }
        // Thirty-six teapots in thirty-six colors, not one.
        let image = image::RgbaImage::from_raw(embed::SIZE, embed::SIZE, embedded[0].clone()).unwrap();
        let colors: std::collections::HashSet<[u8; 4]> = image.pixels().map(|p| p.0).collect();
        assert!(colors.len() > 200, "{}: {} colors", mode.name(), colors.len());
    }
    finish(r);
}

/// The binding model: a GL program's frame recorded one `Lighting::draw` per draw, with the
/// caller's own commands between them (a scissor before each draw; before every other draw, its
/// own vertex and index buffers bound over ffvk's and `forget_bindings`), draws the same bytes as
/// the same draws in one run, in every mode.
#[test]
fn draws_recorded_one_by_one_between_the_callers_own_commands_draw_what_one_run_draws() {
    for mode in LightingMode::ALL {
        let state = embed::gl_state(mode).unwrap().lighting;
        let frames = [embed::EmbedFrame {
            state,
            color_array: true,
            grid: 4,
            topology: ffvk::Topology::TriangleList,
        }];
        let run = embed::render_frames(None, true, embed::SIZE, &frames).expect("the run renders");
        let by_draw = embed::render_frames_draw_by_draw(None, true, embed::SIZE, &frames)
            .expect("the draws render one by one with validation on");
        if let Some(i) = run[0]
            .chunks(4)
            .zip(by_draw[0].chunks(4))
            .position(|(a, b)| a != b)
        {
            let save = |bytes: &[u8], name: &str| {
                let image = image::RgbaImage::from_raw(embed::SIZE, embed::SIZE, bytes.to_vec()).unwrap();
                save_for_inspection(&image, &format!("{}_{name}", mode.name()))
                    .display()
                    .to_string()
            };
            panic!(
                "{}: pixel {i} is {:?} in the run but {:?} drawn one by one; images {} and {}",
                mode.name(),
                &run[0][i * 4..i * 4 + 4],
                &by_draw[0][i * 4..i * 4 + 4],
                save(&run[0], "run"),
                save(&by_draw[0], "draw_by_draw")
            );
        }
        assert_eq!(run[0].len(), by_draw[0].len());
        // Sixteen teapots, not a blank image.
        let colors: std::collections::HashSet<&[u8]> = run[0].chunks(4).collect();
        assert!(colors.len() > 50, "{}: {} colors", mode.name(), colors.len());
    }
}

/// Two `Lighting`s of one device (a layer's two vertex layouts) drawing alternately into one
/// command buffer, one draw at a time, draw what they draw when everything is bound anew before
/// every draw: each one forgets what it bound when the other has recorded since.
#[test]
fn two_lightings_alternating_in_one_command_buffer_rebind_after_each_other() {
    for mode in LightingMode::ALL {
        let mut gl = embed::gl_state(mode).unwrap();
        gl.enable(Cap::ColorMaterial).unwrap();
        let state = gl.lighting;
        let remembered = embed::render_alternating(None, true, &state, 4, false)
            .expect("alternating draws render with validation on");
        let fresh = embed::render_alternating(None, true, &state, 4, true).expect("fresh binds render");
        assert!(
            remembered == fresh,
            "{}: the alternating draws differ from the same draws bound anew",
            mode.name()
        );
        let colors: std::collections::HashSet<&[u8]> = fresh.chunks(4).collect();
        assert!(colors.len() > 50, "{}: {} colors", mode.name(), colors.len());
    }
}

/// Without a color array every vertex takes GL's current color: the same bytes as a color
/// array holding that color at every vertex, lit through COLOR_MATERIAL in each mode, and
/// unlit.
#[test]
fn without_a_color_array_every_vertex_takes_the_current_color() {
    let c = Vec4::new(0.3, 0.6, 0.9, 1.0);
    let mut states = Vec::new();
    for mode in LightingMode::ALL {
        let mut gl = embed::gl_state(mode).unwrap();
        gl.enable(Cap::ColorMaterial).unwrap();
        gl.color(c).unwrap();
        states.push(gl.lighting);
    }
    let mut unlit = states[0];
    unlit.lighting = false;
    states.push(unlit);
    let frames: Vec<embed::EmbedFrame> = states
        .iter()
        .map(|s| embed::EmbedFrame {
            state: *s,
            color_array: false,
            grid: 0,
            topology: ffvk::Topology::TriangleList,
        })
        .collect();
    let embedded =
        embed::render_frames(None, true, embed::SIZE, &frames).expect("renders with validation on");
    let mut r = renderer();
    let mut teapot = embed::teapot().unwrap();
    for v in &mut teapot.vertices {
        v.color = c.to_array();
    }
    let mesh = r.upload(&teapot).unwrap();
    for (k, (state, bytes)) in states.iter().zip(&embedded).enumerate() {
        let pixels = renderer_frame(&mut r, &mesh, state);
        let what = if state.lighting {
            state.mode.name()
        } else {
            "unlit"
        };
        assert_same_bytes(&pixels, bytes, &format!("current_color_{what}_{k}"));
    }
    finish(r);
}

/// ffvk's uniform block moved to descriptor set 2 (the SPIR-V's set rewritten, empty layouts
/// below it): the same bytes as in set 0, with the validation layer on.
#[test]
fn the_uniform_block_may_live_in_another_descriptor_set() {
    let frames: Vec<embed::EmbedFrame> = LightingMode::ALL
        .iter()
        .map(|&mode| embed::EmbedFrame {
            state: embed::gl_state(mode).unwrap().lighting,
            color_array: true,
            grid: 0,
            topology: ffvk::Topology::TriangleList,
        })
        .collect();
    let in_set_0 = embed::render_frames_in_set(None, true, 64, 0, &frames).unwrap();
    let in_set_2 = embed::render_frames_in_set(None, true, 64, 2, &frames).unwrap();
    for (mode, (a, b)) in LightingMode::ALL.iter().zip(in_set_0.iter().zip(&in_set_2)) {
        assert!(a == b, "{} mode: set 2 draws other bytes than set 0", mode.name());
    }
}

/// 10,000 draws in one frame, each with its own material: one command buffer, the per-draw
/// state memory growing chunk by chunk, every quad its own color from the CPU reference.
/// Draws of one mesh merge into instanced commands, but never across a chunk of the frame
/// slot's record memory: 300 draws fill chunks of 64, 128 and 256 records, and every draw still
/// lights with its own material, in the modes that merge (vertex and flat) and in the
/// fragment mode's small-draw path.
#[test]
fn merged_draws_of_one_mesh_across_record_chunks_each_light_as_the_reference_says() {
    const SIDE: u32 = 20;
    const DRAWS: u32 = 300;
    let mut r = renderer();
    let cell = 2.0 / SIDE as f32;
    let mesh = r.upload(&quad(0.0, 0.0, cell, cell, 0.0, Vec4::ONE)).unwrap();
    for mode in LightingMode::ALL {
        let states: Vec<GlState> = (0..DRAWS)
            .map(|k| {
                let mut gl = lit_state();
                let d = Vec4::new(
                    (k % 97) as f32 / 96.0,
                    (k % 13) as f32 / 12.0,
                    (k % 7) as f32 / 6.0,
                    1.0,
                );
                gl.material(Face::FrontAndBack, MaterialParam::Diffuse(d))
                    .unwrap();
                gl.lighting_mode(mode);
                gl
            })
            .collect();
        let mut frame = Frame::new(2 * SIDE, 2 * SIDE);
        frame.depth_test = false;
        for (k, gl) in states.iter().enumerate() {
            let (i, j) = (k as u32 % SIDE, k as u32 / SIDE);
            let at = glam::Vec3::new(-1.0 + i as f32 * cell, 1.0 - (j + 1) as f32 * cell, 0.0);
            frame.draws.push(Draw::new(
                &mesh,
                Mat4::from_translation(at),
                Mat4::IDENTITY,
                gl.lighting,
            ));
        }
        let image = r.render(&frame).unwrap().into_rgba_image();
        for (k, gl) in states.iter().enumerate() {
            let (i, j) = (k as u32 % SIDE, k as u32 / SIDE);
            assert_cell_lit(&image, (i, j), gl, &format!("{} draw {k}", mode.name()));
        }
    }
    finish(r);
}

#[test]
fn ten_thousand_draws_with_distinct_states_in_one_command_buffer_each_light_as_the_reference_says() {
    const SIDE: u32 = 100;
    let mut r = renderer();
    // One 2x2-pixel quad per draw, in NDC.
    let cell = 2.0 / SIDE as f32;
    let mut meshes = Vec::new();
    for j in 0..SIDE {
        for i in 0..SIDE {
            let (x0, y0) = (-1.0 + i as f32 * cell, 1.0 - (j + 1) as f32 * cell);
            let q = quad(x0, y0, x0 + cell, y0 + cell, 0.0, Vec4::ONE);
            meshes.push(q);
        }
    }
    let uploaded: Vec<ffvk::Mesh> = meshes.iter().map(|m| r.upload(m).unwrap()).collect();
    let states: Vec<GlState> = (0..SIDE * SIDE)
        .map(|k| {
            let mut gl = lit_state();
            let d = Vec4::new(
                (k % 97) as f32 / 96.0,
                (k % 89) as f32 / 88.0,
                (k % 83) as f32 / 82.0,
                1.0,
            );
            gl.material(Face::FrontAndBack, MaterialParam::Diffuse(d))
                .unwrap();
            gl.lighting_mode(
                [LightingMode::Vertex, LightingMode::Fragment, LightingMode::Flat][k as usize % 3],
            );
            gl
        })
        .collect();
    let mut frame = Frame::new(2 * SIDE, 2 * SIDE);
    frame.depth_test = false;
    for (mesh, gl) in uploaded.iter().zip(&states) {
        frame
            .draws
            .push(Draw::new(mesh, Mat4::IDENTITY, Mat4::IDENTITY, gl.lighting));
    }
    let image = r.render(&frame).unwrap().into_rgba_image();
    for j in 0..SIDE {
        for i in 0..SIDE {
            let gl = &states[(j * SIDE + i) as usize];
            assert_cell_lit(&image, (i, j), gl, &format!("draw {}", j * SIDE + i));
        }
    }
    finish(r);
}

#[test]
fn bad_vertex_layouts_and_draws_are_clear_errors() {
    use ash::vk;
    use ffvk::{Attribute, LightingError, VertexInput};
    let mut input = VertexInput::interleaved();
    input.normal = Some(Attribute::new(3, 0, vk::Format::R32G32B32_SFLOAT));
    let e = input.validate().unwrap_err().to_string();
    assert!(
        e.contains("normal") && e.contains("binding 3") && e.contains("[0]"),
        "{e}"
    );
    let mut input = VertexInput::interleaved();
    input.color = Some(Attribute::new(0, 24, vk::Format::R32G32B32A32_UINT));
    let e = input.validate().unwrap_err();
    assert!(
        matches!(
            e,
            ffvk::Error::Lighting(LightingError::AttributeFormat { ref attribute, .. }) if attribute == "color"
        ),
        "{e}"
    );
    let mut input = VertexInput::interleaved();
    input.bindings.push(input.bindings[0]);
    assert!(input.validate().unwrap_err().to_string().contains("listed twice"));
}

/// A caller's device made with plain ash (lavapipe, one graphics queue, dynamic rendering,
/// no provoking-vertex extension), destroyed on drop.
pub(crate) struct PlainDevice {
    pub(crate) entry: ash::Entry,
    pub(crate) instance: ash::Instance,
    pub(crate) physical: ash::vk::PhysicalDevice,
    pub(crate) device: ash::Device,
}

impl PlainDevice {
    pub(crate) fn new() -> PlainDevice {
        use ash::vk;
        // SAFETY: loads the system's Vulkan loader; the create infos outlive the calls.
        unsafe {
            let entry = ash::Entry::load().unwrap();
            let app = vk::ApplicationInfo::default().api_version(vk::API_VERSION_1_3);
            let instance = entry
                .create_instance(&vk::InstanceCreateInfo::default().application_info(&app), None)
                .unwrap();
            let physical = instance
                .enumerate_physical_devices()
                .unwrap()
                .into_iter()
                .find(|&p| {
                    instance
                        .get_physical_device_properties(p)
                        .device_name_as_c_str()
                        .is_ok_and(|n| n.to_string_lossy().contains("llvmpipe"))
                })
                .expect("lavapipe");
            let priorities = [1.0];
            let queues = [vk::DeviceQueueCreateInfo::default()
                .queue_family_index(0)
                .queue_priorities(&priorities)];
            let mut v13 = vk::PhysicalDeviceVulkan13Features::default().dynamic_rendering(true);
            let info = vk::DeviceCreateInfo::default()
                .queue_create_infos(&queues)
                .push_next(&mut v13);
            let device = instance.create_device(physical, &info, None).unwrap();
            PlainDevice {
                entry,
                instance,
                physical,
                device,
            }
        }
    }
}

impl Drop for PlainDevice {
    fn drop(&mut self) {
        // SAFETY: nothing of ffvk's is left on the device (the tests drop it first).
        unsafe {
            self.device.destroy_device(None);
            self.instance.destroy_instance(None);
        }
    }
}

#[test]
fn features_the_caller_did_not_enable_are_named_in_the_error() {
    use ffvk::vk::{Device, EnabledFeatures};
    use ffvk::{Lighting, LightingOptions, RasterState, Target, VertexInput};
    let plain = PlainDevice::new();
    // SAFETY: the device comes from this physical device and outlives every ffvk object here.
    let e = unsafe {
        Device::from_caller(
            &plain.instance,
            plain.physical,
            plain.device.clone(),
            EnabledFeatures::default(),
        )
    }
    .err()
    .expect("dynamic rendering is required");
    assert!(
        matches!(
            e,
            ffvk::Error::NotEnabled {
                flag: "dynamic_rendering",
                ..
            }
        ),
        "{e}"
    );
    let features = EnabledFeatures::default()
        .with_dynamic_rendering(true)
        .with_provoking_vertex_last(false);
    // SAFETY: as above.
    let device =
        unsafe { Device::from_caller(&plain.instance, plain.physical, plain.device.clone(), features) }
            .unwrap();
    let mut lighting = Lighting::new(
        &device,
        &LightingOptions::new(Target::OFFSCREEN, VertexInput::interleaved()),
    )
    .unwrap();
    let mut gl = lit_state();
    lighting
        .prepare(&gl.lighting, RasterState::default(), false)
        .unwrap();
    gl.lighting_mode(LightingMode::Flat);
    let e = lighting
        .prepare(&gl.lighting, RasterState::default(), false)
        .unwrap_err();
    assert!(
        matches!(
            e,
            ffvk::Error::NotEnabled {
                flag: "provoking_vertex_last",
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().contains("flat mode"), "{e}");

    // A run whose second draw is bad fails naming it, with nothing recorded.
    use ffvk::ash::vk;
    use ffvk::{Geometry, LitDraw};
    // SAFETY: the pool and its buffer are made, begun and destroyed on this device here; nothing
    // is submitted.
    let (pool, cmd) = unsafe {
        let pool = plain
            .device
            .create_command_pool(&vk::CommandPoolCreateInfo::default().queue_family_index(0), None)
            .unwrap();
        let cmd = plain
            .device
            .allocate_command_buffers(
                &vk::CommandBufferAllocateInfo::default()
                    .command_pool(pool)
                    .command_buffer_count(1),
            )
            .unwrap()[0];
        plain
            .device
            .begin_command_buffer(cmd, &vk::CommandBufferBeginInfo::default())
            .unwrap();
        (pool, cmd)
    };
    gl.lighting_mode(LightingMode::Vertex);
    let buffers = [(vk::Buffer::null(), 0)];
    let good = LitDraw::new(
        &gl.lighting,
        Mat4::IDENTITY,
        Mat4::IDENTITY,
        &buffers,
        Geometry::vertices(3),
    );
    let flat = Mat4::from_scale(glam::Vec3::new(1.0, 0.0, 1.0));
    let singular = LitDraw::new(
        &gl.lighting,
        flat,
        Mat4::IDENTITY,
        &buffers,
        Geometry::vertices(3),
    );
    lighting.begin_frame(0).unwrap();
    // SAFETY: the run fails at its second draw's checks, which come before anything is
    // recorded, so neither the rendering pass the contract asks for nor the null buffer is
    // ever reached.
    let e = unsafe { lighting.draw_run(cmd, 0, &[good, singular]) }.unwrap_err();
    assert!(matches!(e, ffvk::Error::InRun { index: 1, .. }), "{e}");
    assert!(e.to_string().starts_with("draw 1 of the run: "), "{e}");
    assert!(e.to_string().contains("modelview"), "{e}");
    // Primitive restart on a list is refused naming the mode, before anything is recorded.
    let restarted = LitDraw::new(
        &gl.lighting,
        Mat4::IDENTITY,
        Mat4::IDENTITY,
        &buffers,
        Geometry::indexed(vk::Buffer::null(), vk::IndexType::UINT16, 6)
            .with_topology(ffvk::Topology::LineList)
            .with_primitive_restart(true),
    );
    // SAFETY: as above: the draw fails its checks before anything is recorded.
    let e = unsafe { lighting.draw_run(cmd, 0, &[restarted]) }.unwrap_err();
    assert!(
        e.to_string().contains("primitive restart is on for GL_LINES"),
        "{e}"
    );
    drop(lighting);
    drop(device);
    // SAFETY: the command buffer was never submitted.
    unsafe { plain.device.destroy_command_pool(pool, None) };
}

/// The lighting variants reach a caller's device through `LitDraw::state` as they reach the
/// Renderer: the same bytes in every mode, and not GL's image.
#[test]
fn the_lighting_variants_draw_the_same_bytes_through_a_callers_device() {
    use ffvk::gl::state::{Attenuation, LightModelParam, LightParam, SpecularModel, SpotEdge};
    use glam::Vec3;
    let variant = |mode| {
        let mut gl = embed::gl_state(mode).unwrap();
        gl.light_model(LightModelParam::SpecularModel(SpecularModel::PhongReflect))
            .unwrap();
        gl.load_modelview(embed::view()).unwrap();
        gl.enable(Cap::Light(1)).unwrap();
        gl.light(1, LightParam::Position(Vec4::new(0.5, 2.0, 1.0, 1.0)))
            .unwrap();
        gl.light(1, LightParam::SpotDirection(Vec3::new(-0.2, -1.0, -0.5)))
            .unwrap();
        gl.light(1, LightParam::SpotCutoff(30.0)).unwrap();
        gl.light(
            1,
            LightParam::SpotEdge(SpotEdge::SmoothstepInnerOuter { inner_degrees: 15.0 }),
        )
        .unwrap();
        gl.light(
            1,
            LightParam::Attenuation(Attenuation::GltfInverseSquare { range: Some(5.0) }),
        )
        .unwrap();
        gl.light(1, LightParam::Diffuse(Vec4::new(2.0, 1.5, 1.0, 1.0)))
            .unwrap();
        gl.lighting
    };
    let frames: Vec<embed::EmbedFrame> = LightingMode::ALL
        .iter()
        .map(|&mode| embed::EmbedFrame {
            state: variant(mode),
            color_array: true,
            grid: 0,
            topology: ffvk::Topology::TriangleList,
        })
        .collect();
    let embedded =
        embed::render_frames(None, true, embed::SIZE, &frames).expect("renders with validation on");
    let mut r = renderer();
    let mesh = r.upload(&embed::teapot().unwrap()).unwrap();
    for (mode, bytes) in LightingMode::ALL.into_iter().zip(&embedded) {
        let pixels = renderer_frame(&mut r, &mesh, &variant(mode));
        assert_same_bytes(&pixels, bytes, &format!("variants_{}", mode.name()));
        let gl = renderer_frame(&mut r, &mesh, &embed::gl_state(mode).unwrap().lighting);
        assert_ne!(
            gl.rgba(),
            pixels.rgba(),
            "{}: the variants change the image",
            mode.name()
        );
    }
    finish(r);
}

/// The embedding example's teapot drawn as one lit line strip through its indices
/// (`glDrawElements(GL_LINE_STRIP, …)`) on a caller's device draws the bytes the Renderer draws
/// with the same mesh and `Draw::with_topology`, in every mode; and it is lines, not the teapot's
/// triangles.
#[test]
fn a_callers_device_draws_a_lit_line_strip_as_the_renderer_does() {
    let frames: Vec<embed::EmbedFrame> = LightingMode::ALL
        .iter()
        .map(|&mode| embed::EmbedFrame {
            state: embed::gl_state(mode).unwrap().lighting,
            color_array: true,
            grid: 0,
            topology: ffvk::Topology::LineStrip,
        })
        .collect();
    let embedded = embed::render_frames(None, true, embed::SIZE, &frames).unwrap();
    let mut r = renderer();
    let mesh = r.upload(&embed::teapot().unwrap()).unwrap();
    let clear = embed::CLEAR.map(|c| (c * 255.0).round() as u8);
    for (frame, bytes) in frames.iter().zip(embedded) {
        let mut f = Frame::new(embed::SIZE, embed::SIZE);
        f.clear_color = Vec4::from_array(embed::CLEAR);
        f.draws.push(
            Draw::new(&mesh, embed::view(), embed::projection(), frame.state)
                .with_topology(ffvk::Topology::LineStrip),
        );
        let pixels = r.render(&f).unwrap();
        let what = format!("line strip {}", frame.state.mode.name());
        assert_same_bytes(&pixels, &bytes, &what);
        let triangles = renderer_frame(&mut r, &mesh, &frame.state);
        let lit = pixels.rgba().chunks(4).filter(|px| px[..3] != clear[..3]).count();
        let differ = pixels
            .rgba()
            .chunks(4)
            .zip(triangles.rgba().chunks(4))
            .filter(|(a, b)| a != b)
            .count();
        assert!(
            lit > 1000 && differ > 1000,
            "{what}: {lit} pixels drawn, {differ} unlike the solid teapot's"
        );
    }
    finish(r);
}

/// An embedder's own gpu-allocator `Allocator` serves ffvk's buffers beside the embedder's
/// (feature `shared-allocator`): ffvk's allocations are named `ffvk: …` in its report while
/// ffvk holds them, and none is left once ffvk's objects are dropped; the embedder's stays.
#[test]
fn an_embedders_allocator_serves_ffvks_buffers_and_gets_every_one_back() {
    use ffvk::gpu_allocator::vulkan::{
        AllocationCreateDesc, AllocationScheme, Allocator, AllocatorCreateDesc,
    };
    use ffvk::gpu_allocator::{AllocatorDebugSettings, MemoryLocation};
    use ffvk::vk::{Device, EnabledFeatures};
    use ffvk::{Lighting, LightingOptions, RasterState, Target, VertexInput};
    use std::sync::{Arc, Mutex};
    let plain = PlainDevice::new();
    let allocator = Allocator::new(&AllocatorCreateDesc {
        instance: plain.instance.clone(),
        device: plain.device.clone(),
        physical_device: plain.physical,
        debug_settings: AllocatorDebugSettings::default(),
        buffer_device_address: false,
        allocation_sizes: Default::default(),
    })
    .unwrap();
    let allocator = Arc::new(Mutex::new(allocator));
    let names = |a: &Arc<Mutex<Allocator>>| -> Vec<String> {
        let report = a.lock().unwrap().generate_report();
        report.allocations.iter().map(|r| r.name.clone()).collect()
    };
    let own = allocator
        .lock()
        .unwrap()
        .allocate(&AllocationCreateDesc {
            name: "embedder's vertices",
            requirements: ffvk::ash::vk::MemoryRequirements {
                size: 4096,
                alignment: 256,
                memory_type_bits: !0,
            },
            location: MemoryLocation::CpuToGpu,
            linear: true,
            allocation_scheme: AllocationScheme::GpuAllocatorManaged,
        })
        .unwrap();

    let features = EnabledFeatures::default().with_dynamic_rendering(true);
    // SAFETY: the device comes from this physical device and outlives every ffvk object here;
    // the allocator was made for it.
    let device = unsafe {
        Device::from_caller_with_allocator(
            &plain.instance,
            plain.physical,
            plain.device.clone(),
            features,
            allocator.clone(),
        )
    }
    .unwrap();
    let mut lighting = Lighting::new(
        &device,
        &LightingOptions::new(Target::OFFSCREEN, VertexInput::interleaved()),
    )
    .unwrap();
    let gl = lit_state();
    lighting
        .prepare(&gl.lighting, RasterState::default(), false)
        .unwrap();
    lighting.begin_frame(0).unwrap();
    // Staging a draw writes its state block and record into ffvk's uniform memory.
    let buffers = [(ffvk::ash::vk::Buffer::null(), 0)];
    let draw = ffvk::LitDraw::new(
        &gl.lighting,
        Mat4::IDENTITY,
        Mat4::IDENTITY,
        &buffers,
        ffvk::Geometry::vertices(3),
    );
    lighting.stage_draw(0, &draw).unwrap();
    let held = names(&allocator);
    assert!(held.iter().any(|n| n == "embedder's vertices"), "{held:?}");
    let ffvk_held: Vec<&String> = held.iter().filter(|n| n.starts_with("ffvk: ")).collect();
    assert!(
        !ffvk_held.is_empty(),
        "ffvk took nothing from the allocator: {held:?}"
    );
    assert_eq!(device.memory_usage().live, ffvk_held.len(), "{held:?}");

    drop(lighting);
    assert_eq!(device.memory_usage().live, 0);
    drop(device);
    assert_eq!(names(&allocator), vec!["embedder's vertices".to_owned()]);
    allocator.lock().unwrap().free(own).unwrap();
    // The allocator goes before the device it allocates from.
    drop(allocator);
}
