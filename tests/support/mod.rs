pub mod gl_reference;
