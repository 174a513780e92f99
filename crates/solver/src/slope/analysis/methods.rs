//! The methods engineers compare with Spencer's, answered side by side on the same slices: what
//! a plan asks for and what each method found.

use crate::budget::Budget;
use crate::slope::accuracy::{estimate, Accuracy, Recut};
use crate::slope::slices::{SliceModel, Sliced};
pub use crate::slope::spencer::methods::Method;
use crate::slope::spencer::methods::{
    bishop, janbu, morgenstern_price, ordinary, InterSliceFunction, MethodFactor,
};
use crate::slope::spencer::SpencerSolution;

/// One method's answer and its accuracy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MethodAnswer {
    /// What the method found.
    pub factor: MethodFactor,
    /// The accuracy of its F ([`with_accuracy`]; none until estimated, or without an F).
    pub accuracy: Option<Accuracy>,
}

impl From<MethodFactor> for MethodAnswer {
    fn from(factor: MethodFactor) -> Self {
        Self {
            factor,
            accuracy: None,
        }
    }
}

/// Each method asked for, present only when asked.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MethodFactors {
    /// Morgenstern–Price.
    pub morgenstern_price: Option<MethodAnswer>,
    /// Bishop's simplified method.
    pub bishop: Option<MethodAnswer>,
    /// Janbu's simplified method.
    pub janbu: Option<MethodAnswer>,
    /// The ordinary method.
    pub ordinary: Option<MethodAnswer>,
}

impl MethodFactors {
    /// `method`'s answer, when it was asked for.
    pub fn of(&self, method: Method) -> Option<&MethodAnswer> {
        match method {
            Method::MorgensternPrice => self.morgenstern_price.as_ref(),
            Method::Bishop => self.bishop.as_ref(),
            Method::Janbu => self.janbu.as_ref(),
            Method::Ordinary => self.ordinary.as_ref(),
        }
    }
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
                let found = found.unwrap_or(MethodFactor {
                    factor_of_safety: None,
                    lambda: None,
                    iterations: 0,
                });
                out.morgenstern_price = Some(found.into());
            }
            Method::Bishop => out.bishop = Some(bishop(model).into()),
            Method::Janbu => out.janbu = Some(janbu(model).into()),
            Method::Ordinary => out.ordinary = Some(ordinary(model).into()),
        }
    }
    out
}

/// Each answered method's accuracy on `problem` (model §6.2): its F at two more slice counts,
/// each model made as the answer's was by `prepare` (strength dropped where Spencer's state has
/// negative effective stress, as the plan says); Morgenstern–Price starts from its own (F, λ).
/// The re-cut surface is the headline's when it has one (else made once here, within `budget`).
pub fn with_accuracy<P: Sliced>(
    found: &mut MethodFactors,
    problem: &P,
    function: &InterSliceFunction,
    prepare: &dyn Fn(&SliceModel) -> SliceModel,
    mut recut: Option<Recut>,
    budget: &Budget,
) {
    let mut assess = |answer: &mut Option<MethodAnswer>, method: Method| {
        let Some(answer) = answer.as_mut() else {
            return;
        };
        let Some(f) = answer.factor.factor_of_safety else {
            return;
        };
        let start = (f, answer.factor.lambda.unwrap_or(0.0));
        let factor = |model: &SliceModel| -> Option<f64> {
            let model = prepare(model);
            match method {
                Method::MorgensternPrice => morgenstern_price(&model, function, start),
                Method::Bishop => bishop(&model),
                Method::Janbu => janbu(&model),
                Method::Ordinary => ordinary(&model),
            }
            .factor_of_safety
        };
        let recut = recut.get_or_insert_with(|| Recut::of(problem, budget));
        answer.accuracy = Some(estimate(recut, f, &factor));
    };
    assess(&mut found.morgenstern_price, Method::MorgensternPrice);
    assess(&mut found.bishop, Method::Bishop);
    assess(&mut found.janbu, Method::Janbu);
    assess(&mut found.ordinary, Method::Ordinary);
}
