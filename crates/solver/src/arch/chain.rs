//! The chain formulation: statics of a chain of blocks between two supports leaves only three
//! redundant forces (the reaction at the first support), so every stress resultant is an affine
//! function of them and of the load factors. The limit-analysis programmes then have four
//! variables — the three redundants and δ or λ — instead of three per interface, and no
//! equilibrium rows: the model holds only what the scene needs (Heyman 1966's thrust line with
//! its three degrees of freedom; Livesley 1978 §2.2 reduces H r = w the same way).
//!
//! Notation, in the scaled units of [`super::equilibrium`] (forces / W, lengths / L about an
//! origin o inside the assembly): F_k = (F_x, F_y, M_o) is the wrench that interface k exerts on
//! block k (on the far support for the last interface). Block k in equilibrium gives
//! F_{k+1} = F_k + L_k, L_k the loads on block k, so F_k = x + C_k with x = F_0 and C_k the sum
//! of the loads on the blocks before k. The resultants follow from the wrench by
//! (q, s, t) = D_k F_k, D_k the inverse of E_k = [ν, P_q×ν; ν, P_s×ν; τ, P_s×τ] (columns).
//!
//! Kinematics is the transpose: the deformation rates of interface k (relative normal velocity
//! at P_q and P_s, relative sliding) are E_kᵀ ΔV_k for the relative twist ΔV_k of the two blocks,
//! so a mechanism's block twists are the running sums of ΔV_k = D_kᵀ d_k from the first support.

use super::equilibrium::{force_scale, LiveLoad};
use super::geometry::Assembly;

type Matrix3 = [[f64; 3]; 3];

fn cross(a: (f64, f64), b: (f64, f64)) -> f64 {
    a.0 * b.1 - a.1 * b.0
}

/// A point relative to the origin of the moments, in units of L.
fn scale_point(p: (f64, f64), origin: (f64, f64), length_scale: f64) -> (f64, f64) {
    (
        (p.0 - origin.0) / length_scale,
        (p.1 - origin.1) / length_scale,
    )
}

fn apply(m: &Matrix3, v: [f64; 3]) -> [f64; 3] {
    [
        m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
        m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
        m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2],
    ]
}

fn apply_transpose(m: &Matrix3, v: [f64; 3]) -> [f64; 3] {
    [
        m[0][0] * v[0] + m[1][0] * v[1] + m[2][0] * v[2],
        m[0][1] * v[0] + m[1][1] * v[1] + m[2][1] * v[2],
        m[0][2] * v[0] + m[1][2] * v[1] + m[2][2] * v[2],
    ]
}

/// The affine statics of a chain in scaled units.
#[derive(Debug, Clone, PartialEq)]
pub struct ChainStatics {
    /// D_k per interface: wrench → (q, s, t).
    decompose: Vec<Matrix3>,
    /// D_k C_k for the dead load (resultants at x = 0 and dead factor 1).
    dead: Vec<[f64; 3]>,
    /// D_k C_k for the live load.
    live: Vec<[f64; 3]>,
    /// Block centroids relative to the origin, in units of L.
    centroids: Vec<(f64, f64)>,
    /// Largest component of the scaled live wrenches (0 without live loads).
    pub live_scale: f64,
    /// The origin o of the moments.
    origin: (f64, f64),
    /// The length scale L.
    length_scale: f64,
}

/// The resultant of one interface as an affine function of the redundants and load factors.
#[derive(Debug, Clone, Copy)]
pub struct InterfaceAffine<'a> {
    /// The 3×3 map of the redundants x.
    pub map: &'a Matrix3,
    /// The part per unit dead-load factor.
    pub dead: [f64; 3],
    /// The part per unit live-load factor.
    pub live: [f64; 3],
}

impl ChainStatics {
    /// The statics of `assembly` with dead weight γ·area and the given live loads, in the
    /// scaling of [`super::equilibrium::assemble_equilibrium`] (same W and L).
    pub fn new(
        assembly: &Assembly,
        unit_weight: f64,
        other_dead_loads: &[LiveLoad],
        live_loads: &[LiveLoad],
    ) -> Self {
        let force_scale = force_scale(assembly, unit_weight, other_dead_loads);
        let length_scale = assembly.length_scale();
        let corners: usize = assembly.blocks.iter().map(|b| b.corners.len()).sum();
        let origin = assembly
            .blocks
            .iter()
            .flat_map(|b| b.corners.iter())
            .fold((0.0, 0.0), |o, c| {
                (o.0 + c.0 / corners as f64, o.1 + c.1 / corners as f64)
            });
        let scaled = |p| scale_point(p, origin, length_scale);
        let n = assembly.blocks.len();
        let centroids: Vec<(f64, f64)> =
            assembly.blocks.iter().map(|b| scaled(b.centroid)).collect();
        let mut dead_loads = vec![[0.0; 3]; n];
        for (b, block) in assembly.blocks.iter().enumerate() {
            let w = unit_weight * block.area / force_scale;
            dead_loads[b] = [0.0, -w, cross(centroids[b], (0.0, -w))];
        }
        let mut live_loads_scaled = vec![[0.0; 3]; n];
        for (sums, loads) in [
            (&mut dead_loads, other_dead_loads),
            (&mut live_loads_scaled, live_loads),
        ] {
            for load in loads {
                let f = (load.fx / force_scale, load.fy / force_scale);
                let l = &mut sums[load.block];
                l[0] += f.0;
                l[1] += f.1;
                l[2] += cross(scaled(load.point), f) + load.moment / (force_scale * length_scale);
            }
        }
        let live_scale = live_loads_scaled
            .iter()
            .flatten()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        let mut decompose = Vec::with_capacity(n + 1);
        let mut dead = Vec::with_capacity(n + 1);
        let mut live = Vec::with_capacity(n + 1);
        let (mut c_dead, mut c_live) = ([0.0; 3], [0.0; 3]);
        for (k, interface) in assembly.interfaces.iter().enumerate() {
            let (nu, tau) = (interface.normal, interface.tangent);
            let (pq, ps) = (scaled(interface.extrados), scaled(interface.intrados));
            let (cq, cs, ct) = (cross(pq, nu), cross(ps, nu), cross(ps, tau));
            // Rows of D = E⁻¹: t = F·τ, n = q + s = F·ν, q = (M − n·c_s − t·c_t)/(c_q − c_s).
            let denominator = cq - cs;
            let q_row = [
                (-cs * nu.0 - ct * tau.0) / denominator,
                (-cs * nu.1 - ct * tau.1) / denominator,
                1.0 / denominator,
            ];
            let s_row = [nu.0 - q_row[0], nu.1 - q_row[1], -q_row[2]];
            let d = [q_row, s_row, [tau.0, tau.1, 0.0]];
            dead.push(apply(&d, c_dead));
            live.push(apply(&d, c_live));
            decompose.push(d);
            if k < n {
                for i in 0..3 {
                    c_dead[i] += dead_loads[k][i];
                    c_live[i] += live_loads_scaled[k][i];
                }
            }
        }
        Self {
            decompose,
            dead,
            live,
            centroids,
            live_scale,
            origin,
            length_scale,
        }
    }

    /// The scaled wrench (F_x, F_y, M_o) of a force `force` (in units of W) acting at `point`.
    pub fn wrench(&self, point: (f64, f64), force: (f64, f64)) -> [f64; 3] {
        let arm = scale_point(point, self.origin, self.length_scale);
        [force.0, force.1, cross(arm, force)]
    }

    /// Number of interfaces.
    pub fn interfaces(&self) -> usize {
        self.decompose.len()
    }

    /// The resultant (q, s, t) of interface k as `map·x + dead_factor·dead + live_factor·live`.
    pub fn affine(&self, k: usize) -> InterfaceAffine<'_> {
        InterfaceAffine {
            map: &self.decompose[k],
            dead: self.dead[k],
            live: self.live[k],
        }
    }

    /// All resultants (scaled) for redundants `x` and the load factors.
    pub fn resultants(&self, x: [f64; 3], dead_factor: f64, live_factor: f64) -> Vec<[f64; 3]> {
        (0..self.interfaces())
            .map(|k| {
                let r = apply(&self.decompose[k], x);
                std::array::from_fn(|i| {
                    r[i] + dead_factor * self.dead[k][i] + live_factor * self.live[k][i]
                })
            })
            .collect()
    }

    /// Block velocities in the layout of the equilibrium-row multipliers (u, v at the centroid
    /// and ω·L per block) from the deformation rates d_k (normal rate at P_q, at P_s, sliding).
    pub fn block_velocities(&self, deformation: &[[f64; 3]]) -> Vec<f64> {
        let mut twist = [0.0; 3];
        let mut out = Vec::with_capacity(3 * self.centroids.len());
        for (k, g) in self.centroids.iter().enumerate() {
            let relative = apply_transpose(&self.decompose[k], deformation[k]);
            for i in 0..3 {
                twist[i] += relative[i];
            }
            // Twist (u, v, ω̂) at the origin → velocity of the centroid.
            out.extend([
                twist[0] - twist[2] * g.1,
                twist[1] + twist[2] * g.0,
                twist[2],
            ]);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arch::equilibrium::assemble_equilibrium;
    use crate::arch::{CircularArch, VoussoirShape};
    use std::num::NonZeroUsize;

    #[test]
    fn resultants_of_any_redundants_are_in_equilibrium() {
        // The affine resultants satisfy the assembled H r + λ₀w + λp = 0 whatever x is
        // (1e-12: rounding in scaled units).
        let arch = CircularArch::new(
            10.0,
            1.0,
            NonZeroUsize::new(9).unwrap(),
            10.0,
            -5.0,
            VoussoirShape::Curved,
        )
        .unwrap()
        .assembly();
        let loads = [LiveLoad {
            block: 3,
            point: (1.0, 9.0),
            fx: 0.3,
            fy: -2.0,
            moment: 0.7,
        }];
        let chain = ChainStatics::new(&arch, 2.0, &[], &loads);
        let eq = assemble_equilibrium(&arch, 2.0, &[], &loads);
        for x in [[0.0, 0.0, 0.0], [0.4, 0.5, -0.2], [-3.0, 1.0, 2.0]] {
            let r: Vec<f64> = chain
                .resultants(x, 0.8, 1.7)
                .into_iter()
                .flatten()
                .collect();
            let residual = eq.residual(&r, 0.8, 1.7);
            assert!(residual.iter().all(|v| v.abs() < 1e-12), "{residual:?}");
        }
    }
}
