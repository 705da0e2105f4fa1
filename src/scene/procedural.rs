//! Procedural scenes for fast tests and demos.

use super::Scene;
use aokit_shaders::glam::{Vec3, vec3};
use std::f32::consts::TAU;

/// Append the quad `a b c d` (counter-clockwise) as two triangles.
pub fn push_quad(scene: &mut Scene, a: Vec3, b: Vec3, c: Vec3, d: Vec3) {
    scene.triangles.push([a, b, c]);
    scene.triangles.push([a, c, d]);
}

/// Append an axis-aligned box.
pub fn push_box(scene: &mut Scene, lo: Vec3, hi: Vec3) {
    let c = |x: bool, y: bool, z: bool| {
        vec3(if x { hi.x } else { lo.x }, if y { hi.y } else { lo.y }, if z { hi.z } else { lo.z })
    };
    let (f, t) = (false, true);
    push_quad(scene, c(f, f, t), c(t, f, t), c(t, t, t), c(f, t, t)); // +z
    push_quad(scene, c(t, f, f), c(f, f, f), c(f, t, f), c(t, t, f)); // −z
    push_quad(scene, c(t, f, t), c(t, f, f), c(t, t, f), c(t, t, t)); // +x
    push_quad(scene, c(f, f, f), c(f, f, t), c(f, t, t), c(f, t, f)); // −x
    push_quad(scene, c(f, t, t), c(t, t, t), c(t, t, f), c(f, t, f)); // +y
    push_quad(scene, c(f, f, f), c(t, f, f), c(t, f, t), c(f, f, t)); // −y
}

/// A round tower (radius 3, height 10) open towards +x, with a spiral staircase of 48 steps
/// around a central column and a ground plane: many overlapping occluders at every depth.
pub fn spiral_tower() -> Scene {
    let mut s = Scene { name: "tower".into(), ..Default::default() };
    push_quad(&mut s, vec3(-12.0, 0.0, 12.0), vec3(12.0, 0.0, 12.0), vec3(12.0, 0.0, -12.0), vec3(-12.0, 0.0, -12.0));
    let (radius, height, segments) = (3.0f32, 10.0f32, 40);
    let ring = |a: f32, r: f32, y: f32| vec3(r * a.cos(), y, r * a.sin());
    for i in 0..segments {
        let a0 = TAU * i as f32 / segments as f32;
        let a1 = TAU * (i + 1) as f32 / segments as f32;
        let mid = 0.5 * (a0 + a1);
        if mid.cos() > 0.7 {
            continue; // the slot the camera looks through
        }
        // Wall with thickness 0.3: inner and outer surfaces plus a top cap.
        let (ri, ro) = (radius, radius + 0.3);
        push_quad(&mut s, ring(a0, ri, 0.0), ring(a1, ri, 0.0), ring(a1, ri, height), ring(a0, ri, height));
        push_quad(&mut s, ring(a1, ro, 0.0), ring(a0, ro, 0.0), ring(a0, ro, height), ring(a1, ro, height));
        push_quad(&mut s, ring(a0, ri, height), ring(a1, ri, height), ring(a1, ro, height), ring(a0, ro, height));
        // Central column.
        push_quad(&mut s, ring(a1, 0.4, 0.0), ring(a0, 0.4, 0.0), ring(a0, 0.4, height), ring(a1, 0.4, height));
    }
    // Steps: slabs spanning 0.4 … 2.9 in radius, 22.5° each, rising 0.2 per step.
    for k in 0..48 {
        let a0 = TAU * k as f32 / 16.0;
        let a1 = a0 + TAU / 16.0;
        let y = 0.2 * (k + 1) as f32;
        let (r0, r1) = (0.4, 2.9);
        let (b0, b1) = (y - 0.12, y);
        let (p, q, r, t) = (ring(a0, r0, 0.0), ring(a1, r0, 0.0), ring(a1, r1, 0.0), ring(a0, r1, 0.0));
        let up = |v: Vec3, h: f32| vec3(v.x, h, v.z);
        push_quad(&mut s, up(p, b1), up(t, b1), up(r, b1), up(q, b1)); // tread
        push_quad(&mut s, up(p, b0), up(q, b0), up(r, b0), up(t, b0)); // underside
        push_quad(&mut s, up(p, b0), up(t, b0), up(t, b1), up(p, b1)); // riser
        push_quad(&mut s, up(q, b1), up(r, b1), up(r, b0), up(q, b0)); // back
        push_quad(&mut s, up(t, b0), up(r, b0), up(r, b1), up(t, b1)); // outer edge
    }
    s
}
