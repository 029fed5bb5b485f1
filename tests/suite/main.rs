//! ffvk's integration tests: one binary, modules by area.

mod conformance;
mod determinism;
mod gl_oracle;
mod gl_reference;
mod golden;
mod layout;
mod lighting;
mod reference;
mod render_path;
mod scene;
mod state;
mod support;
