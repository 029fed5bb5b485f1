//! ffvk's integration tests: one binary, modules by area.

mod layout;
mod lighting;
mod reference;
mod render_path;
mod scene;
mod state;
mod support;
