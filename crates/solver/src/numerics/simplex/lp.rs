//! The rows of a programme of [`super`]: stored sparse and normalised to unit length, but for
//! one column that may change between solves (stored whole), with the dot products the simplex
//! method takes of them.

/// A programme max c·y subject to A y ≤ b, rows normalised to unit length and stored sparse,
/// but for one column that may change between solves (stored whole).
#[derive(Debug, Clone)]
pub struct Lp {
    pub(super) n: usize,
    /// Compressed rows: row i's entries are `index[start[i]..start[i + 1]]`, `value[..]`.
    start: Vec<usize>,
    index: Vec<usize>,
    value: Vec<f64>,
    /// The column that may change (`set_column`) and its entry in every row.
    moving: usize,
    moving_value: Vec<f64>,
    pub(super) b: Vec<f64>,
    pub(super) c: Vec<f64>,
    /// The factor each row was divided by (its Euclidean norm).
    pub(super) norms: Vec<f64>,
}

/// One row of an [`Lp`]: its sparse entries and its entry in the moving column.
#[derive(Debug, Clone, Copy)]
pub(super) struct RowView<'a> {
    index: &'a [usize],
    value: &'a [f64],
    moving: (usize, f64),
}

impl RowView<'_> {
    pub(super) fn dot(&self, v: &[f64]) -> f64 {
        let sparse: f64 = self
            .index
            .iter()
            .zip(self.value)
            .map(|(&j, a)| a * v[j])
            .sum();
        sparse + self.moving.1 * v[self.moving.0]
    }

    /// out += alpha·row.
    pub(super) fn add_to(&self, alpha: f64, out: &mut [f64]) {
        for (&j, a) in self.index.iter().zip(self.value) {
            out[j] += alpha * a;
        }
        out[self.moving.0] += alpha * self.moving.1;
    }
}

impl Lp {
    /// A programme with n variables and objective c (max c·y), no rows yet, whose column
    /// `moving` (< n) may be changed between solves.
    pub fn new(c: Vec<f64>, moving: usize) -> Self {
        Self {
            n: c.len(),
            start: vec![0],
            index: Vec::new(),
            value: Vec::new(),
            moving,
            moving_value: Vec::new(),
            b: Vec::new(),
            c,
            norms: Vec::new(),
        }
    }

    /// Adds the row a·y ≤ b (a of length n); returns its index. A zero row is kept as 0 ≤ b.
    pub fn push_row(&mut self, a: &[f64], b: f64) -> usize {
        let norm = a.iter().map(|v| v * v).sum::<f64>().sqrt();
        let norm = if norm > 0.0 { norm } else { 1.0 };
        for (j, &v) in a.iter().enumerate() {
            if v != 0.0 && j != self.moving {
                self.index.push(j);
                self.value.push(v / norm);
            }
        }
        self.start.push(self.index.len());
        let moving = a.get(self.moving).copied().unwrap_or(0.0);
        self.moving_value.push(moving / norm);
        self.b.push(b / norm);
        self.norms.push(norm);
        self.b.len() - 1
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.b.len()
    }

    /// Number of variables.
    pub fn variables(&self) -> usize {
        self.n
    }

    /// The column that may change between solves.
    pub fn moving_column(&self) -> usize {
        self.moving
    }

    pub(super) fn row(&self, i: usize) -> RowView<'_> {
        let range = self.start[i]..self.start[i + 1];
        RowView {
            index: &self.index[range.clone()],
            value: &self.value[range],
            moving: (self.moving, self.moving_value[i]),
        }
    }

    /// Entry j of row i as given (not normalised).
    pub fn entry(&self, i: usize, j: usize) -> f64 {
        let row = self.row(i);
        let v = if j == self.moving {
            row.moving.1
        } else {
            row.index
                .iter()
                .position(|&k| k == j)
                .map_or(0.0, |p| row.value[p])
        };
        v * self.norms[i]
    }

    /// Sets the moving column to `column[i]` in every row i (as given, not normalised), keeping
    /// each row's normalisation factor (so the other entries stay bit for bit); returns the
    /// change of every row's normalised entry, for [`super::Basis::column_changed`].
    pub(super) fn set_column(&mut self, column: &[f64]) -> Vec<f64> {
        let mut change = Vec::with_capacity(self.rows());
        for ((m, &v), norm) in self.moving_value.iter_mut().zip(column).zip(&self.norms) {
            let new = v / norm;
            change.push(new - *m);
            *m = new;
        }
        change
    }
}

pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

pub(super) fn axpy(alpha: f64, x: &[f64], y: &mut [f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi += alpha * xi;
    }
}
