//! The line of thrust: at every interface, the point of action of the resultant of q and s,
//! (q·P_q + s·P_s)/(q + s) (model §1.1), with the normal and shear forces and the eccentricity;
//! and the reactions of the two supports, the forces the first and last interfaces carry.

use super::geometry::Assembly;

/// The resultant on one interface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThrustPoint {
    /// Interface index (0-based).
    pub interface: usize,
    /// Point of action; `None` when the normal force vanishes.
    pub point: Option<(f64, f64)>,
    /// Normal force q + s (compression positive).
    pub normal_force: f64,
    /// Shear force t.
    pub shear_force: f64,
    /// Distance of the point of action from the middle of the joint, positive towards the
    /// extrados; `None` when the normal force vanishes.
    pub eccentricity: Option<f64>,
    /// The eccentricity as a fraction of the joint's length t: e/t in [−½, ½] for an admissible
    /// state under Heyman's limits; |e/t| ≤ 1/6 is the middle third (the whole joint in
    /// compression under a linear stress distribution).
    pub eccentricity_ratio: Option<f64>,
}

impl ThrustPoint {
    /// Whether the point of action lies in the middle third of the joint (|e/t| ≤ 1/6).
    pub fn is_in_middle_third(&self) -> Option<bool> {
        self.eccentricity_ratio.map(|r| r.abs() <= 1.0 / 6.0)
    }
}

/// The force a support exerts on the structure, in the section's axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SupportReaction {
    /// Interface index of the support contact (0 or n for a chain).
    pub interface: usize,
    /// Horizontal component (+x).
    pub horizontal: f64,
    /// Vertical component (+y, up).
    pub vertical: f64,
}

/// The reactions of the supports for the resultants `r`, one per support contact (the first
/// and the last interface of a chain), in interface order; `None` when there are no
/// resultants. An interface acts on its upper block with (q + s)·ν + t·τ: a support below the
/// normal pushes the structure with that force, one above it with its opposite.
pub fn support_reactions(assembly: &Assembly, r: &[[f64; 3]]) -> Option<Vec<SupportReaction>> {
    if r.len() != assembly.interfaces.len() || r.is_empty() {
        return None;
    }
    let reactions = assembly
        .interfaces
        .iter()
        .zip(r)
        .enumerate()
        .filter_map(|(k, (interface, &[q, s, t]))| {
            let sign = match (interface.lower, interface.upper) {
                (None, Some(_)) => 1.0,
                (Some(_), None) => -1.0,
                _ => return None,
            };
            Some(SupportReaction {
                interface: k,
                horizontal: sign * ((q + s) * interface.normal.0 + t * interface.tangent.0),
                vertical: sign * ((q + s) * interface.normal.1 + t * interface.tangent.1),
            })
        })
        .collect();
    Some(reactions)
}

/// A normal force at or below this fraction of the largest has no point of action: the
/// answer does not determine it (the interior-point tolerance is 1e-10, and the state of an
/// assembly is taken 1e-7 inside its factor), and the ratio of two such small numbers is
/// noise (a point hundreds of lengths away).
const UNDEFINED_NORMAL: f64 = 1e-6;

/// The thrust line of the resultants `r` (q, s, t per interface).
pub fn thrust_line(assembly: &Assembly, r: &[[f64; 3]]) -> Vec<ThrustPoint> {
    let scale = r
        .iter()
        .map(|x| x[0].abs() + x[1].abs())
        .fold(0.0, f64::max);
    assembly
        .interfaces
        .iter()
        .zip(r)
        .enumerate()
        .map(|(k, (interface, &[q, s, t]))| {
            let normal = q + s;
            let defined = normal.abs() > UNDEFINED_NORMAL * scale && scale > 0.0;
            let point = defined.then(|| {
                (
                    (q * interface.extrados.0 + s * interface.intrados.0) / normal,
                    (q * interface.extrados.1 + s * interface.intrados.1) / normal,
                )
            });
            ThrustPoint {
                interface: k,
                point,
                normal_force: normal,
                shear_force: t,
                eccentricity: defined.then(|| 0.5 * interface.length() * (q - s) / normal),
                eccentricity_ratio: defined.then(|| 0.5 * (q - s) / normal),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arch::{solve_dead_load, ArchProblem, InterfaceLimits, LimitSettings};
    use crate::reference::semicircle;

    #[test]
    fn reactions_carry_the_weight_of_the_semicircle() {
        // A semicircle of middle radius R and thickness D has the area π·R·D exactly (half an
        // annulus: (π/2)((R + D/2)² − (R − D/2)²)). Standing under its own weight (γ = 2), the two
        // vertical reactions carry 2·π·R·D and the horizontal ones cancel; by symmetry both
        // supports carry half the weight. 1e-8: the interior-point tolerance.
        let arch = semicircle(60, 10.0, 1.5);
        let problem = ArchProblem::new(
            arch.assembly(),
            2.0,
            InterfaceLimits::heyman(),
            None,
            vec![],
        )
        .unwrap();
        let solution = solve_dead_load(&problem, &LimitSettings::default());
        assert_eq!(solution.load_factor, Some(1.0));
        let reactions = support_reactions(problem.assembly(), &solution.resultants).unwrap();
        let [a, b] = [reactions[0], reactions[1]];
        assert_eq!(reactions.len(), 2);
        let weight = 2.0 * std::f64::consts::PI * 10.0 * 1.5;
        assert!(((a.vertical + b.vertical) - weight).abs() < 1e-8 * weight);
        assert!((a.horizontal + b.horizontal).abs() < 1e-8 * weight);
        assert!((a.vertical - b.vertical).abs() < 1e-6 * weight);
        // The springing joints are horizontal: the vertical reaction is their normal force.
        let line = thrust_line(problem.assembly(), &solution.resultants);
        assert!((a.vertical - line[0].normal_force).abs() < 1e-9 * weight);
    }

    #[test]
    fn eccentricity_ratio_is_the_position_across_the_joint() {
        // q at the extrados end alone: the point of action is the extrados end, e/t = +1/2;
        // q = s: the middle, e/t = 0, in the middle third; q = 2s: e/t = 1/6, its edge.
        let arch = semicircle(2, 10.0, 1.0);
        let assembly = arch.assembly();
        let r = vec![[1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 1.0, 0.0]];
        let line = thrust_line(&assembly, &r);
        assert_eq!(line[0].eccentricity_ratio, Some(0.5));
        assert_eq!(line[0].point, Some(assembly.interfaces[0].extrados));
        assert_eq!(line[1].eccentricity_ratio, Some(0.0));
        assert_eq!(line[1].is_in_middle_third(), Some(true));
        assert!((line[2].eccentricity_ratio.unwrap() - 1.0 / 6.0).abs() < 1e-15);
        assert_eq!(line[0].is_in_middle_third(), Some(false));
    }
}
