//! The memory an arch analysis may take, bounded before it runs.
//!
//! Livesley's general formulation is solved by an interior-point method whose sparse
//! factorisation grows with the interfaces: a 230-byte request for a multi-ring arch with
//! crushing reached 1.2 GB. The service refuses what would not fit and shares the rest
//! ([`memory_bound`] is what a solve reserves). The bound is linear in the interfaces, with a
//! cost per interface measured as peak resident memory over 27 requests (1–8 rings, 1–3 spans,
//! 4,000–20,000 interfaces; docs/operations.md): 11.5–12.0 KB without crushing or friction
//! checks, 19–26 KB with them (cutting-plane rounds and friction steps keep a second
//! programme), the chain formulation ≤ 3.2 KB per block. Each is taken with a third more.

use super::analysis::{ArchPlan, Friction, Programme};
use super::limit::{self, ArchProblem};

/// Bytes per interface of the general formulation without crushing or friction.
const PLAIN_PER_INTERFACE: usize = 16 * 1024;
/// Bytes per interface of the general formulation with crushing or a friction iteration.
const RICH_PER_INTERFACE: usize = 34 * 1024;
/// Bytes per block of the chain formulation (every option).
const CHAIN_PER_BLOCK: usize = 4 * 1024;
/// What any analysis takes besides (the problem, the answer, the thread).
const BASE: usize = 2 * 1024 * 1024;

/// Whether `plan` analyses `problem` on the chain's three redundants (a chain without passive
/// forces, the chain formulation asked for): small programmes, whatever the options.
pub fn on_chain(problem: &ArchProblem, plan: &ArchPlan) -> bool {
    limit::on_chain(problem, &plan.settings)
}

/// An upper bound on the memory, in bytes, of an analysis on the chain formulation.
pub fn chain_memory_bound(blocks: usize) -> usize {
    BASE.saturating_add(CHAIN_PER_BLOCK.saturating_mul(blocks))
}

/// An upper bound on the memory, in bytes, that analysing `problem` as `plan` says takes.
pub fn memory_bound(problem: &ArchProblem, plan: &ArchPlan) -> usize {
    let assembly = problem.assembly();
    // A rolling load's stops are held whole (every stop's loads) and one stop's problem per
    // thread is built from them.
    let stops = match &plan.programme {
        Programme::Rolling(stops) => stops.iter().map(Vec::len).sum::<usize>(),
        Programme::DeadLoad | Programme::LiveLoad => 0,
    };
    let stops = stops.saturating_mul(2 * std::mem::size_of::<super::equilibrium::LiveLoad>());
    if on_chain(problem, plan) {
        return chain_memory_bound(assembly.blocks.len()).saturating_add(stops);
    }
    // A friction check (when the mechanism slides) solves programmes of the same size one after
    // the other; the iteration of its own, cutting planes and rolling stops keep more.
    let rich = problem.crushing().is_some()
        || (plan.friction == Friction::NonAssociative && problem.has_friction())
        || matches!(plan.programme, Programme::Rolling(_));
    let per_interface = if rich {
        RICH_PER_INTERFACE
    } else {
        PLAIN_PER_INTERFACE
    };
    BASE.saturating_add(per_interface.saturating_mul(assembly.interfaces.len()))
        .saturating_add(stops)
}
