//! Constant tables of spec svao-raysd: per-pixel rotation (§4.1.1), VAO sample radii (§4.2)
//! and the 4×4 SD-map jitter (§7.2).

use crate::glam::{UVec2, Vec2, vec2};

/// The reference implementation's π: it uses 3.141 for every 2π in the angle code, kept for
/// exactness (spec svao-raysd §1).
#[allow(clippy::approx_constant)]
pub const REFERENCE_PI: f32 = 3.141;

/// Bayer 4×4 ranks `k` stored as the R8Unorm texel `floor(k·255/16)` (spec §4.1.1), row-major
/// `[y][x]`.
const ROTATION_TEXELS: [[u32; 4]; 4] = [[0, 127, 31, 159], [191, 63, 223, 95], [47, 175, 15, 143], [239, 111, 207, 79]];

/// Per-pixel rotation angle ξ = (u8/255)·2·3.141 at `(p.x mod 4, p.y mod 4)` (spec §4.1.1; the
/// reference uses 3.141 for π).
#[inline]
pub fn rotation_angle(p: UVec2) -> f32 {
    let texel = ROTATION_TEXELS[(p.y % 4) as usize][(p.x % 4) as usize];
    (texel as f32 / 255.0) * 2.0 * REFERENCE_PI
}

/// `(sin ξ, cos ξ)` of [`rotation_angle`] for every cell, `[y][x]`, rounded from f64: the
/// kernels read this instead of evaluating two transcendentals per pixel (tests tie it to the
/// formula).
#[allow(clippy::excessive_precision)]
pub const ROTATION_SIN_COS: [[[f32; 2]; 4]; 4] = [
    [
        [0.0, 1.0],
        [0.01290994230657816, -0.999916672706604],
        [0.6915943622589111, 0.7222861051559448],
        [-0.7000154256820679, -0.7141277194023132],
    ],
    [
        [-0.9999751448631287, -0.007047745399177074],
        [0.999823808670044, 0.018771694973111153],
        [-0.7100116014480591, 0.7041899561882019],
        [0.7182192802429199, -0.6958168745040894],
    ],
    [
        [0.9159459471702576, 0.40130165219306946],
        [-0.9205881357192993, -0.3905348479747772],
        [0.36117663979530334, 0.9324974417686462],
        [-0.3720850944519043, -0.9281986355781555],
    ],
    [
        [-0.38513123989105225, 0.9228618144989014],
        [0.39592504501342773, -0.9182828068733215],
        [-0.9260013103485107, 0.37752023339271545],
        [0.9303640127182007, -0.3666371703147888],
    ],
];

/// `(sin ξ, cos ξ)` of the per-pixel rotation at `(p.x mod 4, p.y mod 4)` (spec §4.1 step 6).
#[inline]
pub fn rotation_sin_cos(p: UVec2) -> Vec2 {
    let e = ROTATION_SIN_COS[(p.y % 4) as usize][(p.x % 4) as usize];
    vec2(e[0], e[1])
}

/// Normalized VAO sample radii ρ_i = sqrt(1 − ψ_i^(2/3)), ψ_i = VdC(8 + i), as hard-coded to 6
/// decimals in the reference (spec §4.2 table; SVAO paper appendix 7.1).
pub const VAO_RADII: [f32; 8] = [0.917883, 0.564429, 0.734504, 0.359545, 0.820004, 0.470149, 0.650919, 0.205215];

/// Normalized half-chords `sqrt(1 − ρ_i²)` of [`VAO_RADII`]: `h_i = R·sqrt(1 − ρ_i²)` (spec §4.2).
#[allow(clippy::excessive_precision)]
pub const VAO_HALF_CHORDS: [f32; 8] = [
    0.39685115218162537,
    0.825481653213501,
    0.6786043643951416,
    0.933127760887146,
    0.5723578333854675,
    0.8825870752334595,
    0.7591471672058105,
    0.9787169098854065,
];

/// HBAO+ kernel radii ρ_i = 2·asin(ψ_i^1.25)/π, ψ_i = VdC(8 + i) (spec svao-raysd §4.5 table,
/// the code's literals).
#[allow(clippy::excessive_precision)]
pub const HBAO_RADII: [f32; 8] = [
    0.019897607325877215,
    0.3239192018939078,
    0.15013283288204182,
    0.5608856339193332,
    0.07874804859295396,
    0.4306374970658152,
    0.23159241868180838,
    0.74770696488701,
];

/// Normalized half-chords `sqrt(1 − ρ_i²)` of [`HBAO_RADII`] (hemisphere clipping, spec §4.5).
#[allow(clippy::excessive_precision)]
pub const HBAO_HALF_CHORDS: [f32; 8] = [
    0.9998020230139091,
    0.9460847481301101,
    0.988665834592666,
    0.827893293645327,
    0.9968945505131431,
    0.9025249836546853,
    0.9728129067858372,
    0.6640288357138232,
];

/// HBAO+ sample weights `pdf_i = 0.9·(1 − ρ_i)^1.5` (spec §4.5, the kernel maximum's envelope).
#[allow(clippy::excessive_precision)]
pub const HBAO_PDFS: [f32; 8] = [
    0.8732722978109168,
    0.5003114146979276,
    0.7051298285229405,
    0.26188400744516105,
    0.7958113716137286,
    0.3866569336017646,
    0.6062195963682379,
    0.11405134245105371,
];

/// Disc directions `(sin α_i, cos α_i)` with `α_i = (i/8)·2·3.141` (spec §4.2; 3.141 as in the
/// reference), rounded from f64.
#[allow(clippy::excessive_precision)]
pub const VAO_DIRECTIONS: [[f32; 2]; 8] = [
    [0.0, 1.0],
    [0.7070019841194153, 0.7072115540504456],
    [0.9999999403953552, 0.0002963267907034606],
    [0.7074210047721863, -0.706792414188385],
    [0.0005926535814069211, -0.9999998211860657],
    [-0.7065827250480652, -0.7076303958892822],
    [-0.9999995827674866, -0.0008889802847988904],
    [-0.7078397870063782, 0.7063730359077454],
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
