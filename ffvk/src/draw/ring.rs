//! The per-draw GL state in flight: for each frame slot, host-visible uniform memory (the
//! device-local memory the host can map, where the device has it) holding one [`DrawBlock`]
//! per draw recorded for that slot, each seen through a dynamic offset.
//!
//! A slot's memory is written while its draws are recorded and read when the GPU runs them,
//! so a slot may be reset ([`UniformRing::reset`]) only when the caller's fence for the frame
//! that last used it has signalled. A slot grows by chunks: a full chunk is never moved
//! (recorded draws still point at it); a new, twice as large one is added, and the next reset
//! keeps only the largest.

use std::sync::Arc;

use ash::vk;

use crate::error::{Error, LightingError, Result};
use crate::gpu::layout::DrawBlock;
use crate::vk::objects::{DescriptorPool, DescriptorSetLayout};
use crate::vk::{Buffer, Device, MemoryUse};

/// Draws the first chunk of a slot holds.
const FIRST_CHUNK_DRAWS: u64 = 64;

/// One buffer of blocks and the descriptor set that points at it.
struct Chunk {
    // Field order is drop order: the set's pool before the buffer it points at.
    descriptors: DescriptorPool,
    buffer: Buffer,
    capacity: u64,
}

/// The chunks of one frame slot and how many blocks its last chunk holds.
#[derive(Default)]
struct Slot {
    chunks: Vec<Chunk>,
    used: u64,
}

/// Uniform memory for the draws of `slots` frames in flight.
pub(crate) struct UniformRing {
    slots: Vec<Slot>,
    /// Bytes between blocks: the block size rounded up to the offset alignment.
    stride: u64,
    device: Arc<Device>,
}

impl UniformRing {
    /// An empty ring of `slots` frame slots (memory comes with the first draws).
    pub(crate) fn new(device: &Arc<Device>, slots: u32) -> Result<Self> {
        if slots == 0 {
            return Err(LightingError::NoFrameSlots.into());
        }
        let align = device.limits.min_uniform_buffer_offset_alignment.max(16);
        let stride = (std::mem::size_of::<DrawBlock>() as u64).div_ceil(align) * align;
        Ok(UniformRing {
            slots: (0..slots).map(|_| Slot::default()).collect(),
            stride,
            device: device.clone(),
        })
    }

    /// How many frame slots the ring has.
    pub(crate) fn slots(&self) -> u32 {
        self.slots.len() as u32
    }

    fn slot_mut(&mut self, slot: u32) -> Result<&mut Slot> {
        let slots = self.slots.len() as u32;
        self.slots
            .get_mut(slot as usize)
            .ok_or_else(|| LightingError::FrameSlot { slot, slots }.into())
    }

    /// Forgets the blocks of `slot`, keeping its largest chunk for reuse. The caller
    /// guarantees that no submitted work still reads them.
    pub(crate) fn reset(&mut self, slot: u32) -> Result<()> {
        let s = self.slot_mut(slot)?;
        // The last chunk is the largest: each new one doubles the one before.
        if let Some(last) = s.chunks.pop() {
            s.chunks.clear();
            s.chunks.push(last);
        }
        s.used = 0;
        Ok(())
    }

    /// Stores `block` for a draw of `slot`; returns the descriptor set and dynamic offset
    /// that draw binds.
    pub(crate) fn push(
        &mut self,
        slot: u32,
        block: &DrawBlock,
        set_layout: &DescriptorSetLayout,
    ) -> Result<(vk::DescriptorSet, u32)> {
        let stride = self.stride;
        let slots = self.slots.len() as u32;
        // Fields borrowed apart: the slot mutably, the device shared.
        let s = self
            .slots
            .get_mut(slot as usize)
            .ok_or(LightingError::FrameSlot { slot, slots })?;
        let full = s.chunks.last().is_none_or(|c| s.used == c.capacity);
        if full {
            let capacity = s.chunks.last().map_or(FIRST_CHUNK_DRAWS, |c| c.capacity * 2);
            s.chunks
                .push(Chunk::new(&self.device, capacity, stride, set_layout)?);
            s.used = 0;
        }
        let chunk = s
            .chunks
            .last_mut()
            .ok_or(Error::Internal("no uniform chunk after one was added"))?;
        let offset = s.used * stride;
        chunk.buffer.write(offset, bytemuck::bytes_of(block))?;
        s.used += 1;
        let offset = u32::try_from(offset).map_err(|_| LightingError::TooManyDraws { draws: s.used })?;
        Ok((chunk.descriptors.set(), offset))
    }
}

impl Chunk {
    fn new(
        device: &Arc<Device>,
        capacity: u64,
        stride: u64,
        set_layout: &DescriptorSetLayout,
    ) -> Result<Self> {
        let buffer = Buffer::new(
            device,
            "uniform buffer",
            capacity * stride,
            vk::BufferUsageFlags::UNIFORM_BUFFER,
            MemoryUse::Uniforms,
        )?;
        let sizes = [vk::DescriptorPoolSize {
            ty: vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
            descriptor_count: 1,
        }];
        let descriptors = DescriptorPool::with_one_set(device, &sizes, set_layout)?;
        let info = [vk::DescriptorBufferInfo {
            buffer: buffer.raw(),
            offset: 0,
            range: std::mem::size_of::<DrawBlock>() as u64,
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
