//! `POST /slope/spencer`: Spencer's method for one slip circle or the critical one (model §2, §3).
//!
//! [`request`] holds the types clients send, [`input`] validates them once into the solver's
//! plan, [`family`] is the route family (the analysis on the blocking pool, the answers built
//! from it) whose handlers and registration are in [`routes`], [`response`] builds the answer
//! whole and [`drawing`] the picture, both from the solver's results. Slices are numbered from
//! 1 at the lower end of the slip surface, as the thesis prints them.

pub mod checks;
pub mod contours;
pub mod design;
pub mod drawdown;
pub mod drawing;
pub mod family;
pub mod fills;
pub mod input;
pub mod lines;
pub mod loads;
pub mod methods;
pub mod options;
pub mod outputs;
pub mod request;
pub mod response;
pub mod routes;
pub mod section;
pub mod simple_search;
pub mod slices;
pub mod solve;
pub mod solved;
pub mod strength;
pub mod study;
pub mod supports;
pub mod tables;
pub mod warnings;
pub mod water;
