//! ffvk's shader library from C: the interface version and each file's text
//! (`ffvkShaderLibraryFile`), for a compiler's include callback or for inlining; `make install-c`
//! installs the same files beside `ffvk.h`, under `ffvk/`.

use std::ffi::{c_char, CStr};

use crate::result::{check_ptr, fail, guard, FfvkResult};

/// The shader library's interface version (`FFVK_LIBRARY_VERSION` in `ffvk/state.glsl`): a
/// change of the state block, a function's inputs or outputs, a specialization constant or
/// what the caller defines is a new version.
#[no_mangle]
pub extern "C" fn ffvkShaderLibraryVersion() -> u32 {
    ffvk::shaders::LIBRARY_VERSION
}

/// Writes the text of the library file `name` (as a shader includes it: `"ffvk/lighting.glsl"`)
/// to `*source` and its length in bytes to `*length`. The text is ffvk's, valid for the life
/// of the process, and not NUL-terminated. `FFVK_ERROR_INVALID_ARGUMENT` for a null or
/// misaligned pointer and for a name the library does not have (the message lists its files);
/// `*source` is then null and `*length` 0.
///
/// # Safety
///
/// `name` is null or a NUL-terminated string; `source` and `length` are null or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkShaderLibraryFile(
    name: *const c_char,
    source: *mut *const c_char,
    length: *mut usize,
) -> FfvkResult {
    const F: &str = "ffvkShaderLibraryFile";
    guard(|| {
        if let Err(code) = check_ptr(F, "source", source, "where to write the file's text") {
            return code;
        }
        if let Err(code) = check_ptr(F, "length", length, "where to write the text's length") {
            return code;
        }
        // SAFETY: both checked non-null and aligned; the caller's contract makes them
        // writable. Cleared first, so that a caller reading them after an error reads nothing.
        unsafe {
            *source = std::ptr::null();
            *length = 0;
        }
        if name.is_null() {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{F}: name is a null pointer: expected a file's name, as \"ffvk/lighting.glsl\""),
            );
        }
        // SAFETY: the caller's contract: a NUL-terminated string.
        let given = unsafe { CStr::from_ptr(name) }.to_string_lossy();
        let Some(file) = ffvk::shaders::file(&given) else {
            let names: Vec<&str> = ffvk::shaders::FILES.iter().map(|f| f.name).collect();
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!(
                    "{F}: name {given:?}: the shader library has no such file (expected one of {})",
                    names.join(", ")
                ),
            );
        };
        // SAFETY: checked above; the text is static.
        unsafe {
            *source = file.source.as_ptr().cast();
            *length = file.source.len();
        }
        FfvkResult::FFVK_SUCCESS
    })
}
