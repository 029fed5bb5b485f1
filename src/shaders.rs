//! SPIR-V compiled from `glsl/` by build.rs, embedded in the binary.

include!(concat!(env!("OUT_DIR"), "/shaders.rs"));

/// The SPIR-V of one stage file (for example `"phong.frag"`).
pub fn spirv(name: &str) -> Option<&'static [u8]> {
    SHADERS.iter().find(|(n, _)| *n == name).map(|(_, bytes)| *bytes)
}
