//! Device memory: which memory type each use gets, and the one allocator of a device, which
//! places every buffer and image inside large blocks (one `vkAllocateMemory` per block, not per
//! resource) and gives large resources memory of their own.
//!
//! The choice of type is a pure function of the device's memory table, so it is tested with
//! the tables of a discrete GPU and of lavapipe alike ([`choose_memory_type`]); so is the
//! placement inside a block ([`Ranges`]).

use std::collections::BTreeMap;
use std::sync::Arc;

use ash::vk;

use super::device::Device;
use crate::error::{Error, Result};

/// What a resource's memory is for; decides its memory type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum MemoryUse {
    /// Read and written by the GPU alone: vertex and index buffers, attachments. Device-local
    /// memory the host cannot see where the device has it (a discrete GPU's VRAM), filled by
    /// copies; on devices whose device-local memory is host-visible (lavapipe, integrated
    /// GPUs) the host writes it directly.
    Gpu,
    /// Written by the host for every frame and read by the GPU: the draws' state blocks and
    /// records.
    /// Device-local and host-visible where the device offers it (a GPU's BAR), else host
    /// memory.
    Uniforms,
    /// Written once by the host and copied by the GPU into [`MemoryUse::Gpu`] memory. Host
    /// memory, leaving a GPU's small host-visible VRAM to the uniforms.
    Staging,
    /// Written by the GPU and read by the host: the rendered image. Host-cached where the
    /// device offers it, since the host reads every byte.
    Readback,
}

impl MemoryUse {
    /// The memory types this use accepts, best first, as (flags it must have, flags it must
    /// not have). The last entry is the least the use needs.
    fn preferences(self) -> &'static [(vk::MemoryPropertyFlags, vk::MemoryPropertyFlags)] {
        const DL: vk::MemoryPropertyFlags = vk::MemoryPropertyFlags::DEVICE_LOCAL;
        const HV: vk::MemoryPropertyFlags = vk::MemoryPropertyFlags::HOST_VISIBLE;
        const NONE: vk::MemoryPropertyFlags = vk::MemoryPropertyFlags::empty();
        // Host access without flushes: every mapped use asks for coherent memory.
        const MAPPED: vk::MemoryPropertyFlags =
            vk::MemoryPropertyFlags::from_raw(HV.as_raw() | vk::MemoryPropertyFlags::HOST_COHERENT.as_raw());
        const MAPPED_DL: vk::MemoryPropertyFlags =
            vk::MemoryPropertyFlags::from_raw(MAPPED.as_raw() | DL.as_raw());
        const CACHED: vk::MemoryPropertyFlags = vk::MemoryPropertyFlags::from_raw(
            MAPPED.as_raw() | vk::MemoryPropertyFlags::HOST_CACHED.as_raw(),
        );
        match self {
            MemoryUse::Gpu => &[(DL, HV), (DL, NONE), (NONE, NONE)],
            MemoryUse::Uniforms => &[(MAPPED_DL, NONE), (MAPPED, NONE)],
            MemoryUse::Staging => &[(MAPPED, DL), (MAPPED, NONE)],
            MemoryUse::Readback => &[(CACHED, NONE), (MAPPED, NONE)],
        }
    }
}

/// Flags of memory types no ffvk resource may use: protected memory, lazily allocated
/// (transient attachments only) and AMD's device-coherent or uncached types (slow, meant for
/// debugging).
const NEVER: vk::MemoryPropertyFlags = vk::MemoryPropertyFlags::from_raw(
    vk::MemoryPropertyFlags::PROTECTED.as_raw()
        | vk::MemoryPropertyFlags::LAZILY_ALLOCATED.as_raw()
        | vk::MemoryPropertyFlags::DEVICE_COHERENT_AMD.as_raw()
        | vk::MemoryPropertyFlags::DEVICE_UNCACHED_AMD.as_raw(),
);

/// The memory type a resource of `usage` gets among those `type_bits` allows (its memory
/// requirements), or `None` when none is acceptable.
pub fn choose_memory_type(
    memory: &vk::PhysicalDeviceMemoryProperties,
    type_bits: u32,
    usage: MemoryUse,
) -> Option<u32> {
    acceptable_memory_types(memory, type_bits, usage).first().copied()
}

/// Every memory type a resource of `usage` may use, best first: where the first is full (a
/// GPU's small BAR, say), the next is tried.
pub fn acceptable_memory_types(
    memory: &vk::PhysicalDeviceMemoryProperties,
    type_bits: u32,
    usage: MemoryUse,
) -> Vec<u32> {
    let count = memory.memory_type_count.min(vk::MAX_MEMORY_TYPES as u32);
    let mut out: Vec<u32> = Vec::new();
    for &(with, without) in usage.preferences() {
        for i in 0..count {
            let flags = memory.memory_types[i as usize].property_flags;
            let fits = type_bits & (1 << i) != 0
                && flags.contains(with)
                && !flags.intersects(without)
                && !flags.intersects(NEVER);
            if fits && !out.contains(&i) {
                out.push(i);
            }
        }
    }
    out
}

/// Whether the host can map memory of these flags without flushing or invalidating.
pub(crate) fn is_mapped(flags: vk::MemoryPropertyFlags) -> bool {
    flags.contains(vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT)
}

/// `value` rounded up to a multiple of `align`; `None` past u64::MAX.
fn align_up(value: u64, align: u64) -> Option<u64> {
    value.div_ceil(align).checked_mul(align)
}

/// The free ranges of one block: first fit, neighbours merged when freed.
#[derive(Debug, Clone)]
pub struct Ranges {
    size: u64,
    /// Offset → length of every free range; no two touch.
    free: BTreeMap<u64, u64>,
    used: u64,
}

impl Ranges {
    /// A block of `size` bytes, all free.
    pub fn new(size: u64) -> Self {
        Ranges {
            size,
            free: BTreeMap::from([(0, size)]),
            used: 0,
        }
    }

    /// The offset of `size` bytes aligned to `align` (a power of two), or `None` when no free
    /// range holds them.
    pub fn allocate(&mut self, size: u64, align: u64) -> Option<u64> {
        let (start, len, at) = self.free.iter().find_map(|(&start, &len)| {
            let at = align_up(start, align)?;
            (at.checked_add(size)? <= start + len).then_some((start, len, at))
        })?;
        self.free.remove(&start);
        if at > start {
            self.free.insert(start, at - start);
        }
        if at + size < start + len {
            self.free.insert(at + size, start + len - at - size);
        }
        self.used += size;
        Some(at)
    }

    /// Returns `size` bytes at `offset`, which [`Ranges::allocate`] gave out.
    pub fn free(&mut self, offset: u64, size: u64) {
        let mut start = offset;
        let mut len = size;
        if let Some((&before, &before_len)) = self.free.range(..offset).next_back() {
            debug_assert!(before + before_len <= offset, "range freed twice");
            if before + before_len == offset {
                self.free.remove(&before);
                start = before;
                len += before_len;
            }
        }
        debug_assert!(
            self.free
                .range(offset..)
                .next()
                .is_none_or(|(&after, _)| offset + size <= after),
            "range freed twice"
        );
        if let Some(&after_len) = self.free.get(&(offset + size)) {
            self.free.remove(&(offset + size));
            len += after_len;
        }
        self.free.insert(start, len);
        self.used = self.used.saturating_sub(size);
    }

    /// Bytes given out and not yet returned.
    pub fn used(&self) -> u64 {
        self.used
    }

    /// The block's size.
    pub fn size(&self) -> u64 {
        self.size
    }

    /// How many separate free ranges there are (1 when nothing is allocated).
    pub fn free_ranges(&self) -> usize {
        self.free.len()
    }
}

/// The first block of a memory type; each block added while others are alive is twice as
/// large as the last, up to [`MAX_BLOCK`].
const FIRST_BLOCK: u64 = 8 << 20;
/// The largest block.
const MAX_BLOCK: u64 = 256 << 20;

/// One `vkAllocateMemory` shared by many resources.
struct Block {
    memory: vk::DeviceMemory,
    ranges: Ranges,
    /// The whole block mapped, for host-visible coherent types.
    mapped: Option<MappedPtr>,
}

/// A pointer into mapped device memory.
#[derive(Debug, Clone, Copy)]
pub(crate) struct MappedPtr(*mut u8);

// SAFETY: the pointer is plain address arithmetic into a mapping that lives as long as its
// memory; who may write through it is decided by the owners of the allocations (`&mut`).
unsafe impl Send for MappedPtr {}
// SAFETY: as above.
unsafe impl Sync for MappedPtr {}

impl MappedPtr {
    pub(crate) fn get(self) -> *mut u8 {
        self.0
    }
}

/// How much device memory a device's allocator holds and how much of it is in use.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct MemoryUsage {
    /// Shared blocks allocated.
    pub blocks: usize,
    /// Their bytes.
    pub block_bytes: u64,
    /// Resources with memory of their own (too large to share a block).
    pub dedicated: usize,
    /// Their bytes.
    pub dedicated_bytes: u64,
    /// Allocations alive: resources not yet dropped. Zero once every buffer and image of the
    /// device is gone; more means something still holds one.
    pub live: usize,
    /// Bytes those allocations use (with alignment), blocks and dedicated memory together.
    pub used_bytes: u64,
}

/// Where one allocation lives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Placement {
    /// Inside block `index` of its memory type.
    Block(usize),
    /// In memory of its own.
    Dedicated,
}

/// A piece of device memory: the memory object, the offset to bind at and, for host-visible
/// types, where it is mapped. Returned to the device's allocator when dropped.
pub struct Allocation {
    device: Arc<Device>,
    memory: vk::DeviceMemory,
    offset: u64,
    size: u64,
    type_index: u32,
    placement: Placement,
    mapped: Option<MappedPtr>,
}

impl Allocation {
    /// The memory object to bind.
    pub fn memory(&self) -> vk::DeviceMemory {
        self.memory
    }
    /// The offset to bind at.
    pub fn offset(&self) -> u64 {
        self.offset
    }
    /// The bytes it spans (the requirement's size, rounded up to the device's granularity).
    pub fn size(&self) -> u64 {
        self.size
    }
    /// Its memory type's index.
    pub fn memory_type(&self) -> u32 {
        self.type_index
    }
    /// Where the host sees its first byte, when the memory is host-visible and coherent.
    pub(crate) fn mapped(&self) -> Option<MappedPtr> {
        self.mapped
    }
    /// The device it belongs to.
    pub(crate) fn device(&self) -> &Arc<Device> {
        &self.device
    }
}

impl Drop for Allocation {
    fn drop(&mut self) {
        self.device.allocator().free(
            &self.device.raw,
            self.type_index,
            self.placement,
            self.memory,
            self.offset,
            self.size,
        );
    }
}

/// The blocks of every memory type of one device.
pub(crate) struct Allocator {
    memory: vk::PhysicalDeviceMemoryProperties,
    /// `bufferImageGranularity`: every allocation starts and ends on a multiple of it, so a
    /// buffer and an image never share a page that would need it.
    granularity: u64,
    /// Vulkan 1.1's maxMemoryAllocationSize (0: unknown).
    max_allocation: u64,
    /// Per memory type: its blocks (`None`: freed, the slot reused later).
    blocks: Vec<Vec<Option<Block>>>,
    dedicated: usize,
    dedicated_bytes: u64,
    live: usize,
}

impl Allocator {
    pub(crate) fn new(
        memory: vk::PhysicalDeviceMemoryProperties,
        granularity: u64,
        max_allocation: u64,
    ) -> Self {
        let types = memory.memory_type_count as usize;
        Allocator {
            memory,
            granularity: granularity.max(1),
            max_allocation,
            blocks: (0..types).map(|_| Vec::new()).collect(),
            dedicated: 0,
            dedicated_bytes: 0,
            live: 0,
        }
    }

    pub(crate) fn usage(&self) -> MemoryUsage {
        let mut usage = MemoryUsage {
            dedicated: self.dedicated,
            dedicated_bytes: self.dedicated_bytes,
            live: self.live,
            used_bytes: self.dedicated_bytes,
            ..MemoryUsage::default()
        };
        for block in self.blocks.iter().flatten().flatten() {
            usage.blocks += 1;
            usage.block_bytes += block.ranges.size();
            usage.used_bytes += block.ranges.used();
        }
        usage
    }

    fn heap_size(&self, type_index: u32) -> u64 {
        let heap = self.memory.memory_types[type_index as usize].heap_index;
        self.memory.memory_heaps[heap as usize].size
    }

    /// The size of a new block of `type_index`: doubling with each block of the type alive
    /// (so sizes that come and go do not ratchet it up), never more than an eighth of its heap
    /// or the device's largest allocation.
    fn block_size(&self, type_index: u32) -> u64 {
        let alive = self.blocks[type_index as usize].iter().flatten().count() as u32;
        // 8 MiB << 5 is MAX_BLOCK; a larger shift would only overflow.
        let growth = (FIRST_BLOCK << alive.min(5)).min(MAX_BLOCK);
        let mut size = growth.min(self.heap_size(type_index) / 8);
        if self.max_allocation != 0 {
            size = size.min(self.max_allocation);
        }
        size.max(self.granularity)
    }

    /// `requirements.size` bytes of `type_index` for `what`.
    fn allocate(
        &mut self,
        device: &ash::Device,
        what: &'static str,
        requirements: &vk::MemoryRequirements,
        type_index: u32,
    ) -> Result<(vk::DeviceMemory, u64, u64, Placement, Option<MappedPtr>)> {
        // A size that cannot even be rounded up is larger than any heap.
        let size = align_up(requirements.size.max(1), self.granularity).unwrap_or(u64::MAX);
        let align = requirements.alignment.max(self.granularity).max(1);
        self.check(what, size, type_index)?;
        let index = type_index as usize;
        let block_size = self.block_size(type_index);
        if size > block_size / 2 {
            let (memory, mapped) = self.allocate_memory(device, what, size, type_index)?;
            self.dedicated += 1;
            self.dedicated_bytes += size;
            self.live += 1;
            return Ok((memory, 0, size, Placement::Dedicated, mapped));
        }
        let found = self.blocks[index].iter_mut().enumerate().find_map(|(i, b)| {
            let b = b.as_mut()?;
            let offset = b.ranges.allocate(size, align)?;
            Some((i, offset))
        });
        let (i, offset) = match found {
            Some(found) => found,
            None => {
                let (memory, mapped) = self.allocate_memory(device, what, block_size, type_index)?;
                let mut ranges = Ranges::new(block_size);
                let Some(offset) = ranges.allocate(size, align) else {
                    // SAFETY: the memory was just allocated and nothing uses it.
                    unsafe { device.free_memory(memory, None) };
                    return Err(Error::Internal("a new memory block cannot hold half its size"));
                };
                let block = Block {
                    memory,
                    ranges,
                    mapped,
                };
                let slots = &mut self.blocks[index];
                let i = match slots.iter().position(Option::is_none) {
                    Some(free) => {
                        slots[free] = Some(block);
                        free
                    }
                    None => {
                        slots.push(Some(block));
                        slots.len() - 1
                    }
                };
                (i, offset)
            }
        };
        let block = self.blocks[index][i]
            .as_ref()
            .ok_or(Error::Internal("the memory block just used is gone"))?;
        // SAFETY: the offset lies inside the block's mapping, which covers the whole block.
        let mapped = block
            .mapped
            .map(|p| MappedPtr(unsafe { p.0.add(offset as usize) }));
        self.live += 1;
        Ok((block.memory, offset, size, Placement::Block(i), mapped))
    }

    /// Refuses, before asking the driver, a size that can never succeed: larger than the
    /// type's heap or than maxMemoryAllocationSize. (Drivers that allocate from the host,
    /// lavapipe among them, may otherwise try and take the machine's memory with them.)
    fn check(&self, what: &'static str, size: u64, type_index: u32) -> Result<()> {
        let heap_size = self.heap_size(type_index);
        let too_large = |limit, limit_name| Error::TooLarge {
            what,
            bytes: size,
            limit,
            limit_name,
        };
        if size > heap_size {
            return Err(too_large(heap_size, "memory heap"));
        }
        if self.max_allocation != 0 && size > self.max_allocation {
            return Err(too_large(self.max_allocation, "maxMemoryAllocationSize"));
        }
        Ok(())
    }

    /// One `vkAllocateMemory`, mapped whole when the type is host-visible and coherent.
    fn allocate_memory(
        &self,
        device: &ash::Device,
        what: &'static str,
        size: u64,
        type_index: u32,
    ) -> Result<(vk::DeviceMemory, Option<MappedPtr>)> {
        let flags = self.memory.memory_types[type_index as usize].property_flags;
        let failed = |result| Error::DeviceMemory {
            what,
            bytes: size,
            memory_type: type_index,
            flags: format!("{flags:?}"),
            result,
        };
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(size)
            .memory_type_index(type_index);
        // SAFETY: a valid allocate info on a live device.
        let memory = unsafe { device.allocate_memory(&info, None) }.map_err(failed)?;
        if !is_mapped(flags) {
            return Ok((memory, None));
        }
        // SAFETY: host-visible memory, not mapped yet; it stays mapped until it is freed
        // (freeing unmaps it).
        match unsafe { device.map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty()) } {
            Ok(p) => Ok((memory, Some(MappedPtr(p.cast())))),
            Err(result) => {
                // SAFETY: the memory was just allocated and nothing uses it.
                unsafe { device.free_memory(memory, None) };
                Err(failed(result))
            }
        }
    }

    fn free(
        &mut self,
        device: &ash::Device,
        type_index: u32,
        placement: Placement,
        memory: vk::DeviceMemory,
        offset: u64,
        size: u64,
    ) {
        self.live -= 1;
        let index = match placement {
            Placement::Dedicated => {
                self.dedicated -= 1;
                self.dedicated_bytes -= size;
                // SAFETY: the allocation owned this memory alone and its resource is gone.
                unsafe { device.free_memory(memory, None) };
                return;
            }
            Placement::Block(i) => i,
        };
        let slots = &mut self.blocks[type_index as usize];
        // An allocation in a block already freed would be a bug of this allocator; freeing
        // nothing is then the safe answer (this runs in Drop, where a panic would abort).
        let Some(block) = slots[index].as_mut() else {
            return;
        };
        block.ranges.free(offset, size);
        let empty = block.ranges.used() == 0;
        // An empty block goes back to the driver unless it is the type's only one: a renderer
        // that changes image size frees and allocates the same amount again.
        let others = slots.iter().filter(|b| b.is_some()).count() > 1;
        if empty && others {
            if let Some(block) = slots[index].take() {
                // SAFETY: no allocation is left in the block.
                unsafe { device.free_memory(block.memory, None) };
            }
        }
    }

    /// Frees every block. Called by the device's `Drop`: every allocation holds the device,
    /// so none is alive then.
    pub(crate) fn free_all(&mut self, device: &ash::Device) {
        // Every allocation holds an Arc of the device, so `live` is 0 here by construction
        // (no check: this runs in the device's Drop).
        for block in self.blocks.iter_mut().flatten().filter_map(Option::take) {
            // SAFETY: no allocation is left (see above) and the device is idle.
            unsafe { device.free_memory(block.memory, None) };
        }
    }
}

/// Memory of the type `usage` asks for, for a resource of `requirements`; `what` names the
/// resource in errors.
pub fn allocate(
    device: &Arc<Device>,
    what: &'static str,
    requirements: &vk::MemoryRequirements,
    usage: MemoryUse,
) -> Result<Allocation> {
    let types = acceptable_memory_types(&device.memory, requirements.memory_type_bits, usage);
    let mut failure = None;
    for type_index in types {
        let placed = device
            .allocator()
            .allocate(&device.raw, what, requirements, type_index);
        match placed {
            Ok((memory, offset, size, placement, mapped)) => {
                return Ok(Allocation {
                    device: device.clone(),
                    memory,
                    offset,
                    size,
                    type_index,
                    placement,
                    mapped,
                })
            }
            // Full or too small: the next acceptable type may have room.
            Err(
                e @ (Error::TooLarge { .. }
                | Error::DeviceMemory {
                    result: vk::Result::ERROR_OUT_OF_DEVICE_MEMORY,
                    ..
                }),
            ) => {
                failure.get_or_insert(e);
            }
            Err(e) => return Err(e),
        }
    }
    Err(failure
        .unwrap_or_else(|| Error::MissingFeature(format!("a memory type for the {what} ({usage:?} use)"))))
}

#[cfg(test)]
mod tests {
    use super::*;

    type F = vk::MemoryPropertyFlags;

    /// A memory table from (heap sizes) and (flags, heap) per type.
    fn table(heaps: &[(u64, bool)], types: &[(F, u32)]) -> vk::PhysicalDeviceMemoryProperties {
        let mut m = vk::PhysicalDeviceMemoryProperties {
            memory_type_count: types.len() as u32,
            memory_heap_count: heaps.len() as u32,
            ..Default::default()
        };
        for (i, &(size, local)) in heaps.iter().enumerate() {
            m.memory_heaps[i] = vk::MemoryHeap {
                size,
                flags: if local {
                    vk::MemoryHeapFlags::DEVICE_LOCAL
                } else {
                    vk::MemoryHeapFlags::empty()
                },
            };
        }
        for (i, &(flags, heap)) in types.iter().enumerate() {
            m.memory_types[i] = vk::MemoryType {
                property_flags: flags,
                heap_index: heap,
            };
        }
        m
    }

    const GIB: u64 = 1 << 30;

    /// The table an NVIDIA data-center GPU (H100, driver 580) reports: VRAM, host memory, and
    /// the 256 MiB window of VRAM the host can map (the BAR).
    fn discrete_gpu() -> vk::PhysicalDeviceMemoryProperties {
        let dl = F::DEVICE_LOCAL;
        let hv = F::HOST_VISIBLE | F::HOST_COHERENT;
        table(
            &[(80 * GIB, true), (1000 * GIB, false), (256 << 20, true)],
            &[
                (F::empty(), 1),
                (dl, 0),
                (dl, 0),
                (hv, 1),
                (hv | F::HOST_CACHED, 1),
                (dl | hv, 2),
            ],
        )
    }

    /// lavapipe's table: one heap of host memory, one type with every host flag.
    fn lavapipe() -> vk::PhysicalDeviceMemoryProperties {
        table(
            &[(16 * GIB, true)],
            &[(
                F::DEVICE_LOCAL | F::HOST_VISIBLE | F::HOST_COHERENT | F::HOST_CACHED,
                0,
            )],
        )
    }

    #[test]
    fn on_a_discrete_gpu_meshes_and_attachments_live_in_vram_the_host_cannot_map() {
        let m = discrete_gpu();
        assert_eq!(choose_memory_type(&m, !0, MemoryUse::Gpu), Some(1));
        // A resource that only allows the second VRAM type gets it.
        assert_eq!(choose_memory_type(&m, 1 << 2, MemoryUse::Gpu), Some(2));
    }

    #[test]
    fn on_a_discrete_gpu_uniforms_go_to_the_bar_and_staging_to_host_memory() {
        let m = discrete_gpu();
        assert_eq!(choose_memory_type(&m, !0, MemoryUse::Uniforms), Some(5));
        assert_eq!(choose_memory_type(&m, !0, MemoryUse::Staging), Some(3));
        // Without the BAR, uniforms fall back to host memory.
        assert_eq!(choose_memory_type(&m, !(1 << 5), MemoryUse::Uniforms), Some(3));
    }

    #[test]
    fn when_the_bar_is_full_uniforms_fall_back_to_host_memory() {
        let m = discrete_gpu();
        assert_eq!(
            acceptable_memory_types(&m, !0, MemoryUse::Uniforms),
            vec![5, 3, 4]
        );
        assert_eq!(
            acceptable_memory_types(&m, !0, MemoryUse::Gpu),
            vec![1, 2, 5, 0, 3, 4]
        );
    }

    #[test]
    fn readback_prefers_host_cached_memory() {
        let m = discrete_gpu();
        assert_eq!(choose_memory_type(&m, !0, MemoryUse::Readback), Some(4));
        assert_eq!(choose_memory_type(&m, !(1 << 4), MemoryUse::Readback), Some(3));
    }

    #[test]
    fn a_mapped_use_never_gets_memory_the_host_cannot_see() {
        let m = discrete_gpu();
        let vram_only = (1 << 1) | (1 << 2);
        for usage in [MemoryUse::Uniforms, MemoryUse::Staging, MemoryUse::Readback] {
            assert_eq!(choose_memory_type(&m, vram_only, usage), None, "{usage:?}");
        }
    }

    #[test]
    fn on_lavapipe_every_use_shares_the_one_host_visible_type() {
        let m = lavapipe();
        for usage in [
            MemoryUse::Gpu,
            MemoryUse::Uniforms,
            MemoryUse::Staging,
            MemoryUse::Readback,
        ] {
            assert_eq!(choose_memory_type(&m, !0, usage), Some(0), "{usage:?}");
        }
        assert!(
            is_mapped(m.memory_types[0].property_flags),
            "lavapipe writes meshes directly"
        );
    }

    #[test]
    fn protected_lazy_and_device_coherent_types_are_never_chosen() {
        let m = table(
            &[(8 * GIB, true)],
            &[
                (F::DEVICE_LOCAL | F::PROTECTED, 0),
                (F::DEVICE_LOCAL | F::LAZILY_ALLOCATED, 0),
                (
                    F::DEVICE_LOCAL | F::HOST_VISIBLE | F::HOST_COHERENT | F::DEVICE_COHERENT_AMD,
                    0,
                ),
                (F::DEVICE_LOCAL | F::HOST_VISIBLE | F::HOST_COHERENT, 0),
            ],
        );
        for usage in [MemoryUse::Gpu, MemoryUse::Uniforms, MemoryUse::Readback] {
            assert_eq!(choose_memory_type(&m, !0, usage), Some(3), "{usage:?}");
        }
    }

    #[test]
    fn a_size_no_heap_or_allocation_can_hold_is_refused_naming_what_and_how_much() {
        let allocator = Allocator::new(discrete_gpu(), 1024, 4 * GIB);
        let e = allocator
            .check("vertex buffer", 5 * GIB, 1)
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "vertex buffer: 5368709120 bytes of device memory asked for, more than the device's \
             maxMemoryAllocationSize (4294967296 bytes)"
        );
        let e = allocator.check("uniform buffer", GIB, 5).unwrap_err().to_string();
        assert!(e.contains("memory heap (268435456 bytes)"), "{e}");
        assert!(allocator.check("color image", 3 * GIB, 1).is_ok());
    }

    /// A block placeholder: the size arithmetic never touches its memory.
    fn fake_block(size: u64) -> Option<Block> {
        Some(Block {
            memory: vk::DeviceMemory::null(),
            ranges: Ranges::new(size),
            mapped: None,
        })
    }

    #[test]
    fn blocks_double_with_the_blocks_alive_and_stay_within_an_eighth_of_their_heap() {
        let mut allocator = Allocator::new(discrete_gpu(), 1024, 0);
        assert_eq!(allocator.block_size(1), 8 << 20);
        allocator.blocks[1].push(fake_block(8 << 20));
        assert_eq!(allocator.block_size(1), 16 << 20);
        allocator.blocks[1].extend((0..40).map(|_| fake_block(1)));
        assert_eq!(
            allocator.block_size(1),
            256 << 20,
            "at most 256 MiB, however many blocks"
        );
        // Freed blocks do not count.
        allocator.blocks[1] = vec![None, None, fake_block(8 << 20)];
        assert_eq!(allocator.block_size(1), 16 << 20);
        // The 256 MiB BAR gets 32 MiB blocks at most.
        allocator.blocks[5].extend((0..4).map(|_| fake_block(1)));
        assert_eq!(allocator.block_size(5), 32 << 20);
    }

    #[test]
    fn ranges_are_aligned_reused_and_merged_when_freed() {
        let mut r = Ranges::new(1024);
        let a = r.allocate(100, 64).unwrap();
        let b = r.allocate(100, 64).unwrap();
        let c = r.allocate(100, 256).unwrap();
        assert_eq!((a, b, c), (0, 128, 256));
        assert_eq!(r.used(), 300);
        // The gap left by alignment (228..256) and the tail are free.
        assert_eq!(r.free_ranges(), 3);
        r.free(b, 100);
        // The hole b left is taken again by something that fits it.
        assert_eq!(r.allocate(64, 64), Some(128));
        r.free(128, 64);
        r.free(a, 100);
        r.free(c, 100);
        assert_eq!(r.used(), 0);
        assert_eq!(r.free_ranges(), 1, "every range merged back into one");
        assert_eq!(r.allocate(1024, 1), Some(0));
        assert_eq!(r.allocate(1, 1), None, "a full block has no room");
    }

    #[test]
    fn a_request_larger_than_any_free_range_is_refused() {
        let mut r = Ranges::new(256);
        let a = r.allocate(96, 1).unwrap();
        let _b = r.allocate(64, 1).unwrap();
        r.free(a, 96);
        // 96 + 96 bytes are free, but not in one piece.
        assert_eq!(r.allocate(128, 1), None);
        assert_eq!(r.allocate(96, 1), Some(0));
        assert_eq!(r.allocate(u64::MAX, 1), None, "no overflow on absurd sizes");
    }
}
