//! How the C API's structs grow without breaking a program built against an older `ffvk.h`.
//!
//! The rule (stated in the header on each struct, and in docs/c-api.md):
//!
//! - A struct the API reads from the caller and that may grow starts with `uint32_t
//!   struct_size`, which the caller sets to `sizeof` of the struct as its `ffvk.h` declared it.
//!   Today these are `FfvkRendererCreateInfo`, `FfvkDrawInfo` (version 2 added `layout`, version 3 `raster_source`,
//!   version 4 `texture1` .. `texture3`) and `FfvkVertexLayoutInfo` (version 2 added `texcoord1` ..
//!   `texcoord3`).
//! - Such a struct grows only at its end: a new version of the header appends fields and never
//!   removes, reorders or retypes one. Each published header that changed a struct's size is a
//!   version of that struct, numbered from 1 (the first header: every struct is at version 1).
//! - The library accepts the size of every version it knows, reads only the prefix that size
//!   covers (never a byte past it) and gives each field beyond it the default its documentation
//!   names. Any other size (0, too small, between two versions, or larger than the newest
//!   version this library knows, from a newer header than the library) is refused with
//!   `FFVK_ERROR_INVALID_ARGUMENT` and a message naming the function, the struct, the size given
//!   and the sizes accepted.
//! - A struct without `struct_size` never changes: `FfvkAttribute`, `FfvkMeshArrays` and
//!   `FfvkRaster` (which `ffvkRasterDefaults` fills whole, so a larger one would overrun an
//!   older caller's). New raster state is appended to `FfvkDrawInfo` itself, as new fields of a
//!   new version, with GL's initial value as the default.
//! - New behaviour that needs no struct comes as new functions; no function's signature changes.
//!
//! How to add a version (for ffvk's maintainers, in `render/versions.rs`): append the fields to
//! the struct with a doc comment naming each one's default; freeze the previous version with
//! `frozen_version!` (once it was published, so that its size no longer follows the struct's);
//! append a [`Version`] to the struct's [`Versioned::VERSIONS`] whose `first_field` is the
//! offset of the first new field; and give the new fields their defaults in
//! [`Versioned::defaults`]. The checks fail to compile when a struct grew without a version,
//! when a version's fields start inside the previous version's tail padding (a caller's
//! padding bytes would be read as fields), or when a frozen version's fields moved.

use std::mem::{size_of, MaybeUninit};

use crate::result::{fail, FfvkResult};

/// One published version of a struct.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Version {
    /// `sizeof` the struct as the header of this version declared it.
    pub size: usize,
    /// Where this version's first new field lies in the struct (0 for version 1: the struct
    /// starts with `struct_size`).
    pub first_field: usize,
}

/// A struct the caller passes with a `struct_size`: `FfvkRendererCreateInfo`, `FfvkDrawInfo`
/// and `FfvkVertexLayoutInfo` (their versions are in `render/versions.rs`).
///
/// # Safety
///
/// The type is `#[repr(C)]` with `struct_size: u32` as its first field, and every field
/// accepts any bit pattern (integers, raw pointers, nullable function pointers, Vulkan's
/// transparent handles and enums): the caller's bytes are copied into it as they are, and
/// checked afterwards by the entry point.
pub unsafe trait Versioned: Sized {
    /// The struct's C name, for messages.
    const NAME: &'static str;
    /// Its published versions, oldest first; the last is the struct as this crate declares it.
    const VERSIONS: &'static [Version];
    /// The struct with every field at its documented default (what a field beyond the
    /// caller's version reads as), and `struct_size` the current size.
    fn defaults() -> Self;
}

/// Fails to compile unless `T`'s versions are consistent: version 1 starts at the struct's
/// start, each later version is larger and its fields start at or after the previous size,
/// and the last version is the struct as declared now.
pub(crate) const fn check_versions<T: Versioned>() {
    let v = T::VERSIONS;
    assert!(!v.is_empty(), "a versioned struct has at least version 1");
    assert!(v[0].first_field == 0, "version 1 starts at the struct's start");
    let mut i = 1;
    while i < v.len() {
        assert!(
            v[i].size > v[i - 1].size,
            "a version is larger than the one before it: the new fields fit in the previous version's tail padding; pad to its size first"
        );
        assert!(
            v[i].first_field >= v[i - 1].size,
            "a version's new fields start at or after the previous version's size, never in its tail padding"
        );
        i += 1;
    }
    assert!(
        v[v.len() - 1].size == size_of::<T>(),
        "the struct's size is not its last version's: a field was added without a Version in ffvk-c/src/render/versions.rs (see ffvk-c/src/abi.rs)"
    );
}

/// Declares a frozen copy of a published version of a struct (a `#[repr(C)]` struct with that
/// version's fields, whose size is the version's size on every target), and fails to compile
/// unless the current struct still has each of those fields at the same offset with the same
/// type.
macro_rules! frozen_version {
    ($(#[$doc:meta])* $frozen:ident of $current:ident { $($field:ident: $ty:ty),* $(,)? }) => {
        $(#[$doc])*
        #[repr(C)]
        #[allow(dead_code)]
        struct $frozen {
            $($field: $ty),*
        }
        const _: () = {
            $(assert!(
                ::std::mem::offset_of!($frozen, $field) == ::std::mem::offset_of!($current, $field),
                concat!(
                    stringify!($current), "::", stringify!($field),
                    " moved: a published version's fields keep their offsets"
                )
            );)*
        };
        const _: () = {
            /// Fails to compile unless each frozen field has the current field's type.
            #[allow(dead_code)]
            fn same_types(current: &$current) {
                $(let _: &$ty = &current.$field;)*
            }
        };
    };
}
pub(crate) use frozen_version;

/// The sizes `T` accepts, for a message: `136 (version 1)`, `136 (version 1) or 144 (version 2)`.
fn accepted<T: Versioned>() -> String {
    let sizes: Vec<String> = T::VERSIONS
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{} (version {})", v.size, i + 1))
        .collect();
    sizes.join(" or ")
}

/// Reads the caller's `T` at `ptr`: its `struct_size` must be the size of a version of `T`,
/// of which exactly that many bytes are read; the fields beyond them keep their defaults.
/// Otherwise `FFVK_ERROR_INVALID_ARGUMENT` naming `function`, the struct, the size given and
/// the sizes accepted, and nothing past `struct_size` is read.
///
/// # Safety
///
/// `ptr` is non-null and aligned for `T` (the entry point checked both), and points at a `u32`
/// `struct_size` followed by at least that many bytes in all, as the caller's header declared
/// the struct.
pub(crate) unsafe fn read<T: Versioned>(function: &str, ptr: *const T) -> Result<T, FfvkResult> {
    // SAFETY: struct_size is T's first field (checked at compile time above), a u32 at ptr,
    // which is aligned for T and so for u32.
    let given = unsafe { ptr.cast::<u32>().read() };
    let newest = T::VERSIONS[T::VERSIONS.len() - 1].size;
    if !T::VERSIONS.iter().any(|v| v.size == given as usize) {
        let why = if given as usize > newest {
            format!(
                ": larger than any version this library (ffvk-c {}) knows, so the program was built against a newer ffvk.h than the library it runs with",
                env!("CARGO_PKG_VERSION")
            )
        } else if (given as usize) < T::VERSIONS[0].size {
            String::from(": smaller than version 1")
        } else {
            String::from(": between versions, not the size of any ffvk.h's struct")
        };
        let name = T::NAME;
        return Err(fail(
            FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
            format!(
                "{function}: {name}.struct_size is {given}{why}: expected sizeof({name}) as a published ffvk.h declares it, {}",
                accepted::<T>()
            ),
        ));
    }
    let mut value = MaybeUninit::new(T::defaults());
    // SAFETY: the caller's contract: `given` bytes are readable at ptr; given <= size_of::<T>()
    // (it is one of T's versions, the largest of which is T), so they fit in `value`. Each
    // version's fields start at or after the previous version's size (checked at compile
    // time), so the bytes copied are whole fields of the caller's version and its padding;
    // every field of T takes any bit pattern (Versioned's contract).
    unsafe {
        std::ptr::copy_nonoverlapping(ptr.cast::<u8>(), value.as_mut_ptr().cast::<u8>(), given as usize);
    }
    // SAFETY: initialized from defaults, then partly overwritten by valid field values.
    Ok(unsafe { value.assume_init() })
}

#[cfg(test)]
mod tests {
    use std::mem::offset_of;

    use super::*;

    /// A struct at version 2: version 1 had `struct_size` and `a`; version 2 appended `b`.
    #[repr(C)]
    struct Grown {
        struct_size: u32,
        a: u32,
        b: u64,
    }

    /// Version 1 of [`Grown`] as an old header declared it.
    #[repr(C)]
    struct GrownV1 {
        struct_size: u32,
        a: u32,
    }

    // SAFETY: repr(C), struct_size first, integer fields.
    unsafe impl Versioned for Grown {
        const NAME: &'static str = "Grown";
        const VERSIONS: &'static [Version] = &[
            Version {
                size: size_of::<GrownV1>(),
                first_field: 0,
            },
            Version {
                size: size_of::<Grown>(),
                first_field: offset_of!(Grown, b),
            },
        ];
        fn defaults() -> Self {
            Grown {
                struct_size: size_of::<Grown>() as u32,
                a: 0,
                b: 7,
            }
        }
    }

    const _: () = check_versions::<Grown>();

    fn message() -> String {
        // SAFETY: never null; copied at once.
        unsafe { std::ffi::CStr::from_ptr(crate::result::ffvkResultMessage()) }
            .to_string_lossy()
            .into_owned()
    }

    #[test]
    fn a_version_1_struct_is_read_up_to_its_size_and_the_later_fields_take_their_defaults() {
        // Version 1 followed by bytes that version 2 would read as `b`: they are not read.
        #[repr(C)]
        struct Followed {
            v1: GrownV1,
            after: u64,
        }
        let followed = Followed {
            v1: GrownV1 {
                struct_size: size_of::<GrownV1>() as u32,
                a: 3,
            },
            after: 0xDEAD_BEEF,
        };
        let ptr = std::ptr::from_ref(&followed).cast::<Grown>();
        // SAFETY: aligned for Grown (Followed has its alignment); struct_size bytes readable.
        let read = unsafe { read("grow", ptr) }.expect("version 1's size is accepted");
        assert_eq!(
            (read.a, read.b),
            (3, 7),
            "b is its default, not the bytes after version 1"
        );
    }

    #[test]
    fn the_newest_version_is_read_whole() {
        let grown = Grown {
            struct_size: size_of::<Grown>() as u32,
            a: 3,
            b: 9,
        };
        // SAFETY: a whole, aligned struct.
        let read = unsafe { read("grow", &grown) }.expect("version 2's size is accepted");
        assert_eq!((read.a, read.b), (3, 9));
    }

    #[test]
    fn a_size_that_is_no_versions_size_is_refused_naming_the_sizes_accepted() {
        for (size, why) in [
            (0, "smaller than version 1"),
            (4, "smaller than version 1"),
            (12, "between versions"),
            (24, "larger than any version this library (ffvk-c 0.1.0) knows"),
        ] {
            let grown = Grown {
                struct_size: size,
                a: 3,
                b: 9,
            };
            // SAFETY: a whole, aligned struct.
            let code = unsafe { read("grow", &grown) }.err();
            assert_eq!(code, Some(FfvkResult::FFVK_ERROR_INVALID_ARGUMENT), "size {size}");
            let text = message();
            for word in [
                &format!("grow: Grown.struct_size is {size}: {why}"),
                "expected sizeof(Grown) as a published ffvk.h declares it, 8 (version 1) or 16 (version 2)",
            ] {
                assert!(text.contains(word), "{text:?} does not say {word:?}");
            }
        }
    }
}
