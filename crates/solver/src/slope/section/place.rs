//! Where a surface's sliding mass is: which of the masses it cuts out of the ground (the largest
//! that something drives, or the one asked for), placed in the solver's frame (the section
//! mirrored when its crest lies to the left) and cut into slices ([`Cut::new`]).

use std::num::NonZeroUsize;

use super::cut::Cut;
use super::model::Section;
use super::shape::SlipShape;
use crate::slope::error::{SlopeError, SlopeParameter};
use crate::slope::spencer::{drives_towards_toe, Seismic};

/// Places `shape` on `section` and cuts it, in the solver's frame: mirrored (with `mirror`, the
/// section seen from behind, when the caller has it) when the crest lies to the left.
pub(super) fn place(
    section: &Section,
    mirror: Option<&Section>,
    shape: &SlipShape,
    slices: NonZeroUsize,
    seismic: Seismic,
    moment_centre: Option<(f64, f64)>,
) -> Result<Cut, SlopeError> {
    place_checked(section, mirror, shape, slices, seismic, moment_centre, true)
}

/// [`place`] of the `index`-th mass a circle cuts, counted from the left from 0, instead of the
/// largest that something drives.
pub(super) fn place_mass(
    section: &Section,
    shape: &SlipShape,
    slices: NonZeroUsize,
    seismic: Seismic,
    index: usize,
) -> Result<Cut, SlopeError> {
    let mut pieces = super::ends::ends(section, shape)?;
    pieces.sort_by(|a, b| a.0.total_cmp(&b.0));
    let Some(&ends) = pieces.get(index) else {
        return Err(SlopeError::NoSlipMass {
            parameter: SlopeParameter::CircleMass,
            reason: format!(
                "the circle cuts {} mass(es) out of the ground: mass {} is not one of them",
                pieces.len(),
                index + 1
            ),
        });
    };
    let cut = place_between(section, None, shape, ends, slices, seismic, None)?;
    if !drives_towards_toe(&cut.model) {
        return Err(SlopeError::NoSlipMass {
            parameter: SlopeParameter::CircleMass,
            reason: format!(
                "nothing drives mass {} towards its toe: it lies under level ground, symmetric \
                 about the centre's vertical",
                index + 1
            ),
        });
    }
    Ok(cut)
}

/// [`place`] for a search, which solves the cut at once and counts a mass that nothing drives
/// as no candidate either way (Spencer's method checks what drives a circle's mass): a surface
/// of one piece is not checked twice.
pub(super) fn place_for_search(
    section: &Section,
    mirror: &Section,
    shape: &SlipShape,
    slices: NonZeroUsize,
    seismic: Seismic,
) -> Result<Cut, SlopeError> {
    place_checked(section, Some(mirror), shape, slices, seismic, None, false)
}

/// [`place`]; `check_single`: whether a surface of one piece is checked for what drives it.
fn place_checked(
    section: &Section,
    mirror: Option<&Section>,
    shape: &SlipShape,
    slices: NonZeroUsize,
    seismic: Seismic,
    moment_centre: Option<(f64, f64)>,
    check_single: bool,
) -> Result<Cut, SlopeError> {
    // The largest mass that something drives towards the toe: a lens under level ground
    // beside a shallow slide on the face does not slide, the slide does.
    let pieces = super::ends::ends(section, shape)?;
    if let (false, [ends]) = (check_single, pieces.as_slice()) {
        return place_between(
            section,
            mirror,
            shape,
            *ends,
            slices,
            seismic,
            moment_centre,
        );
    }
    let mut first_error = None;
    for (i, &ends) in pieces.iter().enumerate() {
        match place_between(section, mirror, shape, ends, slices, seismic, moment_centre) {
            Ok(cut) if drives_towards_toe(&cut.model) => return Ok(cut),
            Ok(_) => {}
            Err(e) if i == 0 => first_error = Some(e),
            Err(_) => {}
        }
    }
    Err(first_error.unwrap_or_else(|| SlopeError::NoSlipMass {
        parameter: SlopeParameter::CircleCentre,
        reason: "nothing drives the circle's mass towards the toe: it lies under level ground, \
                 symmetric about the centre's vertical — move the centre towards the slope"
            .to_owned(),
    }))
}

/// The mass between `entry` and `exit`, cut in the frame where the crest lies to the right.
fn place_between(
    section: &Section,
    mirror: Option<&Section>,
    shape: &SlipShape,
    (entry, exit): (f64, f64),
    slices: NonZeroUsize,
    seismic: Seismic,
    moment_centre: Option<(f64, f64)>,
) -> Result<Cut, SlopeError> {
    let ground = &section.ground;
    let rises_left = ground.y_at(entry) > ground.y_at(exit)
        || (ground.y_at(entry) == ground.y_at(exit) && {
            let p = ground.points();
            p[0].1 > p[p.len() - 1].1
        });
    if rises_left {
        let owned;
        let mirrored = match mirror {
            Some(m) => m,
            None => {
                owned = section.mirrored();
                &owned
            }
        };
        let centre = moment_centre.map(|c| (-c.0, c.1));
        Cut::new(
            mirrored,
            &shape.mirrored(),
            (-exit, -entry),
            slices,
            seismic,
            centre,
            true,
        )
    } else {
        Cut::new(
            section,
            shape,
            (entry, exit),
            slices,
            seismic,
            moment_centre,
            false,
        )
    }
}
