//! Errors the model reports instead of panicking.

/// Everything that can go wrong when building or evaluating the crane model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModelError {
    /// A parameter is outside the range the model supports; the name says which.
    InvalidParameter(&'static str),
    /// A matrix that must be invertible (or positive definite) was not; the name says which.
    Singular(&'static str),
    /// An iterative solver did not converge within its bounded number of iterations.
    NoConvergence(&'static str),
    /// The requested boom angle cannot be reached by the luffing cylinder.
    OutOfReach,
    /// A value became NaN or infinite.
    NotFinite(&'static str),
}

impl core::fmt::Display for ModelError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            ModelError::InvalidParameter(what) => write!(f, "invalid parameter: {what}"),
            ModelError::Singular(what) => write!(f, "singular matrix: {what}"),
            ModelError::NoConvergence(what) => write!(f, "no convergence: {what}"),
            ModelError::OutOfReach => write!(f, "boom angle out of the cylinder's reach"),
            ModelError::NotFinite(what) => write!(f, "non-finite value: {what}"),
        }
    }
}
