//! Small dense matrices of run-time size inside a fixed capacity, for the work
//! whose size is a parameter (the finite-element mesh, the augmented system of
//! eq. 2.68). No heap: storage is an array of `CAP × CAP`; only the leading
//! `n × n` block is used. Loops are bounded by `n ≤ CAP`.

use crate::{ModelError, Real};

/// An `n × n` matrix stored in a `CAP × CAP` array.
#[derive(Clone, Copy, Debug)]
pub struct Square<T, const CAP: usize> {
    n: usize,
    a: [[T; CAP]; CAP],
}

impl<T: Real, const CAP: usize> Square<T, CAP> {
    /// An `n × n` zero matrix; fails if `n` exceeds the capacity.
    pub fn zeros(n: usize) -> Result<Self, ModelError> {
        if n > CAP {
            return Err(ModelError::InvalidParameter("matrix size exceeds capacity"));
        }
        Ok(Square {
            n,
            a: [[T::zero(); CAP]; CAP],
        })
    }

    /// The size `n`.
    pub fn dim(&self) -> usize {
        self.n
    }

    /// Entry (i, j); zero outside the `n × n` block.
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> T {
        self.a
            .get(i)
            .and_then(|r| r.get(j))
            .copied()
            .unwrap_or_else(T::zero)
    }

    /// Sets entry (i, j); ignored outside the capacity.
    #[inline]
    pub fn set(&mut self, i: usize, j: usize, v: T) {
        if let Some(x) = self.a.get_mut(i).and_then(|r| r.get_mut(j)) {
            *x = v;
        }
    }

    /// Adds `v` to entry (i, j).
    #[inline]
    pub fn add(&mut self, i: usize, j: usize, v: T) {
        if let Some(x) = self.a.get_mut(i).and_then(|r| r.get_mut(j)) {
            *x += v;
        }
    }

    /// `self · x` for a vector of length `n`.
    pub fn mul_vec(&self, x: &[T; CAP]) -> [T; CAP] {
        let mut y = [T::zero(); CAP];
        for (i, yi) in y.iter_mut().enumerate().take(self.n) {
            let row = &self.a[i];
            let mut s = T::zero();
            for j in 0..self.n {
                s += row[j] * x[j];
            }
            *yi = s;
        }
        y
    }

    /// The matrix restricted to the listed rows and columns (boundary conditions).
    pub fn select(&self, keep: &[usize]) -> Result<Self, ModelError> {
        let mut out = Self::zeros(keep.len())?;
        for (i, &ki) in keep.iter().enumerate() {
            for (j, &kj) in keep.iter().enumerate() {
                out.set(i, j, self.get(ki, kj));
            }
        }
        Ok(out)
    }

    /// Solves `self · x = b` by LU with partial pivoting (the matrix is consumed).
    pub fn solve(mut self, b: &[T; CAP]) -> Result<[T; CAP], ModelError> {
        let n = self.n;
        let mut x = *b;
        let scale = self.max_abs();
        let tiny = scale * T::default_epsilon() * T::lit(n.max(1) as f64);
        for k in 0..n {
            let mut p = k;
            let mut best = self.a[k][k].abs();
            for i in (k + 1)..n {
                let v = self.a[i][k].abs();
                if v > best {
                    best = v;
                    p = i;
                }
            }
            if !(best > tiny) {
                return Err(ModelError::Singular("dense LU"));
            }
            self.a.swap(k, p);
            x.swap(k, p);
            let pivot = self.a[k][k];
            for i in (k + 1)..n {
                let f = self.a[i][k] / pivot;
                if f != T::zero() {
                    for j in k..n {
                        let akj = self.a[k][j];
                        self.a[i][j] -= f * akj;
                    }
                    let xk = x[k];
                    x[i] -= f * xk;
                }
            }
        }
        for k in (0..n).rev() {
            let mut s = x[k];
            for j in (k + 1)..n {
                s -= self.a[k][j] * x[j];
            }
            x[k] = s / self.a[k][k];
        }
        Ok(x)
    }

    /// Largest absolute entry.
    pub fn max_abs(&self) -> T {
        let mut m = T::zero();
        for i in 0..self.n {
            for j in 0..self.n {
                m = m.max(self.a[i][j].abs());
            }
        }
        m
    }

    /// Lower-triangular Cholesky factor L with `self = L·Lᵀ`.
    pub fn cholesky(&self) -> Result<Self, ModelError> {
        let n = self.n;
        let mut l = Self::zeros(n)?;
        for j in 0..n {
            let mut d = self.a[j][j];
            for k in 0..j {
                d -= l.a[j][k] * l.a[j][k];
            }
            if !(d > T::zero()) {
                return Err(ModelError::Singular(
                    "Cholesky: matrix not positive definite",
                ));
            }
            let djj = d.sqrt();
            l.a[j][j] = djj;
            for i in (j + 1)..n {
                let mut s = self.a[i][j];
                for k in 0..j {
                    s -= l.a[i][k] * l.a[j][k];
                }
                l.a[i][j] = s / djj;
            }
        }
        Ok(l)
    }
}
