//! The committed SPIR-V modules (one per entry point, `assets/spirv/`), embedded at compile time.

// `VAO_MAIN`, … and `ALL`: one constant per `assets/spirv/*.spv`, written by build.rs.
include!(concat!(env!("OUT_DIR"), "/modules.rs"));

/// The module of entry point `entry`.
pub fn of(entry: &str) -> Option<&'static [u8]> {
    ALL.iter().find(|(name, _)| *name == entry).map(|m| m.1)
}

/// SPIR-V words of a module (validates the magic number and alignment).
pub fn words(bytes: &[u8]) -> Vec<u32> {
    ash::util::read_spv(&mut std::io::Cursor::new(bytes)).expect("committed SPIR-V is well-formed")
}
