//! What a [`Lighting`] remembers having bound, and in which command buffer (its module docs,
//! "Bindings"): the next recording call into the same command buffer binds only what differs.

use ash::vk;

use super::Lighting;
use crate::draw::record::RunState;

/// What a [`Lighting`] last bound: the command buffer, the device's recording count just after
/// that recording ([`Device::recordings`](crate::vk::Device)), and the bindings.
pub(super) struct Remembered {
    cmd: vk::CommandBuffer,
    recording: u64,
    run: RunState,
}

impl Lighting {
    /// Forgets what ffvk bound: call it after recording commands of your own that bind a
    /// pipeline, descriptor sets, vertex buffers or an index buffer into a command buffer ffvk
    /// draws into, and after resetting or beginning anew a command buffer ffvk drew into, before
    /// ffvk's next draw there ([`Lighting::begin_frame`] forgets too). ffvk then binds everything
    /// its next draw needs. Viewports, scissors, clears, barriers, dynamic state and rendering
    /// passes of your own need no call: they bind nothing.
    pub fn forget_bindings(&self) {
        *self
            .remembered
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner()) = None;
    }

    /// Runs `record` with what ffvk remembers having bound in `cmd` (nothing, for another
    /// command buffer than the last, or when another `Lighting` on this device recorded since:
    /// its binds may have replaced these), and remembers what it leaves bound.
    pub(super) fn with_remembered(&self, cmd: vk::CommandBuffer, record: impl FnOnce(&mut RunState)) {
        let mut remembered = self
            .remembered
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        let before = self
            .device
            .recordings
            .fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        let mut run = match remembered.take() {
            Some(last) if last.cmd == cmd && last.recording == before => last.run,
            _ => RunState::default(),
        };
        record(&mut run);
        *remembered = Some(Remembered {
            cmd,
            recording: before.wrapping_add(1),
            run,
        });
    }
}
