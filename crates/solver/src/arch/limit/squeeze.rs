//! The state programme over a few contacts: the squeezed ones change, every other contact
//! keeps its force, and the blocks they touch stay in equilibrium with those forces held.
//!
//! An interior-point state squeezed by a self-stress carries it on the contacts of the
//! self-stress's loop, far above the loads (the first blocks of two rings and their supports
//! at a springing); the rest of the state is as good as any. Relieving the squeeze there is a
//! programme of a few dozen unknowns instead of the whole structure's, and it has an interior
//! (the squeeze can be relieved by any amount up to the least), which the whole programme at
//! the optimum has not.

use super::rows::Row;
use crate::arch::equilibrium::{Equilibrium, RESULTANTS_PER_INTERFACE};

/// The programme over the columns of some contacts.
pub(super) struct Local {
    /// The equilibrium rows the contacts' columns appear in, over those columns.
    pub eq: Equilibrium,
    /// Their right-hand sides: the original ones less every other column's term at `x`.
    pub b_eq: Vec<f64>,
    /// The contacts' limit rows (not the passive bounds), renumbered.
    pub rows: Vec<Row>,
    /// The column of `x` that each local column is.
    pub columns: Vec<usize>,
    /// How far `x` goes beyond the rows raised by the margin (≥ 0): the programme's rows are
    /// raised by that much more, so that `x` itself is admissible.
    pub excess: f64,
}

/// The programme over the columns of `contacts`, all other columns held at `x`, with equations
/// H x = `b_eq` and `rows` raised by `margin`.
pub(super) fn local_programme(
    eq: &Equilibrium,
    rows: &[Row],
    x: &[f64],
    b_eq: &[f64],
    margin: f64,
    contacts: &[usize],
) -> Local {
    let mut local_column = vec![None; eq.columns];
    let mut columns = Vec::with_capacity(RESULTANTS_PER_INTERFACE * contacts.len());
    for &k in contacts {
        let first = RESULTANTS_PER_INTERFACE * k;
        for (j, slot) in local_column
            .iter_mut()
            .enumerate()
            .skip(first)
            .take(RESULTANTS_PER_INTERFACE)
        {
            *slot = Some(columns.len());
            columns.push(j);
        }
    }
    let mut local_row = vec![None; eq.rows];
    let mut equations = Vec::new();
    for &(i, j, _) in &eq.triplets {
        if local_column[j].is_some() && local_row[i].is_none() {
            local_row[i] = Some(equations.len());
            equations.push(i);
        }
    }
    let mut b: Vec<f64> = equations.iter().map(|&i| b_eq[i]).collect();
    let mut triplets = Vec::new();
    for &(i, j, v) in &eq.triplets {
        let Some(r) = local_row[i] else { continue };
        match local_column[j] {
            Some(c) => triplets.push((r, c, v)),
            None => b[r] -= v * x[j],
        }
    }
    let mut excess = 0.0f64;
    let mut local_rows = Vec::new();
    for row in rows {
        let entries = &row.entries[..row.len];
        if entries.is_empty() || entries.iter().any(|&(j, _)| local_column[j].is_none()) {
            continue;
        }
        let lhs: f64 = entries.iter().map(|&(j, v)| v * x[j]).sum();
        excess = excess.max(lhs - row.b - margin);
        let mut renumbered = row.entries;
        for e in renumbered.iter_mut().take(row.len) {
            e.0 = local_column[e.0].unwrap_or(0);
        }
        local_rows.push(Row {
            entries: renumbered,
            len: row.len,
            b: row.b,
            tag: row.tag,
            cut: row.cut,
        });
    }
    Local {
        eq: Equilibrium {
            rows: equations.len(),
            columns: columns.len(),
            resultant_columns: columns.len(),
            triplets,
            dead: vec![0.0; equations.len()],
            live: vec![0.0; equations.len()],
            force_scale: eq.force_scale,
            length_scale: eq.length_scale,
        },
        b_eq: b,
        rows: local_rows,
        columns,
        excess,
    }
}
