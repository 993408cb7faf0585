//! The generalized symmetric-definite eigenproblem K·x = ω²·M·x (eq. 2.17).
//!
//! Reduced to standard form with the Cholesky factor of M (C = L⁻¹·K·L⁻ᵀ) and
//! solved by cyclic Jacobi rotations, as the thesis's `JACOBI` did: simple, no heap,
//! a bounded number of sweeps, and accurate for the small matrices of a boom.
//! The eigenvectors come out mass-orthonormal (xᵀMx = 1).

use crate::structure::dense::Square;
use crate::{ModelError, Real};

/// Most Jacobi sweeps before giving up.
const MAX_SWEEPS: usize = 60;

/// Eigenvalues (ascending) and M-orthonormal eigenvectors (columns).
#[derive(Debug, Clone)]
pub struct EigenPairs<T, const CAP: usize> {
    /// ω² in ascending order; only the first `n` are meaningful.
    pub values: [T; CAP],
    /// Column `k` is the eigenvector of `values[k]`.
    pub vectors: Square<T, CAP>,
}

/// Solves K·x = λ·M·x for symmetric K and symmetric positive definite M.
pub fn generalized_eigen<T: Real, const CAP: usize>(
    k: &Square<T, CAP>,
    m: &Square<T, CAP>,
) -> Result<EigenPairs<T, CAP>, ModelError> {
    let n = k.dim();
    if m.dim() != n {
        return Err(ModelError::InvalidParameter("K and M differ in size"));
    }
    let l = m.cholesky()?;
    // C = L⁻¹ K L⁻ᵀ: first Y = L⁻¹ K (forward substitution column by column), then C = Y L⁻ᵀ.
    let mut y = Square::<T, CAP>::zeros(n)?;
    for j in 0..n {
        for i in 0..n {
            let mut s = k.get(i, j);
            for p in 0..i {
                s -= l.get(i, p) * y.get(p, j);
            }
            y.set(i, j, s / l.get(i, i));
        }
    }
    let mut c = Square::<T, CAP>::zeros(n)?;
    for i in 0..n {
        for j in 0..n {
            let mut s = y.get(i, j);
            for p in 0..j {
                s -= c.get(i, p) * l.get(j, p);
            }
            c.set(i, j, s / l.get(j, j));
        }
    }
    // Symmetrize against rounding.
    for i in 0..n {
        for j in (i + 1)..n {
            let v = (c.get(i, j) + c.get(j, i)) * T::lit(0.5);
            c.set(i, j, v);
            c.set(j, i, v);
        }
    }
    let mut v = Square::<T, CAP>::zeros(n)?;
    for i in 0..n {
        v.set(i, i, T::one());
    }
    jacobi(&mut c, &mut v)?;
    // Back-transform: x = L⁻ᵀ v (backward substitution), then sort ascending.
    let mut x = Square::<T, CAP>::zeros(n)?;
    for col in 0..n {
        for i in (0..n).rev() {
            let mut s = v.get(i, col);
            for p in (i + 1)..n {
                s -= l.get(p, i) * x.get(p, col);
            }
            x.set(i, col, s / l.get(i, i));
        }
    }
    let mut order = [0usize; CAP];
    for (i, o) in order.iter_mut().enumerate().take(n) {
        *o = i;
    }
    order[..n].sort_unstable_by(|&a, &b| {
        c.get(a, a)
            .partial_cmp(&c.get(b, b))
            .unwrap_or(core::cmp::Ordering::Equal)
    });
    let mut out = EigenPairs {
        values: [T::zero(); CAP],
        vectors: Square::zeros(n)?,
    };
    for (dst, &src) in order[..n].iter().enumerate() {
        out.values[dst] = c.get(src, src);
        for i in 0..n {
            out.vectors.set(i, dst, x.get(i, src));
        }
    }
    Ok(out)
}

/// Cyclic Jacobi: diagonalizes the symmetric `a` in place, accumulating rotations in `v`.
fn jacobi<T: Real, const CAP: usize>(
    a: &mut Square<T, CAP>,
    v: &mut Square<T, CAP>,
) -> Result<(), ModelError> {
    let n = a.dim();
    let eps = T::default_epsilon();
    for _sweep in 0..MAX_SWEEPS {
        let mut off = T::zero();
        let mut diag = T::zero();
        for i in 0..n {
            diag += a.get(i, i) * a.get(i, i);
            for j in (i + 1)..n {
                off += a.get(i, j) * a.get(i, j);
            }
        }
        if off <= eps * eps * diag * T::lit(1e-4) || off == T::zero() {
            return Ok(());
        }
        for p in 0..n {
            for q in (p + 1)..n {
                let apq = a.get(p, q);
                // Skip entries already negligible against both diagonal terms.
                if apq.abs() <= eps * T::lit(1e-2) * (a.get(p, p).abs().min(a.get(q, q).abs())) {
                    a.set(p, q, T::zero());
                    a.set(q, p, T::zero());
                    continue;
                }
                let theta = (a.get(q, q) - a.get(p, p)) / (T::lit(2.0) * apq);
                let t = theta.signum() / (theta.abs() + (theta * theta + T::one()).sqrt());
                let t = if theta == T::zero() { T::one() } else { t };
                let c = T::one() / (t * t + T::one()).sqrt();
                let s = t * c;
                for r in 0..n {
                    let (arp, arq) = (a.get(r, p), a.get(r, q));
                    a.set(r, p, c * arp - s * arq);
                    a.set(r, q, s * arp + c * arq);
                }
                for r in 0..n {
                    let (apr, aqr) = (a.get(p, r), a.get(q, r));
                    a.set(p, r, c * apr - s * aqr);
                    a.set(q, r, s * apr + c * aqr);
                }
                for r in 0..n {
                    let (vrp, vrq) = (v.get(r, p), v.get(r, q));
                    v.set(r, p, c * vrp - s * vrq);
                    v.set(r, q, s * vrp + c * vrq);
                }
            }
        }
    }
    Err(ModelError::NoConvergence("Jacobi eigen-solver"))
}
