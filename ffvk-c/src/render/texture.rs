//! Textures a draw samples (`ffvkCreateTexture`): a descriptor set naming the caller's image
//! view and sampler, bound to a texture unit by `FfvkDrawInfo`'s `texture` (unit 0) and, from
//! its version 4, `texture1` .. `texture3`.

use ffvk::ash::vk;
use ffvk::gl::texture::MAX_TEXTURE_UNITS;
use ffvk::TextureBinding;

use super::{invalid, with_renderer, FfvkDrawInfo, FfvkRenderer};
use crate::result::{check_ptr, from_error, misaligned, FfvkResult};
use crate::vk_types::*;

/// A descriptor set naming the caller's image view and sampler (`ffvkCreateTexture`).
pub struct FfvkTexture {
    pub(super) binding: TextureBinding,
}

/// The texture a draw binds to each unit, `GL_TEXTURE0` first (null: none, GL's texture object
/// 0), each checked aligned.
pub(super) fn of_draw(
    function: &str,
    draw: &FfvkDrawInfo,
) -> Result<[*const FfvkTexture; MAX_TEXTURE_UNITS], FfvkResult> {
    let textures = [draw.texture, draw.texture1, draw.texture2, draw.texture3];
    for (i, &t) in textures.iter().enumerate() {
        if misaligned(t) {
            let field = if i == 0 {
                "texture".to_string()
            } else {
                format!("texture{i}")
            };
            return Err(invalid(format!(
                "{function}: {field} {t:p} is not aligned: expected a texture from ffvkCreateTexture or null"
            )));
        }
    }
    Ok(textures)
}

/// The bindings of a draw's textures ([`of_draw`]'s), a unit each.
///
/// # Safety
///
/// Each texture is null or live (and aligned: [`of_draw`] checked it) for `'a`.
pub(super) unsafe fn bindings<'a>(
    textures: &[*const FfvkTexture; MAX_TEXTURE_UNITS],
) -> [Option<&'a TextureBinding>; MAX_TEXTURE_UNITS] {
    // SAFETY: the caller's contract: null or a live texture.
    textures.map(|t| unsafe { t.as_ref() }.map(|t| &t.binding))
}

/// Makes a texture binding naming the caller's image view (2D, color, sampled as floats, in
/// `VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL` whenever a draw that uses it executes) and
/// sampler. ffvk owns the descriptor set; the view and sampler stay the caller's. Records
/// nothing. Returns `FFVK_SUCCESS` with `*texture` set, or an error code with `*texture` null
/// (`FFVK_ERROR_INVALID_ARGUMENT` for a null pointer or handle).
///
/// # Safety
///
/// `renderer` is null or live; `view` and `sampler` are live objects of its device and outlive
/// every command buffer that draws with the texture; `texture` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkCreateTexture(
    renderer: *mut FfvkRenderer,
    view: VkImageView,
    sampler: VkSampler,
    texture: *mut *mut FfvkTexture,
) -> FfvkResult {
    const F: &str = "ffvkCreateTexture";
    if !texture.is_null() && !misaligned(texture) {
        // SAFETY: checked non-null and aligned; the caller's contract makes it writable. Null
        // until a texture is made, so that a caller's cleanup after an error frees nothing.
        unsafe { *texture = std::ptr::null_mut() };
    }
    with_renderer(renderer, F, |r| {
        if let Err(code) = check_ptr(F, "texture", texture, "where to write the texture") {
            return code;
        }
        if view == vk::ImageView::null() || sampler == vk::Sampler::null() {
            return invalid("ffvkCreateTexture: view or sampler is VK_NULL_HANDLE: expected the caller's image view and sampler");
        }
        // SAFETY: the caller's contract on view and sampler.
        match unsafe { r.lighting.bind_texture(view, sampler) } {
            Ok(binding) => {
                // SAFETY: checked non-null.
                unsafe { *texture = Box::into_raw(Box::new(FfvkTexture { binding })) };
                FfvkResult::FFVK_SUCCESS
            }
            Err(e) => from_error("ffvkCreateTexture", &e),
        }
    })
}

/// Frees a texture binding; null is ignored. The caller first makes sure no submitted command
/// buffer still uses it.
///
/// # Safety
///
/// `texture` is null or from `ffvkCreateTexture`, not yet destroyed.
#[no_mangle]
pub unsafe extern "C" fn ffvkDestroyTexture(texture: *mut FfvkTexture) {
    // SAFETY: the caller's contract: made by this API, destroyed once.
    unsafe { crate::result::free(texture) }
}
