//! The names of an interface's stress resultants and of their limits (Livesley's q, s, t, the
//! friction variables u, v and crushing's m), shared by the limits, the mechanism and the
//! errors that name them.

/// A stress resultant of an interface: Livesley's q, s, t and the friction variables u, v.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Resultant {
    /// Normal force at the extrados end.
    Q,
    /// Normal force at the intrados end.
    S,
    /// Shear.
    T,
    /// μ(q + s) − t: sliding in the positive tangent direction when it vanishes.
    U,
    /// μ(q + s) + t: sliding in the negative tangent direction when it vanishes.
    V,
    /// The moment–normal force limit of crushing (the rectangular stress block): `Upper` with
    /// the resultant pressed towards the extrados end, `Lower` towards the intrados end.
    M,
    /// A passive force of a fill at its bound (not a limit of an interface: it makes no hinge,
    /// and it is not listed among a mechanism's active limits).
    Passive,
}

/// Which limit of a resultant.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bound {
    /// The lower limit (no tension, friction).
    Lower,
    /// The upper limit (crushing, shear capacity).
    Upper,
}
