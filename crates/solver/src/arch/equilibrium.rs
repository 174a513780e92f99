//! The equilibrium equations H r + λ₀·w + λ·p = 0 of a rigid-block assembly (Livesley 1978,
//! §2.2): three rows per block (force in x, force in y, moment about the block centroid), three
//! columns per interface (q, s, t). See the module `arch` for the sign conventions.
//!
//! The system is assembled non-dimensionally so that the linear programme is well scaled
//! whatever the units: forces are divided by the total dead weight W and moments by W·L, L being
//! the size of the assembly. Resultants therefore come out of the solver in units of W.

use super::geometry::Assembly;

/// Number of stress resultants per interface (q, s, t).
pub const RESULTANTS_PER_INTERFACE: usize = 3;
/// Number of equilibrium equations per block (x, y, moment).
pub const EQUATIONS_PER_BLOCK: usize = 3;

/// A live load: a force (fx, fy) applied at `point` of block `block` plus a moment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LiveLoad {
    /// Index of the loaded block (0-based).
    pub block: usize,
    /// Point of application.
    pub point: (f64, f64),
    /// Horizontal force component.
    pub fx: f64,
    /// Vertical force component (up positive).
    pub fy: f64,
    /// Applied moment, counter-clockwise positive.
    pub moment: f64,
}

/// One horizontal passive force of a fill on a voussoir (see [`super::fill::passive_forces`]): `direction`·p with 0 ≤ p ≤ `capacity`, acting
/// at `point` (the centroid of the largest pressure over the part of the extrados it covers).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PassiveForce {
    /// Index of the voussoir (0-based).
    pub block: usize,
    /// Point of application on the extrados.
    pub point: (f64, f64),
    /// +1: pushes the voussoir towards +x; −1: towards −x (always into the arch, away from the
    /// fill).
    pub direction: f64,
    /// The largest force: ∫ mobilisation·K_p·γ_f·(road − y) |dy| over that part of the extrados.
    pub capacity: f64,
}

/// The assembled, scaled equilibrium equations.
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// Number of rows (3 per block).
    pub rows: usize,
    /// Number of columns: 3 per interface (q, s, t), then one per passive force.
    pub columns: usize,
    /// Number of resultant columns (3 per interface); the passive forces follow them.
    pub resultant_columns: usize,
    /// Non-zeros of H as (row, column, value).
    pub triplets: Vec<(usize, usize, f64)>,
    /// Dead-load vector w, scaled by the total weight.
    pub dead: Vec<f64>,
    /// Live-load vector p, scaled by the total weight.
    pub live: Vec<f64>,
    /// Force scale: the total dead weight W.
    pub force_scale: f64,
    /// Length scale L (moments are divided by W·L).
    pub length_scale: f64,
}

fn cross(a: (f64, f64), b: (f64, f64)) -> f64 {
    a.0 * b.1 - a.1 * b.0
}

/// The force scale W of the non-dimensional equations: the total dead weight (the blocks'
/// and any other dead loads', such as a fill's).
pub(crate) fn force_scale(assembly: &Assembly, unit_weight: f64, dead_loads: &[LiveLoad]) -> f64 {
    let others: f64 = dead_loads.iter().map(|l| l.fx.hypot(l.fy)).sum();
    (unit_weight * assembly.total_area() + others).max(f64::MIN_POSITIVE)
}

/// Assembles H, w and p for `assembly` with dead weight `unit_weight`·area per block plus the
/// other `dead_loads` (a fill's weight, say).
pub fn assemble_equilibrium(
    assembly: &Assembly,
    unit_weight: f64,
    dead_loads: &[LiveLoad],
    live_loads: &[LiveLoad],
) -> Equilibrium {
    let n = assembly.blocks.len();
    let force_scale = force_scale(assembly, unit_weight, dead_loads);
    let length_scale = assembly.length_scale();
    let mut triplets = Vec::with_capacity(18 * n);
    for (k, interface) in assembly.interfaces.iter().enumerate() {
        // The interface pushes its upper block along +ν and its lower block along −ν.
        let neighbours = [
            interface.upper.map(|b| (b, 1.0)),
            interface.lower.map(|b| (b, -1.0)),
        ];
        for (block, sign) in neighbours.into_iter().flatten() {
            let g = assembly.blocks[block].centroid;
            let arm_q = (interface.extrados.0 - g.0, interface.extrados.1 - g.1);
            let arm_s = (interface.intrados.0 - g.0, interface.intrados.1 - g.1);
            let (nu, tau) = (interface.normal, interface.tangent);
            let (row, col) = (EQUATIONS_PER_BLOCK * block, RESULTANTS_PER_INTERFACE * k);
            triplets.extend([
                (row, col, sign * nu.0),
                (row + 1, col, sign * nu.1),
                (row + 2, col, sign * cross(arm_q, nu) / length_scale),
                (row, col + 1, sign * nu.0),
                (row + 1, col + 1, sign * nu.1),
                (row + 2, col + 1, sign * cross(arm_s, nu) / length_scale),
                (row, col + 2, sign * tau.0),
                (row + 1, col + 2, sign * tau.1),
                (row + 2, col + 2, sign * cross(arm_s, tau) / length_scale),
            ]);
        }
    }
    let rows = EQUATIONS_PER_BLOCK * n;
    let mut dead = vec![0.0; rows];
    for (b, block) in assembly.blocks.iter().enumerate() {
        // The weight acts through the centroid: no moment about it.
        dead[EQUATIONS_PER_BLOCK * b + 1] = -unit_weight * block.area / force_scale;
    }
    let mut live = vec![0.0; rows];
    for (vector, loads) in [(&mut dead, dead_loads), (&mut live, live_loads)] {
        for load in loads {
            let g = assembly.blocks[load.block].centroid;
            let arm = (load.point.0 - g.0, load.point.1 - g.1);
            let row = EQUATIONS_PER_BLOCK * load.block;
            vector[row] += load.fx / force_scale;
            vector[row + 1] += load.fy / force_scale;
            vector[row + 2] +=
                (load.moment + cross(arm, (load.fx, load.fy))) / (force_scale * length_scale);
        }
    }
    let resultant_columns = RESULTANTS_PER_INTERFACE * assembly.interfaces.len();
    Equilibrium {
        rows,
        columns: resultant_columns,
        resultant_columns,
        triplets,
        dead,
        live,
        force_scale,
        length_scale,
    }
}

impl Equilibrium {
    /// Adds one column per passive force (in units of the force scale W): a horizontal force
    /// `direction`·p at `point` of its block.
    pub fn add_passive(&mut self, assembly: &Assembly, passive: &[PassiveForce]) {
        for force in passive {
            let column = self.columns;
            self.columns += 1;
            let g = assembly.blocks[force.block].centroid;
            let arm = (force.point.0 - g.0, force.point.1 - g.1);
            let row = EQUATIONS_PER_BLOCK * force.block;
            self.triplets.extend([
                (row, column, force.direction),
                (
                    row + 2,
                    column,
                    cross(arm, (force.direction, 0.0)) / self.length_scale,
                ),
            ]);
        }
    }

    /// The residual H r + λ₀·w + λ·p for resultants `r` in the scaled units.
    pub fn residual(&self, r: &[f64], dead_factor: f64, live_factor: f64) -> Vec<f64> {
        let mut out: Vec<f64> = self
            .dead
            .iter()
            .zip(&self.live)
            .map(|(w, p)| dead_factor * w + live_factor * p)
            .collect();
        for &(i, j, v) in &self.triplets {
            out[i] += v * r[j];
        }
        out
    }
}
