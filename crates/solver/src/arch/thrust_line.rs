//! The line of thrust: at every interface, the point of action of the resultant of q and s,
//! (q·P_q + s·P_s)/(q + s) (SPEC §1.1), with the normal and shear forces and the eccentricity.

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
}

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
            let defined = normal.abs() > 1e-12 * scale && scale > 0.0;
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
            }
        })
        .collect()
}
