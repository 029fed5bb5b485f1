//! The bodies of `ffvk`'s commands, one module each (main.rs parses and dispatches).

pub(crate) mod common;
pub(crate) mod compare;
pub(crate) mod info;
pub(crate) mod render;
pub(crate) mod results;
pub(crate) mod scene;
