//! Pinhole camera conventions of spec svao-raysd §1: uv origin top-left with v downwards,
//! right-handed view space looking down −Z, linear depth `d > 0` along −Z.

use crate::common::lanes::{LaneVec2, LaneVec3, Lanes};
use crate::glam::{UVec2, Vec2, Vec3};

/// Projection of the full render target (inner image plus guard band), as push-constant data.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct ViewParams {
    /// Full target size `W×H` in pixels (inner size + 2·guard).
    pub res: Vec2,
    /// `(tx, ty)`: tangents of the half field of view of the FULL target (spec svao-raysd §1).
    pub tan_half_fov: Vec2,
    /// Near plane distance (view depth).
    pub near: f32,
    /// Far plane distance: depths at or beyond it are background.
    pub far: f32,
    /// G-buffer guard band `g` in pixels (spec svao-raysd §1, default 64).
    pub guard: u32,
    pub _pad: u32,
}

impl ViewParams {
    /// Full target width and height as integers.
    #[inline]
    pub fn size(&self) -> UVec2 {
        UVec2::new(self.res.x as u32, self.res.y as u32)
    }

    /// Centre uv of pixel `p`: `(p + 0.5)/res` (spec svao-raysd §1).
    #[inline]
    pub fn pixel_uv(&self, p: UVec2) -> Vec2 {
        self.pixel_uv_lanes::<f32>(p)
    }

    /// [`Self::pixel_uv`] per lane.
    #[inline]
    pub fn pixel_uv_lanes<L: Lanes>(&self, p: L::U2) -> L::V2 {
        L::V2::new(
            (L::index_to_float(L::texel_x(p)) + 0.5) / self.res.x,
            (L::index_to_float(L::texel_y(p)) + 0.5) / self.res.y,
        )
    }

    /// Centre uv of texel `p` as a multiply by the (loop-invariant) reciprocal resolution; for
    /// the per-sample fetches, where [`Self::pixel_uv`]'s division would cost.
    #[inline]
    pub fn texel_uv(&self, p: UVec2) -> Vec2 {
        self.texel_uv_lanes::<f32>(p)
    }

    /// [`Self::texel_uv`] per lane.
    #[inline]
    pub fn texel_uv_lanes<L: Lanes>(&self, p: L::U2) -> L::V2 {
        let r = self.res.recip();
        L::V2::new((L::index_to_float(L::texel_x(p)) + 0.5) * r.x, (L::index_to_float(L::texel_y(p)) + 0.5) * r.y)
    }

    /// uv→view: `ndc = (2u−1, 1−2v)`, `X = (ndc.x·d·tx, ndc.y·d·ty, −d)` (spec svao-raysd §1).
    #[inline]
    pub fn uv_to_view(&self, uv: Vec2, d: f32) -> Vec3 {
        self.uv_to_view_lanes::<f32>(uv, d)
    }

    /// [`Self::uv_to_view`] per lane.
    #[inline]
    pub fn uv_to_view_lanes<L: Lanes>(&self, uv: L::V2, d: L) -> L::V3 {
        let (nx, ny) = (uv.x() * 2.0 - 1.0, -(uv.y() * 2.0) + 1.0);
        L::V3::new(nx * d * self.tan_half_fov.x, ny * d * self.tan_half_fov.y, -d)
    }

    /// view→uv: `u = 0.5 + 0.5·X.x/(tx·(−X.z))`, `v = 0.5 − 0.5·X.y/(ty·(−X.z))` (spec svao-raysd §1).
    #[inline]
    pub fn view_to_uv(&self, x: Vec3) -> Vec2 {
        self.view_to_uv_lanes::<f32>(x)
    }

    /// [`Self::view_to_uv`] per lane.
    #[inline]
    pub fn view_to_uv_lanes<L: Lanes>(&self, x: L::V3) -> L::V2 {
        let half_inv_depth = L::splat(0.5) / -x.z();
        L::V2::new(
            x.x() * half_inv_depth / self.tan_half_fov.x + 0.5,
            -(x.y() * half_inv_depth / self.tan_half_fov.y) + 0.5,
        )
    }

    /// Texel containing `uv` after clamping it into the target: `floor(sat(uv)·res)`, kept
    /// inside `[0, res−1]`. Its centre is spec svao-raysd §1's `snap(saturate(uv), res)`.
    #[inline]
    pub fn texel_of_uv(&self, uv: Vec2) -> UVec2 {
        self.texel_of_uv_lanes::<f32>(uv)
    }

    /// [`Self::texel_of_uv`] per lane ([`Lanes::floor_index`] truncates the non-negative
    /// coordinate, i.e. takes its floor, and keeps it inside the target).
    #[inline]
    pub fn texel_of_uv_lanes<L: Lanes>(&self, uv: L::V2) -> L::U2 {
        let size = self.size();
        let x = (crate::common::math::sat(uv.x()) * self.res.x).floor_index(L::index_splat(size.x));
        let y = (crate::common::math::sat(uv.y()) * self.res.y).floor_index(L::index_splat(size.y));
        L::texel(x, y)
    }

    /// Is pixel `p` inside the inner image `[g, W−g) × [g, H−g)`?
    #[inline]
    pub fn is_inner(&self, p: UVec2) -> bool {
        let size = self.size();
        p.x >= self.guard && p.y >= self.guard && p.x + self.guard < size.x && p.y + self.guard < size.y
    }

    /// Row-major index of pixel `p` in a full-target buffer.
    #[inline]
    pub fn index(&self, p: UVec2) -> usize {
        self.index_lanes::<f32>(p) as usize
    }

    /// [`Self::index`] per lane.
    #[inline]
    pub fn index_lanes<L: Lanes>(&self, p: L::U2) -> L::Index {
        crate::common::lanes::row_major_index::<L>(p, self.size().x)
    }
}

/// A perspective camera placed in the world: the view matrices plus [`ViewParams`].
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct Camera {
    /// World → view (right-handed, looking down −Z).
    pub world_to_view: crate::glam::Mat4,
    /// View → world.
    pub view_to_world: crate::glam::Mat4,
    /// Projection of the full target.
    pub view: ViewParams,
}

impl Camera {
    /// Look-at camera whose vertical field of view `fov_y` (radians) covers the INNER image of
    /// `inner` pixels; the guard band `guard` widens the frustum at the same focal length, so the
    /// full target is `inner + 2·guard` (spec svao-raysd §1: 1920×1080 → 2048×1208).
    ///
    /// The arithmetic is the contract's (`assets/README.md`, "Expressions": `look_at`,
    /// `inverse_rigid`, `tan` in binary64 rounded once), so an engine evaluating
    /// [`CONSTANTS`] gets these bits.
    #[cfg(not(target_arch = "spirv"))]
    pub fn look_at(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        fov_y: f32,
        inner: UVec2,
        guard: u32,
        near: f32,
        far: f32,
    ) -> Self {
        use crate::glam::{Mat4, Vec4};
        // Right-handed view basis: x = right, y = up, z = backwards (the camera looks down −Z).
        let forward = (target - eye).normalize();
        let right = forward.cross(up).normalize();
        let true_up = right.cross(forward);
        let view_to_world =
            Mat4::from_cols(right.extend(0.0), true_up.extend(0.0), (-forward).extend(0.0), eye.extend(1.0));
        // The rigid inverse: rotation transposed, translation −Rᵀ·E.
        let world_to_view = Mat4::from_cols(
            Vec4::new(right.x, true_up.x, -forward.x, 0.0),
            Vec4::new(right.y, true_up.y, -forward.y, 0.0),
            Vec4::new(right.z, true_up.z, -forward.z, 0.0),
            Vec4::new(-right.dot(eye), -true_up.dot(eye), -(-forward).dot(eye), 1.0),
        );
        let full = inner + 2 * guard;
        let ty_inner = ((0.5 * fov_y) as f64).tan() as f32;
        // Same focal length: the tangent grows with the pixel count.
        let ty = ty_inner * full.y as f32 / inner.y as f32;
        let tx = ty * full.x as f32 / full.y as f32;
        Camera {
            world_to_view,
            view_to_world,
            view: ViewParams { res: full.as_vec2(), tan_half_fov: Vec2::new(tx, ty), near, far, guard, _pad: 0 },
        }
    }

    /// Camera position in the world.
    #[inline]
    pub fn eye(&self) -> Vec3 {
        self.view_to_world.w_axis.truncate()
    }

    /// Unit world-space direction of the primary ray through `uv` of the full target.
    #[inline]
    pub fn primary_ray_direction(&self, uv: Vec2) -> Vec3 {
        self.view_to_world.transform_vector3(self.view.uv_to_view(uv, 1.0)).normalize()
    }

    /// Linear view depth of a world point at ray distance `t` along `direction` from the eye:
    /// `t·cos θ`, with θ the angle to the view axis.
    #[inline]
    pub fn linear_depth_of_hit(&self, direction: Vec3, t: f32) -> f32 {
        t * -self.world_to_view.transform_vector3(direction).z
    }
}

/// How [`Camera`] and [`ViewParams`] are computed from an engine's camera ([`Camera::look_at`]):
/// the rows every technique's constants table ends with. Symbols: eye E, target T, up U (world
/// space), vertical field of view `fov_y` of the INNER image (radians), inner image `w×h`, guard
/// band `g` pixels per side, full target `W×H = (w + 2g)×(h + 2g)`, near n, far f.
#[cfg(not(target_arch = "spirv"))]
pub const CONSTANTS: &[crate::technique::Constant] = {
    use crate::technique::Constant as C;
    &[
        C::new(
            "Camera.world_to_view",
            "the inverse of Camera.view_to_world (rigid: rotation Rᵀ, translation −Rᵀ·E with R = [r u −d]): \
             world → right-handed view space looking down −Z",
        )
        .expr("inverse_rigid(look_at(eye, target, up))"),
        C::new(
            "Camera.view_to_world",
            "look-at, column-major: columns (r, 0), (u, 0), (−d, 0), (E, 1) with d = normalize(T − E), \
             r = normalize(d × U), u = r × d",
        )
        .expr("look_at(eye, target, up)"),
        C::new("Camera.view", "the frame's ViewParams (ViewParams rows)").expr("ViewParams"),
        C::new(
            "ViewParams.res",
            "(W, H) = (w + 2g, h + 2g) as f32: the full target, inner image plus guard band (pixels)",
        )
        .expr("vec2(W, H)"),
        C::new(
            "ViewParams.tan_half_fov",
            "(tx, ty) of the FULL target: ty = tan(fov_y/2)·H/h (the same focal length over the guard band), \
             tx = ty·W/H",
        )
        .expr("vec2(tan(0.5 * fov_y) * H / h * W / H, tan(0.5 * fov_y) * H / h)"),
        C::new("ViewParams.near", "n: near plane distance (view depth, world units)").expr("near"),
        C::new("ViewParams.far", "f: far plane distance (view depth, world units); depths ≥ f are background")
            .expr("far"),
        C::new("ViewParams.guard", "g: the G-buffer's guard band, pixels per side (the inputs are W×H)").expr("g"),
        C::new("ViewParams._pad", "0").expr("0"),
    ]
};
