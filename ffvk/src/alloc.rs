//! Fallible allocation for ffvk's large host buffers (mesh data, pixels): where input decides
//! how much memory is needed, running out is an error naming what was being allocated and how
//! much, not an abort of the whole process.

/// A host allocation that failed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("cannot allocate {bytes} bytes of host memory for {what}")]
#[non_exhaustive]
pub struct AllocError {
    /// What the memory was for, e.g. `"mesh vertices"`.
    pub what: &'static str,
    /// How much was asked for.
    pub bytes: u64,
}

/// An empty vector with room for `len` elements, or the error naming `what`.
pub fn try_vec<T>(len: usize, what: &'static str) -> Result<Vec<T>, AllocError> {
    let bytes = (len as u64).saturating_mul(std::mem::size_of::<T>() as u64);
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| AllocError { what, bytes })?;
    Ok(v)
}

/// A copy of `items`, or the error naming `what`.
pub fn try_copy<T: Copy>(items: &[T], what: &'static str) -> Result<Vec<T>, AllocError> {
    let mut v = try_vec(items.len(), what)?;
    v.extend_from_slice(items);
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_impossible_allocation_is_an_error_naming_it() {
        let e = try_vec::<u64>(usize::MAX / 4, "test data").unwrap_err();
        assert_eq!(e.what, "test data");
        assert!(e.to_string().contains("test data"), "{e}");
        assert_eq!(try_vec::<u8>(16, "small").unwrap().capacity(), 16);
        assert_eq!(try_copy(&[1, 2, 3], "copy").unwrap(), vec![1, 2, 3]);
    }
}
