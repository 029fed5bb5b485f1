//! Gives libffvk_c.so a SONAME, so that programs linked with it record the library's name
//! rather than the path it was found at.
fn main() {
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libffvk_c.so");
}
