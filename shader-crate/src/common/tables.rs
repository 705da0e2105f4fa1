//! Constant tables of spec svao-raysd: per-pixel rotation (§4.1.1), VAO sample radii (§4.2)
//! and the 4×4 SD-map jitter (§7.2).

use crate::glam::{UVec2, Vec2, vec2};

/// Bayer 4×4 ranks `k` stored as the R8Unorm texel `floor(k·255/16)` (spec §4.1.1), row-major
/// `[y][x]`.
const ROTATION_TEXELS: [[u32; 4]; 4] = [
    [0, 127, 31, 159],
    [191, 63, 223, 95],
    [47, 175, 15, 143],
    [239, 111, 207, 79],
];

/// Per-pixel rotation angle ξ = (u8/255)·2·3.141 at `(p.x mod 4, p.y mod 4)` (spec §4.1.1; the
/// reference uses 3.141 for π).
#[inline]
pub fn rotation_angle(p: UVec2) -> f32 {
    let texel = ROTATION_TEXELS[(p.y % 4) as usize][(p.x % 4) as usize];
    (texel as f32 / 255.0) * 2.0 * 3.141
}

/// Normalized VAO sample radii ρ_i = sqrt(1 − ψ_i^(2/3)), ψ_i = VdC(8 + i), as hard-coded to 6
/// decimals in the reference (spec §4.2 table; SVAO paper appendix 7.1).
pub const VAO_RADII: [f32; 8] = [
    0.917883, 0.564429, 0.734504, 0.359545, 0.820004, 0.470149, 0.650919, 0.205215,
];

/// Number of AO samples per pixel (spec §2).
pub const AO_SAMPLES: u32 = 8;

/// SD-map jitter at the reference's HEAD ("scrambled ray-sd samples"), index
/// `(y mod 4)·4 + (x mod 4)` (spec §7.2). A Latin hypercube over the 16×16 sub-grid of a
/// 4×4-pixel block.
#[allow(clippy::excessive_precision)]
pub const SD_JITTER_SCRAMBLED: [[f32; 2]; 16] = [
    [0.6483604982495308, 0.914070401340723],
    [0.7279119342565536, 0.1037941575050354],
    [0.48886989802122116, 0.699178121984005],
    [0.3848271369934082, 0.25951504334807396],
    [0.1555836834013462, 0.8020274639129639],
    [0.2205628715455532, 0.2412630058825016],
    [0.9962188489735126, 0.5846633277833462],
    [0.8776040785014629, 0.3954884633421898],
    [0.9271227307617664, 0.831196017563343],
    [0.9490576796233654, 0.14202157780528069],
    [0.20916065946221352, 0.5476771481335163],
    [0.16468944773077965, 0.4869129806756973],
    [0.43544455617666245, 0.9515445046126842],
    [0.44085410237312317, 0.011881716549396515],
    [0.7173641100525856, 0.6695209294557571],
    [0.6563677340745926, 0.35924511030316353],
];

/// Paper-era jitter table (stratum centres, "default sobol", spec §7.2).
pub const SD_JITTER_PAPER: [[f32; 2]; 16] = [
    [0.125, 0.125],
    [0.375, 0.875],
    [0.625, 0.625],
    [0.875, 0.375],
    [0.875, 0.375],
    [0.625, 0.625],
    [0.375, 0.875],
    [0.125, 0.125],
    [0.625, 0.625],
    [0.875, 0.375],
    [0.125, 0.125],
    [0.375, 0.875],
    [0.375, 0.875],
    [0.125, 0.125],
    [0.875, 0.375],
    [0.625, 0.625],
];

/// Which SD-map jitter table to use (spec §7.2).
#[repr(u32)]
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum JitterTable {
    /// No jitter: texel centres (0.5, 0.5).
    None = 0,
    /// The reference's HEAD table (default).
    Scrambled = 1,
    /// The paper-era stratum-centre table.
    Paper = 2,
}

/// Jitter of SD texel `q` inside its texel (spec §7.2: index uses the guard-inclusive `q`).
#[inline]
pub fn sd_jitter(q: UVec2, table: u32) -> Vec2 {
    let i = ((q.y % 4) * 4 + (q.x % 4)) as usize;
    if table == JitterTable::Scrambled as u32 {
        vec2(SD_JITTER_SCRAMBLED[i][0], SD_JITTER_SCRAMBLED[i][1])
    } else if table == JitterTable::Paper as u32 {
        vec2(SD_JITTER_PAPER[i][0], SD_JITTER_PAPER[i][1])
    } else {
        vec2(0.5, 0.5)
    }
}
