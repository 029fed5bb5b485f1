pub mod presets;
pub mod state;
