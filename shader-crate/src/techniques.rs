//! The registry: every technique aokit offers, one line each. A technique is its folder
//! (kernels, settings rows, pass graph, its [`Declaration`](crate::technique::Declaration)) plus
//! its line here; the CLI, the reports and both executors find it through this list.

use crate::technique::Registered;

/// Every technique, in the order listings show them.
pub static TECHNIQUES: &[&dyn Registered] = &[
    &crate::vao::settings::VAO,
    &crate::svao::settings::HBAO,
    &crate::svao::settings::RAYSD,
    &crate::svao::settings::HBAO_SD,
    &crate::svao::settings::SDSVAO,
    &crate::svao::settings::RAYSVAO,
    &crate::gtao::settings::GTAO,
    &crate::vbao::settings::VBAO,
    &crate::vbaosd::settings::VBAO_SD,
    &crate::raymarch::settings::RAYMARCH,
    &crate::hybrid::settings::HYBRID,
    &crate::groundtruth::settings::GROUNDTRUTH,
];

/// The technique called `name`.
pub fn find(name: &str) -> Option<&'static dyn Registered> {
    TECHNIQUES.iter().copied().find(|t| t.name() == name)
}

/// The registered names, comma-separated (for messages and help).
pub fn names() -> String {
    TECHNIQUES.iter().map(|t| t.name()).collect::<Vec<_>>().join(", ")
}
