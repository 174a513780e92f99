//! What a solve of [`super`] ends with: an optimal vertex, or why not.

/// Why a solve did not end at an optimal vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SimplexFailure {
    /// A row cannot be met while the others are (the dual simplex found no pivot).
    Infeasible,
    /// The objective grows without bound along an edge.
    Unbounded,
    /// The basis is singular or became so; or the vertex failed its final check.
    Singular,
    /// The pivot limit was reached.
    MaxPivots,
}

/// An optimal vertex.
#[derive(Debug, Clone, PartialEq)]
pub struct Vertex {
    /// The optimal y.
    pub y: Vec<f64>,
    /// The multiplier of every row of the programme (zero off the basis), for the rows as
    /// given (not normalised): c = Σ z_i a_i.
    pub multipliers: Vec<f64>,
    /// Pivots this solve took.
    pub pivots: usize,
}
