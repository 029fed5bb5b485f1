//! ffvk's integration tests: one binary, modules by area.

mod bench;
mod browser;
mod conformance;
mod determinism;
mod embedding;
mod files;
mod fuzz;
mod gl_oracle;
mod gltf_files;
mod golden;
mod hostile;
mod hostile_gltf;
mod layout;
mod lighting;
mod memory;
mod reference;
mod regression;
mod render_path;
mod report;
mod scene;
mod specialization;
mod state;
mod support;
mod texture_conformance;
mod texturing;
mod topology;
