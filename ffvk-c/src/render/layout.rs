//! Vertex layouts a renderer draws with besides the one its create info gave
//! (`ffvkCreateVertexLayout`): GL draws each call with whatever arrays are enabled, and one
//! renderer serves them all.

use ffvk::gl::state::Face;
use ffvk::{MaterialArray, VertexInput, VertexLayout};

use crate::enums::*;
use crate::render::{
    attribute, invalid, slice, with_renderer, FfvkAttribute, FfvkRenderer, FFVK_MAX_VERTEX_BINDINGS,
};
use crate::result::{check_ptr, from_error, misaligned, FfvkResult};
use crate::vk_types::*;

/// One material parameter given per vertex (Mesa's material attributes: `glMaterial` between
/// `glBegin` and `glEnd`): `face` `GL_FRONT`, `GL_BACK` or `GL_FRONT_AND_BACK`; `pname`
/// `GL_AMBIENT`, `GL_DIFFUSE`, `GL_SPECULAR`, `GL_EMISSION` (RGBA,
/// `VK_FORMAT_R32G32B32A32_SFLOAT`) or `GL_SHININESS` (`VK_FORMAT_R32_SFLOAT`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct FfvkMaterialAttribute {
    /// `GL_FRONT`, `GL_BACK` or `GL_FRONT_AND_BACK`.
    pub face: u32,
    /// `GL_AMBIENT`, `GL_DIFFUSE`, `GL_SPECULAR`, `GL_EMISSION` or `GL_SHININESS`.
    pub pname: u32,
    /// Where it lives in the layout's bindings.
    pub attribute: FfvkAttribute,
}

/// What `ffvkCreateVertexLayout` takes: a layout of GL's arrays. Set `struct_size` to
/// `sizeof(FfvkVertexLayoutInfo)` (the struct grows as `FfvkDrawInfo` does: later versions
/// append fields and read only what the caller's size covers; this header's is version 2,
/// which appended `texcoord1` .. `texcoord3`, the arrays of the texture units past the first,
/// which glClientActiveTexture selects in GL). Formats are GL's: positions 2 to 4 floats or
/// `GL_SHORT`s (`R16G16_SSCALED`..), normals 3 floats or `GL_BYTE`s or
/// `GL_SHORT`s (`R8G8B8_SNORM`, `R16G16B16_SNORM`, or their four-component forms with padding),
/// colors 3 or 4 floats, signed or unsigned bytes or shorts, or `B8G8R8A8_UNORM`
/// (`GL_BGRA`), texture coordinates 1 to 4 floats or shorts. Signed normalized normals and
/// colors convert as GL 2.1 says, (2c + 1)/(2^b − 1), not as Vulkan's SNORM.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct FfvkVertexLayoutInfo {
    /// `sizeof(FfvkVertexLayoutInfo)`.
    pub struct_size: u32,
    /// The vertex buffer bindings (per-vertex rate), in the order draws pass their buffers.
    pub bindings: *const VkVertexInputBindingDescription,
    /// How many `bindings`, at most `FFVK_MAX_VERTEX_BINDINGS`.
    pub binding_count: u32,
    /// Object-space position (`glVertexPointer`).
    pub position: FfvkAttribute,
    /// Normals (`glNormalPointer`), or null: every vertex takes the context's current normal
    /// (`ffvkNormal3f`).
    pub normal: *const FfvkAttribute,
    /// Colors (`glColorPointer`), or null: the context's current color (`ffvkColor4f`).
    pub color: *const FfvkAttribute,
    /// Texture coordinates (`glTexCoordPointer`), or null: the context's current ones
    /// (`ffvkTexCoord4f`).
    pub texcoord: *const FfvkAttribute,
    /// Secondary colors (`glSecondaryColorPointer`, three components), or null: the context's
    /// current secondary color (`ffvkSecondaryColor3f`); summed with lighting off under
    /// `GL_COLOR_SUM`.
    pub secondary_color: *const FfvkAttribute,
    /// Fog coordinates (`glFogCoordPointer`, one float: `VK_FORMAT_R32_SFLOAT`), or null: the
    /// context's current fog coordinate (`ffvkFogCoordf`).
    pub fog_coord: *const FfvkAttribute,
    /// Material parameters given per vertex, or null with `material_count` 0. Drawn in the
    /// vertex and flat modes; a draw lit per fragment with such a layout is refused.
    pub materials: *const FfvkMaterialAttribute,
    /// How many `materials` (at most 10: five parameters, two faces).
    pub material_count: u32,
    /// Version 2: texture unit 1's coordinates (glClientActiveTexture(`GL_TEXTURE1`) then
    /// glTexCoordPointer), or null (the default, and what a version 1 caller gets): every
    /// vertex takes unit 1's current coordinates (`ffvkMultiTexCoord4f(GL_TEXTURE1, …)`). Read
    /// while unit 1 textures (its `GL_TEXTURE_2D` enabled with a texture in
    /// `FfvkDrawInfo::texture1`), through unit 1's texture matrix and coordinate generation.
    /// `texcoord` is unit 0's.
    pub texcoord1: *const FfvkAttribute,
    /// Version 2: unit 2's coordinates, as `texcoord1` (null by default: unit 2's current ones).
    pub texcoord2: *const FfvkAttribute,
    /// Version 2: unit 3's coordinates, as `texcoord1` (null by default: unit 3's current ones).
    pub texcoord3: *const FfvkAttribute,
}

/// A vertex layout of one renderer (`ffvkCreateVertexLayout`), named by `FfvkDrawInfo::layout`.
#[derive(Debug)]
pub struct FfvkVertexLayout {
    /// The handle the renderer's `Lighting` gave.
    pub(crate) layout: VertexLayout,
    /// The layout's bindings: a draw passes one buffer each.
    pub(crate) binding_count: u32,
}

/// The layout `info` describes.
///
/// # Safety
///
/// `info`'s pointers are null or point at what their counts say.
unsafe fn vertex_input(function: &str, info: &FfvkVertexLayoutInfo) -> Result<VertexInput, FfvkResult> {
    if info.binding_count > FFVK_MAX_VERTEX_BINDINGS {
        return Err(invalid(format!(
            "{function}: binding_count is {}: expected at most {FFVK_MAX_VERTEX_BINDINGS} (FFVK_MAX_VERTEX_BINDINGS)",
            info.binding_count
        )));
    }
    if info.material_count > 10 {
        return Err(invalid(format!(
            "{function}: material_count is {}: expected at most 10 (five parameters of two faces)",
            info.material_count
        )));
    }
    // SAFETY: the caller's contract: binding_count descriptions at bindings (checked bounded).
    let bindings = unsafe { slice(function, "bindings", info.bindings, info.binding_count) }?.to_vec();
    for (what, ptr) in [
        ("normal", info.normal),
        ("color", info.color),
        ("texcoord", info.texcoord),
        ("secondary_color", info.secondary_color),
        ("fog_coord", info.fog_coord),
        ("texcoord1", info.texcoord1),
        ("texcoord2", info.texcoord2),
        ("texcoord3", info.texcoord3),
    ] {
        if misaligned(ptr) {
            return Err(invalid(format!(
                "{function}: {what} {ptr:p} is not aligned: expected an FfvkAttribute or null"
            )));
        }
    }
    // SAFETY: the caller's contract: each is null or points at an attribute (checked aligned).
    let (normal, color, texcoord, secondary, fog) = unsafe {
        (
            info.normal.as_ref(),
            info.color.as_ref(),
            info.texcoord.as_ref(),
            info.secondary_color.as_ref(),
            info.fog_coord.as_ref(),
        )
    };
    // SAFETY: as above.
    let units =
        [info.texcoord1, info.texcoord2, info.texcoord3].map(|a| unsafe { a.as_ref() }.map(attribute));
    let position = attribute(&info.position);
    let mut input = VertexInput::new(bindings, position, position)
        .with_normal(normal.map(attribute))
        .with_color(color.map(attribute))
        .with_texcoord(texcoord.map(attribute))
        .with_unit_texcoords(units)
        .with_secondary_color(secondary.map(attribute))
        .with_fog_coord(fog.map(attribute));
    // SAFETY: the caller's contract: material_count entries at materials (checked bounded).
    let materials = unsafe { slice(function, "materials", info.materials, info.material_count) }?;
    for (i, m) in materials.iter().enumerate() {
        let face = match m.face {
            GL_FRONT => Face::Front,
            GL_BACK => Face::Back,
            GL_FRONT_AND_BACK => Face::FrontAndBack,
            other => {
                return Err(invalid(format!(
                    "{function}: materials[{i}].face is {}: expected GL_FRONT, GL_BACK or GL_FRONT_AND_BACK",
                    enum_name(other)
                )))
            }
        };
        let which = match m.pname {
            GL_AMBIENT => MaterialArray::Ambient,
            GL_DIFFUSE => MaterialArray::Diffuse,
            GL_SPECULAR => MaterialArray::Specular,
            GL_EMISSION => MaterialArray::Emission,
            GL_SHININESS => MaterialArray::Shininess,
            other => {
                return Err(invalid(format!(
                    "{function}: materials[{i}].pname is {}: expected GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION or GL_SHININESS (GL_AMBIENT_AND_DIFFUSE is two entries)",
                    enum_name(other)
                )))
            }
        };
        input = input.with_material(face, which, Some(attribute(&m.attribute)));
    }
    Ok(input)
}

/// Adds a vertex layout to `renderer` and writes its handle to `*layout`: draws name it in
/// `FfvkDrawInfo::layout` (null there: the create info's layout) and pass one buffer per
/// binding of it. Checked as the create info's layout is (formats each array takes, offsets
/// within strides, the device's limits and vertex formats); pipelines for it are made on the
/// first draw that needs them. An equal layout made before shares its pipelines. Free the
/// handle with `ffvkDestroyVertexLayout` (the renderer keeps the layout's pipelines until it is
/// destroyed). Errors: `FFVK_ERROR_INVALID_ARGUMENT` naming the field, value and what was
/// expected (nothing written to `*layout` then), or a Vulkan error.
///
/// # Safety
///
/// `renderer` is null or live and used by one thread at a time; `info` is null or points at
/// `info->struct_size` bytes of an `FfvkVertexLayoutInfo` whose pointers are null or point at
/// what their counts say; `layout` is null or points at room for one pointer.
#[no_mangle]
pub unsafe extern "C" fn ffvkCreateVertexLayout(
    renderer: *mut FfvkRenderer,
    info: *const FfvkVertexLayoutInfo,
    layout: *mut *mut FfvkVertexLayout,
) -> FfvkResult {
    const F: &str = "ffvkCreateVertexLayout";
    with_renderer(renderer, F, |r| {
        let checked = check_ptr(F, "info", info, "an FfvkVertexLayoutInfo")
            .and_then(|()| check_ptr(F, "layout", layout.cast_const(), "room for the layout's handle"));
        if let Err(code) = checked {
            return code;
        }
        if r.recording.is_some() {
            return invalid(format!(
                "{F}: a recording scope is open: expected ffvkEndDraws first (a layout is made between scopes)"
            ));
        }
        let result = (|| {
            // SAFETY: checked non-null and aligned; the caller's contract: struct_size bytes.
            let info = unsafe { crate::abi::read(F, info) }?;
            // SAFETY: the caller's contract on the info's pointers.
            let input = unsafe { vertex_input(F, &info) }?;
            let binding_count = input.bindings.len() as u32;
            let handle = r.lighting.vertex_layout(input).map_err(|e| from_error(F, &e))?;
            Ok(Box::into_raw(Box::new(FfvkVertexLayout {
                layout: handle,
                binding_count,
            })))
        })();
        match result {
            Ok(made) => {
                // SAFETY: checked non-null and aligned; room for one pointer.
                unsafe { layout.write(made) };
                FfvkResult::FFVK_SUCCESS
            }
            Err(code) => code,
        }
    })
}

/// Frees a layout handle from `ffvkCreateVertexLayout`; null does nothing. Draws recorded with
/// it stay valid (the renderer keeps the layout's pipelines).
///
/// # Safety
///
/// `layout` is null or from `ffvkCreateVertexLayout`, not yet destroyed, and named by no draw
/// of an open scope.
#[no_mangle]
pub unsafe extern "C" fn ffvkDestroyVertexLayout(layout: *mut FfvkVertexLayout) {
    // SAFETY: the caller's contract: made by this API, destroyed once.
    unsafe { crate::result::free(layout) }
}

/// The layout a draw names, and how many vertex buffers it takes: `layout`'s, or with null,
/// the renderer's own (`binding_count` of its create info).
///
/// # Safety
///
/// `layout` is null or a live handle (checked aligned here).
pub(crate) unsafe fn of_draw(
    function: &str,
    layout: *const FfvkVertexLayout,
    renderer_bindings: u32,
) -> Result<(Option<VertexLayout>, u32), FfvkResult> {
    if misaligned(layout) {
        return Err(invalid(format!(
            "{function}: layout {layout:p} is not aligned: expected a layout from ffvkCreateVertexLayout or null"
        )));
    }
    // SAFETY: checked aligned; the caller's contract: null or live.
    Ok(match unsafe { layout.as_ref() } {
        Some(l) => (Some(l.layout), l.binding_count),
        None => (None, renderer_bindings),
    })
}
