//! A solved Spencer request: the analysis' answer and the wall time of the whole solve, what the
//! response, the warnings and the drawing read.

use std::ops::Deref;

use thrustline_solver::slope::analysis::SlopeAnswer;

/// The analysis' answer and how long the solve took.
#[derive(Debug, Clone)]
pub struct SolvedSlope {
    /// What the analysis answered.
    pub answer: SlopeAnswer,
    /// What the request's studies answered (nothing without studies).
    pub studies: crate::study::StudyAnswers,
    /// Wall time of the whole solve in milliseconds.
    pub solve_time_ms: f64,
}

impl Deref for SolvedSlope {
    type Target = SlopeAnswer;

    fn deref(&self) -> &SlopeAnswer {
        &self.answer
    }
}
