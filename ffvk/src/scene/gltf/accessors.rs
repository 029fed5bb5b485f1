//! Reading an accessor safely: its bounds (and its sparse substitutions') checked against
//! the buffers before anything is read, the problems as typed values, the read itself. A
//! leaf of the glTF reader: the primitives (`primitives.rs`) and the quantized attributes
//! (`quantized.rs`) both read through it.

use super::{Context, LoadError, LoadErrorKind};
use crate::alloc::try_vec;

/// Which elements of an accessor a bounds problem is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AccessorPart {
    /// The accessor's own elements.
    Elements,
    /// The indices of its sparse substitution.
    SparseIndices,
    /// The values of its sparse substitution.
    SparseValues,
}

impl AccessorPart {
    /// What a message about this part starts with (nothing for the elements themselves).
    fn prefix(self) -> &'static str {
        match self {
            AccessorPart::Elements => "",
            AccessorPart::SparseIndices => "sparse indices: ",
            AccessorPart::SparseValues => "sparse values: ",
        }
    }
}

/// Why an accessor's data could not be read: it is not inside its buffer view and buffer,
/// or the `gltf` crate's reader did not return it all.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum AccessorProblem {
    /// An accessor with no elements.
    #[error("count is 0: expected at least 1")]
    Empty,

    /// A buffer view whose byteStride is smaller than the element.
    #[error(
        "{}buffer view {view} has byteStride {stride}: expected at least {element} (the element size)",
        .part.prefix()
    )]
    Stride {
        /// The elements whose buffer view it is.
        part: AccessorPart,
        /// The buffer view's index.
        view: usize,
        /// Its byteStride, in bytes.
        stride: usize,
        /// The size of one element, in bytes.
        element: usize,
    },

    /// `count` elements of `element` bytes from byte `offset`, `stride` apart where the view
    /// has a byteStride, that end past their buffer view.
    #[error("{}", overrun_text(self))]
    ViewOverrun {
        /// The elements that overrun.
        part: AccessorPart,
        /// How many elements are read.
        count: usize,
        /// The size of one element, in bytes.
        element: usize,
        /// The buffer view's byteStride, where it has one (the elements are packed otherwise).
        stride: Option<usize>,
        /// Where the first element starts in the buffer view, in bytes (the byteOffset).
        offset: usize,
        /// The buffer view's index.
        view: usize,
        /// The buffer view's byteLength.
        view_length: usize,
    },

    /// A buffer view that ends past its buffer (which holds `available` bytes).
    #[error(
        "{}buffer view {view} (bytes {view_offset}..+{view_length}) overruns buffer {buffer} \
         ({available} bytes)",
        .part.prefix()
    )]
    BufferOverrun {
        /// The elements whose buffer view it is.
        part: AccessorPart,
        /// The buffer view's index.
        view: usize,
        /// The buffer view's byteOffset in its buffer.
        view_offset: usize,
        /// The buffer view's byteLength.
        view_length: usize,
        /// The buffer's index.
        buffer: usize,
        /// The bytes the buffer holds (0 for a buffer that was not loaded).
        available: usize,
    },

    /// A sparse substitution of none or of more elements than the accessor has.
    #[error("sparse count is {sparse}: expected 1..={count} (the accessor count)")]
    SparseCount {
        /// The sparse substitution's count.
        sparse: usize,
        /// The accessor's count.
        count: usize,
    },

    /// A sparse substitution's buffer view with a byteStride (glTF 2.0: sparse data is
    /// tightly packed and its views have none).
    #[error("{}buffer view {view} has byteStride {stride}: expected none (sparse data is tightly packed)", .part.prefix())]
    SparseStride {
        /// The sparse indices or values.
        part: AccessorPart,
        /// The buffer view's index.
        view: usize,
        /// Its byteStride, in bytes.
        stride: usize,
    },

    /// A sparse index that names no element of the accessor.
    #[error("sparse index {position} is {index}: expected less than {count} (the accessor's count)")]
    SparseIndexOutOfRange {
        /// Where the index is among the sparse indices.
        position: usize,
        /// Its value.
        index: u32,
        /// The accessor's count.
        count: usize,
    },

    /// A sparse index not greater than the one before it (glTF 2.0: they strictly increase).
    #[error("sparse index {position} is {index}, after {previous}: expected strictly increasing indices")]
    SparseIndexOrder {
        /// Where the index is among the sparse indices.
        position: usize,
        /// Its value.
        index: u32,
        /// The index before it.
        previous: u32,
    },

    /// Data the `gltf` crate's reader could not find (e.g. an accessor without a buffer view).
    #[error("its data could not be read from its buffer view")]
    Unreadable,

    /// The reader stopped after `read` elements.
    #[error("read {read} elements: expected {count} (its count)")]
    ShortRead {
        /// How many elements the reader returned.
        read: usize,
        /// The accessor's count.
        count: usize,
    },
}

/// [`AccessorProblem::ViewOverrun`]'s message: where the elements end, and, where the view's
/// byteStride spaces them, that stride and the largest that would fit.
fn overrun_text(problem: &AccessorProblem) -> String {
    let AccessorProblem::ViewOverrun {
        part,
        count,
        element,
        stride,
        offset,
        view,
        view_length,
    } = *problem
    else {
        return String::new();
    };
    // In u128: the product of a hostile stride and count may not fit a usize.
    let spacing = stride.unwrap_or(element) as u128;
    let end = spacing * (count as u128 - 1) + (offset + element) as u128;
    let head = format!("{}{count} elements of {element} bytes", part.prefix());
    match stride {
        Some(stride) if stride != element && count > 1 => {
            let fits = (view_length as u128).saturating_sub((offset + element) as u128) / (count as u128 - 1);
            format!(
                "{head}, {stride} apart (buffer view {view}'s byteStride), from byte {offset} end at \
                 byte {end} and overrun buffer view {view} ({view_length} bytes): expected a \
                 byteStride of at most {fits} or a longer view"
            )
        }
        _ => format!(
            "{head} from byte {offset} end at byte {end} and overrun buffer view {view} \
             ({view_length} bytes)"
        ),
    }
}

/// Checks that an accessor's elements lie inside its buffer view and buffer, so the `gltf`
/// crate's reader neither panics nor silently stops short.
fn check_accessor_bounds(
    accessor: &gltf::Accessor,
    buffers: &[gltf::buffer::Data],
) -> Result<(), AccessorProblem> {
    let count = accessor.count();
    if count == 0 {
        return Err(AccessorProblem::Empty);
    }
    let element = accessor.size();
    let view_fits = |view: gltf::buffer::View, offset: usize, count: usize, element: usize, part| {
        let stride = view.stride().unwrap_or(element);
        if stride < element {
            return Err(AccessorProblem::Stride {
                part,
                view: view.index(),
                stride,
                element,
            });
        }
        let end = stride
            .checked_mul(count - 1)
            .and_then(|x| x.checked_add(offset))
            .and_then(|x| x.checked_add(element));
        match end {
            Some(end) if end <= view.length() => {}
            _ => {
                return Err(AccessorProblem::ViewOverrun {
                    part,
                    count,
                    element,
                    stride: view.stride(),
                    offset,
                    view: view.index(),
                    view_length: view.length(),
                })
            }
        }
        let buffer = view.buffer().index();
        let available = buffers.get(buffer).map_or(0, |b| b.len());
        if view
            .offset()
            .checked_add(view.length())
            .is_none_or(|end| end > available)
        {
            return Err(AccessorProblem::BufferOverrun {
                part,
                view: view.index(),
                view_offset: view.offset(),
                view_length: view.length(),
                buffer,
                available,
            });
        }
        Ok(())
    };
    if let Some(view) = accessor.view() {
        view_fits(view, accessor.offset(), count, element, AccessorPart::Elements)?;
    }
    if let Some(sparse) = accessor.sparse() {
        let n = sparse.count();
        if n == 0 || n > count {
            return Err(AccessorProblem::SparseCount { sparse: n, count });
        }
        let indices = sparse.indices();
        let values = sparse.values();
        for (view, part) in [
            (indices.view(), AccessorPart::SparseIndices),
            (values.view(), AccessorPart::SparseValues),
        ] {
            if let Some(stride) = view.stride() {
                return Err(AccessorProblem::SparseStride {
                    part,
                    view: view.index(),
                    stride,
                });
            }
        }
        let size = indices.index_type().size();
        view_fits(
            indices.view(),
            indices.offset(),
            n,
            size,
            AccessorPart::SparseIndices,
        )?;
        check_sparse_indices(&indices, n, count, buffers)?;
        view_fits(
            values.view(),
            values.offset(),
            n,
            element,
            AccessorPart::SparseValues,
        )?;
    }
    Ok(())
}

/// Checks the `n` sparse indices (inside their view and buffer, as checked before) strictly
/// increase and stay below the accessor's `count`: the `gltf` crate's reader drops a
/// substitution that breaks this without a word.
fn check_sparse_indices(
    indices: &gltf::accessor::sparse::Indices,
    n: usize,
    count: usize,
    buffers: &[gltf::buffer::Data],
) -> Result<(), AccessorProblem> {
    use gltf::accessor::sparse::IndexType;
    let view = indices.view();
    let size = indices.index_type().size();
    // Sparse index views are tightly packed (glTF 2.0 forbids them a byteStride).
    let start = view.offset() + indices.offset();
    let bytes = buffers
        .get(view.buffer().index())
        .and_then(|b| b.get(start..start + n * size))
        .ok_or(AccessorProblem::Unreadable)?;
    let mut previous: Option<u32> = None;
    for (position, raw) in bytes.chunks_exact(size).enumerate() {
        let index = match indices.index_type() {
            IndexType::U8 => u32::from(raw[0]),
            IndexType::U16 => u32::from(u16::from_le_bytes([raw[0], raw[1]])),
            IndexType::U32 => u32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]),
        };
        if index as usize >= count {
            return Err(AccessorProblem::SparseIndexOutOfRange {
                position,
                index,
                count,
            });
        }
        if let Some(previous) = previous.filter(|&p| index <= p) {
            return Err(AccessorProblem::SparseIndexOrder {
                position,
                index,
                previous,
            });
        }
        previous = Some(index);
    }
    Ok(())
}

/// Reads one attribute or index accessor after its bounds check, as `T`. The reader's
/// iterator is made (by `iter`) only after the check: the `gltf` crate's iterators compute
/// `count - 1` when they are made, which overflows (a panic with overflow checks) for a count
/// of 0.
pub(super) fn read_checked<T, I>(
    cx: &Context,
    primitive: &str,
    accessor: &gltf::Accessor,
    buffers: &[gltf::buffer::Data],
    iter: impl FnOnce() -> Option<I>,
) -> Result<Vec<T>, LoadError>
where
    I: Iterator<Item = T>,
{
    let data_error = |problem| {
        cx.error(LoadErrorKind::AccessorData {
            primitive: primitive.to_owned(),
            accessor: accessor.index(),
            problem: Box::new(problem),
        })
    };
    check_accessor_bounds(accessor, buffers).map_err(data_error)?;
    let iter = iter().ok_or_else(|| data_error(AccessorProblem::Unreadable))?;
    let mut values = try_vec(accessor.count(), "accessor data").map_err(|source| {
        cx.error(LoadErrorKind::Alloc {
            primitive: primitive.to_owned(),
            source,
        })
    })?;
    // At most count elements: the bounds check says the data holds that many.
    values.extend(iter.take(accessor.count()));
    if values.len() != accessor.count() {
        return Err(data_error(AccessorProblem::ShortRead {
            read: values.len(),
            count: accessor.count(),
        }));
    }
    Ok(values)
}
