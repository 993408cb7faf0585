//! The boom's modes: finite-element model with the thesis's boundary conditions,
//! its eigenmodes classified and a basis selected, and the time-invariant modal
//! data the multibody equations need (thesis §2.2, §2.6, eqs. 3.1–3.11).
//!
//! Two values, as in MuJoCo's model/data split:
//! * [`ModalAnalysis`] is the structural analysis (big, built once on the host);
//! * [`BoomModes`] is what the dynamics keep: a few hundred numbers, no nodal
//!   matrices, small enough to ship to the microcontroller as constant data.

use crate::data::crane::CraneData;
use crate::structure::dense::Square;
use crate::structure::eigen::generalized_eigen;
use crate::structure::fe::{
    BeamElement, BeamMesh, NodalMatrix, NodalVector, DOF_PER_NODE, MAX_DOF, MAX_ELEMENTS,
};
use crate::data::section::boom_section_at;
use crate::{ModelError, Real};

/// Most modes a basis may keep.
pub const MAX_MODES: usize = 8;

/// What a mode of the constrained boom does (thesis listing's classification).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ModeKind {
    /// Axial motion only.
    Longitudinal,
    /// Bending of the part A0–A (pinned at A0, clamped at A).
    BendingFootToLug,
    /// Bending of the part A–C (clamped at A, free at the tip C).
    BendingLugToTip,
    /// None of the above within rounding (degenerate frequencies mixing modes).
    Mixed,
}

impl ModeKind {
    /// A short label for tables and JSON.
    pub fn label(self) -> &'static str {
        match self {
            ModeKind::Longitudinal => "longitudinal",
            ModeKind::BendingFootToLug => "bending A0-A",
            ModeKind::BendingLugToTip => "bending A-C",
            ModeKind::Mixed => "mixed",
        }
    }
}

/// One retained mode: the `ordinal`-th (0 = lowest) mode of a kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ModeChoice {
    /// The kind of mode.
    pub kind: ModeKind,
    /// 0 for the lowest of that kind, 1 for the next, …
    pub ordinal: usize,
}

/// The thesis's basis (§4.3): first longitudinal, first bending of A0–A, first two
/// bending of A–C, in the order of the listing's `XXX` columns.
pub const THESIS_BASIS: [ModeChoice; 4] = [
    ModeChoice {
        kind: ModeKind::Longitudinal,
        ordinal: 0,
    },
    ModeChoice {
        kind: ModeKind::BendingFootToLug,
        ordinal: 0,
    },
    ModeChoice {
        kind: ModeKind::BendingLugToTip,
        ordinal: 0,
    },
    ModeChoice {
        kind: ModeKind::BendingLugToTip,
        ordinal: 1,
    },
];

/// Refinement of the boom mesh. The listing's rule: equal elements in A0–G, and in
/// G–C elements of length (A0A − A0G)/`elements_g_to_lug` so that A falls on a node,
/// the last one taking what is left. The thesis: 2 and 2, giving 2 + 10 = 12 elements.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MeshRefinement {
    /// Elements between A0 and G.
    pub elements_foot_to_g: usize,
    /// Elements between G and A.
    pub elements_g_to_lug: usize,
}

impl MeshRefinement {
    /// The thesis's 12-element mesh.
    pub const THESIS: MeshRefinement = MeshRefinement {
        elements_foot_to_g: 2,
        elements_g_to_lug: 2,
    };
}

/// Where the thesis reads transverse deflections: nodes 3, 8 and 13 of its mesh
/// (G, a node of A–C, and the tip C), given as distances from A0 (m).
pub const DEFLECTION_STATIONS_M: [f64; 3] = [2.0, 2.0 + 5.0 * (5.822651887 - 2.0) / 2.0, 19.5];

/// The structural analysis of the boom: mesh, matrices, all constrained modes.
#[derive(Debug, Clone)]
pub struct ModalAnalysis<T> {
    /// The finite-element mesh.
    pub mesh: BeamMesh<T>,
    /// M_αα, all nodal dof.
    pub mass: NodalMatrix<T>,
    /// K, all nodal dof.
    pub stiffness: NodalMatrix<T>,
    /// ∫ρ φᵀJφ dV (AA).
    pub skew: NodalMatrix<T>,
    /// ∫ρ φ dV (A).
    pub first_moment: [NodalVector<T>; 2],
    /// Index of the node at A.
    pub lug_node: usize,
    /// Free dof after the boundary conditions, ascending.
    free: [usize; MAX_DOF],
    n_free: usize,
    /// ω² of every constrained mode, ascending.
    values: [T; MAX_DOF],
    /// Mass-normalized mode shapes over all nodal dof (zero at fixed dof), as columns.
    vectors: NodalMatrix<T>,
    kinds: [ModeKind; MAX_DOF],
}

impl<T: Real> ModalAnalysis<T> {
    /// Builds and solves the boom of `crane` with the given mesh refinement.
    pub fn new(crane: &CraneData, refinement: MeshRefinement) -> Result<Self, ModelError> {
        let mesh = boom_mesh::<T>(crane, refinement)?;
        let lug_node = refinement.elements_foot_to_g + refinement.elements_g_to_lug;
        // Boundary conditions (listing: rows 1, 2, 14, 15 dropped): x and y of node 1
        // at the pin A0; transverse displacement and rotation of the node at A.
        let fixed = [
            0,
            1,
            DOF_PER_NODE * lug_node + 1,
            DOF_PER_NODE * lug_node + 2,
        ];
        Self::with_boundary_conditions(mesh, lug_node, &fixed)
    }

    /// Solves a mesh with arbitrary fixed dof; `lug_node` only affects classification.
    pub fn with_boundary_conditions(
        mesh: BeamMesh<T>,
        lug_node: usize,
        fixed: &[usize],
    ) -> Result<Self, ModelError> {
        let asm = mesh.assemble()?;
        let n = mesh.n_dof();
        let mut free = [0usize; MAX_DOF];
        let mut n_free = 0;
        for d in 0..n {
            if !fixed.contains(&d) {
                free[n_free] = d;
                n_free += 1;
            }
        }
        let k = asm.stiffness.select(&free[..n_free])?;
        let m = asm.mass.select(&free[..n_free])?;
        let pairs = generalized_eigen(&k, &m)?;
        let mut vectors = Square::zeros(n)?;
        let mut kinds = [ModeKind::Mixed; MAX_DOF];
        for col in 0..n_free {
            // Sign convention: the largest translational component is positive.
            let mut big = T::zero();
            for (r, &d) in free[..n_free].iter().enumerate() {
                let x = pairs.vectors.get(r, col);
                if d % DOF_PER_NODE != 2 && x.abs() > big.abs() {
                    big = x;
                }
            }
            let sign = if big < T::zero() { -T::one() } else { T::one() };
            for (r, &d) in free[..n_free].iter().enumerate() {
                vectors.set(d, col, sign * pairs.vectors.get(r, col));
            }
            kinds[col] = classify(&vectors, col, n, lug_node);
        }
        Ok(ModalAnalysis {
            mesh,
            mass: asm.mass,
            stiffness: asm.stiffness,
            skew: asm.skew,
            first_moment: asm.first_moment,
            lug_node,
            free,
            n_free,
            values: pairs.values,
            vectors,
            kinds,
        })
    }

    /// Number of constrained modes (free dof).
    pub fn mode_count(&self) -> usize {
        self.n_free
    }

    /// Natural frequency ω (rad/s) of constrained mode `k` (ascending).
    pub fn frequency_rad_s(&self, k: usize) -> T {
        self.values
            .get(k)
            .copied()
            .unwrap_or_else(T::zero)
            .max(T::zero())
            .sqrt()
    }

    /// Kind of constrained mode `k`.
    pub fn kind(&self, k: usize) -> ModeKind {
        self.kinds.get(k).copied().unwrap_or(ModeKind::Mixed)
    }

    /// Component `dof` of mode shape `k`.
    pub fn shape(&self, dof: usize, k: usize) -> T {
        self.vectors.get(dof, k)
    }

    /// Index (ascending order) of the `ordinal`-th mode of `kind`.
    pub fn find(&self, choice: ModeChoice) -> Result<usize, ModelError> {
        (0..self.n_free)
            .filter(|&k| self.kinds[k] == choice.kind)
            .nth(choice.ordinal)
            .ok_or(ModelError::InvalidParameter("the mesh has no such mode"))
    }

    /// The boom's centre of mass from A0 along the axis (m): (A·e0)_x / m,
    /// since the axial shape functions interpolate position exactly.
    pub fn centre_of_mass_m(&self) -> T {
        let e0 = self.mesh.rest_positions();
        let mut first = T::zero();
        for d in 0..self.mesh.n_dof() {
            first += self.first_moment[0][d] * e0[d];
        }
        first / self.mesh.mass_kg()
    }

    /// Static nodal deflection under nodal forces `f` with the boundary conditions.
    pub fn static_deflection(&self, f: &NodalVector<T>) -> Result<NodalVector<T>, ModelError> {
        let k = self.stiffness.select(&self.free[..self.n_free])?;
        let mut rhs = [T::zero(); MAX_DOF];
        for (r, &d) in self.free[..self.n_free].iter().enumerate() {
            rhs[r] = f[d];
        }
        let x = k.solve(&rhs)?;
        let mut out = [T::zero(); MAX_DOF];
        for (r, &d) in self.free[..self.n_free].iter().enumerate() {
            out[d] = x[r];
        }
        Ok(out)
    }

    /// Reduces to the modal basis `basis` with Rayleigh damping ratio `zeta` at the
    /// two lowest retained frequencies: the time-invariant data of eqs. 3.1–3.11.
    pub fn reduce<const M: usize>(
        &self,
        basis: &[ModeChoice; M],
        zeta: T,
    ) -> Result<BoomModes<T, M>, ModelError> {
        if M == 0 || M > MAX_MODES {
            return Err(ModelError::InvalidParameter(
                "retained mode count must be 1..=8",
            ));
        }
        let n = self.mesh.n_dof();
        let mut cols = [0usize; M];
        for (c, choice) in cols.iter_mut().zip(basis.iter()) {
            *c = self.find(*choice)?;
        }
        for i in 0..M {
            for j in (i + 1)..M {
                if cols[i] == cols[j] {
                    return Err(ModelError::InvalidParameter("a mode is selected twice"));
                }
            }
        }
        let chi = |d: usize, k: usize| self.vectors.get(d, cols[k]);
        let e0 = self.mesh.rest_positions();
        let me0 = self.mass.mul_vec(&e0);
        let ge0 = self.skew.mul_vec(&e0);
        let mut out = BoomModes::<T, M> {
            mass_kg: self.mesh.mass_kg(),
            length_m: self.mesh.node_x(self.mesh.n_nodes() - 1),
            lug_x_m: self.mesh.node_x(self.lug_node),
            ..BoomModes::zeroed()
        };
        let tip = self.mesh.n_nodes() - 1;
        for k in 0..M {
            out.kinds[k] = self.kinds[cols[k]];
            out.omega_rad_s[k] = self.frequency_rad_s(cols[k]);
            for d in 0..n {
                let x = chi(d, k);
                out.first_moment_modes[0][k] += self.first_moment[0][d] * x;
                out.first_moment_modes[1][k] += self.first_moment[1][d] * x;
                out.inertia_coupling[k] += x * me0[d];
                out.skew_rest[k] += x * ge0[d];
            }
            for j in 0..M {
                let mut s = T::zero();
                for a in 0..n {
                    let xa = chi(a, k);
                    if xa == T::zero() {
                        continue;
                    }
                    for b in 0..n {
                        s += xa * self.skew.get(a, b) * chi(b, j);
                    }
                }
                out.skew_modes[k][j] = s;
            }
            out.tip_modes[0][k] = chi(DOF_PER_NODE * tip, k);
            out.tip_modes[1][k] = chi(DOF_PER_NODE * tip + 1, k);
            out.lug_rotation_modes[k] = chi(DOF_PER_NODE * self.lug_node + 2, k);
        }
        for d in 0..n {
            out.first_moment_rest[0] += self.first_moment[0][d] * e0[d];
            out.first_moment_rest[1] += self.first_moment[1][d] * e0[d];
            out.inertia_rest += e0[d] * me0[d];
        }
        for (s, &station) in DEFLECTION_STATIONS_M.iter().enumerate() {
            let node = self.nearest_node(T::lit(station));
            out.deflection_nodes[s] = node + 1;
            for k in 0..M {
                out.deflection_modes[s][k] = chi(DOF_PER_NODE * node + 1, k);
            }
        }
        // Rayleigh damping from ζ at the two lowest retained frequencies (eqs. 2.54–2.56).
        let (mut w1, mut w2) = (
            T::max_value().unwrap_or_else(T::one),
            T::max_value().unwrap_or_else(T::one),
        );
        for &w in out.omega_rad_s.iter() {
            if w < w1 {
                w2 = w1;
                w1 = w;
            } else if w < w2 {
                w2 = w;
            }
        }
        if M == 1 {
            out.rayleigh_alpha = T::lit(2.0) * zeta * w1;
        } else {
            let two = T::lit(2.0);
            out.rayleigh_alpha = two * w1 * w2 * (zeta * w2 - zeta * w1) / (w2 * w2 - w1 * w1);
            out.rayleigh_beta = two * (zeta * w1 - zeta * w2) / (w1 * w1 - w2 * w2);
        }
        for k in 0..M {
            let w = out.omega_rad_s[k];
            out.damping[k] = out.rayleigh_alpha + out.rayleigh_beta * w * w;
        }
        // Static deflections projected on the modes by least squares (thesis listing:
        // η = (χᵀχ)⁻¹χᵀα): per unit body-frame gravity (x, y) and per unit tip force.
        for axis in 0..2 {
            let mut fg = [T::zero(); MAX_DOF];
            for (d, f) in fg.iter_mut().enumerate().take(n) {
                *f = self.first_moment[axis][d];
            }
            let mut ft = [T::zero(); MAX_DOF];
            ft[DOF_PER_NODE * tip + axis] = T::one();
            let eta_g = self.project(&self.static_deflection(&fg)?, &cols)?;
            let eta_t = self.project(&self.static_deflection(&ft)?, &cols)?;
            for k in 0..M {
                out.static_gravity[k][axis] = eta_g[k];
                out.static_tip[k][axis] = eta_t[k];
            }
        }
        Ok(out)
    }

    /// Least-squares modal coordinates of a nodal vector: (χᵀχ)⁻¹χᵀα.
    fn project<const M: usize>(
        &self,
        alpha: &NodalVector<T>,
        cols: &[usize; M],
    ) -> Result<[T; M], ModelError> {
        let n = self.mesh.n_dof();
        let mut gram = Square::<T, MAX_MODES>::zeros(M)?;
        let mut rhs = [T::zero(); MAX_MODES];
        for i in 0..M {
            for d in 0..n {
                rhs[i] += self.vectors.get(d, cols[i]) * alpha[d];
            }
            for j in 0..M {
                let mut s = T::zero();
                for d in 0..n {
                    s += self.vectors.get(d, cols[i]) * self.vectors.get(d, cols[j]);
                }
                gram.set(i, j, s);
            }
        }
        let x = gram.solve(&rhs)?;
        let mut out = [T::zero(); M];
        out.copy_from_slice(&x[..M]);
        Ok(out)
    }

    fn nearest_node(&self, x: T) -> usize {
        let mut best = 0;
        for i in 0..self.mesh.n_nodes() {
            if (self.mesh.node_x(i) - x).abs() < (self.mesh.node_x(best) - x).abs() {
                best = i;
            }
        }
        best
    }
}

/// Classifies mode `col` by where its energy-free "size" sits (listing's test on zeros).
fn classify<T: Real>(v: &NodalMatrix<T>, col: usize, n: usize, lug_node: usize) -> ModeKind {
    let (mut axial, mut left, mut right) = (T::zero(), T::zero(), T::zero());
    for d in 0..n {
        let x = v.get(d, col) * v.get(d, col);
        let node = d / DOF_PER_NODE;
        if d % DOF_PER_NODE == 0 {
            axial += x;
        } else if node <= lug_node {
            left += x;
        } else {
            right += x;
        }
    }
    let total = axial + left + right;
    let tol = T::lit(1e-6) * total;
    if left + right <= tol {
        ModeKind::Longitudinal
    } else if axial + right <= tol {
        ModeKind::BendingFootToLug
    } else if axial + left <= tol {
        ModeKind::BendingLugToTip
    } else {
        ModeKind::Mixed
    }
}

/// The boom mesh of `crane` (SPEC §3): element section = mean of the exact section
/// over the element (3-point Gauss, exact for the polynomial A(x) and I(x)), so the
/// element mass is exactly ρ∫A dx. (The listing takes the section at the mean of
/// the end dimensions; the difference in boom mass is below 0.05 %.)
pub fn boom_mesh<T: Real>(crane: &CraneData, r: MeshRefinement) -> Result<BeamMesh<T>, ModelError> {
    let boom = &crane.boom;
    if r.elements_foot_to_g == 0 || r.elements_g_to_lug == 0 {
        return Err(ModelError::InvalidParameter(
            "mesh refinement counts must be positive",
        ));
    }
    let h1 = boom.foot_to_g_m / r.elements_foot_to_g as f64;
    let h2 = (boom.foot_to_lug_m - boom.foot_to_g_m) / r.elements_g_to_lug as f64;
    let mut ends = [0.0f64; MAX_ELEMENTS + 1];
    let mut count = 0;
    let mut x = 0.0;
    let mut push = |x_end: f64, count: &mut usize| -> Result<(), ModelError> {
        *count += 1;
        *ends
            .get_mut(*count)
            .ok_or(ModelError::InvalidParameter("mesh exceeds 24 elements"))? = x_end;
        Ok(())
    };
    for _ in 0..r.elements_foot_to_g {
        x += h1;
        push(x, &mut count)?;
    }
    let length = boom.length_m();
    // Full elements of h2 while one fits with at least 5 % of h2 to spare; the rest
    // is the last, short element (0.298 m on the thesis mesh, node 13 at the tip).
    while length - x >= 1.05 * h2 {
        x += h2;
        push(x, &mut count)?;
    }
    push(length, &mut count)?;
    let mut elements = [BeamElement {
        length_m: T::one(),
        area_m2: T::one(),
        second_moment_m4: T::one(),
        density_kg_m3: T::one(),
        youngs_modulus_pa: T::one(),
    }; MAX_ELEMENTS];
    const GAUSS3: [(f64, f64); 3] = [
        (0.112_701_665_379_258_31, 5.0 / 18.0),
        (0.5, 8.0 / 18.0),
        (0.887_298_334_620_741_7, 5.0 / 18.0),
    ];
    for k in 0..count {
        let (a, b) = (ends[k], ends[k + 1]);
        let (mut area, mut second) = (0.0, 0.0);
        for &(xi, w) in GAUSS3.iter() {
            let s = boom_section_at(boom, a + xi * (b - a));
            area += w * s.area_m2;
            second += w * s.second_moment_m4;
        }
        elements[k] = BeamElement {
            length_m: T::lit(b - a),
            area_m2: T::lit(area),
            second_moment_m4: T::lit(second),
            density_kg_m3: T::lit(boom.density_kg_m3),
            youngs_modulus_pa: T::lit(boom.youngs_modulus_pa),
        };
    }
    BeamMesh::new(&elements[..count])
}

/// Per-kind operations of [`BoomModes`]' fields, picked by the field list in
/// `boom_modes!`: a conversion between float types, a zero, and the f32 source
/// text of a value.
mod field {
    use super::ModeKind;
    use crate::Real;
    use core::fmt::{Result, Write};

    /// The shortest f32 literal that reads back to the same bits.
    fn number(w: &mut dyn Write, x: f32) -> Result {
        write!(w, "{x:?}")
    }

    fn list(w: &mut dyn Write, a: &[f32]) -> Result {
        w.write_str("[")?;
        for (i, x) in a.iter().enumerate() {
            if i > 0 {
                w.write_str(", ")?;
            }
            number(w, *x)?;
        }
        w.write_str("]")
    }

    pub mod scalar {
        use super::*;
        pub fn cast<T: Real, U: Real>(x: &T) -> U {
            U::lit(x.to_f64())
        }
        pub fn zero<T: Real>() -> T {
            T::zero()
        }
        pub fn write(w: &mut dyn Write, x: &f32) -> Result {
            number(w, *x)
        }
    }

    pub mod array {
        use super::*;
        pub fn cast<T: Real, U: Real, const N: usize>(a: &[T; N]) -> [U; N] {
            core::array::from_fn(|i| scalar::cast(&a[i]))
        }
        pub fn zero<T: Real, const N: usize>() -> [T; N] {
            [T::zero(); N]
        }
        pub fn write<const N: usize>(w: &mut dyn Write, a: &[f32; N]) -> Result {
            list(w, a)
        }
    }

    pub mod matrix {
        use super::*;
        pub fn cast<T: Real, U: Real, const R: usize, const C: usize>(a: &[[T; C]; R]) -> [[U; C]; R] {
            core::array::from_fn(|i| array::cast(&a[i]))
        }
        pub fn zero<T: Real, const R: usize, const C: usize>() -> [[T; C]; R] {
            [[T::zero(); C]; R]
        }
        pub fn write<const R: usize, const C: usize>(w: &mut dyn Write, a: &[[f32; C]; R]) -> Result {
            w.write_str("[")?;
            for row in a {
                list(w, row)?;
                w.write_str(", ")?;
            }
            w.write_str("]")
        }
    }

    pub mod kinds {
        use super::*;
        pub fn cast<const N: usize>(a: &[ModeKind; N]) -> [ModeKind; N] {
            *a
        }
        pub fn zero<const N: usize>() -> [ModeKind; N] {
            [ModeKind::Mixed; N]
        }
        pub fn write<const N: usize>(w: &mut dyn Write, a: &[ModeKind; N]) -> Result {
            w.write_str("[")?;
            for k in a {
                write!(w, "ModeKind::{k:?}, ")?;
            }
            w.write_str("]")
        }
    }

    pub mod copy {
        use super::*;
        pub fn cast<const N: usize>(a: &[usize; N]) -> [usize; N] {
            *a
        }
        pub fn zero<const N: usize>() -> [usize; N] {
            [0; N]
        }
        pub fn write<const N: usize>(w: &mut dyn Write, a: &[usize; N]) -> Result {
            write!(w, "{a:?}")
        }
    }
}

/// Defines [`BoomModes`] from one field list: the struct, its conversion
/// between float types, its zero and its writer as Rust source all follow the
/// list, so a field added to it cannot be forgotten by one of them.
macro_rules! boom_modes {
    ($(#[$meta:meta])* pub struct BoomModes { $( $(#[doc = $doc:literal])* $name:ident : $ty:ty => $kind:ident, )* }) => {
        $(#[$meta])*
        pub struct BoomModes<T, const M: usize> {
            $( $(#[doc = $doc])* pub $name: $ty, )*
        }

        impl<T: Real, const M: usize> BoomModes<T, M> {
            /// Converts to another float type (f64 analysis → f32 controller data).
            pub fn cast<U: Real>(&self) -> BoomModes<U, M> {
                BoomModes { $( $name: field::$kind::cast(&self.$name), )* }
            }

            /// Every field zero (modes of kind [`ModeKind::Mixed`]): the start of
            /// the reduction, which fills them in.
            fn zeroed() -> Self {
                BoomModes { $( $name: field::$kind::zero(), )* }
            }

            /// Writes this value as Rust source of a `const` named `name` of type
            /// `BoomModes<f32, M>`, every number as the shortest f32 literal that
            /// reads back to the same bits: how the controller gets its modes
            /// without FE or eigen work.
            pub fn write_f32_const(&self, name: &str, w: &mut impl core::fmt::Write) -> core::fmt::Result {
                let m = self.cast::<f32>();
                writeln!(w, "pub const {name}: BoomModes<f32, {M}> = BoomModes {{")?;
                $(
                    write!(w, "    {}: ", stringify!($name))?;
                    field::$kind::write(w, &m.$name)?;
                    writeln!(w, ",")?;
                )*
                writeln!(w, "}};")
            }
        }
    };
}

boom_modes! {
    /// The time-invariant modal data of the boom for `M` retained modes: everything
    /// the per-step dynamics need, nothing more (thesis §2.6). Mode shapes χ are
    /// mass-normalized (χᵀMχ = I) so M_ηη = I (eq. 3.8) and χᵀKχ = diag(ω²).
    /// Arrays, not nalgebra types, so the value can be written out as constant data.
    #[derive(Debug, Clone, Copy, PartialEq)]
    pub struct BoomModes {
        /// Kind of each retained mode.
        kinds: [ModeKind; M] => kinds,
        /// Natural frequency ω of each retained mode (rad/s).
        omega_rad_s: [T; M] => array,
        /// Modal damping χᵀCχ = α + β·ω² (1/s), Rayleigh (eqs. 2.53–2.56).
        damping: [T; M] => array,
        /// Rayleigh α (1/s).
        rayleigh_alpha: T => scalar,
        /// Rayleigh β (s).
        rayleigh_beta: T => scalar,
        /// Boom mass m (kg, eq. 3.1).
        mass_kg: T => scalar,
        /// A·e0: first moment of mass of the undeformed boom in its body frame (kg·m).
        first_moment_rest: [T; 2] => array,
        /// A·χ (eq. 3.4): first moment per unit modal coordinate, rows x and y (kg·m).
        first_moment_modes: [[T; M]; 2] => matrix,
        /// e0ᵀ·M_αα·e0 (eq. 3.5): rotary inertia of the undeformed boom about A0 (kg·m²).
        inertia_rest: T => scalar,
        /// χᵀ·M_αα·e0 (eqs. 3.5, 3.10, 3.11).
        inertia_coupling: [T; M] => array,
        /// χᵀ·AA·e0 (eq. 3.6 with AA = ∫ρφᵀJφ).
        skew_rest: [T; M] => array,
        /// χᵀ·AA·χ (eqs. 3.6, 3.11), skew-symmetric.
        skew_modes: [[T; M]; M] => matrix,
        /// Boom length A0C (m).
        length_m: T => scalar,
        /// Distance A0A (m).
        lug_x_m: T => scalar,
        /// Displacement of the tip C per unit modal coordinate, rows x and y (body frame).
        tip_modes: [[T; M]; 2] => matrix,
        /// Rotation at A per unit modal coordinate (ψ_A·χ, eq. 3.31): zero with the thesis's BCs.
        lug_rotation_modes: [T; M] => array,
        /// The nodes (1-based, thesis numbering on its mesh) whose deflection is reported.
        deflection_nodes: [usize; 3] => copy,
        /// Transverse displacement of those nodes per unit modal coordinate.
        deflection_modes: [[T; M]; 3] => matrix,
        /// Least-squares modal coordinates of the static deflection per unit body-frame
        /// gravity (columns x, y in m/s²): the thesis's initial state, part 1.
        static_gravity: [[T; 2]; M] => matrix,
        /// Least-squares modal coordinates of the static deflection per unit tip force
        /// (columns x, y in N, body frame): the thesis's initial state, part 2.
        static_tip: [[T; 2]; M] => matrix,
    }
}

impl<T: Real, const M: usize> BoomModes<T, M> {
    /// The tip's static compliance across the boom (m/N, body frame y) in the
    /// retained modes: a force F across the boom at C moves C by F·Σ_k χ_Cy,k²/ω_k²
    /// (mass-normalized modes, χᵀKχ = diag(ω²), so a static force excites each mode
    /// by χ_Cy,k·F/ω_k²). What the model's tip gives under a swinging load's pull,
    /// which lengthens its pendulum (`moment_limiter::held_pendulum`). A mode
    /// without stiffness (ω = 0) adds nothing rather than infinity.
    pub fn tip_compliance_across_m_per_n(&self) -> T {
        let mut c = T::zero();
        for (chi, w) in self.tip_modes[1].iter().zip(self.omega_rad_s.iter()) {
            let w2 = *w * *w;
            if w2 > T::zero() {
                c += *chi * *chi / w2;
            }
        }
        c
    }
}
