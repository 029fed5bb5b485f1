//! Textures a draw samples (`ffvkCreateTexture`, `ffvkCreateCubeMap`): a descriptor set naming
//! the caller's image view and sampler, bound to a texture unit by `FfvkDrawInfo`'s `texture`
//! (unit 0) and, from its version 4, `texture1` .. `texture3`; cube maps by its version 5's
//! `cube_map` .. `cube_map3`; `ffvkCreateTextureWithFormat` and `ffvkCreateCubeMapWithFormat`
//! give the texture's base internal format.

use ffvk::ash::vk;
use ffvk::draw::texture::TextureTarget;
use ffvk::gl::texture::{BaseFormat, MAX_TEXTURE_UNITS};
use ffvk::TextureBinding;

use super::base_format::base_format;
use super::{invalid, with_renderer, FfvkDrawInfo, FfvkRenderer};
use crate::result::{check_ptr, from_error, misaligned, FfvkResult};
use crate::vk_types::*;

/// A descriptor set naming the caller's image view and sampler: a 2D texture
/// (`ffvkCreateTexture`) or a cube map (`ffvkCreateCubeMap`).
pub struct FfvkTexture {
    pub(super) binding: TextureBinding,
}

/// What a draw binds to each unit, `GL_TEXTURE0` first (null: none, GL's texture object 0):
/// its 2D textures and its cube maps.
#[derive(Clone, Copy)]
pub(super) struct UnitBindings {
    pub(super) textures: [*const FfvkTexture; MAX_TEXTURE_UNITS],
    pub(super) cube_maps: [*const FfvkTexture; MAX_TEXTURE_UNITS],
}

/// A unit's field of `FfvkDrawInfo`: `texture`, `texture1`, …, or `cube_map`, `cube_map1`, ….
fn field(base: &str, unit: usize) -> String {
    if unit == 0 {
        base.to_string()
    } else {
        format!("{base}{unit}")
    }
}

/// The textures and cube maps a draw binds to each unit, each checked aligned and, where not
/// null, of its field's target: a cube map where a 2D texture goes, or the reverse, is refused
/// naming the field and the unit.
///
/// # Safety
///
/// Each of the draw's textures and cube maps is null, misaligned (refused) or live.
pub(super) unsafe fn of_draw(function: &str, draw: &FfvkDrawInfo) -> Result<UnitBindings, FfvkResult> {
    let units = UnitBindings {
        textures: [draw.texture, draw.texture1, draw.texture2, draw.texture3],
        cube_maps: [draw.cube_map, draw.cube_map1, draw.cube_map2, draw.cube_map3],
    };
    let slots = [
        (
            &units.textures,
            "texture",
            TextureTarget::Texture2D,
            "ffvkCreateTexture",
        ),
        (
            &units.cube_maps,
            "cube_map",
            TextureTarget::CubeMap,
            "ffvkCreateCubeMap",
        ),
    ];
    for (bound, base, _, maker) in slots {
        for (i, &t) in bound.iter().enumerate() {
            if misaligned(t) {
                let what = if maker == "ffvkCreateTexture" {
                    "a texture"
                } else {
                    "a cube map"
                };
                return Err(invalid(format!(
                    "{function}: {} {t:p} is not aligned: expected {what} from {maker} or null",
                    field(base, i)
                )));
            }
        }
    }
    for (bound, base, expected, maker) in slots {
        for (i, &t) in bound.iter().enumerate() {
            // SAFETY: the caller's contract: null or live; checked aligned above.
            let Some(t) = (unsafe { t.as_ref() }) else {
                continue;
            };
            if t.binding.target() != expected {
                let (given, other) = match expected {
                    TextureTarget::CubeMap => ("a 2D texture", "texture"),
                    _ => ("a cube map", "cube_map"),
                };
                return Err(invalid(format!(
                    "{function}: {} (unit {i}, GL_TEXTURE{i}) {:p} is {given} ({}): expected a {} binding from {maker} or null ({given} goes in {})",
                    field(base, i),
                    t,
                    t.binding.target().gl_name(),
                    expected.gl_name(),
                    field(other, i)
                )));
            }
        }
    }
    Ok(units)
}

/// The bindings of a draw's textures or cube maps ([`of_draw`]'s), a unit each.
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

/// The binding `function` makes: of `target`, naming the caller's `view` and `sampler`, with
/// base format `internalformat` (checked; `GL_RGBA` when `None`), written at `out`; `param` is
/// the out parameter's name, `what` what it receives.
///
/// # Safety
///
/// As `ffvkCreateTexture`'s: `renderer` is null or live, `view` and `sampler` live objects of
/// its device, `out` null or writable.
unsafe fn create(
    function: &str,
    renderer: *mut FfvkRenderer,
    (view, sampler): (VkImageView, VkSampler),
    (target, internalformat): (TextureTarget, Option<u32>),
    (param, what): (&str, &str),
    out: *mut *mut FfvkTexture,
) -> FfvkResult {
    if !out.is_null() && !misaligned(out) {
        // SAFETY: checked non-null and aligned; the caller's contract makes it writable. Null
        // until a binding is made, so that a caller's cleanup after an error frees nothing.
        unsafe { *out = std::ptr::null_mut() };
    }
    with_renderer(renderer, function, |r| {
        if let Err(code) = check_ptr(function, param, out, &format!("where to write the {what}")) {
            return code;
        }
        let format = match internalformat.map(|f| base_format(function, f)) {
            Some(Ok(format)) => format,
            Some(Err(code)) => return code,
            None => BaseFormat::Rgba,
        };
        if view == vk::ImageView::null() || sampler == vk::Sampler::null() {
            let views = match target {
                TextureTarget::CubeMap => "cube image view",
                _ => "image view",
            };
            return invalid(format!(
                "{function}: view or sampler is VK_NULL_HANDLE: expected the caller's {views} and sampler"
            ));
        }
        // SAFETY: the caller's contract on view and sampler.
        let bound = unsafe {
            match target {
                TextureTarget::CubeMap => r.lighting.bind_cube_map(view, sampler),
                _ => r.lighting.bind_texture(view, sampler),
            }
        };
        match bound {
            Ok(binding) => {
                let binding = binding.with_base_format(format);
                // SAFETY: checked non-null and aligned.
                unsafe { *out = Box::into_raw(Box::new(FfvkTexture { binding })) };
                FfvkResult::FFVK_SUCCESS
            }
            Err(e) => from_error(function, &e),
        }
    })
}

/// Makes a texture binding naming the caller's image view (2D, color, sampled as floats, in
/// `VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL` whenever a draw that uses it executes) and
/// sampler. ffvk owns the descriptor set; the view and sampler stay the caller's. Records
/// nothing. Its base internal format is `GL_RGBA` (`ffvkCreateTextureWithFormat` gives
/// another). Returns `FFVK_SUCCESS` with `*texture` set, or an error code with `*texture` null
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
    let target = (TextureTarget::Texture2D, None);
    // SAFETY: the caller's contract, as create's.
    unsafe {
        create(
            "ffvkCreateTexture",
            renderer,
            (view, sampler),
            target,
            ("texture", "texture"),
            texture,
        )
    }
}

/// `ffvkCreateTexture` with the texture's base internal format (`glTexImage2D`'s
/// `internalformat`, GL 2.1 table 3.15): `GL_ALPHA`, `GL_LUMINANCE`, `GL_LUMINANCE_ALPHA`,
/// `GL_INTENSITY`, `GL_RGB` or `GL_RGBA`. It says which components the texture has, and so
/// what the texture environment reads (table 3.22): a `GL_LUMINANCE` light map modulates the
/// color and leaves the alpha, a `GL_ALPHA` texture leaves the color, `GL_INTENSITY` is its
/// value in all four. The view gives the components as GL converts RGBA pixels: luminance and
/// intensity are the view's R, alpha its A. A `GL_LUMINANCE` or `GL_INTENSITY` image of
/// `VK_FORMAT_R8_UNORM` needs no swizzle; a `GL_ALPHA` one of `R8_UNORM` needs the view's
/// `components.a = VK_COMPONENT_SWIZZLE_R`, a `GL_LUMINANCE_ALPHA` one of `R8G8_UNORM`
/// `components.a = VK_COMPONENT_SWIZZLE_G`. A component the format lacks is never read. The
/// bits and any sRGB decode are the view's `VkFormat`'s, so a sized format (`GL_LUMINANCE8`,
/// `GL_SRGB8_ALPHA8`) is refused naming the base format to give.
///
/// The format is fixed for the binding's life: `ffvkDraw` keys the draw's pipeline on it and
/// `ffvkEndDraws` reads it again to record, so a binding whose format could change in between
/// would record a draw other than the one checked. A program that redefines a texture with
/// another `internalformat` makes another binding of its view (a binding is no Vulkan object
/// and cheap to make; several of one view may live at once) and destroys the old one with
/// `ffvkDestroyTexture` once no submitted command buffer uses it.
///
/// Returns `FFVK_SUCCESS` with `*texture` set, or an error code with `*texture` null:
/// `FFVK_ERROR_INVALID_ARGUMENT` for a null pointer or handle, or an `internalformat` that is
/// none of the six (the message names the function, the parameter, the value by its GL name
/// and what was expected), as the renderer's entry points refuse any enum they do not take.
///
/// # Safety
///
/// As `ffvkCreateTexture`.
#[no_mangle]
pub unsafe extern "C" fn ffvkCreateTextureWithFormat(
    renderer: *mut FfvkRenderer,
    view: VkImageView,
    sampler: VkSampler,
    internalformat: u32,
    texture: *mut *mut FfvkTexture,
) -> FfvkResult {
    let target = (TextureTarget::Texture2D, Some(internalformat));
    // SAFETY: the caller's contract, as create's.
    unsafe {
        create(
            "ffvkCreateTextureWithFormat",
            renderer,
            (view, sampler),
            target,
            ("texture", "texture"),
            texture,
        )
    }
}

/// Makes a cube map binding (`GL_TEXTURE_CUBE_MAP`'s texture object) naming the caller's image
/// view and sampler, for `FfvkDrawInfo`'s `cube_map` .. `cube_map3` (version 5). The view is a
/// `VK_IMAGE_VIEW_TYPE_CUBE` view of six array layers in GL's face order
/// (`GL_TEXTURE_CUBE_MAP_POSITIVE_X`, `_NEGATIVE_X`, `_POSITIVE_Y`, `_NEGATIVE_Y`,
/// `_POSITIVE_Z`, `_NEGATIVE_Z`), each face's row 0 at t = 0 as glTexImage2D's first row,
/// color, sampled as floats, in `VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL` whenever a draw that
/// uses it executes. GL 2.1 filters each face on its own: a sampler created with
/// `VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT` in its flags does so (the device needs
/// `VK_EXT_non_seamless_cube_map` enabled: `FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP` from
/// `ffvkDeviceRequirements`); without it, linear filtering near an edge also reads the
/// neighbouring face (Vulkan's seamless filtering). ffvk owns the descriptor set; the view
/// and sampler stay the caller's. Records nothing. Its base internal format is `GL_RGBA`
/// (`ffvkCreateCubeMapWithFormat` gives another). Free it with `ffvkDestroyTexture`. Returns
/// `FFVK_SUCCESS` with `*cube_map` set, or an error code with `*cube_map` null
/// (`FFVK_ERROR_INVALID_ARGUMENT` for a null or misaligned pointer or a null handle).
///
/// A cube map is drawn only from a `cube_map*` field and a 2D texture only from a `texture*`
/// one: `ffvkDraw` refuses either in the other's field, naming the field and the unit.
///
/// # Safety
///
/// As `ffvkCreateTexture`: `renderer` is null or live; `view` and `sampler` are live objects of
/// its device and outlive every command buffer that draws with the cube map; `cube_map` is null
/// or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkCreateCubeMap(
    renderer: *mut FfvkRenderer,
    view: VkImageView,
    sampler: VkSampler,
    cube_map: *mut *mut FfvkTexture,
) -> FfvkResult {
    let target = (TextureTarget::CubeMap, None);
    // SAFETY: the caller's contract, as create's.
    unsafe {
        create(
            "ffvkCreateCubeMap",
            renderer,
            (view, sampler),
            target,
            ("cube_map", "cube map"),
            cube_map,
        )
    }
}

/// `ffvkCreateCubeMap` with the cube map's base internal format, every face's: as
/// `ffvkCreateTextureWithFormat` takes it, read from the view as it reads it, and fixed for the
/// binding's life likewise. Errors as `ffvkCreateTextureWithFormat`'s.
///
/// # Safety
///
/// As `ffvkCreateCubeMap`.
#[no_mangle]
pub unsafe extern "C" fn ffvkCreateCubeMapWithFormat(
    renderer: *mut FfvkRenderer,
    view: VkImageView,
    sampler: VkSampler,
    internalformat: u32,
    cube_map: *mut *mut FfvkTexture,
) -> FfvkResult {
    let target = (TextureTarget::CubeMap, Some(internalformat));
    // SAFETY: the caller's contract, as create's.
    unsafe {
        create(
            "ffvkCreateCubeMapWithFormat",
            renderer,
            (view, sampler),
            target,
            ("cube_map", "cube map"),
            cube_map,
        )
    }
}

/// Frees a texture or cube map binding; null is ignored. It may be freed as soon as the last
/// `ffvkDraw` that names it has returned, inside an open scope too: `ffvkDraw` copies what it
/// names, and the binding is no Vulkan object. The view and sampler it names stay the
/// caller's, alive until every command buffer that draws with them has executed.
///
/// # Safety
///
/// `texture` is null or from `ffvkCreateTexture` or `ffvkCreateCubeMap`, not yet destroyed.
#[no_mangle]
pub unsafe extern "C" fn ffvkDestroyTexture(texture: *mut FfvkTexture) {
    // SAFETY: the caller's contract: made by this API, destroyed once.
    unsafe { crate::result::free(texture) }
}
