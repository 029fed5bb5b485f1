//! Embedding ffvk in your own Vulkan renderer.
//!
//! Everything Vulkan here is the caller's, made with plain `ash`: the instance, the device
//! and its queue, the command pool and buffer, the color and depth images, the vertex and
//! index buffers, the readback buffer and the fence. ffvk gets the device through
//! `ffvk::vk::Device::from_caller` and records GL's lighting into the caller's command buffer
//! with `ffvk::Lighting`; it never submits or waits.
//!
//! The teapot is drawn in the three lighting modes and written to `out/embed/`:
//!
//! ```sh
//! cargo run --release -p ffvk --features images --example embed            # lavapipe by default
//! FFVK_DEVICE=NVIDIA cargo run --release -p ffvk --features images --example embed
//! ```
//!
//! The vertex layout is the caller's own: positions in binding 0 (`R32G32B32_SFLOAT`),
//! normals and 8-bit colors interleaved in binding 1. The test suite renders the same
//! frames through `ffvk::Renderer` and requires identical bytes.

use std::ffi::{c_void, CStr};
use std::sync::Mutex;

use ffvk::ash::{ext, vk};
use ffvk::gl::state::{Cap, Face, GlState, LightModelParam, LightParam, LightingMode, MaterialParam};
use ffvk::glam::{Mat4, Vec3, Vec4};
use ffvk::mesh::MeshData;
use ffvk::vk::EnabledFeatures;
use ffvk::{
    Attribute, DrawValues, Geometry, Lighting, LightingOptions, LitDraw, RasterState, Target, VertexInput,
};

/// The size of the images `main` writes.
pub const SIZE: u32 = 256;
/// The clear color.
pub const CLEAR: [f32; 4] = [0.08, 0.08, 0.1, 1.0];
pub(crate) const COLOR_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;
pub(crate) const DEPTH_FORMAT: vk::Format = vk::Format::D32_SFLOAT;

/// The camera: eye space from world space.
pub fn view() -> Mat4 {
    Mat4::look_at_rh(Vec3::new(0.0, 1.2, 3.0), Vec3::new(0.0, -0.05, 0.0), Vec3::Y)
}

/// A GL projection (clip z in [-w, w]).
pub fn projection() -> Mat4 {
    Mat4::perspective_rh_gl(40f32.to_radians(), 1.0, 0.5, 10.0)
}

/// GL's state for the teapot, set through GL's entry points: a brass-like material, two
/// lights (a white directional key light and a warm positional fill), two-sided lighting.
pub fn gl_state(mode: LightingMode) -> Result<GlState, ffvk::Error> {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting)?;
    gl.enable(Cap::Light(0))?;
    gl.enable(Cap::Light(1))?;
    gl.lighting_mode(mode);
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Ambient(Vec4::new(0.33, 0.22, 0.03, 1.0)),
    )?;
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Diffuse(Vec4::new(0.78, 0.57, 0.11, 1.0)),
    )?;
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Specular(Vec4::new(0.99, 0.94, 0.81, 1.0)),
    )?;
    gl.material(Face::FrontAndBack, MaterialParam::Shininess(27.9))?;
    gl.light_model(LightModelParam::TwoSide(true))?;
    gl.load_modelview(view())?;
    gl.light(0, LightParam::Position(Vec4::new(1.0, 1.5, 1.2, 0.0)))?;
    gl.light(1, LightParam::Position(Vec4::new(-2.0, 0.5, 1.0, 1.0)))?;
    gl.light(1, LightParam::Diffuse(Vec4::new(0.6, 0.4, 0.3, 1.0)))?;
    gl.light(1, LightParam::LinearAttenuation(0.3))?;
    Ok(gl)
}

/// The teapot the example draws.
pub fn teapot() -> Result<MeshData, ffvk::MeshError> {
    ffvk::mesh::teapot::teapot(12)
}

/// One image: the teapot under `state`, with or without its color array (without one,
/// every vertex takes the state's current color, as after glColor in GL).
pub struct EmbedFrame {
    /// GL's state for the draw.
    pub state: ffvk::gl::state::FixedFunctionState,
    /// Whether the mesh has a color array (binding 1, 8-bit colors).
    pub color_array: bool,
    /// 0: one teapot. n: n × n small teapots in one run of draws, each with its own material
    /// and modelview ([`grid_objects`]) under the one shared `state`, as an emulation layer
    /// records a frame of many objects.
    pub grid: u32,
    /// How the teapot's indices are drawn: its triangles, or (say) one lit line strip through
    /// them, as `glDrawElements(GL_LINE_STRIP, …)` would.
    pub topology: ffvk::Topology,
}

/// The objects of an `n` × `n` frame under `state`: each teapot's modelview and its own values
/// (the state's, with a diffuse color and shininess of its own, as after a glMaterial call).
pub fn grid_objects(state: &ffvk::gl::state::FixedFunctionState, n: u32) -> Vec<(Mat4, DrawValues)> {
    let n = n.max(1);
    let cell = 2.4 / n as f32;
    (0..n * n)
        .map(|k| {
            let (i, j) = ((k % n) as f32, (k / n) as f32);
            let at = Vec3::new(
                -1.2 + cell * (i + 0.5),
                1.0 - cell * (j + 0.5),
                -0.4 * j / n as f32,
            );
            let modelview = view() * Mat4::from_translation(at) * Mat4::from_scale(Vec3::splat(cell * 0.45));
            let mut values = DrawValues::of(state);
            let t = k as f32 / (n * n) as f32;
            let diffuse = Vec4::new(0.2 + 0.8 * t, 0.9 - 0.7 * t, 0.3 + 0.5 * (1.0 - t), 1.0);
            values.front.diffuse = diffuse;
            values.back.diffuse = diffuse * 0.5;
            values.front.shininess = 5.0 + 100.0 * t;
            (modelview, values)
        })
        .collect()
}

/// Renders the teapot in each mode with its color array; see [`render_frames`].
pub fn render_modes(
    device_name: Option<&str>,
    validation: bool,
) -> Result<Vec<(LightingMode, Vec<u8>)>, String> {
    let frames = LightingMode::ALL
        .iter()
        .map(|&mode| {
            Ok(EmbedFrame {
                state: gl_state(mode).map_err(|e| e.to_string())?.lighting,
                color_array: true,
                grid: 0,
                topology: ffvk::Topology::TriangleList,
            })
        })
        .collect::<Result<Vec<_>, String>>()?;
    let images = render_frames(device_name, validation, SIZE, &frames)?;
    Ok(LightingMode::ALL.into_iter().zip(images).collect())
}

/// Runs `work` on a fresh [`App`] at `size` and fails with the validation layer's messages,
/// if it reported any, after the app (and so every Vulkan object) is gone.
pub(crate) fn with_app<T>(
    device_name: Option<&str>,
    validation: bool,
    size: u32,
    work: impl FnOnce(&mut App) -> Result<T, String>,
) -> Result<T, String> {
    let mut app = App::new(device_name, validation, size)?;
    let result = work(&mut app);
    let messages = app.messages();
    drop(app);
    let value = result?;
    if !messages.is_empty() {
        return Err(format!("validation messages:\n{}", messages.join("\n")));
    }
    Ok(value)
}

/// Renders `frames` at `size`×`size` on the device whose name contains `device_name`
/// (lavapipe by default); returns RGBA8 rows, top row first, one image per frame. With
/// `validation`, the Khronos validation layer is on and any message it reports is an error.
pub fn render_frames(
    device_name: Option<&str>,
    validation: bool,
    size: u32,
    frames: &[EmbedFrame],
) -> Result<Vec<Vec<u8>>, String> {
    render_frames_in_set(device_name, validation, size, 0, frames)
}

/// [`render_frames`] recorded as a GL program issues its draws: one `Lighting::draw` per draw,
/// with commands of the caller's own between them (the scissor set again before every draw;
/// before every other draw, the caller's own vertex and index buffers bound over ffvk's, then
/// `Lighting::forget_bindings`), so that ffvk binds only what its draw needs anew.
pub fn render_frames_draw_by_draw(
    device_name: Option<&str>,
    validation: bool,
    size: u32,
    frames: &[EmbedFrame],
) -> Result<Vec<Vec<u8>>, String> {
    with_app(device_name, validation, size, |app| app.render(frames, 0, true))
}

/// An `n` × `n` grid under `state` drawn one `Lighting::draw` at a time into one command
/// buffer, alternating between two `Lighting`s of one device (the layout with the color array,
/// and the one without), as a layer with a `Lighting` per vertex layout records; with
/// `forget_each`, `forget_bindings` before every draw (everything bound anew each time).
pub fn render_alternating(
    device_name: Option<&str>,
    validation: bool,
    state: &ffvk::gl::state::FixedFunctionState,
    n: u32,
    forget_each: bool,
) -> Result<Vec<u8>, String> {
    with_app(device_name, validation, SIZE, |app| {
        app.render_alternating(state, n, forget_each)
    })
}

/// [`render_frames`] with ffvk's uniform block at descriptor set `set_index`, as a renderer
/// whose own shaders use the lower sets would ask.
pub fn render_frames_in_set(
    device_name: Option<&str>,
    validation: bool,
    size: u32,
    set_index: u32,
    frames: &[EmbedFrame],
) -> Result<Vec<Vec<u8>>, String> {
    with_app(device_name, validation, size, |app| {
        app.render(frames, set_index, false)
    })
}

#[allow(dead_code)] // the test suite includes this file for render_modes
fn main() {
    let device = std::env::var("FFVK_DEVICE").ok();
    let validation = std::env::var_os("FFVK_VALIDATION").is_some_and(|v| v != "0");
    let images = match render_modes(device.as_deref(), validation) {
        Ok(images) => images,
        Err(e) => {
            eprintln!("embed: {e}");
            std::process::exit(1);
        }
    };
    // One more frame in vertex mode: `normalize` for scaled-down teapots, `grid` and
    // `topology` as EmbedFrame says. A failure ends the example.
    let one = |normalize: bool, grid: u32, topology: ffvk::Topology| {
        let rendered = gl_state(LightingMode::Vertex)
            .map_err(|e| e.to_string())
            .and_then(|mut gl| {
                if normalize {
                    gl.enable(Cap::Normalize).map_err(|e| e.to_string())?;
                }
                let frame = EmbedFrame {
                    state: gl.lighting,
                    color_array: true,
                    grid,
                    topology,
                };
                render_frames(device.as_deref(), validation, SIZE, &[frame])
            });
        match rendered {
            Ok(mut images) => images.pop().unwrap_or_default(),
            Err(e) => {
                eprintln!("embed: {e}");
                std::process::exit(1);
            }
        }
    };
    // A frame of 64 teapots with a material each, under one shared state, in one run (scaled
    // down: GL_NORMALIZE keeps their normals unit length).
    let grid = one(true, 8, ffvk::Topology::TriangleList);
    // The teapot's indices drawn as one lit line strip (glDrawElements(GL_LINE_STRIP)).
    let strip = one(false, 0, ffvk::Topology::LineStrip);
    let out = std::path::Path::new("out/embed");
    let named = images
        .into_iter()
        .map(|(mode, rgba)| (format!("teapot_{}.png", mode.name()), rgba))
        .chain([
            ("teapots_8x8.png".to_string(), grid),
            ("teapot_line_strip.png".to_string(), strip),
        ]);
    for (name, rgba) in named {
        let path = out.join(name);
        let Some(image) = image::RgbaImage::from_raw(SIZE, SIZE, rgba) else {
            eprintln!("embed: {} is not {SIZE} x {SIZE} RGBA8", path.display());
            std::process::exit(1);
        };
        if let Err(e) = ffvk::images::save_png(&image, &path) {
            eprintln!("embed: {e}");
            std::process::exit(1);
        }
        println!("-> {}", path.display());
    }
}

/// Host time per draw to record runs through `Lighting::draw_run`, in ns, one entry per frame.
#[derive(Debug, Default)]
pub struct RecordTimes {
    /// Draws sharing one state, each with its own values (materials) and modelview.
    pub shared_state_own_values: Vec<f64>,
    /// Draws sharing one state, each with only its own modelview.
    pub modelview_only: Vec<f64>,
    /// Draws each with a whole state of its own (its material in it).
    pub state_each: Vec<f64>,
}

/// How long recording costs an emulation layer: runs of `objects` draws, each its own draw
/// command (a triangle of its own), recorded `frames` times after one warm-up frame and never
/// submitted, on the device whose name contains `device_name`.
pub fn record_times(device_name: Option<&str>, objects: u32, frames: u32) -> Result<RecordTimes, String> {
    let mut app = App::new(device_name, false, SIZE)?;
    app.time_runs(objects, frames)
}

/// What a frame draws with and into.
pub(crate) struct Scene {
    /// Positions (binding 0); normals and colors (binding 1).
    pub(crate) buffers: [(vk::Buffer, u64); 2],
    pub(crate) index_buffer: vk::Buffer,
    pub(crate) index_count: u32,
    readback: vk::Buffer,
    color: (vk::Image, vk::ImageView),
    depth: (vk::Image, vk::ImageView),
}

/// A buffer or image's memory.
struct Allocation {
    memory: vk::DeviceMemory,
}

/// The caller's renderer: every Vulkan object is created and destroyed here.
pub(crate) struct App {
    _entry: ash::Entry,
    instance: ash::Instance,
    messenger: Option<(ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    messages: Box<Mutex<Vec<String>>>,
    physical: vk::PhysicalDevice,
    pub(crate) device: ash::Device,
    /// VK_EXT_line_rasterization's Bresenham lines are enabled: GL's aliased lines.
    bresenham_lines: bool,
    queue: vk::Queue,
    pool: vk::CommandPool,
    pub(crate) cmd: vk::CommandBuffer,
    fence: vk::Fence,
    images: Vec<(vk::Image, vk::ImageView, Allocation)>,
    buffers: Vec<(vk::Buffer, Allocation)>,
    /// Width and height of the images.
    size: u32,
}

unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _kind: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    if severity.contains(vk::DebugUtilsMessageSeverityFlagsEXT::ERROR)
        || severity.contains(vk::DebugUtilsMessageSeverityFlagsEXT::WARNING)
    {
        // SAFETY: the layer passes valid callback data; user is the App's boxed Mutex,
        // alive until the messenger is destroyed.
        let (text, sink) = unsafe {
            (
                CStr::from_ptr((*data).p_message).to_string_lossy().into_owned(),
                &*(user as *const Mutex<Vec<String>>),
            )
        };
        if let Ok(mut m) = sink.lock() {
            m.push(text);
        }
    }
    vk::FALSE
}

impl App {
    fn new(device_name: Option<&str>, validation: bool, size: u32) -> Result<Self, String> {
        // SAFETY: loads the system's Vulkan loader.
        let entry = unsafe { ash::Entry::load() }.map_err(|e| e.to_string())?;
        let layers = [c"VK_LAYER_KHRONOS_validation".as_ptr()];
        let extensions = [ext::debug_utils::NAME.as_ptr()];
        let app = vk::ApplicationInfo::default().api_version(vk::API_VERSION_1_3);
        let mut info = vk::InstanceCreateInfo::default().application_info(&app);
        if validation {
            info = info
                .enabled_layer_names(&layers)
                .enabled_extension_names(&extensions);
        }
        // SAFETY: the create info and its strings outlive the call.
        let instance =
            unsafe { entry.create_instance(&info, None) }.map_err(|e| format!("vkCreateInstance: {e}"))?;
        let messages = Box::new(Mutex::new(Vec::new()));
        let messenger = if validation {
            let loader = ext::debug_utils::Instance::new(&entry, &instance);
            let info = vk::DebugUtilsMessengerCreateInfoEXT::default()
                .message_severity(
                    vk::DebugUtilsMessageSeverityFlagsEXT::ERROR
                        | vk::DebugUtilsMessageSeverityFlagsEXT::WARNING,
                )
                .message_type(
                    vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                        | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION,
                )
                .pfn_user_callback(Some(on_message))
                .user_data(&*messages as *const Mutex<Vec<String>> as *mut c_void);
            // SAFETY: the user data is boxed and outlives the messenger (destroyed in Drop).
            let m = unsafe { loader.create_debug_utils_messenger(&info, None) }
                .map_err(|e| format!("vkCreateDebugUtilsMessengerEXT: {e}"))?;
            Some((loader, m))
        } else {
            None
        };

        // SAFETY: the instance is alive.
        let physicals = unsafe { instance.enumerate_physical_devices() }.map_err(|e| e.to_string())?;
        let wanted = device_name.unwrap_or("llvmpipe").to_lowercase();
        let physical = physicals
            .iter()
            .copied()
            .find(|&p| {
                // SAFETY: p comes from the enumeration.
                let props = unsafe { instance.get_physical_device_properties(p) };
                props
                    .device_name_as_c_str()
                    .is_ok_and(|n| n.to_string_lossy().to_lowercase().contains(&wanted))
            })
            .ok_or_else(|| format!("no Vulkan device named like {wanted:?}"))?;
        // SAFETY: physical is valid.
        let families = unsafe { instance.get_physical_device_queue_family_properties(physical) };
        let family = families
            .iter()
            .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
            .ok_or("no graphics queue")? as u32;
        let priorities = [1.0];
        let queues = [vk::DeviceQueueCreateInfo::default()
            .queue_family_index(family)
            .queue_priorities(&priorities)];
        // GL draws its lines by the diamond-exit rule: Bresenham lines, where the device has them.
        // SAFETY: physical is valid.
        let bresenham_lines = unsafe { instance.enumerate_device_extension_properties(physical) }
            .map_err(|e| e.to_string())?
            .iter()
            .any(|e| e.extension_name_as_c_str() == Ok(ext::line_rasterization::NAME));
        let mut device_extensions = vec![ext::provoking_vertex::NAME.as_ptr()];
        if bresenham_lines {
            device_extensions.push(ext::line_rasterization::NAME.as_ptr());
        }
        let mut v13 = vk::PhysicalDeviceVulkan13Features::default()
            .dynamic_rendering(true)
            .synchronization2(true);
        let mut provoking =
            vk::PhysicalDeviceProvokingVertexFeaturesEXT::default().provoking_vertex_last(true);
        let mut lines = vk::PhysicalDeviceLineRasterizationFeaturesEXT::default()
            .bresenham_lines(true)
            .stippled_bresenham_lines(true);
        let mut info = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_extension_names(&device_extensions)
            .push_next(&mut v13)
            .push_next(&mut provoking);
        if bresenham_lines {
            info = info.push_next(&mut lines);
        }
        // SAFETY: the create info and what it points to outlive the call.
        let device = unsafe { instance.create_device(physical, &info, None) }
            .map_err(|e| format!("vkCreateDevice: {e}"))?;
        // SAFETY: family and index 0 were requested.
        let queue = unsafe { device.get_device_queue(family, 0) };
        let pool_info = vk::CommandPoolCreateInfo::default()
            .queue_family_index(family)
            .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
        // SAFETY: valid create infos on a live device.
        let (pool, fence) = unsafe {
            (
                device
                    .create_command_pool(&pool_info, None)
                    .map_err(|e| e.to_string())?,
                device
                    .create_fence(&vk::FenceCreateInfo::default(), None)
                    .map_err(|e| e.to_string())?,
            )
        };
        let alloc = vk::CommandBufferAllocateInfo::default()
            .command_pool(pool)
            .level(vk::CommandBufferLevel::PRIMARY)
            .command_buffer_count(1);
        // SAFETY: the pool is alive.
        let cmd = unsafe { device.allocate_command_buffers(&alloc) }.map_err(|e| e.to_string())?[0];
        Ok(App {
            _entry: entry,
            instance,
            messenger,
            messages,
            physical,
            device,
            bresenham_lines,
            queue,
            pool,
            cmd,
            fence,
            images: Vec::new(),
            buffers: Vec::new(),
            size,
        })
    }

    fn messages(&self) -> Vec<String> {
        self.messages.lock().map(|m| m.clone()).unwrap_or_default()
    }

    fn memory(
        &self,
        req: vk::MemoryRequirements,
        flags: vk::MemoryPropertyFlags,
    ) -> Result<Allocation, String> {
        // SAFETY: physical is valid.
        let props = unsafe { self.instance.get_physical_device_memory_properties(self.physical) };
        let index = (0..props.memory_type_count)
            .find(|&i| {
                req.memory_type_bits & (1 << i) != 0
                    && props.memory_types[i as usize].property_flags.contains(flags)
            })
            .ok_or("no suitable memory type")?;
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(req.size)
            .memory_type_index(index);
        // SAFETY: a valid allocate info.
        let memory = unsafe { self.device.allocate_memory(&info, None) }.map_err(|e| e.to_string())?;
        Ok(Allocation { memory })
    }

    /// A host-visible buffer holding `bytes`.
    pub(crate) fn buffer(&mut self, bytes: &[u8], usage: vk::BufferUsageFlags) -> Result<vk::Buffer, String> {
        let info = vk::BufferCreateInfo::default()
            .size(bytes.len().max(4) as u64)
            .usage(usage);
        // SAFETY: a valid create info.
        let buffer = unsafe { self.device.create_buffer(&info, None) }.map_err(|e| e.to_string())?;
        // SAFETY: the buffer is alive.
        let req = unsafe { self.device.get_buffer_memory_requirements(buffer) };
        let memory = self.memory(
            req,
            vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
        )?;
        // SAFETY: fresh memory of the required size; mapped once to fill it.
        unsafe {
            self.device
                .bind_buffer_memory(buffer, memory.memory, 0)
                .map_err(|e| e.to_string())?;
            let ptr = self
                .device
                .map_memory(memory.memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .map_err(|e| e.to_string())?;
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr as *mut u8, bytes.len());
            self.device.unmap_memory(memory.memory);
        }
        self.buffers.push((buffer, memory));
        Ok(buffer)
    }

    fn image(
        &mut self,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
    ) -> Result<(vk::Image, vk::ImageView), String> {
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D {
                width: self.size,
                height: self.size,
                depth: 1,
            })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .usage(usage);
        // SAFETY: a valid create info.
        let image = unsafe { self.device.create_image(&info, None) }.map_err(|e| e.to_string())?;
        // SAFETY: the image is alive.
        let req = unsafe { self.device.get_image_memory_requirements(image) };
        let memory = self
            .memory(req, vk::MemoryPropertyFlags::DEVICE_LOCAL)
            .or_else(|_| self.memory(req, vk::MemoryPropertyFlags::empty()))?;
        // SAFETY: fresh memory of the required size.
        unsafe { self.device.bind_image_memory(image, memory.memory, 0) }.map_err(|e| e.to_string())?;
        let view_info = vk::ImageViewCreateInfo::default()
            .image(image)
            .view_type(vk::ImageViewType::TYPE_2D)
            .format(format)
            .subresource_range(range(aspect));
        // SAFETY: the image is bound.
        let view = unsafe { self.device.create_image_view(&view_info, None) }.map_err(|e| e.to_string())?;
        self.images.push((image, view, memory));
        Ok((image, view))
    }

    /// The teapot's buffers, the readback buffer and the attachments, made on this device.
    pub(crate) fn scene(&mut self) -> Result<Scene, String> {
        // The caller's vertex data: positions alone, then normals with 8-bit colors.
        let mesh = teapot().map_err(|e| e.to_string())?;
        let positions: Vec<[f32; 3]> = mesh.vertices.iter().map(|v| v.position).collect();
        let mut normal_color = Vec::with_capacity(mesh.vertices.len() * 16);
        for v in &mesh.vertices {
            normal_color.extend_from_slice(bytemuck::cast_slice(&v.normal));
            normal_color.extend(v.color.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8));
        }
        let position_buffer = self.buffer(
            bytemuck::cast_slice(&positions),
            vk::BufferUsageFlags::VERTEX_BUFFER,
        )?;
        let normal_buffer = self.buffer(&normal_color, vk::BufferUsageFlags::VERTEX_BUFFER)?;
        let index_buffer = self.buffer(
            bytemuck::cast_slice(&mesh.indices),
            vk::BufferUsageFlags::INDEX_BUFFER,
        )?;
        let readback = self.buffer(
            &vec![0; (self.size * self.size * 4) as usize],
            vk::BufferUsageFlags::TRANSFER_DST,
        )?;
        let (color, color_view) = self.image(
            COLOR_FORMAT,
            vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
            vk::ImageAspectFlags::COLOR,
        )?;
        let (depth, depth_view) = self.image(
            DEPTH_FORMAT,
            vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
            vk::ImageAspectFlags::DEPTH,
        )?;
        Ok(Scene {
            buffers: [(position_buffer, 0), (normal_buffer, 0)],
            index_buffer,
            index_count: mesh.indices.len() as u32,
            readback,
            color: (color, color_view),
            depth: (depth, depth_view),
        })
    }

    /// ffvk on this device: the device wrapped, and a `Lighting` for the vertex layout with
    /// the color array and one without (GL's current color), the block at `set_index`.
    fn lightings(
        &self,
        set_index: u32,
    ) -> Result<(std::sync::Arc<ffvk::vk::Device>, Lighting, Lighting), String> {
        let mut features = EnabledFeatures::default();
        features.dynamic_rendering = true;
        features.provoking_vertex_last = true;
        features.stippled_lines = self.bresenham_lines;
        // SAFETY: the device was made from this physical device of this instance with these
        // features, and outlives the returned device (the caller drops it before `self`).
        let ffvk_device = unsafe {
            ffvk::vk::Device::from_caller(&self.instance, self.physical, self.device.clone(), features)
        }
        .map_err(|e| e.to_string())?;
        // Positions in binding 0; normals and RGBA8 colors interleaved in binding 1.
        let binding = |binding, stride| vk::VertexInputBindingDescription {
            binding,
            stride,
            input_rate: vk::VertexInputRate::VERTEX,
        };
        let without_colors = VertexInput::new(
            vec![binding(0, 12), binding(1, 16)],
            Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
            Attribute::new(1, 0, vk::Format::R32G32B32_SFLOAT),
        );
        // The same buffers with the color attribute; without it, GL's current color.
        let vertex_input =
            without_colors
                .clone()
                .with_color(Some(Attribute::new(1, 12, vk::Format::R8G8B8A8_UNORM)));
        let target = Target::new(COLOR_FORMAT, DEPTH_FORMAT);
        let options = |vertex_input| {
            let mut options = LightingOptions::new(target, vertex_input);
            options.set_index = set_index;
            options
        };
        let with_color_array =
            Lighting::new(&ffvk_device, &options(vertex_input)).map_err(|e| e.to_string())?;
        let with_current_color =
            Lighting::new(&ffvk_device, &options(without_colors)).map_err(|e| e.to_string())?;
        Ok((ffvk_device, with_color_array, with_current_color))
    }

    fn render(
        &mut self,
        frames: &[EmbedFrame],
        set_index: u32,
        by_draw: bool,
    ) -> Result<Vec<Vec<u8>>, String> {
        let scene = self.scene()?;
        let (ffvk_device, mut with_color_array, mut with_current_color) = self.lightings(set_index)?;
        let mut raster = RasterState::default();
        raster.depth_test = true;

        let mut images = Vec::new();
        for frame in frames {
            let lighting = if frame.color_array {
                &mut with_color_array
            } else {
                &mut with_current_color
            };
            lighting.begin_frame(0).map_err(|e| e.to_string())?;
            self.begin(&scene)?;
            let geometry = Geometry::indexed(scene.index_buffer, vk::IndexType::UINT32, scene.index_count)
                .with_topology(frame.topology);
            let buffers = &scene.buffers;
            let draws: Vec<LitDraw> = if frame.grid == 0 {
                vec![LitDraw::new(&frame.state, view(), projection(), buffers, geometry).with_raster(raster)]
            } else {
                // Many objects under one state: each draw carries only its modelview and its
                // own values, and borrows the state it shares with the others.
                grid_objects(&frame.state, frame.grid)
                    .into_iter()
                    .map(|(modelview, values)| {
                        LitDraw::new(&frame.state, modelview, projection(), buffers, geometry)
                            .with_raster(raster)
                            .with_values(Some(values))
                    })
                    .collect()
            };
            if by_draw {
                self.draw_by_draw(lighting, &scene, &draws)?;
            } else {
                // One run: an emulation layer passes all the draws it records back to back,
                // and ffvk binds only what changes between them (draws of one mesh become
                // instances).
                // SAFETY: cmd is recording inside the rendering pass `begin` started on
                // attachments of the target's formats, viewport and scissor set; the buffers
                // live until after the fence wait below; slot 0 is free (the last frame was
                // waited for).
                unsafe { lighting.draw_run(self.cmd, 0, &draws) }.map_err(|e| e.to_string())?;
            }
            images.push(self.finish(&scene)?);
        }
        drop(with_color_array);
        drop(with_current_color);
        drop(ffvk_device);
        Ok(images)
    }

    fn render_alternating(
        &mut self,
        state: &ffvk::gl::state::FixedFunctionState,
        n: u32,
        forget_each: bool,
    ) -> Result<Vec<u8>, String> {
        let scene = self.scene()?;
        let (ffvk_device, mut with_colors, mut without_colors) = self.lightings(0)?;
        let mut raster = RasterState::default();
        raster.depth_test = true;
        with_colors.begin_frame(0).map_err(|e| e.to_string())?;
        without_colors.begin_frame(0).map_err(|e| e.to_string())?;
        self.begin(&scene)?;
        let geometry = Geometry::indexed(scene.index_buffer, vk::IndexType::UINT32, scene.index_count);
        for (i, (modelview, values)) in grid_objects(state, n).into_iter().enumerate() {
            let lighting = if i % 2 == 0 {
                &mut with_colors
            } else {
                &mut without_colors
            };
            if forget_each {
                lighting.forget_bindings();
            }
            let draw = LitDraw::new(state, modelview, projection(), &scene.buffers, geometry)
                .with_raster(raster)
                .with_values(Some(values));
            // SAFETY: as in `render`; both lightings are of this device and its slot 0 is free.
            unsafe { lighting.draw(self.cmd, 0, &draw) }.map_err(|e| format!("draw {i}: {e}"))?;
        }
        let image = self.finish(&scene)?;
        drop(with_colors);
        drop(without_colors);
        drop(ffvk_device);
        Ok(image)
    }

    /// Records `draws` one `Lighting::draw` each, with the caller's own commands between them
    /// (see [`render_frames_draw_by_draw`]).
    fn draw_by_draw(&self, lighting: &mut Lighting, scene: &Scene, draws: &[LitDraw]) -> Result<(), String> {
        let d = &self.device;
        let area = vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: self.size,
                height: self.size,
            },
        };
        for (i, draw) in draws.iter().enumerate() {
            // SAFETY: cmd is recording inside the rendering pass `begin` started; the buffers
            // are the scene's, alive until after the fence wait.
            unsafe {
                d.cmd_set_scissor(self.cmd, 0, &[area]);
                if i % 2 == 1 {
                    // Buffers of the caller's own at ffvk's bindings (as its own draws would
                    // bind them): ffvk must bind its own again.
                    d.cmd_bind_vertex_buffers(self.cmd, 0, &[scene.buffers[1].0], &[0]);
                    d.cmd_bind_index_buffer(self.cmd, scene.index_buffer, 12, vk::IndexType::UINT32);
                    lighting.forget_bindings();
                }
            }
            // SAFETY: as in `render`; what the caller bound is forgotten above.
            unsafe { lighting.draw(self.cmd, 0, draw) }.map_err(|e| format!("draw {i}: {e}"))?;
        }
        Ok(())
    }

    /// Host time to record runs of `objects` draws (see [`record_times`]), `frames` of each kind.
    fn time_runs(&mut self, objects: u32, frames: u32) -> Result<RecordTimes, String> {
        let scene = self.scene()?;
        let (ffvk_device, mut lighting, _) = self.lightings(0)?;
        let mut gl = gl_state(LightingMode::Vertex).map_err(|e| e.to_string())?;
        gl.enable(Cap::Normalize).map_err(|e| e.to_string())?;
        let state = gl.lighting;
        let grid = (f64::from(objects).sqrt().ceil() as u32).max(1);
        let objects_here: Vec<(Mat4, DrawValues)> = grid_objects(&state, grid)
            .into_iter()
            .take(objects as usize)
            .collect();
        // A triangle of its own per draw: no two draws merge, each is a command.
        let triangles = scene.index_count / 3;
        let geometry = |k: usize| {
            Geometry::indexed(scene.index_buffer, vk::IndexType::UINT32, 3)
                .with_first(3 * (k as u32 % triangles))
        };
        let states: Vec<ffvk::gl::state::FixedFunctionState> = objects_here
            .iter()
            .map(|(_, v)| {
                let mut own = state;
                (own.front, own.back, own.current_color) = (v.front, v.back, v.current_color);
                own
            })
            .collect();
        let buffers = &scene.buffers;
        let shared: Vec<LitDraw> = objects_here
            .iter()
            .enumerate()
            .map(|(k, (mv, v))| {
                LitDraw::new(&state, *mv, projection(), buffers, geometry(k)).with_values(Some(*v))
            })
            .collect();
        let modelview_only: Vec<LitDraw> = objects_here
            .iter()
            .enumerate()
            .map(|(k, (mv, _))| LitDraw::new(&state, *mv, projection(), buffers, geometry(k)))
            .collect();
        let state_each: Vec<LitDraw> = objects_here
            .iter()
            .zip(&states)
            .enumerate()
            .map(|(k, ((mv, _), own))| LitDraw::new(own, *mv, projection(), buffers, geometry(k)))
            .collect();
        let mut times = RecordTimes::default();
        for (draws, out) in [
            (&shared, &mut times.shared_state_own_values),
            (&modelview_only, &mut times.modelview_only),
            (&state_each, &mut times.state_each),
        ] {
            // One frame first: the pipeline is made and the frame slot's memory grows.
            for frame in 0..=frames {
                lighting.begin_frame(0).map_err(|e| e.to_string())?;
                self.begin(&scene)?;
                let start = std::time::Instant::now();
                // SAFETY: as in `render`; the command buffer is never submitted, and is reset
                // by the next `begin`.
                unsafe { lighting.draw_run(self.cmd, 0, draws) }.map_err(|e| e.to_string())?;
                let ns = start.elapsed().as_nanos() as f64;
                // SAFETY: ends the pass `begin` started and the recording.
                unsafe {
                    self.device.cmd_end_rendering(self.cmd);
                    self.device
                        .end_command_buffer(self.cmd)
                        .map_err(|e| e.to_string())?;
                }
                if frame > 0 {
                    out.push(ns / draws.len().max(1) as f64);
                }
            }
        }
        drop(lighting);
        drop(ffvk_device);
        Ok(times)
    }

    /// Begins the command buffer and the rendering pass: clear color and depth.
    pub(crate) fn begin(&self, scene: &Scene) -> Result<(), String> {
        let ((color, color_view), (depth, depth_view)) = (scene.color, scene.depth);
        let d = &self.device;
        let barriers = [
            vk::ImageMemoryBarrier2::default()
                .src_stage_mask(vk::PipelineStageFlags2::ALL_COMMANDS)
                .src_access_mask(vk::AccessFlags2::MEMORY_READ | vk::AccessFlags2::MEMORY_WRITE)
                .dst_stage_mask(vk::PipelineStageFlags2::COLOR_ATTACHMENT_OUTPUT)
                .dst_access_mask(vk::AccessFlags2::COLOR_ATTACHMENT_WRITE)
                .old_layout(vk::ImageLayout::UNDEFINED)
                .new_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                .image(color)
                .subresource_range(range(vk::ImageAspectFlags::COLOR)),
            vk::ImageMemoryBarrier2::default()
                .src_stage_mask(vk::PipelineStageFlags2::ALL_COMMANDS)
                .src_access_mask(vk::AccessFlags2::MEMORY_READ | vk::AccessFlags2::MEMORY_WRITE)
                .dst_stage_mask(
                    vk::PipelineStageFlags2::EARLY_FRAGMENT_TESTS
                        | vk::PipelineStageFlags2::LATE_FRAGMENT_TESTS,
                )
                .dst_access_mask(
                    vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_READ
                        | vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_WRITE,
                )
                .old_layout(vk::ImageLayout::UNDEFINED)
                .new_layout(vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL)
                .image(depth)
                .subresource_range(range(vk::ImageAspectFlags::DEPTH)),
        ];
        let color_attachment = [vk::RenderingAttachmentInfo::default()
            .image_view(color_view)
            .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::STORE)
            .clear_value(vk::ClearValue {
                color: vk::ClearColorValue { float32: CLEAR },
            })];
        let depth_attachment = vk::RenderingAttachmentInfo::default()
            .image_view(depth_view)
            .image_layout(vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::DONT_CARE)
            .clear_value(vk::ClearValue {
                depth_stencil: vk::ClearDepthStencilValue {
                    depth: 1.0,
                    stencil: 0,
                },
            });
        let area = vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: self.size,
                height: self.size,
            },
        };
        let rendering = vk::RenderingInfo::default()
            .render_area(area)
            .layer_count(1)
            .color_attachments(&color_attachment)
            .depth_attachment(&depth_attachment);
        let viewport = vk::Viewport {
            x: 0.0,
            y: 0.0,
            width: self.size as f32,
            height: self.size as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        };
        // SAFETY: the command buffer is not pending (every submission is waited for).
        unsafe {
            d.reset_command_buffer(self.cmd, vk::CommandBufferResetFlags::empty())
                .map_err(|e| e.to_string())?;
            d.begin_command_buffer(self.cmd, &vk::CommandBufferBeginInfo::default())
                .map_err(|e| e.to_string())?;
            d.cmd_pipeline_barrier2(
                self.cmd,
                &vk::DependencyInfo::default().image_memory_barriers(&barriers),
            );
            d.cmd_begin_rendering(self.cmd, &rendering);
            d.cmd_set_viewport(self.cmd, 0, &[viewport]);
            d.cmd_set_scissor(self.cmd, 0, &[area]);
        }
        Ok(())
    }

    /// Ends the pass, copies the image out, submits, waits and returns the pixels.
    pub(crate) fn finish(&self, scene: &Scene) -> Result<Vec<u8>, String> {
        let (color, readback) = (scene.color.0, scene.readback);
        let d = &self.device;
        let to_transfer = [vk::ImageMemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::COLOR_ATTACHMENT_OUTPUT)
            .src_access_mask(vk::AccessFlags2::COLOR_ATTACHMENT_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags2::COPY)
            .dst_access_mask(vk::AccessFlags2::TRANSFER_READ)
            .old_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .new_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)
            .image(color)
            .subresource_range(range(vk::ImageAspectFlags::COLOR))];
        let to_host = [vk::BufferMemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::COPY)
            .src_access_mask(vk::AccessFlags2::TRANSFER_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags2::HOST)
            .dst_access_mask(vk::AccessFlags2::HOST_READ)
            .buffer(readback)
            .size(vk::WHOLE_SIZE)];
        let region = vk::BufferImageCopy {
            image_subresource: vk::ImageSubresourceLayers {
                aspect_mask: vk::ImageAspectFlags::COLOR,
                mip_level: 0,
                base_array_layer: 0,
                layer_count: 1,
            },
            image_extent: vk::Extent3D {
                width: self.size,
                height: self.size,
                depth: 1,
            },
            ..Default::default()
        };
        let buffers = [self.cmd];
        let submit = vk::SubmitInfo::default().command_buffers(&buffers);
        // SAFETY: recording inside the pass begun by `begin`; the copy reads the attachment
        // after the barrier; the submission is waited for before anything is reused.
        unsafe {
            d.cmd_end_rendering(self.cmd);
            d.cmd_pipeline_barrier2(
                self.cmd,
                &vk::DependencyInfo::default().image_memory_barriers(&to_transfer),
            );
            d.cmd_copy_image_to_buffer(
                self.cmd,
                color,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                readback,
                &[region],
            );
            d.cmd_pipeline_barrier2(
                self.cmd,
                &vk::DependencyInfo::default().buffer_memory_barriers(&to_host),
            );
            d.end_command_buffer(self.cmd).map_err(|e| e.to_string())?;
            d.queue_submit(self.queue, &[submit], self.fence)
                .map_err(|e| e.to_string())?;
            d.wait_for_fences(&[self.fence], true, u64::MAX)
                .map_err(|e| e.to_string())?;
            d.reset_fences(&[self.fence]).map_err(|e| e.to_string())?;
        }
        let memory = self
            .buffers
            .iter()
            .find(|(b, _)| *b == readback)
            .map(|(_, m)| m.memory)
            .ok_or("the readback buffer")?;
        let len = (self.size * self.size * 4) as usize;
        // SAFETY: host-visible, coherent memory the finished copy wrote; mapped only here.
        let pixels = unsafe {
            let ptr = d
                .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .map_err(|e| e.to_string())?;
            let pixels = std::slice::from_raw_parts(ptr as *const u8, len).to_vec();
            d.unmap_memory(memory);
            pixels
        };
        Ok(pixels)
    }
}

impl Drop for App {
    fn drop(&mut self) {
        // SAFETY: every submission was waited for; children go before their parents.
        unsafe {
            let _ = self.device.device_wait_idle();
            for (image, view, memory) in self.images.drain(..) {
                self.device.destroy_image_view(view, None);
                self.device.destroy_image(image, None);
                self.device.free_memory(memory.memory, None);
            }
            for (buffer, memory) in self.buffers.drain(..) {
                self.device.destroy_buffer(buffer, None);
                self.device.free_memory(memory.memory, None);
            }
            self.device.destroy_fence(self.fence, None);
            self.device.destroy_command_pool(self.pool, None);
            self.device.destroy_device(None);
            if let Some((loader, messenger)) = self.messenger.take() {
                loader.destroy_debug_utils_messenger(messenger, None);
            }
            self.instance.destroy_instance(None);
        }
    }
}

fn range(aspect: vk::ImageAspectFlags) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: aspect,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}
