//! `POST /arch/dead-load` and `POST /arch/live-load`: limit analysis of rigid-block arches
//! (Livesley 1978; model §1, §3).
//!
//! Blocks and interfaces are numbered from 1 in requests and responses, in order of increasing
//! polar angle for circular arches (interface 1 at the right springing), as the thesis prints
//! them. Angles are polar angles in degrees (for block chains: the direction of the joint from
//! its intrados to its extrados end).

pub mod assembly;
pub mod codes;
pub mod design;
pub mod drawing;
pub mod family;
pub mod fill;
pub mod geometry;
pub mod input;
pub mod interfaces;
pub mod material;
pub mod mechanism;
pub mod minimum_thickness;
pub mod plan;
pub mod profile;
pub mod request;
pub mod response;
pub mod rolling;
pub mod routes;
pub mod solve;
pub mod solved;
pub mod study;
pub mod tables;
pub mod thinnest;
pub mod warnings;
