//! Probabilistic studies (model §9.2): samples of uncertain inputs drawn from their
//! distributions (truncated where asked, correlated through a Gaussian copula, by Monte Carlo or
//! Latin hypercube sampling from a seed), an analysis run on each, and the statistics of the
//! answers: probability of failure, mean, standard deviation, reliability indices, histogram.
//!
//! The study knows nothing of what it samples: the caller turns a row of values into an
//! analysis (the service writes them into a copy of the request).

pub mod normal;
pub mod run;
pub mod sampling;
pub mod statistics;

pub use run::{run, Progress};
pub use sampling::{Distribution, Sampling, StudyError, Variable};
pub use statistics::{summarise, Bin, Summary};
