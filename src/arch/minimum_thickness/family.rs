//! The minimum-thickness search as a [`Family`]: the request validated into the arch's shape,
//! material and settings, the search on the pool, and the answer, the tables and the drawing
//! of the arch just too thin to stand.

use std::sync::Arc;

use serde_json::Value;
use thrustline_solver::arch::{MinimumThickness, MinimumThicknessOutcome};

use super::super::drawing;
use super::super::tables::{MinimumThicknessTableDto, MinimumThicknessTableQuery};
use super::super::thinnest::Thinnest;
use super::{plan, response, solve, MinimumThicknessRequest, MinimumThicknessResponse, Planned};
use crate::error::ApiError;
use crate::family::Family;
use crate::state::AppState;
use crate::study::run::Tally;
use crate::table::{csv, Csv};

/// `POST /arch/minimum-thickness` and its twins.
pub struct Thickness;

/// A solved search: the arch's shape, what the search found and the thickness given.
pub struct SolvedThickness {
    /// The arch whose shape was searched.
    pub shape: Thinnest,
    /// What the search found.
    pub result: MinimumThickness,
    /// The thickness given, for the geometric factor of safety.
    pub given: Option<f64>,
}

impl Family for Thickness {
    type Request = MinimumThicknessRequest;
    type Prepared = Planned;
    type Solved = SolvedThickness;
    type Answer = MinimumThicknessResponse;
    type Tables = MinimumThicknessTableQuery;

    const ROUTE: &'static str = "/arch/minimum-thickness";

    fn prepare(request: &MinimumThicknessRequest, _body: &Value) -> Result<Planned, ApiError> {
        plan(request)
    }

    async fn run(
        state: &AppState,
        planned: Planned,
        _tally: Arc<Tally>,
    ) -> Result<SolvedThickness, ApiError> {
        let given = planned.given;
        let (shape, result) = solve(state, planned).await?;
        Ok(SolvedThickness {
            shape,
            result,
            given,
        })
    }

    fn answer(
        _request: &MinimumThicknessRequest,
        solved: &SolvedThickness,
    ) -> MinimumThicknessResponse {
        response(&solved.shape, &solved.result, solved.given)
    }

    fn draw(
        request: &MinimumThicknessRequest,
        solved: &SolvedThickness,
    ) -> Result<String, ApiError> {
        let SolvedThickness {
            shape,
            result,
            given,
        } = solved;
        let (given, curved) = (*given, request.geometry.is_curved());
        let answer = response(shape, result, given);
        let (shown, mechanism) = match &result.outcome {
            Ok(MinimumThicknessOutcome::Found {
                thickness_below,
                mechanism,
                ..
            }) => (shape.assembly(*thickness_below).ok(), mechanism.as_ref()),
            _ => (None, None),
        };
        let title = match (
            answer.thickness,
            answer.thickness_to_radius,
            answer.thickness_to_span,
        ) {
            (Some(d), Some(ratio), _) => format!("Minimum thickness: D = {d:.6}, D/R = {ratio:.6}"),
            (Some(d), _, Some(ratio)) => {
                format!("Minimum thickness: t = {d:.6}, t/span = {ratio:.6}")
            }
            _ => "Minimum thickness: none found".to_owned(),
        };
        let d = if shape.span().is_some() { "t" } else { "D" };
        let caption = match (&shown, answer.thickness_below) {
            (Some(_), Some(below)) => format!(
                "the arch at {d} = {below:.6}, just too thin to stand, and its collapse (the arch \
                 stands from {d} = {:.6} on)",
                answer.thickness.unwrap_or(f64::NAN)
            ),
            _ => answer.detail.clone(),
        };
        let drawn = match shown {
            Some(collapsing) => Some(collapsing),
            None => given
                .and_then(|d| shape.assembly(d).ok())
                .or_else(|| shape.assembly(0.1 * shape.scale()).ok()),
        };
        let drawn =
            drawn.ok_or_else(|| ApiError::invalid("geometry", "the arch cannot be drawn"))?;
        Ok(drawing::minimum_thickness(
            &drawn,
            mechanism.filter(|_| answer.thickness_below.is_some()),
            curved,
            (&title, &caption),
        ))
    }

    fn table(
        answer: &MinimumThicknessResponse,
        table: MinimumThicknessTableDto,
    ) -> Result<Csv, ApiError> {
        match table {
            MinimumThicknessTableDto::Hinges => csv(&answer.hinges),
            MinimumThicknessTableDto::ActiveConstraints => csv(&answer.active_constraints),
        }
    }
}
