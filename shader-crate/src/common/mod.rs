//! Math shared by every technique (spec svao-raysd §1, §4.1, §7.2, §7.3).

pub mod alpha;
pub mod any_hit;
pub mod atomics;
pub mod camera;
pub mod denoise_terms;
pub mod float_order;
pub mod gbuffer_read;
pub mod hash;
pub mod lanes;
pub mod math;
pub mod noise;
pub mod normal_codec;
pub mod read;
pub mod screen_space;
pub mod tables;

pub use camera::ViewParams;
