//! Per-frame memory of the draws in flight: for each frame slot, host-visible memory (the
//! device-local memory the host can map, where the device has it) holding the [`StateBlock`]s
//! (a uniform buffer seen through a dynamic offset) or the [`DrawRecord`]s (a vertex buffer
//! read per instance) written while the slot's draws were recorded.
//!
//! A slot's memory is written while its draws are recorded and read when the GPU runs them,
//! so a slot may be reset ([`Ring::reset`]) only when the caller's fence for the frame that
//! last used it has signalled. A slot grows by chunks: a full chunk is never moved (recorded
//! draws still point at it); a new, twice as large one is added, and the next reset keeps
//! only the largest.
//!
//! [`StateBlock`]: crate::gpu::layout::StateBlock
//! [`DrawRecord`]: crate::gpu::layout::DrawRecord

use std::sync::Arc;

use ash::vk;

use crate::error::{Error, LightingError, Result};
use crate::vk::objects::{DescriptorPool, DescriptorSetLayout};
use crate::vk::{Buffer, Device, MemoryUse};

/// What a ring holds, and so how its chunks are seen by the shaders.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum RingUse {
    /// Uniform blocks, each chunk with a descriptor set (`UNIFORM_BUFFER_DYNAMIC`, binding 0)
    /// whose dynamic offset picks the block.
    Uniforms,
    /// Vertex data read per instance: a chunk is bound as a vertex buffer at offset 0 and a
    /// draw's `firstInstance` picks its element; each chunk also has a descriptor set
    /// (`UNIFORM_BUFFER_DYNAMIC`, binding 0) through which a dynamic offset picks the same
    /// element as a uniform block.
    InstanceData,
}

/// Where an element pushed into a ring lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Pushed {
    /// Its chunk's buffer.
    pub buffer: vk::Buffer,
    /// Its chunk's descriptor set.
    pub set: vk::DescriptorSet,
    /// Its index in the chunk: the byte offset is `index` times the ring's stride.
    pub index: u32,
    /// Its byte offset in the chunk (for a uniform block, the dynamic offset).
    pub offset: u32,
}

/// Elements the first chunk of a slot holds.
const FIRST_CHUNK: u64 = 64;

/// One buffer of elements and the descriptor set that points at it.
struct Chunk {
    // Field order is drop order: the set's pool before the buffer it points at.
    descriptors: DescriptorPool,
    buffer: Buffer,
    capacity: u64,
}

/// The chunks of one frame slot and how many elements its last chunk holds.
#[derive(Default)]
struct Slot {
    chunks: Vec<Chunk>,
    used: u64,
}

/// Memory for elements of one size, for the draws of `slots` frames in flight.
pub(crate) struct Ring {
    slots: Vec<Slot>,
    use_: RingUse,
    /// The element's size in bytes.
    size: u64,
    /// Bytes between elements: the size, rounded up to the offset alignment for uniforms.
    stride: u64,
    device: Arc<Device>,
}

impl Ring {
    /// An empty ring of `slots` frame slots for elements of `size` bytes (memory comes with
    /// the first draws).
    pub(crate) fn new(device: &Arc<Device>, slots: u32, use_: RingUse, size: usize) -> Result<Self> {
        if slots == 0 {
            return Err(LightingError::NoFrameSlots.into());
        }
        let size = size as u64;
        // Uniform blocks and instance elements alike lie the uniform offset alignment apart
        // (the fragment mode binds an instance element as a uniform block too); an instance
        // binding's stride is then this stride (`record_stride`).
        let align = device.limits.min_uniform_buffer_offset_alignment.max(16);
        let stride = size.div_ceil(align) * align;
        if use_ == RingUse::InstanceData && stride != crate::gpu::layout::record_stride(align) {
            return Err(Error::Internal("an instance element that is not a draw record"));
        }
        Ok(Ring {
            slots: (0..slots).map(|_| Slot::default()).collect(),
            use_,
            size,
            stride,
            device: device.clone(),
        })
    }

    /// How many frame slots the ring has.
    pub(crate) fn slots(&self) -> u32 {
        self.slots.len() as u32
    }

    /// Forgets the elements of `slot`, keeping its largest chunk for reuse. The caller
    /// guarantees that no submitted work still reads them.
    pub(crate) fn reset(&mut self, slot: u32) -> Result<()> {
        let slots = self.slots();
        let s = self
            .slots
            .get_mut(slot as usize)
            .ok_or(LightingError::FrameSlot { slot, slots })?;
        // The last chunk is the largest: each new one doubles the one before.
        if let Some(last) = s.chunks.pop() {
            s.chunks.clear();
            s.chunks.push(last);
        }
        s.used = 0;
        Ok(())
    }

    /// Stores `bytes` (one element) for a draw of `slot`; `set_layout` is the layout of the
    /// chunks' descriptor sets. Returns where it lies.
    pub(crate) fn push(
        &mut self,
        slot: u32,
        bytes: &[u8],
        set_layout: &DescriptorSetLayout,
    ) -> Result<Pushed> {
        if bytes.len() as u64 != self.size {
            return Err(Error::Internal("an element of another size pushed into a ring"));
        }
        let slots = self.slots();
        let (stride, size, use_) = (self.stride, self.size, self.use_);
        // Fields borrowed apart: the slot mutably, the device shared.
        let s = self
            .slots
            .get_mut(slot as usize)
            .ok_or(LightingError::FrameSlot { slot, slots })?;
        let full = s.chunks.last().is_none_or(|c| s.used == c.capacity);
        if full {
            let capacity = s.chunks.last().map_or(FIRST_CHUNK, |c| c.capacity * 2);
            let chunk = Chunk::new(&self.device, use_, capacity, (size, stride), set_layout)?;
            s.chunks.push(chunk);
            s.used = 0;
        }
        let chunk = s
            .chunks
            .last_mut()
            .ok_or(Error::Internal("no chunk after one was added"))?;
        let index = s.used;
        let offset = index * stride;
        chunk.buffer.write(offset, bytes)?;
        s.used += 1;
        let too_many = || LightingError::TooManyDraws { draws: index + 1 };
        Ok(Pushed {
            buffer: chunk.buffer.raw(),
            set: chunk.descriptors.set(),
            index: u32::try_from(index).map_err(|_| too_many())?,
            offset: u32::try_from(offset).map_err(|_| too_many())?,
        })
    }
}

impl Chunk {
    fn new(
        device: &Arc<Device>,
        use_: RingUse,
        capacity: u64,
        (size, stride): (u64, u64),
        set_layout: &DescriptorSetLayout,
    ) -> Result<Self> {
        let (what, usage) = match use_ {
            RingUse::Uniforms => ("uniform buffer", vk::BufferUsageFlags::UNIFORM_BUFFER),
            RingUse::InstanceData => (
                "draw record buffer",
                // A texel buffer too: the deferred lighting pass fetches a frame's records by
                // index (texelFetch, which llvmpipe gathers; its storage buffer loads at
                // per-pixel indices take a loop over the lanes).
                vk::BufferUsageFlags::VERTEX_BUFFER
                    | vk::BufferUsageFlags::UNIFORM_BUFFER
                    | vk::BufferUsageFlags::UNIFORM_TEXEL_BUFFER,
            ),
        };
        let buffer = Buffer::new(device, what, capacity * stride, usage, MemoryUse::Uniforms)?;
        let sizes = [vk::DescriptorPoolSize {
            ty: vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
            descriptor_count: 1,
        }];
        let descriptors = DescriptorPool::with_one_set(device, &sizes, set_layout)?;
        let info = [vk::DescriptorBufferInfo {
            buffer: buffer.raw(),
            offset: 0,
            range: size,
        }];
        let write = vk::WriteDescriptorSet::default()
            .dst_set(descriptors.set())
            .dst_binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC)
            .buffer_info(&info);
        // SAFETY: the set is new, so no command buffer uses it; the buffer is alive and as
        // large as the range at every offset the ring hands out.
        unsafe { device.raw.update_descriptor_sets(&[write], &[]) };
        Ok(Chunk {
            descriptors,
            buffer,
            capacity,
        })
    }
}
