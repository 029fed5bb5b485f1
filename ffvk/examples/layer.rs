//! An emulation layer's own pipelines lit by ffvk's shader library.
//!
//! A layer that generates its own shaders cannot draw with ffvk's pipelines; it includes the
//! library instead (`docs/shader-library.md`). Everything here but the library is the layer's:
//! its GLSL (`shaders/layer.vert`, `layer.frag`, `layer.glsl`), its per-draw uniform block, its
//! descriptor set with ffvk's state block at the binding it chose, its specialization
//! constants beside the library's (theirs from ID 100), its pipelines, and a stage ffvk does
//! not have (a vignette after fog, before the alpha test). The Vulkan device, the teapot's
//! buffers, the attachments and the readback are the embedding example's (`embed.rs`).
//!
//! ```sh
//! cargo run --release -p ffvk --features images --example layer    # writes out/layer/*.png
//! ```
//!
//! The test suite (`tests/suite/layer.rs`) holds its images to ffvk's own pipelines byte for
//! byte, its fog and alpha test to Mesa's GL, and its vignette to its own CPU expectation.

#[path = "embed.rs"]
#[allow(dead_code)]
mod embed;

use std::collections::hash_map::{Entry, HashMap};
use std::io::Write as _;

use ffvk::ash::vk;
use ffvk::gl::state::{FixedFunctionState, LightingMode};
use ffvk::gpu::layout::{DrawBlock, SpecConstant, SpecKey};
use ffvk::{PipelineConstants, Topology};

pub use embed::{projection, teapot, view, CLEAR, SIZE};

const LAYER_GLSL: &str = include_str!("shaders/layer.glsl");
const LAYER_VERT: &str = include_str!("shaders/layer.vert");
const LAYER_FRAG: &str = include_str!("shaders/layer.frag");

/// The layer's constants: `LAYER_VIGNETTE` at ID 0, `LAYER_HALF_SIZE` at ID 1 (`layer.glsl`).
const LAYER_CONSTANTS: u32 = 2;
/// Where the library's constants start (`FFVK_SPEC_BASE` in `layer.glsl`).
const LIBRARY_SPEC_BASE: u32 = 100;

/// One image the layer draws: the teapot under `state` (its lighting mode picks the shaders),
/// with or without the layer's vignette.
#[derive(Clone, Copy)]
pub struct LayerFrame {
    /// GL's state.
    pub state: FixedFunctionState,
    /// The layer's own stage on or off.
    pub vignette: bool,
}

/// The layer's vignette factor at window position (x, y) of a `size`-pixel square image, in
/// double precision: what the fragment stage's `vignette` computes, for a CPU expectation of
/// the layer's images.
pub fn vignette(x: f64, y: f64, size: u32) -> f64 {
    let half = size as f64 / 2.0;
    let d = ((x - half).powi(2) + (y - half).powi(2)).sqrt() / half;
    let t = ((d - 0.3) / (1.3 - 0.3)).clamp(0.0, 1.0);
    1.0 - 0.7 * (t * t * (3.0 - 2.0 * t))
}

/// Where the layer's shaders run.
pub enum ShaderTarget<'a> {
    /// Vulkan: GLSL 4.50, compiled to SPIR-V; the switches are specialization constants.
    Vulkan,
    /// OpenGL ES 3: GLSL ES 3.00 text, the library's `ffvk/es.glsl` first, the switches
    /// (`key`'s) and the layer's own values as defines.
    Es {
        /// The library's values, as `SpecKey::for_pipeline` gives them.
        key: &'a SpecKey,
        /// The layer's vignette on or off.
        vignette: bool,
        /// The image's width and height.
        size: u32,
    },
}

/// The layer's GLSL for `stage` ("vert" or "frag") in `mode` for `target`: the `#version`
/// line and the target's lines, the mode's defines, the layer's source with its own include
/// inlined, then the library's (`ffvk::shaders::resolve`, as for a compiler without
/// `#include`).
pub fn source(stage: &str, mode: LightingMode, target: &ShaderTarget) -> Result<String, String> {
    let body = match stage {
        "vert" => LAYER_VERT,
        "frag" => LAYER_FRAG,
        _ => {
            return Err(format!(
                "no layer shader for stage {stage:?} (expected vert or frag)"
            ))
        }
    };
    let mut text = String::new();
    match target {
        ShaderTarget::Vulkan => text.push_str("#version 450\n"),
        ShaderTarget::Es { key, vignette, size } => {
            text.push_str("#version 300 es\n#include \"ffvk/es.glsl\"\n");
            text.push_str(&ffvk::shaders::spec_defines(key));
            text.push_str(&format!(
                "#define LAYER_VALUE_VIGNETTE {}\n#define LAYER_VALUE_HALF_SIZE {:?}\n",
                i32::from(*vignette),
                *size as f32 / 2.0
            ));
        }
    }
    text.push_str(match mode {
        LightingMode::Fragment => "#define PER_FRAGMENT\n",
        LightingMode::Flat => "#define INTERP flat\n",
        _ => "#define INTERP smooth\n",
    });
    text.push_str(&body.replace("#include \"layer.glsl\"", LAYER_GLSL));
    ffvk::shaders::resolve(&text).map_err(|e| format!("layer.{stage}: {e}"))
}

/// The layer's Vulkan GLSL for `stage` in `mode` ([`source`]) compiled by glslc to SPIR-V
/// words.
pub fn compile(stage: &str, mode: LightingMode) -> Result<Vec<u32>, String> {
    let resolved = source(stage, mode, &ShaderTarget::Vulkan)?;
    let glslc = std::env::var_os("GLSLC").unwrap_or_else(|| "glslc".into());
    let mut child = std::process::Command::new(&glslc)
        .arg(format!("-fshader-stage={stage}"))
        .args(["--target-env=vulkan1.3", "-O0", "-Werror"])
        .args(["-o", "-", "-"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .map_err(|e| {
            format!(
                "running {}: {e} (Debian: apt install glslc)",
                glslc.to_string_lossy()
            )
        })?;
    child
        .stdin
        .take()
        .ok_or("glslc's stdin")?
        .write_all(resolved.as_bytes())
        .map_err(|e| format!("writing layer.{stage} to glslc: {e}"))?;
    let out = child.wait_with_output().map_err(|e| format!("glslc: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "glslc on layer.{stage} ({mode:?}): {}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    ffvk::ash::util::read_spv(&mut std::io::Cursor::new(&out.stdout))
        .map_err(|e| format!("glslc's SPIR-V: {e}"))
}

/// The layer's specialization data: the library's values (`SpecKey::for_pipeline`, each at
/// ID `LIBRARY_SPEC_BASE` + its own), then its own two, with the map entries for them.
fn specialization(key: &SpecKey, vignette: bool, size: u32) -> (Vec<vk::SpecializationMapEntry>, Vec<u8>) {
    let entry = |constant_id, offset| vk::SpecializationMapEntry {
        constant_id,
        offset,
        size: 4,
    };
    let library_bytes = std::mem::size_of_val(&key.values) as u32;
    let mut entries: Vec<_> = SpecConstant::ALL
        .iter()
        .map(|c| entry(LIBRARY_SPEC_BASE + c.id(), 4 * c.id()))
        .collect();
    entries.extend((0..LAYER_CONSTANTS).map(|id| entry(id, library_bytes + 4 * id)));
    let mut data = bytemuck::bytes_of(&key.values).to_vec();
    data.extend_from_slice(&i32::from(vignette).to_ne_bytes());
    data.extend_from_slice(&(size as f32 / 2.0).to_ne_bytes());
    (entries, data)
}

/// The layer's Vulkan objects for one frame, destroyed when it goes.
struct LayerObjects {
    device: ash::Device,
    modules: Vec<vk::ShaderModule>,
    set_layout: vk::DescriptorSetLayout,
    pool: vk::DescriptorPool,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
}

impl Drop for LayerObjects {
    fn drop(&mut self) {
        // SAFETY: created on this device; dropped after the frame's fence wait, when nothing
        // pending uses them; destroyed once, children first.
        unsafe {
            self.device.destroy_pipeline(self.pipeline, None);
            self.device.destroy_pipeline_layout(self.layout, None);
            self.device.destroy_descriptor_pool(self.pool, None);
            self.device.destroy_descriptor_set_layout(self.set_layout, None);
            for &m in &self.modules {
                self.device.destroy_shader_module(m, None);
            }
        }
    }
}

impl LayerObjects {
    /// The layer's set layout (its draw block at binding 0, ffvk's state block at binding 3),
    /// one set of it, and its pipeline for `frame` with the SPIR-V `shaders`.
    fn new(
        device: &ash::Device,
        shaders: &(Vec<u32>, Vec<u32>),
        frame: &LayerFrame,
        key: &SpecKey,
        size: u32,
    ) -> Result<(LayerObjects, vk::DescriptorSet), String> {
        let mut objects = LayerObjects {
            device: device.clone(),
            modules: Vec::new(),
            set_layout: vk::DescriptorSetLayout::null(),
            pool: vk::DescriptorPool::null(),
            layout: vk::PipelineLayout::null(),
            pipeline: vk::Pipeline::null(),
        };
        let stages = vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT;
        let bindings = [0, 3].map(|binding| {
            vk::DescriptorSetLayoutBinding::default()
                .binding(binding)
                .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                .descriptor_count(1)
                .stage_flags(stages)
        });
        let sizes = [vk::DescriptorPoolSize {
            ty: vk::DescriptorType::UNIFORM_BUFFER,
            descriptor_count: 2,
        }];
        // SAFETY: valid create infos on a live device; each handle is stored in `objects` as
        // soon as it exists, so that an early return destroys it.
        let set = unsafe {
            objects.set_layout = device
                .create_descriptor_set_layout(
                    &vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings),
                    None,
                )
                .map_err(|e| format!("vkCreateDescriptorSetLayout: {e}"))?;
            objects.pool = device
                .create_descriptor_pool(
                    &vk::DescriptorPoolCreateInfo::default()
                        .max_sets(1)
                        .pool_sizes(&sizes),
                    None,
                )
                .map_err(|e| format!("vkCreateDescriptorPool: {e}"))?;
            let layouts = [objects.set_layout];
            objects.layout = device
                .create_pipeline_layout(
                    &vk::PipelineLayoutCreateInfo::default().set_layouts(&layouts),
                    None,
                )
                .map_err(|e| format!("vkCreatePipelineLayout: {e}"))?;
            for words in [&shaders.0, &shaders.1] {
                let module = device
                    .create_shader_module(&vk::ShaderModuleCreateInfo::default().code(words), None)
                    .map_err(|e| format!("vkCreateShaderModule: {e}"))?;
                objects.modules.push(module);
            }
            device
                .allocate_descriptor_sets(
                    &vk::DescriptorSetAllocateInfo::default()
                        .descriptor_pool(objects.pool)
                        .set_layouts(&layouts),
                )
                .map_err(|e| format!("vkAllocateDescriptorSets: {e}"))?[0]
        };
        let (entries, data) = specialization(key, frame.vignette, size);
        let specialization = vk::SpecializationInfo::default()
            .map_entries(&entries)
            .data(&data);
        let shader_stages = [
            (vk::ShaderStageFlags::VERTEX, objects.modules[0]),
            (vk::ShaderStageFlags::FRAGMENT, objects.modules[1]),
        ]
        .map(|(stage, module)| {
            vk::PipelineShaderStageCreateInfo::default()
                .stage(stage)
                .module(module)
                .name(c"main")
                .specialization_info(&specialization)
        });
        // The teapot's buffers: positions in binding 0; normals and RGBA8 colors in binding 1.
        let vertex_bindings = [(0, 12), (1, 16)].map(|(binding, stride)| vk::VertexInputBindingDescription {
            binding,
            stride,
            input_rate: vk::VertexInputRate::VERTEX,
        });
        let attribute = |location, binding, format, offset| vk::VertexInputAttributeDescription {
            location,
            binding,
            format,
            offset,
        };
        let attributes = [
            attribute(0, 0, vk::Format::R32G32B32_SFLOAT, 0),
            attribute(1, 1, vk::Format::R32G32B32_SFLOAT, 0),
            attribute(2, 1, vk::Format::R8G8B8A8_UNORM, 12),
        ];
        let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&vertex_bindings)
            .vertex_attribute_descriptions(&attributes);
        let assembly = vk::PipelineInputAssemblyStateCreateInfo::default()
            .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let viewport = vk::PipelineViewportStateCreateInfo::default()
            .viewport_count(1)
            .scissor_count(1);
        // GL's flat shading takes a triangle's last vertex.
        let mut provoking = vk::PipelineRasterizationProvokingVertexStateCreateInfoEXT::default()
            .provoking_vertex_mode(vk::ProvokingVertexModeEXT::LAST_VERTEX);
        // StateBlock's projection flips y, so GL's counter-clockwise front faces stay
        // counter-clockwise in Vulkan's terms.
        let mut rasterization = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(vk::CullModeFlags::NONE)
            .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
            .line_width(1.0);
        if frame.state.mode == LightingMode::Flat {
            rasterization = rasterization.push_next(&mut provoking);
        }
        let multisample = vk::PipelineMultisampleStateCreateInfo::default()
            .rasterization_samples(vk::SampleCountFlags::TYPE_1);
        // GL's glEnable(GL_DEPTH_TEST) with its default GL_LESS.
        let depth = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(true)
            .depth_write_enable(true)
            .depth_compare_op(vk::CompareOp::LESS);
        let blend_attachments =
            [vk::PipelineColorBlendAttachmentState::default()
                .color_write_mask(vk::ColorComponentFlags::RGBA)];
        let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend_attachments);
        let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
        let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
        let color_formats = [embed::COLOR_FORMAT];
        let mut rendering = vk::PipelineRenderingCreateInfo::default()
            .color_attachment_formats(&color_formats)
            .depth_attachment_format(embed::DEPTH_FORMAT);
        let info = vk::GraphicsPipelineCreateInfo::default()
            .stages(&shader_stages)
            .vertex_input_state(&vertex_input)
            .input_assembly_state(&assembly)
            .viewport_state(&viewport)
            .rasterization_state(&rasterization)
            .multisample_state(&multisample)
            .depth_stencil_state(&depth)
            .color_blend_state(&blend)
            .dynamic_state(&dynamic)
            .layout(objects.layout)
            .push_next(&mut rendering);
        // SAFETY: the create info and everything it points to live through the call.
        let created = unsafe { device.create_graphics_pipelines(vk::PipelineCache::null(), &[info], None) };
        objects.pipeline = created.map_err(|(_, e)| format!("vkCreateGraphicsPipelines: {e}"))?[0];
        Ok((objects, set))
    }
}

/// Renders `frames` at `size`×`size` with the layer's pipelines on the device whose name
/// contains `device_name` (lavapipe by default); RGBA8 rows, top row first, one image per
/// frame. With `validation`, the Khronos validation layer is on and any message it reports is
/// an error.
pub fn render(
    device_name: Option<&str>,
    validation: bool,
    size: u32,
    frames: &[LayerFrame],
) -> Result<Vec<Vec<u8>>, String> {
    embed::with_app(device_name, validation, size, |app| {
        let scene = app.scene()?;
        let mut shaders: HashMap<LightingMode, (Vec<u32>, Vec<u32>)> = HashMap::new();
        let mut images = Vec::new();
        for frame in frames {
            let state = &frame.state;
            let (modelview, projection) = (view(), projection());
            // GL's state and the draw's values, checked and packed as ffvk packs its own.
            let block = DrawBlock::new(state, modelview, projection).map_err(|e| e.to_string())?;
            let draw_buffer = app.buffer(
                bytemuck::bytes_of(&block.record),
                vk::BufferUsageFlags::UNIFORM_BUFFER,
            )?;
            let state_buffer = app.buffer(
                bytemuck::bytes_of(&block.state),
                vk::BufferUsageFlags::UNIFORM_BUFFER,
            )?;
            let key = SpecKey::for_pipeline(
                state,
                modelview,
                &PipelineConstants::new(Topology::TriangleList, embed::COLOR_FORMAT),
            );
            let compiled = match shaders.entry(state.mode) {
                Entry::Occupied(known) => known.into_mut(),
                Entry::Vacant(new) => {
                    new.insert((compile("vert", state.mode)?, compile("frag", state.mode)?))
                }
            };
            let (objects, set) = LayerObjects::new(&app.device, compiled, frame, &key, size)?;
            let infos = [draw_buffer, state_buffer].map(|buffer| {
                [vk::DescriptorBufferInfo {
                    buffer,
                    offset: 0,
                    range: vk::WHOLE_SIZE,
                }]
            });
            let writes = [(0, &infos[0]), (3, &infos[1])].map(|(binding, info)| {
                vk::WriteDescriptorSet::default()
                    .dst_set(set)
                    .dst_binding(binding)
                    .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                    .buffer_info(info)
            });
            let d = &app.device;
            // SAFETY: the set is not in use; its buffers live as long as the app.
            unsafe { d.update_descriptor_sets(&writes, &[]) };
            app.begin(&scene)?;
            let buffers = scene.buffers.map(|(b, _)| b);
            // SAFETY: recording inside the pass `begin` started (viewport and scissor set), on
            // attachments of the pipeline's formats; every object lives past the fence wait in
            // `finish`.
            unsafe {
                d.cmd_bind_pipeline(app.cmd, vk::PipelineBindPoint::GRAPHICS, objects.pipeline);
                d.cmd_bind_descriptor_sets(
                    app.cmd,
                    vk::PipelineBindPoint::GRAPHICS,
                    objects.layout,
                    0,
                    &[set],
                    &[],
                );
                d.cmd_bind_vertex_buffers(app.cmd, 0, &buffers, &[0, 0]);
                d.cmd_bind_index_buffer(app.cmd, scene.index_buffer, 0, vk::IndexType::UINT32);
                d.cmd_draw_indexed(app.cmd, scene.index_count, 1, 0, 0, 0);
            }
            images.push(app.finish(&scene)?);
            drop(objects);
        }
        Ok(images)
    })
}

/// The frames `main` draws: the teapot in each lighting mode, then with GL's linear fog and an
/// alpha test that drops the back faces (their material's alpha is 0.25), without and with the
/// layer's vignette.
pub fn frames() -> Result<Vec<(String, LayerFrame)>, ffvk::Error> {
    let mut frames = Vec::new();
    for mode in LightingMode::ALL {
        let gl = embed::gl_state(mode)?;
        frames.push((
            format!("teapot_{}", mode.name()),
            LayerFrame {
                state: gl.lighting,
                vignette: false,
            },
        ));
    }
    for mode in [LightingMode::Vertex, LightingMode::Fragment] {
        let state = fogged_state(mode)?;
        for vignette in [false, true] {
            let name = format!(
                "fog_alpha_{}{}",
                mode.name(),
                if vignette { "_vignette" } else { "" }
            );
            frames.push((name, LayerFrame { state, vignette }));
        }
    }
    Ok(frames)
}

/// The embedding example's teapot state with GL's linear fog (from 2 to 4.5 eye units, to a
/// blue-grey) and the alpha test GL_GREATER 0.5, the back material's diffuse alpha 0.25: the
/// teapot's inside, seen through its opening, is dropped.
pub fn fogged_state(mode: LightingMode) -> Result<FixedFunctionState, ffvk::Error> {
    use ffvk::gl::state::{Cap, CompareFunc, Face, FogMode, FogParam, MaterialParam};
    use ffvk::glam::Vec4;
    let mut gl = embed::gl_state(mode)?;
    gl.enable(Cap::Fog)?;
    gl.fog(FogParam::Mode(FogMode::Linear))?;
    gl.fog(FogParam::Start(2.0))?;
    gl.fog(FogParam::End(4.5))?;
    gl.fog(FogParam::Color(Vec4::new(0.35, 0.4, 0.5, 1.0)))?;
    gl.enable(Cap::AlphaTest)?;
    gl.alpha_func(CompareFunc::Greater, 0.5)?;
    gl.material(
        Face::Back,
        MaterialParam::Diffuse(Vec4::new(0.78, 0.57, 0.11, 0.25)),
    )?;
    Ok(gl.lighting)
}

#[allow(dead_code)] // the test suite includes this file for `render` and `frames`
fn main() {
    let device = std::env::var("FFVK_DEVICE").ok();
    let validation = std::env::var_os("FFVK_VALIDATION").is_some_and(|v| v != "0");
    let run = || -> Result<(), String> {
        let frames = frames().map_err(|e| e.to_string())?;
        let only: Vec<LayerFrame> = frames.iter().map(|(_, f)| *f).collect();
        let images = render(device.as_deref(), validation, SIZE, &only)?;
        let out = std::path::Path::new("out/layer");
        for ((name, _), rgba) in frames.iter().zip(images) {
            let path = out.join(format!("{name}.png"));
            let image = ffvk::image::RgbaImage::from_raw(SIZE, SIZE, rgba)
                .ok_or_else(|| format!("{} is not {SIZE} x {SIZE} RGBA8", path.display()))?;
            ffvk::images::save_png(&image, &path).map_err(|e| e.to_string())?;
            println!("-> {}", path.display());
        }
        Ok(())
    };
    if let Err(e) = run() {
        eprintln!("layer: {e}");
        std::process::exit(1);
    }
}
