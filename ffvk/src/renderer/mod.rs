//! The offscreen render path: one device, many frames, many scenes.

use std::sync::Arc;

use ash::vk;

use crate::draw::lighting::{Lighting, LightingOptions, LitDraw};
use crate::draw::pipeline::{RasterState, Target, VertexInput};
use crate::draw::pipeline::{Specialize, COLOR_FORMAT, DEPTH_FORMAT};
use crate::draw::record::Topology;
use crate::draw::texture::{cube_sampler_info, sampler_info};
use crate::error::{vk_error, Error, MeshError, Result};
use crate::gl::state::FixedFunctionState;
use crate::gl::texture::{CubeImage, Sampling, TextureImage};
use crate::mesh::MeshData;
use crate::vk::objects::{CommandPool, Fence, Sampler};
use crate::vk::{
    Buffer, Device, DeviceInfo, Image, Instance, MemoryUsage, MemoryUse, Validation, ValidationSink,
};

mod attachments;
mod deferred;
mod frame;
mod queries;
mod record;
mod states;
mod texture;
mod upload;
pub use deferred::GBUFFER_BYTES_PER_PIXEL;
pub use frame::{Draw, FragmentPath, Frame, FrameStats, Mesh, PipelineStats, Pixels, Recording};
use queries::Queries;
pub use states::MAX_DEFERRED_STATES;
pub use texture::Texture;
pub use upload::Upload;
use upload::{Part, Uploader};

/// How to open a renderer.
#[derive(Debug, Clone, Default)]
#[non_exhaustive]
pub struct RendererOptions {
    /// A substring of the device name; `None` picks lavapipe ("llvmpipe") when present.
    pub device: Option<String>,
    /// Whether to load the validation layer (default: off). With it loaded, validation errors
    /// fail [`Renderer::new`] or the frame that caused them with [`Error::Validation`].
    pub validation: Validation,
    /// Specialized pipelines per lighting state, or the uber-shader.
    pub specialize: Specialize,
    /// How meshes reach device-local memory (default: directly where the host can write it).
    pub upload: Upload,
}

with_fields!(RendererOptions {
    /// Sets [`device`](RendererOptions::device): a substring of the device's name.
    with_device => device: Option<String>,
    /// Sets [`validation`](RendererOptions::validation).
    with_validation => validation: Validation,
    /// Sets [`specialize`](RendererOptions::specialize).
    with_specialize => specialize: Specialize,
    /// Sets [`upload`](RendererOptions::upload).
    with_upload => upload: Upload,
});

/// The most frames [`Renderer::measure_frames`] records in one submission.
pub const MAX_REPEAT: u32 = 4096;

/// What one submission records besides the rendering pass.
#[derive(Debug, Clone, Copy)]
struct Pass {
    /// Copy the color image to the readback buffer after the last pass.
    readback: bool,
    /// Write a timestamp before the first pass and after each.
    timestamps: bool,
    /// Count the pipeline statistics of the (only) pass.
    statistics: bool,
    /// How many times the frame's pass is recorded: measured frames repeated in one
    /// submission, so that submission and waiting stay outside what is measured.
    repeat: u32,
}

impl Pass {
    const RENDER: Pass = Pass {
        readback: true,
        timestamps: false,
        statistics: false,
        repeat: 1,
    };
}

/// The render target of one size, reused while the size stays the same.
struct Targets {
    extent: vk::Extent2D,
    color: Image,
    /// [`DEPTH_FORMAT`], or its stencil form ([`Target::with_stencil`]) for frames that test
    /// the stencil buffer.
    depth: Image,
    /// Whether `depth` has stencil.
    stencil: bool,
    readback: Buffer,
}

/// Draws frames offscreen and returns them as images. Owns its device; meshes hold it too.
///
/// ```
/// use ffvk::gl::state::GlState;
/// use ffvk::glam::{Mat4, Vec3, Vec4};
/// use ffvk::mesh::{MeshData, Vertex};
/// use ffvk::{Draw, Frame, Renderer, RendererOptions};
///
/// // A green quad over the whole of GL's clip space, lighting off (GL's default).
/// let v = |x, y| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, Vec4::new(0.0, 1.0, 0.0, 1.0));
/// let quad = MeshData::new(vec![v(-1.0, -1.0), v(1.0, -1.0), v(1.0, 1.0), v(-1.0, 1.0)], vec![0, 1, 2, 0, 2, 3]);
/// let mut renderer = Renderer::new(&RendererOptions::default())?;
/// let quad = renderer.upload(&quad)?;
/// let gl = GlState::new();
/// let mut frame = Frame::new(4, 4);
/// frame.draws.push(Draw::new(&quad, Mat4::IDENTITY, Mat4::IDENTITY, gl.lighting));
/// let pixels = renderer.render(&frame)?;
/// assert_eq!(pixels.pixel(2, 2), Some([0, 255, 0, 255]));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Renderer {
    // Field order is drop order (after Drop waits for the device): everything that holds the
    // device goes before `device`, the last Arc this renderer keeps.
    targets: Option<Targets>,
    /// The fragment mode's deferred path, made on its first frame.
    deferred: Option<deferred::Deferred>,
    /// The lighting pipelines and per-draw state memory (one frame slot: every frame is
    /// waited for before the next).
    lighting: Lighting,
    commands: CommandPool,
    fence: Fence,
    /// Staging copies of meshes, behind a lock since uploads take `&self`.
    uploader: std::sync::Mutex<Uploader>,
    upload: Upload,
    /// Timestamps and pipeline statistics, where the device has them.
    queries: Queries,
    /// Set when a submission failed: the renderer refuses further frames.
    lost: bool,
    /// The queue of its own device, which it alone submits to.
    queue: vk::Queue,
    /// Its instance's validation messages.
    validation: ValidationSink,
    device: Arc<Device>,
}

impl Renderer {
    /// Opens the instance and device `options` asks for and creates what every frame needs.
    pub fn new(options: &RendererOptions) -> Result<Self> {
        let instance = Instance::new(options.validation)?;
        let device = Device::new(instance, options.device.as_deref())?;
        let lighting = Lighting::new(
            &device,
            &LightingOptions::new(Target::OFFSCREEN, VertexInput::interleaved())
                .with_specialize(options.specialize),
        )?;
        let own = device.own()?;
        let (queue_family, queue, validation) = (own.queue_family, own.queue, own.instance.validation_sink());
        let commands = CommandPool::with_one_buffer(&device, queue_family)?;
        let fence = Fence::new(&device)?;
        let queries = Queries::new(&device)?;
        let uploader = std::sync::Mutex::new(Uploader::new(&device)?);
        let renderer = Renderer {
            targets: None,
            deferred: None,
            lighting,
            commands,
            fence,
            uploader,
            upload: options.upload,
            queries,
            lost: false,
            queue,
            validation,
            device,
        };
        renderer.check_validation()?;
        Ok(renderer)
    }

    /// The device this renderer opened: its name, driver, limits and optional features.
    pub fn device_info(&self) -> &DeviceInfo {
        self.device.info()
    }

    /// The validation messages of this renderer's instance. Messages reported while the
    /// device is destroyed arrive after the renderer is dropped; keep a clone to read them.
    pub fn validation_sink(&self) -> ValidationSink {
        self.validation.clone()
    }

    fn check_validation(&self) -> Result<()> {
        let errors = self.validation_sink().take_errors();
        if errors.is_empty() {
            Ok(())
        } else {
            Err(Error::Validation(errors))
        }
    }

    /// Uploads a mesh. Fails when an index is past the vertices or the index count is not a
    /// multiple of three (a triangle list) or two (a line list).
    pub fn upload(&self, mesh: &MeshData) -> Result<Mesh> {
        let whole = match mesh.topology {
            Topology::TriangleList => 3,
            Topology::EdgeFlaggedTriangles => 6,
            Topology::LineList => 2,
            _ => 1,
        };
        if !mesh.indices.len().is_multiple_of(whole) {
            return Err(MeshError::PartialPrimitive {
                count: mesh.indices.len(),
                topology: mesh.topology.gl_name(),
                per: whole,
            }
            .into());
        }
        let count = mesh.vertices.len();
        if let Some((at, &bad)) = mesh
            .indices
            .iter()
            .enumerate()
            .find(|(_, &i)| i as usize >= count)
        {
            return Err(MeshError::IndexOutOfRange {
                at,
                index: bad,
                vertex_count: count,
            }
            .into());
        }
        let second = &mesh.second_texcoords;
        if !second.is_empty() && second.len() != count {
            return Err(MeshError::SecondTexcoordCount {
                count: second.len(),
                vertex_count: count,
            }
            .into());
        }
        let vertex_part = |what, bytes| Part {
            what,
            bytes,
            usage: vk::BufferUsageFlags::VERTEX_BUFFER,
            read_stage: vk::PipelineStageFlags2::VERTEX_ATTRIBUTE_INPUT,
            read_access: vk::AccessFlags2::VERTEX_ATTRIBUTE_READ,
        };
        let mut parts = vec![
            vertex_part("vertex buffer", bytemuck::cast_slice(&mesh.vertices)),
            Part {
                what: "index buffer",
                bytes: bytemuck::cast_slice(&mesh.indices),
                usage: vk::BufferUsageFlags::INDEX_BUFFER,
                read_stage: vk::PipelineStageFlags2::INDEX_INPUT,
                read_access: vk::AccessFlags2::INDEX_READ,
            },
        ];
        if !second.is_empty() {
            parts.push(vertex_part(
                "second texture coordinate buffer",
                bytemuck::cast_slice(second),
            ));
        }
        let mut uploader = self
            .uploader
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        let mut buffers = uploader.upload(&self.device, &parts, self.upload)?.into_iter();
        let (Some(vertices), Some(indices)) = (buffers.next(), buffers.next()) else {
            return Err(Error::Internal(
                "the uploader returned another number of buffers than parts",
            ));
        };
        let second = buffers.next();
        Ok(Mesh {
            vertex_bindings: [
                (vertices.raw(), 0),
                (second.as_ref().map_or(vk::Buffer::null(), Buffer::raw), 0),
            ],
            second,
            vertices,
            indices,
            index_count: mesh.indices.len() as u32,
            vertex_count: count as u32,
            topology: mesh.topology,
            bounds: mesh.vertices.iter().fold(None, |b, v| {
                let p = glam::Vec3::from(v.position);
                Some(b.map_or((p, p), |(lo, hi): (glam::Vec3, glam::Vec3)| {
                    (lo.min(p), hi.max(p))
                }))
            }),
        })
    }

    /// Uploads a texture with its sampling parameters (glTexImage2D for every level, then
    /// glTexParameter). A texture whose min filter reads mipmaps it lacks is made anyway, as in
    /// GL, and draws with it are untextured ([`Texture::is_complete`]).
    pub fn upload_texture(&self, image: &TextureImage, sampling: &Sampling) -> Result<Texture> {
        let max = self.device.limits.max_image_dimension2_d;
        let (width, height) = (image.width(), image.height());
        if width > max || height > max {
            return Err(Error::InvalidSize { width, height, max });
        }
        let levels = image.levels().len() as u32;
        let gpu_image = Image::with_levels(
            &self.device,
            vk::Extent2D { width, height },
            texture::format(image),
            vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST,
            vk::ImageAspectFlags::COLOR,
            levels,
        )?;
        self.uploader
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
            .upload_image(&self.device, &gpu_image, &[image.levels()])?;
        let sampler = Sampler::new(&self.device, &sampler_info(sampling, levels))?;
        // SAFETY: the view and sampler are this device's and live in the Texture as long as
        // the binding (dropped first); frames that draw it are waited for before it can drop
        // (draw_frame waits, and the Texture is borrowed by the frame).
        let binding = unsafe { self.lighting.bind_texture(gpu_image.view(), sampler.raw()) }?
            .with_base_format(image.base_format);
        let complete = sampling.is_complete(image.has_mipmaps());
        Ok(Texture::new(
            gpu_image,
            sampler,
            binding,
            complete,
            (width, height),
        ))
    }

    /// Uploads a cube map with its sampling parameters (glTexImage2D on each face's target for
    /// every level, then glTexParameter on `GL_TEXTURE_CUBE_MAP`), for
    /// [`Draw::cube_maps`](crate::Draw::cube_maps). Its faces are filtered each on its own, as
    /// GL 2.1 does, where the device has `VK_EXT_non_seamless_cube_map`
    /// ([`DeviceInfo::non_seamless_cube_map`](crate::vk::DeviceInfo::non_seamless_cube_map));
    /// elsewhere across face edges. Incomplete for a mipmap min filter without mipmaps, as in
    /// GL.
    pub fn upload_cube_map(&self, image: &CubeImage, sampling: &Sampling) -> Result<Texture> {
        let max = self.device.limits.max_image_dimension_cube;
        let side = image.size();
        if side > max {
            return Err(Error::InvalidSize {
                width: side,
                height: side,
                max,
            });
        }
        let levels = image.level_count() as u32;
        let gpu_image = Image::cube(
            &self.device,
            side,
            texture::cube_format(image),
            vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST,
            levels,
        )?;
        let faces: Vec<&[crate::gl::texture::Level]> =
            image.faces().iter().map(TextureImage::levels).collect();
        self.uploader
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
            .upload_image(&self.device, &gpu_image, &faces)?;
        let non_seamless = self.device.info.non_seamless_cube_map;
        let sampler = Sampler::new(&self.device, &cube_sampler_info(sampling, levels, non_seamless))?;
        // SAFETY: as upload_texture's.
        let binding = unsafe { self.lighting.bind_cube_map(gpu_image.view(), sampler.raw()) }?
            .with_base_format(image.faces()[0].base_format);
        let complete = sampling.is_complete(image.has_mipmaps());
        Ok(Texture::new(gpu_image, sampler, binding, complete, (side, side)))
    }

    fn ensure_targets(&mut self, width: u32, height: u32, stencil: bool) -> Result<()> {
        let max = self.device.limits.max_image_dimension2_d;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(Error::InvalidSize { width, height, max });
        }
        let extent = vk::Extent2D { width, height };
        if self
            .targets
            .as_ref()
            .is_some_and(|t| t.extent == extent && t.stencil == stencil)
        {
            return Ok(());
        }
        self.targets = None;
        let color = Image::new(
            &self.device,
            extent,
            COLOR_FORMAT,
            vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
            vk::ImageAspectFlags::COLOR,
        )?;
        let (depth_format, depth_aspects) = match stencil {
            false => (DEPTH_FORMAT, vk::ImageAspectFlags::DEPTH),
            true => (
                Target::OFFSCREEN.with_stencil().depth_format,
                vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL,
            ),
        };
        let depth = Image::new(
            &self.device,
            extent,
            depth_format,
            vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
            depth_aspects,
        )?;
        let readback = Buffer::new(
            &self.device,
            "readback buffer",
            width as u64 * height as u64 * 4,
            vk::BufferUsageFlags::TRANSFER_DST,
            MemoryUse::Readback,
        )?;
        self.targets = Some(Targets {
            extent,
            color,
            depth,
            stencil,
            readback,
        });
        Ok(())
    }

    /// Draws `frame` and returns its pixels, row 0 at the top of the view.
    pub fn render(&mut self, frame: &Frame) -> Result<Pixels> {
        self.draw_frame(frame, Pass::RENDER)?;
        self.read_image(frame)
    }

    /// [`Renderer::render`] with timestamps and a pipeline-statistics query around the
    /// rendering pass.
    pub fn render_measured(&mut self, frame: &Frame) -> Result<(Pixels, FrameStats)> {
        let pass = Pass {
            timestamps: true,
            statistics: true,
            ..Pass::RENDER
        };
        let stats = self.draw_frame(frame, pass)?.remove(0);
        Ok((self.read_image(frame)?, stats))
    }

    /// Draws `frame` with the queries of [`Renderer::render_measured`] but without reading
    /// the image back.
    pub fn measure(&mut self, frame: &Frame) -> Result<FrameStats> {
        let pass = Pass {
            readback: false,
            timestamps: true,
            statistics: true,
            repeat: 1,
        };
        Ok(self.draw_frame(frame, pass)?.remove(0))
    }

    /// Draws `frame` `count` times in one submission, with a timestamp
    /// before the first and after each, and returns each one's [`FrameStats`]: the way to
    /// time frames whose GPU work is short, since nothing but the frame itself (its layout
    /// transitions, clears and draws) lies between two timestamps. No pipeline statistics
    /// (they cost GPU time on some devices; [`Renderer::measure`] has them) and no readback;
    /// `wall_ns` is the submission's host time divided by `count`. `count` is 1 to
    /// [`MAX_REPEAT`], else [`Error::TooManyFrames`].
    pub fn measure_frames(&mut self, frame: &Frame, count: u32) -> Result<Vec<FrameStats>> {
        if count == 0 || count > MAX_REPEAT {
            return Err(Error::TooManyFrames {
                count,
                max: MAX_REPEAT,
            });
        }
        let pass = Pass {
            readback: false,
            timestamps: true,
            statistics: false,
            repeat: count,
        };
        self.draw_frame(frame, pass)
    }

    /// Uploads the uniforms, records, submits and waits; returns what the queries measured,
    /// one entry per repeat of the pass.
    fn draw_frame(&mut self, frame: &Frame, pass: Pass) -> Result<Vec<FrameStats>> {
        if self.lost {
            return Err(Error::DeviceLost(
                "render (an earlier submission failed; make a new renderer)",
            ));
        }
        for (i, d) in frame.draws.iter().enumerate() {
            if d.depth_range.iter().any(|r| r.is_nan()) {
                return Err(crate::error::LightingError::RasterEnum {
                    field: "depth_range",
                    value: format!("{:?} (draw {i})", d.depth_range),
                    expected: "numbers (glDepthRange clamps them to [0, 1])",
                }
                .into());
            }
            if !Arc::ptr_eq(d.mesh.vertices.device(), &self.device) {
                return Err(MeshError::ForeignMesh { draw: i }.into());
            }
            let units = d.second_texcoords & 0b1110;
            if units != 0 && d.mesh.second.is_none() {
                return Err(MeshError::NoSecondTexcoords { draw: i, units }.into());
            }
            if d.textures
                .iter()
                .chain(&d.cube_maps)
                .flatten()
                .any(|t| !Arc::ptr_eq(t.image.device(), &self.device))
            {
                return Err(MeshError::ForeignTexture { draw: i }.into());
            }
        }
        let stencil = frame.has_stencil();
        self.ensure_targets(frame.width, frame.height, stencil)?;
        self.lighting.set_stencil_target(stencil);
        // The lit draws first (their time counts as recording, below): consecutive draws under
        // one state borrow it.
        let lits_start = std::time::Instant::now();
        let layouts = self.texcoord_layouts(frame)?;
        let lits = record::lit_draws(frame, &layouts);
        let lits_ns = lits_start.elapsed().as_nanos() as f64;
        // Every pipeline is made before recording starts, so that pipeline creation never
        // lands inside a measured frame. A draw that borrows the state of the draw before it
        // and needs the same raster state, texturing and size class is looked up once: a frame
        // of many objects under one lighting state looks up one pipeline.
        let mut before: Option<(&LitDraw, bool)> = None;
        for (d, lit) in frame.draws.iter().zip(&lits) {
            let small = d.mesh.index_count < crate::draw::pipeline::SMALL_DRAW_VERTICES;
            let same = before.is_some_and(|(b, s)| {
                std::ptr::eq(b.state, lit.state)
                    && (b.raster, b.textures, s) == (lit.raster, lit.textures, small)
            });
            if !same {
                self.lighting.prepare_sized(
                    lit.state,
                    lit.raster,
                    (d.complete_units(), d.complete_cube_maps()),
                    small,
                )?;
            }
            before = Some((lit, small));
        }
        debug_assert!(
            !pass.statistics || pass.repeat == 1,
            "one statistics query per submission"
        );
        if pass.timestamps {
            // Before the first pass, then after each; a deferred frame's also between its two.
            self.queries
                .ensure_timestamps(&self.device, 2 * pass.repeat + 1)?;
        }
        self.lighting.begin_frame(0)?;
        // Every draw is checked and its block written before recording starts, so that a bad
        // draw records nothing; the time counts as recording, as it does in Lighting::draw.
        let staging = std::time::Instant::now();
        // The Renderer's own errors name the draw where it matters (its meshes and textures);
        // the state's errors stay as they are.
        let cpu = self.device.info().is_cpu();
        let eligible = states::eligible(frame, self.lighting.specialize(), cpu);
        self.lighting.set_gbuffer(eligible.is_some());
        let staged = match frame.recording {
            Recording::Run => self.lighting.stage_run(0, &lits).map_err(|(_, e)| e),
            Recording::DrawByDraw => lits.iter().map(|d| self.lighting.stage(0, d, false)).collect(),
        };
        self.lighting.set_gbuffer(false);
        let mut staged = staged?;
        // The lighting pass reads the records from one buffer: a frame whose records span two
        // chunks of the slot (a first frame of many draws, while the slot grows), or lie past
        // the device's texel buffer limit, is drawn forward, staged again.
        let records = deferred::readable_records(&staged, &self.device);
        let deferred_states = match (eligible, records) {
            (Some(states), Some(records)) => Some((states, records)),
            (Some(_), None) => {
                self.lighting.begin_frame(0)?;
                staged = self.lighting.stage_run(0, &lits).map_err(|(_, e)| e)?;
                None
            }
            (None, _) => None,
        };
        let deferred_pass = match (deferred_states, &self.targets) {
            (Some((states, records)), Some(targets)) => {
                let extent = targets.extent;
                let d = match &mut self.deferred {
                    Some(d) => d,
                    None => self.deferred.insert(deferred::Deferred::new(&self.device)?),
                };
                Some(d.pass(
                    &self.lighting,
                    (frame, extent),
                    (&states, records),
                    &staged,
                    pass.statistics,
                )?)
            }
            _ => None,
        };
        let staging_ns = lits_ns + staging.elapsed().as_nanos() as f64;
        let record_ns = staging_ns + self.record(frame, pass, &lits, &staged, deferred_pass.as_ref())?;
        let wall_ns = self.submit_and_wait()? / f64::from(pass.repeat);
        self.check_validation()?;
        // Per repeat: the whole pass; a deferred frame's as its G-buffer pass and the rest.
        let per_pass = if deferred_pass.is_some() { 2 } else { 1 };
        let intervals = if pass.timestamps {
            self.queries
                .read_timestamps(&self.device, per_pass * pass.repeat + 1)?
        } else {
            None
        };
        let gpu_ns: Option<Vec<(f64, Option<f64>)>> = intervals.map(|ns| {
            ns.chunks(per_pass as usize)
                .map(|c| match c {
                    [gbuffer, lighting] => (gbuffer + lighting, Some(*gbuffer)),
                    _ => (c.iter().sum(), None),
                })
                .collect()
        });
        let pipeline = if pass.statistics {
            self.queries.read_statistics()?
        } else {
            None
        };
        let evaluations = match (&deferred_pass, &self.deferred) {
            (Some(p), Some(d)) if p.counter.is_some() => d.evaluations(),
            _ => None,
        };
        Ok((0..pass.repeat as usize)
            .map(|i| FrameStats {
                gpu_ns: gpu_ns.as_ref().map(|ns| ns[i].0),
                gbuffer_ns: gpu_ns.as_ref().and_then(|ns| ns[i].1),
                wall_ns,
                pipeline,
                record_ns,
                deferred: deferred_pass.is_some(),
                evaluations,
            })
            .collect())
    }

    /// The frame's attachments and readback buffer, which `ensure_targets` made.
    fn targets(&self) -> Result<&Targets> {
        self.targets.as_ref().ok_or(Error::Internal(
            "a frame was recorded before its targets were made",
        ))
    }

    /// The readback buffer as an image (after a frame recorded with `readback`).
    fn read_image(&self, frame: &Frame) -> Result<Pixels> {
        let targets = self.targets()?;
        let len = usize::try_from(u64::from(frame.width) * u64::from(frame.height) * 4)
            .map_err(|_| Error::Internal("an image larger than the address space was rendered"))?;
        Ok(Pixels {
            width: frame.width,
            height: frame.height,
            rgba: crate::alloc::try_copy(
                &targets.readback.bytes().ok_or(Error::NotMapped)?[..len],
                "the rendered image",
            )?,
        })
    }

    /// Creates the pipeline a draw of `state` would use in a frame with `depth_test`, so that
    /// the frame does not pay for it; returns the host time that took, in nanoseconds (only a
    /// lookup when the pipeline exists already). In the fragment mode that is the pipeline of
    /// draws of at least [`SMALL_DRAW_VERTICES`](crate::draw::pipeline::SMALL_DRAW_VERTICES)
    /// indices (smaller ones have their own, made before the first frame that draws one).
    /// Drivers may still compile part of a new pipeline at its first draw (lavapipe compiles
    /// fragment code then).
    pub fn prepare(&mut self, state: &FixedFunctionState, depth_test: bool) -> Result<f64> {
        let raster = RasterState {
            depth_test,
            ..RasterState::default()
        };
        let start = std::time::Instant::now();
        self.lighting.prepare_sized(state, raster, (0, 0), false)?;
        Ok(start.elapsed().as_nanos() as f64)
    }

    /// The device this renderer opened, for what [`Renderer::device_info`] does not say (its
    /// memory choices, say).
    pub fn device(&self) -> &Device {
        &self.device
    }

    /// How much device memory this renderer's device holds (meshes, render targets, uniforms)
    /// and how much of it is in use.
    pub fn memory_usage(&self) -> MemoryUsage {
        self.device.memory_usage()
    }

    /// For each use, the memory type gpu-allocator gives it on this device (a probe
    /// allocation): what `ffvk info` prints.
    pub fn memory_choices(&self) -> Vec<(MemoryUse, Option<crate::vk::MemoryChoice>)> {
        self.device.memory_choices()
    }

    /// How many pipelines this renderer has created, and how many of them are specialized.
    pub fn pipeline_counts(&self) -> (usize, usize) {
        self.lighting.pipeline_counts()
    }

    /// Submits the command buffer and waits for it; returns the host time that took, in ns.
    fn submit_and_wait(&mut self) -> Result<f64> {
        let result = self.submit_and_wait_once();
        if result.is_err() {
            // The command buffer may still be pending and the fence signaled: nothing recorded
            // later could be trusted, so wait for the device and refuse further frames.
            let _ = self.device.wait_idle();
            self.lost = true;
        }
        result
    }

    fn submit_and_wait_once(&self) -> Result<f64> {
        let vkd = &self.device.raw;
        let buffers = [self.commands.buffer()];
        let submit = vk::SubmitInfo::default().command_buffers(&buffers);
        let start = std::time::Instant::now();
        // SAFETY: the command buffer is fully recorded; the fence is unsignaled (reset after
        // every wait); &self plus the renderer's exclusive ownership of the queue serialize
        // queue access.
        unsafe {
            vkd.queue_submit(self.queue, &[submit], self.fence.raw())
                .map_err(vk_error("vkQueueSubmit"))?;
            vkd.wait_for_fences(&[self.fence.raw()], true, u64::MAX)
                .map_err(vk_error("vkWaitForFences"))?;
        }
        let wall_ns = start.elapsed().as_nanos() as f64;
        // SAFETY: the fence was signaled and nothing else waits on it.
        unsafe { vkd.reset_fences(&[self.fence.raw()]) }.map_err(vk_error("vkResetFences"))?;
        Ok(wall_ns)
    }
}

fn subresource(aspect: vk::ImageAspectFlags) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: aspect,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

impl Drop for Renderer {
    fn drop(&mut self) {
        // Nothing the fields own may be in use when they are freed, right after this.
        let _ = self.device.wait_idle();
    }
}
