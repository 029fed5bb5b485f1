//! Gives libffvk_c.so a SONAME carrying the major version, `libffvk_c.so.0` for ffvk-c 0.x,
//! so that programs linked with it record that name rather than the path it was found at, and
//! a later release that breaks them gets another. `make install-c` installs the library as
//! `libffvk_c.so.<version>` with the links `libffvk_c.so.<major>` (this name) and
//! `libffvk_c.so`.
fn main() {
    let major = env!("CARGO_PKG_VERSION_MAJOR");
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libffvk_c.so.{major}");
}
