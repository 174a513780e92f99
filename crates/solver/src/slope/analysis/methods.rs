//! The methods engineers compare with Spencer's, answered side by side on the same slices: what
//! a plan asks for and what each method found.

use crate::slope::slices::SliceModel;
use crate::slope::spencer::methods::{
    bishop, janbu, morgenstern_price, ordinary, InterSliceFunction, MethodFactor,
};
use crate::slope::spencer::SpencerSolution;

/// A method of slices beside Spencer's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Morgenstern–Price: X = λ·f(x)·E, force and moment equilibrium.
    MorgensternPrice,
    /// Bishop's simplified: moments about the centre, horizontal inter-slice forces.
    Bishop,
    /// Janbu's simplified (uncorrected): horizontal force equilibrium.
    Janbu,
    /// The ordinary method (Fellenius): no inter-slice forces, moments about the centre.
    Ordinary,
}

/// Each method asked for, present only when asked.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MethodFactors {
    /// Morgenstern–Price.
    pub morgenstern_price: Option<MethodFactor>,
    /// Bishop's simplified method.
    pub bishop: Option<MethodFactor>,
    /// Janbu's simplified method.
    pub janbu: Option<MethodFactor>,
    /// The ordinary method.
    pub ordinary: Option<MethodFactor>,
}

/// Each method of `methods` on `model`; Morgenstern–Price starts from Spencer's (F, tan θ), then
/// Bishop's F with λ = 0, then (1, 0), and answers the first start that converges.
pub fn side_by_side(
    methods: &[Method],
    function: &InterSliceFunction,
    model: &SliceModel,
    spencer: &SpencerSolution,
) -> MethodFactors {
    let mut out = MethodFactors::default();
    for method in methods {
        match method {
            Method::MorgensternPrice => {
                let starts = [
                    spencer
                        .factor_of_safety
                        .zip(spencer.theta_rad.map(f64::tan)),
                    spencer.bishop_factor_of_safety.map(|f| (f, 0.0)),
                    Some((1.0, 0.0)),
                ];
                let found = starts
                    .into_iter()
                    .flatten()
                    .map(|start| morgenstern_price(model, function, start))
                    .find(|m| m.factor_of_safety.is_some());
                out.morgenstern_price = Some(found.unwrap_or(MethodFactor {
                    factor_of_safety: None,
                    lambda: None,
                    iterations: 0,
                }));
            }
            Method::Bishop => out.bishop = Some(bishop(model)),
            Method::Janbu => out.janbu = Some(janbu(model)),
            Method::Ordinary => out.ordinary = Some(ordinary(model)),
        }
    }
    out
}
