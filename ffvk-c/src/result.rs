//! Result codes for what is not a GL error (a missing feature, memory, a Vulkan failure, a
//! misused call), the message behind the last one, and the panic barrier every entry point
//! stands behind.

use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// What an `FfvkResult`-returning entry point reports. Every code but `FFVK_SUCCESS` comes
/// with a message, `ffvkResultMessage()`, naming what failed and what was expected.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(non_camel_case_types)]
pub enum FfvkResult {
    /// It worked.
    FFVK_SUCCESS = 0,
    /// A null pointer, a wrong `struct_size`, a value out of range or a call out of order
    /// (e.g. `ffvkDraw` outside `ffvkBeginDraws` … `ffvkEndDraws`). Nothing changed.
    FFVK_ERROR_INVALID_ARGUMENT = -1,
    /// The device lacks something ffvk needs (Vulkan 1.3, dynamic rendering, a feature the
    /// caller said it enabled), or the caller did not enable it.
    FFVK_ERROR_MISSING_FEATURE = -2,
    /// Host or device memory ran out.
    FFVK_ERROR_OUT_OF_MEMORY = -3,
    /// A Vulkan call failed (the message names it and its `VkResult`), or the device was lost.
    FFVK_ERROR_VULKAN = -4,
    /// The context's GL state cannot be drawn (e.g. a soft spot edge wider than its cutoff, a
    /// modelview that cannot be inverted): the message names the parameter and value.
    FFVK_ERROR_STATE = -5,
    /// An internal error (a panic inside ffvk, caught at the boundary). The object it
    /// happened on should be destroyed.
    FFVK_ERROR_INTERNAL = -6,
}

thread_local! {
    static MESSAGE: RefCell<CString> = RefCell::new(CString::default());
}

/// Stores `message` as this thread's last message and returns `code`.
pub(crate) fn fail(code: FfvkResult, message: impl Into<String>) -> FfvkResult {
    let text = message.into().replace('\0', " ");
    MESSAGE.with(|m| *m.borrow_mut() = CString::new(text).unwrap_or_default());
    code
}

/// The code for one of ffvk's errors, with its message stored: `function`'s name first, and
/// for a feature the caller did not declare, the `FFVK_FEATURE_*` bit that declares it.
pub(crate) fn from_error(function: &str, e: &ffvk::Error) -> FfvkResult {
    use ffvk::Error as E;
    let code = match e {
        E::MissingFeature(_) | E::NotEnabled { .. } | E::NoLoader(_) | E::NoDevice { .. } => {
            FfvkResult::FFVK_ERROR_MISSING_FEATURE
        }
        E::OutOfMemory { .. } | E::Alloc(_) | E::DeviceMemory { .. } | E::TooLarge { .. } => {
            FfvkResult::FFVK_ERROR_OUT_OF_MEMORY
        }
        E::Vulkan { .. } | E::DeviceLost(_) | E::Validation(_) | E::NoValidationLayer => {
            FfvkResult::FFVK_ERROR_VULKAN
        }
        E::State(_) => FfvkResult::FFVK_ERROR_STATE,
        E::InRun { source, .. } if matches!(**source, E::State(_)) => FfvkResult::FFVK_ERROR_STATE,
        E::Internal(_) => FfvkResult::FFVK_ERROR_INTERNAL,
        _ => FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
    };
    let hint = match e {
        E::NotEnabled { flag, .. } => format!(
            " (in C: the FFVK_FEATURE_{} bit of FfvkRendererCreateInfo::enabled_features)",
            flag.to_uppercase()
        ),
        _ => String::new(),
    };
    fail(code, format!("{function}: {e}{hint}"))
}

/// Runs `f` behind the panic barrier: a panic becomes `FFVK_ERROR_INTERNAL` with its message.
pub(crate) fn guard(f: impl FnOnce() -> FfvkResult) -> FfvkResult {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(code) => code,
        Err(payload) => fail(
            FfvkResult::FFVK_ERROR_INTERNAL,
            format!("internal error (a panic inside ffvk): {}", panic_text(&payload)),
        ),
    }
}

/// Whether `ptr` is neither null nor aligned for `T`: it cannot point at a `T` (C's rule as
/// Rust's), so an entry point refuses it as it refuses null instead of following it (which
/// is undefined behaviour, and an abort in a build with debug assertions).
pub(crate) fn misaligned<T>(ptr: *const T) -> bool {
    !ptr.is_null() && !ptr.is_aligned()
}

/// `FFVK_ERROR_INVALID_ARGUMENT` naming `function`'s pointer parameter `name` when it is null
/// or misaligned, and what was `expected` of it.
pub(crate) fn check_ptr<T>(
    function: &str,
    name: &str,
    ptr: *const T,
    expected: &str,
) -> Result<(), FfvkResult> {
    if ptr.is_null() {
        return Err(fail(
            FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
            format!("{function}: {name} is a null pointer: expected {expected}"),
        ));
    }
    if misaligned(ptr) {
        return Err(fail(
            FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
            format!(
                "{function}: {name} {ptr:p} is not aligned to {} bytes: expected {expected}",
                std::mem::align_of::<T>()
            ),
        ));
    }
    Ok(())
}

/// Frees an object the API handed out (null is ignored); a panic while dropping it is caught.
///
/// # Safety
///
/// `ptr` is null or came from `Box::into_raw` and is not used again.
pub(crate) unsafe fn free<T>(ptr: *mut T) {
    if ptr.is_null() {
        return;
    }
    // SAFETY: the caller's contract: a box this API made, freed once.
    let boxed = unsafe { Box::from_raw(ptr) };
    let _ = catch_unwind(AssertUnwindSafe(move || drop(boxed)));
}

/// A caught panic's message.
pub(crate) fn panic_text(payload: &Box<dyn std::any::Any + Send>) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "no message".to_string())
}

/// The message of the last call on this thread that returned an error code (or set a GL error
/// through a context): what failed, the value, what was expected. Never null; "" before any
/// failure. `ffvkDeviceRequirements` sets it when it succeeds too: what the device lacks, or
/// "". The string is ffvk's, valid until the next ffvk call on this thread.
#[no_mangle]
pub extern "C" fn ffvkResultMessage() -> *const c_char {
    catch_unwind(|| MESSAGE.with(|m| m.borrow().as_ptr())).unwrap_or(c"internal error".as_ptr())
}
