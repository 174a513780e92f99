//! The dense simplex method against an independent enumeration of every vertex, from cold and
//! warm bases, with a column changed between solves, on degenerate and infeasible programmes.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use thrustline_solver::numerics::simplex::{
    maximise, set_column, Basis, Lp, SimplexFailure, SimplexSettings,
};

/// A small deterministic generator (xorshift64*), uniform in [−1, 1).
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11;
        2.0 * (bits as f64 / (1u64 << 53) as f64) - 1.0
    }
}

/// Solves the n × n system by Gaussian elimination (None when singular); written with indices,
/// as the textbook writes it (row r is updated from row col of the same matrix).
#[allow(clippy::needless_range_loop)]
fn solve_square(mut m: Vec<Vec<f64>>, mut rhs: Vec<f64>) -> Option<Vec<f64>> {
    let n = rhs.len();
    for col in 0..n {
        let p = (col..n).max_by(|&a, &b| m[a][col].abs().total_cmp(&m[b][col].abs()))?;
        if m[p][col].abs() < 1e-10 {
            return None;
        }
        m.swap(p, col);
        rhs.swap(p, col);
        for r in col + 1..n {
            let f = m[r][col] / m[col][col];
            for k in col..n {
                m[r][k] -= f * m[col][k];
            }
            rhs[r] -= f * rhs[col];
        }
    }
    let mut y = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|k| m[r][k] * y[k]).sum();
        y[r] = (rhs[r] - s) / m[r][r];
    }
    Some(y)
}

/// The best objective over every vertex of {A y ≤ b} (None: no vertex is feasible).
fn enumerate(a: &[Vec<f64>], b: &[f64], c: &[f64]) -> Option<f64> {
    let (m, n) = (a.len(), c.len());
    let mut best: Option<f64> = None;
    let mut subset: Vec<usize> = (0..n).collect();
    loop {
        let rows = subset.iter().map(|&i| a[i].clone()).collect();
        let rhs = subset.iter().map(|&i| b[i]).collect();
        if let Some(y) = solve_square(rows, rhs) {
            let feasible = (0..m).all(|i| {
                let s: f64 = a[i].iter().zip(&y).map(|(p, q)| p * q).sum();
                s <= b[i] + 1e-9
            });
            if feasible {
                let f: f64 = c.iter().zip(&y).map(|(p, q)| p * q).sum();
                best = Some(best.map_or(f, |v: f64| v.max(f)));
            }
        }
        // Next n-subset of 0..m in lexicographic order.
        let mut k = n;
        while k > 0 && subset[k - 1] == m - n + k - 1 {
            k -= 1;
        }
        if k == 0 {
            return best;
        }
        subset[k - 1] += 1;
        for j in k..n {
            subset[j] = subset[j - 1] + 1;
        }
    }
}

/// A random programme in a box |y_k| ≤ 3 (rows 0 … 2n−1), with `extra` random rows through a
/// neighbourhood of the origin (so that it is feasible).
fn random_programme(r: &mut Random, n: usize, extra: usize) -> (Vec<Vec<f64>>, Vec<f64>, Vec<f64>) {
    let mut a = Vec::new();
    let mut b = Vec::new();
    for k in 0..n {
        for sign in [1.0, -1.0] {
            let mut row = vec![0.0; n];
            row[k] = sign;
            a.push(row);
            b.push(3.0);
        }
    }
    for _ in 0..extra {
        a.push((0..n).map(|_| r.next()).collect());
        b.push(0.2 + r.next().abs());
    }
    let c = (0..n).map(|_| r.next()).collect();
    (a, b, c)
}

/// The programme with the last column free to change.
fn programme(a: &[Vec<f64>], b: &[f64], c: &[f64]) -> Lp {
    let mut lp = Lp::new(c.to_vec(), c.len() - 1);
    for (row, &rhs) in a.iter().zip(b) {
        lp.push_row(row, rhs);
    }
    lp
}

fn objective(c: &[f64], y: &[f64]) -> f64 {
    c.iter().zip(y).map(|(p, q)| p * q).sum()
}

#[test]
fn a_textbook_programme() {
    // max x + y with x ≤ 1, y ≤ 2, x + y ≤ 2.5, x, y ≥ 0: 2.5 on the edge x + y = 2.5; from
    // the basis {x ≥ 0, y ≥ 0} (the origin: feasible, both multipliers negative).
    let a = [
        vec![1.0, 0.0],
        vec![0.0, 1.0],
        vec![1.0, 1.0],
        vec![-1.0, 0.0],
        vec![0.0, -1.0],
    ];
    let b = [1.0, 2.0, 2.5, 0.0, 0.0];
    let lp = programme(&a, &b, &[1.0, 1.0]);
    let mut basis = Basis::new(&lp, vec![3, 4]).unwrap();
    let v = maximise(&lp, &mut basis, &SimplexSettings::default()).unwrap();
    assert!(
        (objective(&[1.0, 1.0], &v.y) - 2.5).abs() < 1e-14,
        "{:?}",
        v.y
    );
    // c = Σ z_i a_i with z ≥ 0, only on rows held at equality: here x + y = 2.5 alone.
    assert!(
        (v.multipliers[2] - 1.0).abs() < 1e-14,
        "{:?}",
        v.multipliers
    );
    assert!(v.multipliers.iter().all(|&z| z >= 0.0));
}

#[test]
fn random_programmes_reach_the_best_vertex_from_the_box_corner() {
    let mut r = Random(0x9E37_79B9_7F4A_7C15);
    for case in 0..300 {
        let n = 2 + case % 3;
        let (a, b, c) = random_programme(&mut r, n, 3 + case % 6);
        let best = enumerate(&a, &b, &c).unwrap();
        let lp = programme(&a, &b, &c);
        // The corner y = (3, …, 3): feasible or not, multipliers of either sign.
        let mut basis = Basis::new(&lp, (0..n).map(|k| 2 * k).collect()).unwrap();
        let v = maximise(&lp, &mut basis, &SimplexSettings::default()).unwrap();
        let f = objective(&c, &v.y);
        assert!((f - best).abs() < 1e-9, "case {case}: {f} vs {best}");
        for (i, row) in a.iter().enumerate() {
            assert!(objective(row, &v.y) <= b[i] + 1e-9, "case {case} row {i}");
        }
        // The multipliers reproduce c (weak duality at equality: b·z = c·y).
        let dual: f64 = v.multipliers.iter().zip(&b).map(|(z, b)| z * b).sum();
        assert!((dual - f).abs() < 1e-9, "case {case}: {dual} vs {f}");
    }
}

#[test]
fn a_changed_column_is_solved_warm_to_the_same_vertex_as_cold() {
    let mut r = Random(0xD1B5_4A32_D192_ED03);
    let settings = SimplexSettings::default();
    for case in 0..100 {
        let n = 3 + case % 2;
        let (mut a, b, c) = random_programme(&mut r, n, 6);
        let mut lp = programme(&a, &b, &c);
        let mut basis = Basis::new(&lp, (0..n).map(|k| 2 * k + 1).collect()).unwrap();
        maximise(&lp, &mut basis, &settings).unwrap();
        // Change the last column of the random rows (the box rows keep theirs).
        let j = n - 1;
        for row in a.iter_mut().skip(2 * n) {
            row[j] += 0.3 * r.next();
        }
        let column: Vec<f64> = a.iter().map(|row| row[j]).collect();
        set_column(&mut lp, &column, Some(&mut basis)).unwrap();
        let warm = maximise(&lp, &mut basis, &settings).unwrap();
        let best = enumerate(&a, &b, &c).unwrap();
        assert!((objective(&c, &warm.y) - best).abs() < 1e-9, "case {case}");
        let fresh = programme(&a, &b, &c);
        let mut cold = Basis::new(&fresh, (0..n).map(|k| 2 * k + 1).collect()).unwrap();
        let v = maximise(&fresh, &mut cold, &settings).unwrap();
        assert!((objective(&c, &v.y) - best).abs() < 1e-9, "case {case}");
    }
}

#[test]
fn a_degenerate_apex_does_not_cycle() {
    // 40 facets of a cone all through the apex (0, 0, 1), the optimum: max z.
    let mut a = Vec::new();
    let mut b = Vec::new();
    for k in 0..40 {
        let t = std::f64::consts::TAU * k as f64 / 40.0;
        a.push(vec![t.cos(), t.sin(), 1.0]);
        b.push(1.0);
    }
    for k in 0..3 {
        let mut row = vec![0.0; 3];
        row[k] = -1.0;
        a.push(row);
        b.push(5.0);
    }
    let lp = programme(&a, &b, &[0.0, 0.0, 1.0]);
    let mut basis = Basis::new(&lp, vec![40, 41, 42]).unwrap();
    let v = maximise(&lp, &mut basis, &SimplexSettings::default()).unwrap();
    assert!((v.y[2] - 1.0).abs() < 1e-12, "{:?}", v.y);
}

#[test]
fn an_infeasible_programme_and_a_singular_basis_are_reported() {
    // y ≤ 0 and y ≥ 1.
    let lp = programme(&[vec![1.0], vec![-1.0]], &[0.0, -1.0], &[1.0]);
    let mut basis = Basis::new(&lp, vec![0]).unwrap();
    let outcome = maximise(&lp, &mut basis, &SimplexSettings::default());
    assert_eq!(outcome.unwrap_err(), SimplexFailure::Infeasible);
    // Two parallel rows cannot make a basis in two dimensions.
    let lp = programme(&[vec![1.0, 1.0], vec![2.0, 2.0]], &[1.0, 1.0], &[1.0, 0.0]);
    assert_eq!(
        Basis::new(&lp, vec![0, 1]).unwrap_err(),
        SimplexFailure::Singular
    );
}
