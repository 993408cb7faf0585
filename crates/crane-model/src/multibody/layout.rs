//! The order of the generalized coordinates y (thesis eq. 2.59), written once:
//! body 1's x1, y1, θ1, then its M modal coordinates η1..ηM, then x, y, θ of
//! bodies 2–5 (lug rod, piston rod, cylinder, rope with load). Every index into
//! y, the mass matrix M and the columns of the constraint Jacobian B goes
//! through these functions.

/// Coordinates of each body's rigid motion: x, y, θ.
pub const PER_BODY: usize = 3;
/// Bodies in the model.
pub const BODIES: usize = 5;

/// Number of generalized coordinates with `modes` modal coordinates (M + 15).
pub const fn coordinate_count(modes: usize) -> usize {
    PER_BODY * BODIES + modes
}

/// Index of the modal coordinate η_(k+1) (`k` from 0).
pub const fn mode_index(k: usize) -> usize {
    PER_BODY + k
}

/// Index of the first coordinate (x) of body `body` (1..=5) with `modes`
/// modal coordinates; y and θ follow it.
pub const fn body_index(body: usize, modes: usize) -> usize {
    if body <= 1 {
        0
    } else {
        PER_BODY + modes + PER_BODY * (body - 2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_thesis_layout() {
        // 4 modes: x1 y1 θ1 η1..η4 | lug 7..9 | rod 10..12 | cylinder 13..15 | rope 16..18.
        assert_eq!(coordinate_count(4), 19);
        assert_eq!(mode_index(0), 3);
        assert_eq!([1, 2, 3, 4, 5].map(|b| body_index(b, 4)), [0, 7, 10, 13, 16]);
        assert_eq!(body_index(5, 4) + PER_BODY, coordinate_count(4));
    }
}
