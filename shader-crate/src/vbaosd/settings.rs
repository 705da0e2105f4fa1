//! `vbao-sd`'s declaration and pass graph (host side; spec vbao §8): `vbao`'s settings and
//! XeGTAO passes, with the main pass split in two around a ray-traced SD map — request
//! (flag samples, record ray intervals) → SD map (Ray-SD's trace, ray-tracing pipeline or ray
//! query) → main (the masks from the map's layers).

use crate::common::float_order::{RAY_MAX_CLEAR, RAY_MIN_CLEAR};
use crate::graph::{Elem, Extent, FrameDesc, Graph, Init, Lifetime, Pass, Resource, Size, ray_counter, record};
use crate::gtao::settings::{MainPassResources, xegtao_graph};
use crate::svao::Secondary;
use crate::svao::settings::sd_map_pass;
use crate::technique::{Constant, Declaration, Formula, single_layer};
use crate::vbao::settings::{VbaoSettings, vbao_keys};

/// `vbao-sd` (spec vbao §8): `vbao` at its defaults with the cosine-exact weighting, over a
/// ray-traced SD map at Ray-SD's defaults (¼ resolution, 4 layers).
pub static VBAO_SD: Declaration<VbaoSettings> = Declaration {
    name: "vbao-sd",
    summary: "Visibility-bitmask AO whose samples' thickness comes from a ray-traced stochastic depth map (spec vbao §8)",
    keys: vbao_keys!("sd-res", "sd-layers", "max-count", "sd-guard"),
    defaults,
    graph: |s, frame| Ok(graph(s, frame)),
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: FORMULAS,
    tables: &[],
};

fn defaults() -> VbaoSettings {
    VbaoSettings { weighting: crate::vbao::WEIGHT_COSINE_EXACT, ..VbaoSettings::default() }
}

/// XeGTAO's prefilter → (normals) → `vbao_sd_request` → `sd_map` (Ray-SD's trace over the
/// requested intervals) → `vbao_sd_main` → XeGTAO's denoiser (spec vbao §8).
pub fn graph(s: &VbaoSettings, frame: &FrameDesc) -> Graph {
    let params = s.params(frame);
    let svao = s.sd.frame(frame, Secondary::StochasticDepth);
    let sd_extent = Extent::Reduced { divisor: s.sd.divisor, border: svao.params.sd_guard };
    let texels = |per_texel| Size::Texels { extent: sd_extent, per_texel };
    let per_frame =
        |name, elem, size, init, doc| Resource { name, elem, size, init, lifetime: Lifetime::PerFrame, doc };
    let main = |r: MainPassResources| {
        let resources = vec![
            record("svao_frame", std::slice::from_ref(&svao), "camera + SvaoParams of the SD map (spec svao-raysd §7)"),
            per_frame("ray_min", Elem::U32, texels(1), Init::Fill(RAY_MIN_CLEAR), "per-SD-texel ray tMin, float bits"),
            per_frame("ray_max", Elem::U32, texels(1), Init::Fill(RAY_MAX_CLEAR), "per-SD-texel ray tMax, float bits"),
            per_frame(
                "sd_map",
                Elem::F32,
                texels(svao.params.sd_layers),
                Init::Fill(1f32.to_bits()),
                "N normalized depths per SD texel (spec svao-raysd §7)",
            ),
            ray_counter(),
        ];
        let bytes = bytemuck::bytes_of(&params);
        let request = super::vbao_sd_request::Bindings {
            frame: "svao_frame",
            mips: r.mips,
            normals: r.normals,
            ray_min: "ray_min",
            ray_max: "ray_max",
        };
        let main = super::vbao_sd_main::Bindings {
            frame: "svao_frame",
            mips: r.mips,
            normals: r.normals,
            sd_map: "sd_map",
            terms: r.terms,
            edges: r.edges,
        };
        let passes = vec![
            Pass::compute("vbao_sd_request", request, Extent::Full, bytes),
            sd_map_pass(sd_extent),
            Pass::compute("vbao_sd_main", main, Extent::Full, bytes),
        ];
        (resources, passes)
    };
    xegtao_graph(frame, &params.gtao, s.xegtao.normals_from_depth, main)
}

/// The SD map's size and dispatch (spec svao-raysd §3: `ceil(W/div) + 2·floor(sd-guard/div)`
/// texels per side) as expressions of the settings.
const FORMULAS: &[Formula] = {
    const X: &str = "div_ceil(W, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16))";
    const Y: &str = "div_ceil(H, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16))";
    const TEXELS: &str = "(div_ceil(W, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * div_floor(`sd-guard`, \
                          pick(index(`sd-res`), 1, 2, 4, 8, 16))) * (div_ceil(H, pick(index(`sd-res`), 1, 2, 4, 8, 16)) \
                          + 2 * div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16)))";
    const MAP: &str = "(div_ceil(W, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * div_floor(`sd-guard`, \
                       pick(index(`sd-res`), 1, 2, 4, 8, 16))) * (div_ceil(H, pick(index(`sd-res`), 1, 2, 4, 8, 16)) \
                       + 2 * div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16))) * `sd-layers`";
    &[
        Formula { of: "ray_min", expr: TEXELS },
        Formula { of: "ray_max", expr: TEXELS },
        Formula { of: "sd_map", expr: MAP },
        Formula { of: "sd_map.x", expr: X },
        Formula { of: "sd_map.y", expr: Y },
    ]
};

/// How [`graph`] fills the SD map's record for `vbao-sd`: Ray-SD's `SvaoFrame` with the SD
/// settings of its rows and every other field at Ray-SD's defaults (VAO's fields are unread).
const SD_FRAME: &[Constant] = &[
    Constant::new("SvaoFrame.camera", "the frame's Camera (Camera and ViewParams rows)").expr("Camera"),
    Constant::new("SvaoFrame.params", "SvaoParams (SvaoParams rows)").expr("SvaoParams"),
    Constant::new("SvaoParams.vao", "VaoParams (VaoParams rows; only its view is read)").expr("VaoParams"),
    Constant::new("SvaoParams.secondary", "1 (StochasticDepth)").expr("1"),
    Constant::new("SvaoParams.interval", "1: the SD rays cover the requested intervals only (spec vbao §8.1)").expr("1"),
    Constant::new("SvaoParams.cutoff", "6 (unread)").expr("6.0"),
    Constant::new(
        "SvaoParams.sd_guard",
        "SD guard band in SD texels: floor(`sd-guard`/div), div = 1, 2, 4, 8, 16 for `sd-res` full … sixteenth \
         [floor(512/4) = 128]",
    )
    .expr("div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16))"),
    Constant::new(
        "SvaoParams.sd_low_res",
        "(ceil(W/div), ceil(H/div)) SD texels, div by `sd-res` [4], W×H the full target incl. its guard band",
    )
    .expr("uvec2(div_ceil(W, pick(index(`sd-res`), 1, 2, 4, 8, 16)), div_ceil(H, pick(index(`sd-res`), 1, 2, 4, 8, 16)))"),
    Constant::new("SvaoParams.sd_layers", "N = `sd-layers` [4]").expr("`sd-layers`"),
    Constant::new("SvaoParams.max_count", "max(`max-count`, `sd-layers`) [8]").expr("max(`max-count`, `sd-layers`)"),
    Constant::new("SvaoParams.jitter", "1: the scrambled SD jitter table (spec svao-raysd §7.2)").expr("1"),
    Constant::new("SvaoParams.dual", "0 (single depth)").expr("0"),
    Constant::new("SvaoParams.kernel", "0 (unread)").expr("0"),
    Constant::new("SvaoParams.sample_set", "0 (unread)").expr("0"),
    Constant::new(
        "SvaoParams.noise_frame",
        "the frame index: rotates the SD map's hashes by frame_rotation(f mod 64) and offsets the jitter index by f mod 16",
    )
    .expr("frame"),
    Constant::new("SvaoParams._pad0", "0").expr("0"),
    Constant::new("SvaoParams._pad1", "0").expr("0"),
    Constant::new("SvaoParams._pad2", "0").expr("0"),
    Constant::new("VaoParams.view", "the frame's ViewParams (ViewParams rows)").expr("ViewParams"),
    Constant::new("VaoParams.radius", "R, the frame's AO radius (unread)").expr("radius"),
    Constant::new("VaoParams.exponent", "the frame's AO exponent (unread)").expr("exponent"),
    Constant::new("VaoParams.thickness", "the frame's VAO thickness (unread)").expr("thickness"),
    Constant::new("VaoParams.max_screen_radius", "512 (unread)").expr("512"),
];

/// `vbao`'s constants (every pass's `VbaoParams` and `GtaoParams`, the camera's rows) and the SD
/// map's record.
pub const CONSTANTS: &[Constant] = crate::join_constants![SD_FRAME, crate::vbao::settings::CONSTANTS];
