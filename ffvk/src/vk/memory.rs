//! Device memory through gpu-allocator (the ash ecosystem's allocator): the memory type and the
//! blocks are its; what stays ffvk's is which location each use asks for ([`MemoryUse`]),
//! which resources get memory of their own, errors naming what was being allocated and how
//! much, and the books of what ffvk holds ([`MemoryUsage`]).
//!
//! A device's allocator is ffvk's own, or with the `shared-allocator` feature the embedder's
//! (an `Arc<Mutex<gpu_allocator::vulkan::Allocator>>` of the same device, see
//! `Device::from_caller_with_allocator`); ffvk's
//! allocations in it are named `ffvk: <what>` and all returned when their resources drop.

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};

use ash::vk;
use gpu_allocator::vulkan::{
    Allocation as GpuAllocation, AllocationCreateDesc, AllocationScheme, Allocator as GpuAllocator,
    AllocatorCreateDesc,
};
use gpu_allocator::{AllocationSizes, AllocatorDebugSettings, MemoryLocation};

use crate::error::{Error, Result};

/// What a resource's memory is for; decides the gpu-allocator location it asks for
/// ([`MemoryUse::location`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum MemoryUse {
    /// Read and written by the GPU alone: vertex and index buffers, attachments
    /// ([`MemoryLocation::GpuOnly`]). On devices whose device-local memory is host-visible
    /// (lavapipe, integrated GPUs) the host writes it directly.
    Gpu,
    /// Written by the host for every frame and read by the GPU: the draws' state blocks and
    /// records ([`MemoryLocation::CpuToGpu`]: device-local and host-visible where the device
    /// has it, a GPU's BAR, else host memory).
    Uniforms,
    /// Written once by the host and copied by the GPU into [`MemoryUse::Gpu`] memory
    /// ([`MemoryLocation::CpuToGpu`]; gpu-allocator has no location for host memory that
    /// avoids the BAR, so on a discrete GPU staging may take BAR memory).
    Staging,
    /// Written by the GPU and read by the host: the rendered image
    /// ([`MemoryLocation::GpuToCpu`]: host-cached where the device offers it).
    Readback,
}

impl MemoryUse {
    /// Every use, in the order `ffvk info` prints them.
    pub const ALL: [MemoryUse; 4] = [
        MemoryUse::Gpu,
        MemoryUse::Uniforms,
        MemoryUse::Staging,
        MemoryUse::Readback,
    ];

    /// The location this use asks gpu-allocator for.
    pub fn location(self) -> MemoryLocation {
        match self {
            MemoryUse::Gpu => MemoryLocation::GpuOnly,
            MemoryUse::Uniforms | MemoryUse::Staging => MemoryLocation::CpuToGpu,
            MemoryUse::Readback => MemoryLocation::GpuToCpu,
        }
    }

    /// Whether the host writes or reads the memory (it must then be mapped).
    fn mapped(self) -> bool {
        self != MemoryUse::Gpu
    }
}

/// From this size on a resource gets memory of its own (a dedicated allocation) rather than
/// a place in a shared block: half the first block, so that a block never holds one resource
/// that would fill it.
pub const DEDICATED_BYTES: u64 = FIRST_BLOCK / 2;
/// The first block of a memory type; gpu-allocator doubles the blocks it adds while others
/// are alive, up to [`MAX_BLOCK`].
const FIRST_BLOCK: u64 = 8 << 20;
/// The largest block.
const MAX_BLOCK: u64 = 256 << 20;

/// How much device memory a device's allocator holds and how much of it ffvk uses.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct MemoryUsage {
    /// Memory blocks the allocator holds (with a shared allocator, the embedder's too),
    /// dedicated allocations among them.
    pub blocks: usize,
    /// Their bytes.
    pub block_bytes: u64,
    /// ffvk's resources with memory of their own (from [`DEDICATED_BYTES`] up).
    pub dedicated: usize,
    /// Their bytes.
    pub dedicated_bytes: u64,
    /// ffvk's allocations alive: resources not yet dropped. Zero once every buffer and image
    /// of the device is gone; more means something still holds one.
    pub live: usize,
    /// Bytes those allocations use.
    pub used_bytes: u64,
}

/// A pointer into mapped device memory.
#[derive(Debug, Clone, Copy)]
pub(crate) struct MappedPtr(*mut u8);

// SAFETY: the pointer is plain address arithmetic into a mapping that lives as long as its
// allocation; who may write through it is decided by the allocation's owner (`&mut`).
unsafe impl Send for MappedPtr {}
// SAFETY: as above.
unsafe impl Sync for MappedPtr {}

impl MappedPtr {
    pub(crate) fn get(self) -> *mut u8 {
        self.0
    }
}

/// The allocator of one device: ffvk's own, or the embedder's.
pub(crate) enum DeviceAllocator {
    /// Made by ffvk with the device; `None` once the device's `Drop` has released it (before
    /// the device is destroyed).
    Own(Box<Mutex<Option<GpuAllocator>>>),
    /// The embedder's, shared.
    #[cfg_attr(not(feature = "shared-allocator"), allow(dead_code))]
    Shared(Arc<Mutex<GpuAllocator>>),
}

/// ffvk's books of its own allocations (the allocator's report counts the embedder's too).
#[derive(Default)]
pub(crate) struct Books {
    live: AtomicUsize,
    used: AtomicU64,
    dedicated: AtomicUsize,
    dedicated_bytes: AtomicU64,
}

impl DeviceAllocator {
    /// ffvk's own allocator for a device.
    pub(crate) fn own(
        instance: &ash::Instance,
        device: &ash::Device,
        physical_device: vk::PhysicalDevice,
    ) -> Result<Self> {
        let desc = AllocatorCreateDesc {
            instance: instance.clone(),
            device: device.clone(),
            physical_device,
            // Leaks are warned of through the `log` crate (gpu-allocator's default), and ffvk
            // keeps its own books (MemoryUsage::live).
            debug_settings: AllocatorDebugSettings::default(),
            buffer_device_address: false,
            allocation_sizes: AllocationSizes::new(FIRST_BLOCK, FIRST_BLOCK)
                .with_max_device_memblock_size(MAX_BLOCK)
                .with_max_host_memblock_size(MAX_BLOCK / 4),
        };
        let allocator = GpuAllocator::new(&desc).map_err(|source| Error::Allocator {
            what: "the device's allocator",
            source,
        })?;
        Ok(DeviceAllocator::Own(Box::new(Mutex::new(Some(allocator)))))
    }

    /// The allocator, locked.
    fn lock(&self) -> Locked<'_> {
        // A panic while the lock was held leaves gpu-allocator's books as they were before
        // the call that panicked, or with one allocation more: never inconsistent.
        match self {
            DeviceAllocator::Own(m) => Locked::Own(m.lock().unwrap_or_else(|p| p.into_inner())),
            DeviceAllocator::Shared(m) => Locked::Shared(m.lock().unwrap_or_else(|p| p.into_inner())),
        }
    }

    /// Releases ffvk's own allocator (its blocks), for the device's `Drop`; a shared one is
    /// the embedder's to drop.
    pub(crate) fn release(&mut self) {
        if let DeviceAllocator::Own(m) = self {
            drop(m.get_mut().unwrap_or_else(|p| p.into_inner()).take());
        }
    }
}

/// A locked allocator.
enum Locked<'a> {
    Own(MutexGuard<'a, Option<GpuAllocator>>),
    Shared(MutexGuard<'a, GpuAllocator>),
}

impl Locked<'_> {
    fn get(&mut self) -> Option<&mut GpuAllocator> {
        match self {
            Locked::Own(g) => g.as_mut(),
            Locked::Shared(g) => Some(g),
        }
    }
}

/// What a resource is, for gpu-allocator: a buffer (linear) or an optimally tiled image.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Resource {
    Buffer(vk::Buffer),
    Image(vk::Image),
}

/// One of ffvk's allocations, as the device's allocator gave it.
pub(crate) struct Placed {
    pub(crate) inner: GpuAllocation,
    /// Where the host sees its first byte, when the memory is host-visible and coherent.
    pub(crate) mapped: Option<MappedPtr>,
}

/// What the device knows that an allocation is checked against: its memory table and
/// `maxMemoryAllocationSize` (0: unknown).
pub(crate) struct Limits<'a> {
    pub(crate) memory: &'a vk::PhysicalDeviceMemoryProperties,
    pub(crate) max_allocation: u64,
}

impl DeviceAllocator {
    /// Memory of the location `usage` asks for, for `resource` of `requirements`; `what`
    /// names the resource in errors.
    pub(crate) fn allocate(
        &self,
        books: &Books,
        limits: &Limits,
        what: &'static str,
        resource: Resource,
        requirements: &vk::MemoryRequirements,
        usage: MemoryUse,
    ) -> Result<Placed> {
        check_size(limits, what, requirements)?;
        // gpu-allocator picks among the types the requirements allow: those no ffvk resource
        // may use are taken out of them first.
        let requirements = &vk::MemoryRequirements {
            memory_type_bits: usable_types(limits.memory, requirements.memory_type_bits),
            ..*requirements
        };
        if requirements.memory_type_bits == 0 {
            return Err(Error::MissingFeature(format!(
                "a memory type for the {what} that is not protected, lazily allocated or AMD \
                 device-coherent"
            )));
        }
        let dedicated = requirements.size >= DEDICATED_BYTES;
        let name = format!("ffvk: {what}");
        let desc = AllocationCreateDesc {
            name: &name,
            requirements: *requirements,
            location: usage.location(),
            linear: matches!(resource, Resource::Buffer(_)),
            allocation_scheme: match (dedicated, resource) {
                (false, _) => AllocationScheme::GpuAllocatorManaged,
                (true, Resource::Buffer(b)) => AllocationScheme::DedicatedBuffer(b),
                (true, Resource::Image(i)) => AllocationScheme::DedicatedImage(i),
            },
        };
        let inner = {
            let mut locked = self.lock();
            let allocator = locked
                .get()
                .ok_or(Error::Internal("an allocation on a device being dropped"))?;
            allocator.allocate(&desc).map_err(|source| Error::DeviceMemory {
                what,
                bytes: requirements.size,
                location: usage.location(),
                source,
            })?
        };
        let coherent = vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
        let mapped = inner
            .mapped_ptr()
            .filter(|_| inner.memory_properties().contains(coherent))
            .map(|p| MappedPtr(p.as_ptr().cast()));
        books.add(&inner, 1);
        let placed = Placed { inner, mapped };
        if usage.mapped() && placed.mapped.is_none() {
            let flags = placed.inner.memory_properties();
            self.free(books, placed.inner);
            return Err(Error::MissingFeature(format!(
                "host-visible, coherent memory for the {what} ({usage:?} use): gpu-allocator gave {flags:?}"
            )));
        }
        Ok(placed)
    }

    /// Returns an allocation.
    pub(crate) fn free(&self, books: &Books, inner: GpuAllocation) {
        books.add(&inner, -1);
        if let Some(allocator) = self.lock().get() {
            // gpu-allocator fails a free only for an allocation it does not know, which ffvk
            // never hands it; nothing can be reported from a Drop.
            let _ = allocator.free(inner);
        }
    }

    /// The device's usage (see [`MemoryUsage`]).
    pub(crate) fn usage(&self, books: &Books) -> MemoryUsage {
        let (blocks, block_bytes) = match self.lock().get() {
            Some(a) => {
                let report = a.generate_report();
                (report.blocks.len(), report.total_capacity_bytes)
            }
            None => (0, 0),
        };
        MemoryUsage {
            blocks,
            block_bytes,
            dedicated: books.dedicated.load(Ordering::Relaxed),
            dedicated_bytes: books.dedicated_bytes.load(Ordering::Relaxed),
            live: books.live.load(Ordering::Relaxed),
            used_bytes: books.used.load(Ordering::Relaxed),
        }
    }
}

impl Books {
    /// Counts `inner` in (`sign` 1) or out (-1).
    fn add(&self, inner: &GpuAllocation, sign: i8) {
        let (one, bytes) = (1usize, inner.size());
        let (live, used, dedicated, dedicated_bytes) =
            (&self.live, &self.used, &self.dedicated, &self.dedicated_bytes);
        if sign > 0 {
            live.fetch_add(one, Ordering::Relaxed);
            used.fetch_add(bytes, Ordering::Relaxed);
            if inner.is_dedicated() {
                dedicated.fetch_add(one, Ordering::Relaxed);
                dedicated_bytes.fetch_add(bytes, Ordering::Relaxed);
            }
        } else {
            live.fetch_sub(one, Ordering::Relaxed);
            used.fetch_sub(bytes, Ordering::Relaxed);
            if inner.is_dedicated() {
                dedicated.fetch_sub(one, Ordering::Relaxed);
                dedicated_bytes.fetch_sub(bytes, Ordering::Relaxed);
            }
        }
    }
}

/// Flags of memory types no ffvk resource may use: protected memory, lazily allocated
/// (transient attachments only) and AMD's device-coherent or uncached types (slow, meant for
/// debugging, and needing a feature ffvk does not enable).
const NEVER: vk::MemoryPropertyFlags = vk::MemoryPropertyFlags::from_raw(
    vk::MemoryPropertyFlags::PROTECTED.as_raw()
        | vk::MemoryPropertyFlags::LAZILY_ALLOCATED.as_raw()
        | vk::MemoryPropertyFlags::DEVICE_COHERENT_AMD.as_raw()
        | vk::MemoryPropertyFlags::DEVICE_UNCACHED_AMD.as_raw(),
);

/// `type_bits` without the memory types of [`NEVER`]'s flags.
fn usable_types(memory: &vk::PhysicalDeviceMemoryProperties, type_bits: u32) -> u32 {
    let count = memory.memory_type_count.min(vk::MAX_MEMORY_TYPES as u32);
    (0..count)
        .filter(|&i| !memory.memory_types[i as usize].property_flags.intersects(NEVER))
        .fold(0, |bits, i| bits | (1 << i))
        & type_bits
}

/// Refuses a size no heap the resource may use can hold, or past `maxMemoryAllocationSize`,
/// before asking: the error names the resource and the limit.
fn check_size(limits: &Limits, what: &'static str, requirements: &vk::MemoryRequirements) -> Result<()> {
    let memory = limits.memory;
    let count = memory.memory_type_count.min(vk::MAX_MEMORY_TYPES as u32) as usize;
    let largest_heap = (0..count)
        .filter(|&i| requirements.memory_type_bits & (1 << i) != 0)
        .map(|i| memory.memory_heaps[memory.memory_types[i].heap_index as usize].size)
        .max()
        .unwrap_or(0);
    let too_large = |limit, limit_name| Error::TooLarge {
        what,
        bytes: requirements.size,
        limit,
        limit_name,
    };
    if requirements.size > largest_heap {
        return Err(too_large(largest_heap, "memory heap"));
    }
    if limits.max_allocation != 0 && requirements.size > limits.max_allocation {
        return Err(too_large(limits.max_allocation, "maxMemoryAllocationSize"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_use_asks_for_its_location() {
        assert_eq!(MemoryUse::Gpu.location(), MemoryLocation::GpuOnly);
        assert_eq!(MemoryUse::Uniforms.location(), MemoryLocation::CpuToGpu);
        assert_eq!(MemoryUse::Staging.location(), MemoryLocation::CpuToGpu);
        assert_eq!(MemoryUse::Readback.location(), MemoryLocation::GpuToCpu);
        // Every use but the GPU's is written or read by the host.
        assert!(MemoryUse::ALL
            .iter()
            .all(|u| u.mapped() == (*u != MemoryUse::Gpu)));
    }

    #[test]
    fn protected_lazy_and_amd_device_coherent_types_are_never_offered_to_gpu_allocator() {
        type F = vk::MemoryPropertyFlags;
        let mut memory = vk::PhysicalDeviceMemoryProperties {
            memory_type_count: 5,
            ..Default::default()
        };
        for (i, flags) in [
            F::DEVICE_LOCAL | F::PROTECTED,
            F::DEVICE_LOCAL | F::LAZILY_ALLOCATED,
            F::DEVICE_LOCAL | F::HOST_VISIBLE | F::HOST_COHERENT | F::DEVICE_COHERENT_AMD,
            F::HOST_VISIBLE | F::HOST_COHERENT | F::DEVICE_UNCACHED_AMD,
            F::DEVICE_LOCAL,
        ]
        .into_iter()
        .enumerate()
        {
            memory.memory_types[i].property_flags = flags;
        }
        assert_eq!(usable_types(&memory, !0), 1 << 4);
        assert_eq!(usable_types(&memory, 0b01111), 0);
    }

    #[test]
    fn a_refused_allocation_names_what_how_much_and_where() {
        let e = Error::DeviceMemory {
            what: "vertex buffer",
            bytes: 1 << 40,
            location: MemoryUse::Gpu.location(),
            source: gpu_allocator::AllocationError::OutOfMemory,
        };
        let text = e.to_string();
        assert!(
            text.contains("vertex buffer")
                && text.contains("1099511627776 bytes")
                && text.contains("GpuOnly"),
            "{text}"
        );
    }
}
