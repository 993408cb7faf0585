//! Finite elements of the boom: 2-D Euler–Bernoulli beam elements with an axial
//! degree of freedom (thesis Appendix A, eqs. ), and their assembly.
//!
//! Each node carries (u, v, θ): axial and transverse displacement and rotation in
//! the boom's body frame (x along the undeformed axis from A0). The element
//! integrals are evaluated by 4-point Gauss–Legendre quadrature of the Appendix A
//! shape functions, exact for these polynomials, instead of typed-in tables: the
//! listing's `ES` table has the signs of the rotary-inertia couplings wrong.

use crate::structure::dense::Square;
use crate::{ModelError, Real};

/// Most elements a boom mesh may have.
pub const MAX_ELEMENTS: usize = 24;
/// Most nodes.
pub const MAX_NODES: usize = MAX_ELEMENTS + 1;
/// Degrees of freedom per node: u, v, θ.
pub const DOF_PER_NODE: usize = 3;
/// Most nodal degrees of freedom.
pub const MAX_DOF: usize = DOF_PER_NODE * MAX_NODES;

/// A square matrix over the nodal degrees of freedom.
pub type NodalMatrix<T> = Square<T, MAX_DOF>;
/// A vector over the nodal degrees of freedom.
pub type NodalVector<T> = [T; MAX_DOF];
/// A 6 × 6 element matrix over (u_A, v_A, θ_A, u_B, v_B, θ_B).
pub type ElementMatrix<T> = [[T; 6]; 6];

/// One beam element with a uniform section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamElement<T> {
    /// Length L (m).
    pub length_m: T,
    /// Cross-section area (m²).
    pub area_m2: T,
    /// Second moment of area (m⁴).
    pub second_moment_m4: T,
    /// Density ρ (kg/m³).
    pub density_kg_m3: T,
    /// Young's modulus E (Pa).
    pub youngs_modulus_pa: T,
}

/// Gauss–Legendre points and weights on [0, 1] (4 points: exact to degree 7).
const GAUSS4: [(f64, f64); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_87, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

/// The Appendix A shape functions of an element of length `l` at ξ = x/L.
struct Shape<T> {
    /// Axial row of Φ: (a1, 0, 0, a2, 0, 0).
    axial: [T; 6],
    /// Transverse row of Φ: (0, b1, b2, 0, b3, b4).
    transverse: [T; 6],
    /// Rotation row ψ = d(transverse)/dx: (0, c1, c2, 0, c3, c4).
    slope: [T; 6],
    /// d(axial)/dx.
    axial_strain: [T; 6],
    /// d²(transverse)/dx², the curvature.
    curvature: [T; 6],
}

impl<T: Real> Shape<T> {
    fn at(xi: T, l: T) -> Self {
        let (o, z) = (T::one(), T::zero());
        let (two, three, four, six) = (T::lit(2.0), T::lit(3.0), T::lit(4.0), T::lit(6.0));
        let (x2, x3) = (xi * xi, xi * xi * xi);
        Shape {
            axial: [o - xi, z, z, xi, z, z],
            transverse: [
                z,
                o - three * x2 + two * x3,
                l * (xi - two * x2 + x3),
                z,
                three * x2 - two * x3,
                l * (x3 - x2),
            ],
            slope: [
                z,
                six / l * (x2 - xi),
                o - four * xi + three * x2,
                z,
                six / l * (xi - x2),
                three * x2 - two * xi,
            ],
            axial_strain: [-o / l, z, z, o / l, z, z],
            curvature: [
                z,
                (T::lit(12.0) * xi - six) / (l * l),
                (six * xi - four) / l,
                z,
                (six - T::lit(12.0) * xi) / (l * l),
                (six * xi - two) / l,
            ],
        }
    }
}

/// ∫₀¹ f(shape) dξ by Gauss quadrature, summed into a 6×6 matrix.
fn integrate6<T: Real>(l: T, mut f: impl FnMut(&Shape<T>, usize, usize) -> T) -> ElementMatrix<T> {
    let mut out = [[T::zero(); 6]; 6];
    for &(xi, w) in GAUSS4.iter() {
        let s = Shape::at(T::lit(xi), l);
        let w = T::lit(w);
        for (i, row) in out.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x += w * f(&s, i, j);
            }
        }
    }
    out
}

impl<T: Real> BeamElement<T> {
    fn mass_per_length(&self) -> T {
        self.density_kg_m3 * self.area_m2
    }

    /// Consistent mass matrix with rotary inertia, ∫ρ φᵀφ dV with φ of eq. A-29:
    /// ρA∫(ΦᵀΦ) dx + ρI∫(ψᵀψ) dx.
    pub fn mass(&self) -> ElementMatrix<T> {
        let (l, ra, ri) = (
            self.length_m,
            self.mass_per_length(),
            self.density_kg_m3 * self.second_moment_m4,
        );
        integrate6(l, |s, i, j| {
            l * (ra * (s.axial[i] * s.axial[j] + s.transverse[i] * s.transverse[j])
                + ri * s.slope[i] * s.slope[j])
        })
    }

    /// Stiffness matrix: EA∫u'ᵀu' dx + EI∫v''ᵀv'' dx.
    pub fn stiffness(&self) -> ElementMatrix<T> {
        let (l, ea, ei) = (
            self.length_m,
            self.youngs_modulus_pa * self.area_m2,
            self.youngs_modulus_pa * self.second_moment_m4,
        );
        integrate6(l, |s, i, j| {
            l * (ea * s.axial_strain[i] * s.axial_strain[j] + ei * s.curvature[i] * s.curvature[j])
        })
    }

    /// First moment of mass ∫ρ φ dV (2 × 6), the element part of the thesis's
    /// time-invariant matrix A (eq. 3.3). The rotary part integrates to zero.
    pub fn first_moment(&self) -> [[T; 6]; 2] {
        let (l, ra) = (self.length_m, self.mass_per_length());
        let mut out = [[T::zero(); 6]; 2];
        for &(xi, w) in GAUSS4.iter() {
            let s = Shape::at(T::lit(xi), l);
            let w = T::lit(w) * l * ra;
            for j in 0..6 {
                out[0][j] += w * s.axial[j];
                out[1][j] += w * s.transverse[j];
            }
        }
        out
    }

    /// The skew coupling ∫ρ φᵀ J φ dV with J the 90° rotation [[0, −1], [1, 0]]:
    /// the thesis's AA (eq. 3.7) up to its sign convention for Ĩ.
    pub fn skew(&self) -> ElementMatrix<T> {
        let (l, ra) = (self.length_m, self.mass_per_length());
        integrate6(l, |s, i, j| {
            l * ra * (s.transverse[i] * s.axial[j] - s.axial[i] * s.transverse[j])
        })
    }
}

/// A straight beam made of elements laid end to end from x = 0.
#[derive(Debug, Clone, Copy)]
pub struct BeamMesh<T> {
    n_elements: usize,
    elements: [BeamElement<T>; MAX_ELEMENTS],
}

impl<T: Real> BeamMesh<T> {
    /// A mesh from its elements; fails if there are none or more than [`MAX_ELEMENTS`].
    pub fn new(elements: &[BeamElement<T>]) -> Result<Self, ModelError> {
        if elements.is_empty() || elements.len() > MAX_ELEMENTS {
            return Err(ModelError::InvalidParameter("element count must be 1..=24"));
        }
        let mut all = [elements[0]; MAX_ELEMENTS];
        all[..elements.len()].copy_from_slice(elements);
        for e in elements {
            if !(e.length_m > T::zero() && e.area_m2 > T::zero() && e.second_moment_m4 > T::zero())
            {
                return Err(ModelError::InvalidParameter(
                    "element length, area and second moment must be positive",
                ));
            }
        }
        Ok(BeamMesh {
            n_elements: elements.len(),
            elements: all,
        })
    }

    /// The elements.
    pub fn elements(&self) -> &[BeamElement<T>] {
        &self.elements[..self.n_elements]
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.n_elements + 1
    }

    /// Number of nodal degrees of freedom.
    pub fn n_dof(&self) -> usize {
        DOF_PER_NODE * self.n_nodes()
    }

    /// Distance of node `i` from the first node along the axis (m).
    pub fn node_x(&self, i: usize) -> T {
        self.elements()
            .iter()
            .take(i)
            .fold(T::zero(), |acc, e| acc + e.length_m)
    }

    /// Total mass (kg).
    pub fn mass_kg(&self) -> T {
        self.elements()
            .iter()
            .fold(T::zero(), |acc, e| acc + e.mass_per_length() * e.length_m)
    }

    /// The undeformed nodal positions e0 (eq. 2.10): u = x of the node, v = θ = 0.
    pub fn rest_positions(&self) -> NodalVector<T> {
        let mut e0 = [T::zero(); MAX_DOF];
        for i in 0..self.n_nodes() {
            e0[DOF_PER_NODE * i] = self.node_x(i);
        }
        e0
    }

    /// Assembles the structural matrices (eq. 2.42 and the thesis's time-invariant
    /// matrices of §2.6) over all nodal degrees of freedom, before boundary conditions.
    pub fn assemble(&self) -> Result<Assembly<T>, ModelError> {
        let n = self.n_dof();
        let mut asm = Assembly {
            mass: Square::zeros(n)?,
            stiffness: Square::zeros(n)?,
            skew: Square::zeros(n)?,
            first_moment: [[T::zero(); MAX_DOF]; 2],
        };
        for (k, e) in self.elements().iter().enumerate() {
            let base = DOF_PER_NODE * k;
            let (me, ke, ge, ae) = (e.mass(), e.stiffness(), e.skew(), e.first_moment());
            for i in 0..6 {
                for j in 0..6 {
                    asm.mass.add(base + i, base + j, me[i][j]);
                    asm.stiffness.add(base + i, base + j, ke[i][j]);
                    asm.skew.add(base + i, base + j, ge[i][j]);
                }
                asm.first_moment[0][base + i] += ae[0][i];
                asm.first_moment[1][base + i] += ae[1][i];
            }
        }
        Ok(asm)
    }
}

/// The assembled structural matrices of a beam (before boundary conditions).
#[derive(Debug, Clone)]
pub struct Assembly<T> {
    /// M_αα: consistent mass with rotary inertia (eq. 2.42).
    pub mass: NodalMatrix<T>,
    /// K: stiffness.
    pub stiffness: NodalMatrix<T>,
    /// ∫ρ φᵀJφ dV: skew-symmetric inertia coupling (AA of eq. 3.7).
    pub skew: NodalMatrix<T>,
    /// ∫ρ φ dV: first moment of mass (A of eq. 3.3), rows x and y.
    pub first_moment: [NodalVector<T>; 2],
}
