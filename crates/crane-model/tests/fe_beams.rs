//! Verification of the beam finite elements (thesis Appendix A) on uniform beams,
//! through exactly the element, assembly, boundary-condition and eigen code the
//! boom uses, against closed-form Euler–Bernoulli and bar theory.
//!
//! Test beam: L = 10 m, A = 0.01 m², I = 1e-5 m⁴ (radius of gyration r = 31.6 mm,
//! slenderness L/r = 316, so the rotary inertia the element mass carries shifts the
//! third cantilever frequency by only ~3e-4), steel ρ = 7850 kg/m³, E = 2.1e11 Pa.
//! Meshes: 20 equal elements (bending and axial frequency tests).

use crane_model::structure::fe::{BeamElement, BeamMesh, ElementMatrix, DOF_PER_NODE};
use crane_model::structure::modal::ModalAnalysis;
use nalgebra::SMatrix;

const LENGTH: f64 = 10.0;
const AREA: f64 = 0.01;
const SECOND_MOMENT: f64 = 1e-5;
const DENSITY: f64 = 7850.0;
const YOUNGS: f64 = 2.1e11;
/// Element count of every uniform-beam mesh in this file.
const ELEMENTS: usize = 20;

fn element(length_m: f64) -> BeamElement<f64> {
    BeamElement {
        length_m,
        area_m2: AREA,
        second_moment_m4: SECOND_MOMENT,
        density_kg_m3: DENSITY,
        youngs_modulus_pa: YOUNGS,
    }
}

fn uniform_mesh(n: usize) -> BeamMesh<f64> {
    let els = vec![element(LENGTH / n as f64); n];
    BeamMesh::new(&els).expect("valid mesh")
}

/// Euler–Bernoulli bending frequency ω = (βL)²/L²·√(EI/ρA).
fn bending_omega(beta_l: f64) -> f64 {
    beta_l * beta_l / (LENGTH * LENGTH) * (YOUNGS * SECOND_MOMENT / (DENSITY * AREA)).sqrt()
}

/// Fraction of a mode's (Euclidean) size that sits in the axial dof u.
fn axial_fraction(an: &ModalAnalysis<f64>, k: usize) -> f64 {
    let n = an.mesh.n_dof();
    let (mut ax, mut all) = (0.0, 0.0);
    for d in 0..n {
        let x = an.shape(d, k);
        all += x * x;
        if d % DOF_PER_NODE == 0 {
            ax += x * x;
        }
    }
    ax / all
}

/// Frequencies of the first `count` pure bending modes (no axial content), and of
/// the first pure axial mode, ascending.
fn split_modes(an: &ModalAnalysis<f64>, count: usize) -> (Vec<f64>, f64) {
    let mut bending = Vec::new();
    let mut axial = None;
    for k in 0..an.mode_count() {
        let f = axial_fraction(an, k);
        if f < 1e-12 && bending.len() < count {
            bending.push(an.frequency_rad_s(k));
        } else if f > 1.0 - 1e-12 && axial.is_none() {
            axial = Some(an.frequency_rad_s(k));
        }
    }
    assert_eq!(bending.len(), count, "not enough pure bending modes");
    (bending, axial.expect("a pure axial mode"))
}

#[test]
fn cantilever_first_three_bending_frequencies_match_euler_bernoulli() {
    let mesh = uniform_mesh(ELEMENTS);
    // Clamped at node 0: u, v, θ fixed.
    let an = ModalAnalysis::with_boundary_conditions(mesh, ELEMENTS, &[0, 1, 2]).expect("eigen");
    let (bending, _) = split_modes(&an, 3);
    // β_nL of a clamped–free Euler–Bernoulli beam (roots of cos βL·cosh βL = −1).
    let beta_l = [1.875_104, 4.694_091, 7.854_757];
    for (n, (&w, &bl)) in bending.iter().zip(beta_l.iter()).enumerate() {
        let exact = bending_omega(bl);
        let err = (w - exact).abs() / exact;
        println!(
            "cantilever mode {}: FE {w:.6} rad/s, EB {exact:.6} rad/s, rel err {err:.3e}",
            n + 1
        );
        // Cantilever bending frequency n within 0.5 % of Euler–Bernoulli (βL from cos·cosh = −1).
        assert!(err < 5e-3, "cantilever mode {} off by {err:e}", n + 1);
    }
}

#[test]
fn pinned_pinned_first_three_bending_frequencies_match_euler_bernoulli() {
    let mesh = uniform_mesh(ELEMENTS);
    let last = DOF_PER_NODE * ELEMENTS;
    // Pin at node 0 (u, v fixed), roller at the last node (v fixed): rotations free.
    let an =
        ModalAnalysis::with_boundary_conditions(mesh, ELEMENTS, &[0, 1, last + 1]).expect("eigen");
    let (bending, _) = split_modes(&an, 3);
    for (n, &w) in bending.iter().enumerate() {
        let exact = bending_omega((n + 1) as f64 * core::f64::consts::PI);
        let err = (w - exact).abs() / exact;
        println!(
            "pinned-pinned mode {}: FE {w:.6} rad/s, EB {exact:.6} rad/s, rel err {err:.3e}",
            n + 1
        );
        // Simply supported bending frequency n within 0.5 % of Euler–Bernoulli (βL = nπ).
        assert!(err < 5e-3, "pinned-pinned mode {} off by {err:e}", n + 1);
    }
}

#[test]
fn fixed_free_bar_first_axial_frequency_matches_bar_theory() {
    let mesh = uniform_mesh(ELEMENTS);
    let an = ModalAnalysis::with_boundary_conditions(mesh, ELEMENTS, &[0, 1, 2]).expect("eigen");
    let (_, axial) = split_modes(&an, 1);
    let exact = core::f64::consts::FRAC_PI_2 * (YOUNGS / DENSITY).sqrt() / LENGTH;
    let err = (axial - exact).abs() / exact;
    println!("fixed-free bar: FE {axial:.6} rad/s, exact {exact:.6} rad/s, rel err {err:.3e}");
    // First axial frequency of a fixed–free bar within 0.5 % of π/2·√(E/ρ)/L.
    assert!(err < 5e-3, "axial frequency off by {err:e}");
}

/// The classical consistent matrices of a Hermite beam element with an axial bar
/// (Przemieniecki): mass ρAL/420·[…] + rotary ρI/(30L)·[…] + axial ρAL/6·[2 1; 1 2],
/// stiffness EI/L³·[…] + EA/L·[1 −1; −1 1], over (u_A, v_A, θ_A, u_B, v_B, θ_B).
fn textbook_matrices(e: &BeamElement<f64>) -> (ElementMatrix<f64>, ElementMatrix<f64>) {
    let l = e.length_m;
    let (ra, ri) = (
        e.density_kg_m3 * e.area_m2,
        e.density_kg_m3 * e.second_moment_m4,
    );
    let (ea, ei) = (
        e.youngs_modulus_pa * e.area_m2,
        e.youngs_modulus_pa * e.second_moment_m4,
    );
    let bend_idx = [1usize, 2, 4, 5];
    let mt = [
        [156.0, 22.0 * l, 54.0, -13.0 * l],
        [22.0 * l, 4.0 * l * l, 13.0 * l, -3.0 * l * l],
        [54.0, 13.0 * l, 156.0, -22.0 * l],
        [-13.0 * l, -3.0 * l * l, -22.0 * l, 4.0 * l * l],
    ];
    let mr = [
        [36.0, 3.0 * l, -36.0, 3.0 * l],
        [3.0 * l, 4.0 * l * l, -3.0 * l, -l * l],
        [-36.0, -3.0 * l, 36.0, -3.0 * l],
        [3.0 * l, -l * l, -3.0 * l, 4.0 * l * l],
    ];
    let kb = [
        [12.0, 6.0 * l, -12.0, 6.0 * l],
        [6.0 * l, 4.0 * l * l, -6.0 * l, 2.0 * l * l],
        [-12.0, -6.0 * l, 12.0, -6.0 * l],
        [6.0 * l, 2.0 * l * l, -6.0 * l, 4.0 * l * l],
    ];
    let mut m = [[0.0; 6]; 6];
    let mut k = [[0.0; 6]; 6];
    for i in 0..4 {
        for j in 0..4 {
            m[bend_idx[i]][bend_idx[j]] = ra * l / 420.0 * mt[i][j] + ri / (30.0 * l) * mr[i][j];
            k[bend_idx[i]][bend_idx[j]] = ei / (l * l * l) * kb[i][j];
        }
    }
    let ax = [0usize, 3];
    for i in 0..2 {
        for j in 0..2 {
            m[ax[i]][ax[j]] = ra * l / 6.0 * if i == j { 2.0 } else { 1.0 };
            k[ax[i]][ax[j]] = ea / l * if i == j { 1.0 } else { -1.0 };
        }
    }
    (m, k)
}

/// Elements of very different proportions: the checks must hold for any A, I, ρ, E, L.
fn odd_elements() -> [BeamElement<f64>; 3] {
    [
        element(0.5),
        BeamElement {
            length_m: 1.911_325_943_5,
            area_m2: 0.045,
            second_moment_m4: 2.57e-3,
            density_kg_m3: 5750.0,
            youngs_modulus_pa: 2.0e11,
        },
        BeamElement {
            length_m: 0.298,
            area_m2: 0.026,
            second_moment_m4: 5.2e-4,
            density_kg_m3: 5750.0,
            youngs_modulus_pa: 2.0e11,
        },
    ]
}

#[test]
fn element_matrices_equal_the_textbook_consistent_matrices() {
    for e in odd_elements() {
        let (m, k) = (e.mass(), e.stiffness());
        let (mt, kt) = textbook_matrices(&e);
        let (mscale, kscale) = (
            mt.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs())),
            kt.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs())),
        );
        let (mut dm, mut dk) = (0.0f64, 0.0f64);
        for i in 0..6 {
            for j in 0..6 {
                dm = dm.max((m[i][j] - mt[i][j]).abs() / mscale);
                dk = dk.max((k[i][j] - kt[i][j]).abs() / kscale);
            }
        }
        println!(
            "L = {}: max |M − M_textbook|/max|M| = {dm:.2e}, K: {dk:.2e}",
            e.length_m
        );
        // Consistent mass with rotary inertia equals ρAL/420·[156 22L 54 −13L …] + ρI/(30L)·[36 3L −36 3L …] + ρAL/6·[2 1; 1 2] (Przemieniecki).
        assert!(
            dm < 1e-13,
            "mass matrix differs from the textbook by {dm:e}"
        );
        // Stiffness equals EI/L³·[12 6L −12 6L …] + EA/L·[1 −1; −1 1] (Przemieniecki).
        assert!(
            dk < 1e-13,
            "stiffness matrix differs from the textbook by {dk:e}"
        );
    }
}

#[test]
fn element_stiffness_annihilates_rigid_body_motions() {
    for e in odd_elements() {
        let (k, l) = (e.stiffness(), e.length_m);
        let kscale = k.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
        // Axial translation, transverse translation, small rigid rotation about node A (v = x·θ).
        let motions: [[f64; 6]; 3] = [
            [1.0, 0.0, 0.0, 1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0, 0.0, l, 1.0],
        ];
        for r in motions {
            let rnorm = r.iter().map(|x| x * x).sum::<f64>().sqrt();
            let f: Vec<f64> = (0..6)
                .map(|i| (0..6).map(|j| k[i][j] * r[j]).sum())
                .collect();
            let fmax = f.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            let rel = fmax / (kscale * rnorm);
            println!("L = {l}: rigid motion {r:?}: |K·r|/(|K|·|r|) = {rel:.2e}");
            // A rigid-body motion stores no strain energy: K·r = 0 to rounding.
            assert!(
                rel < 1e-13,
                "K does not annihilate rigid motion {r:?}: {rel:e}"
            );
        }
    }
}

#[test]
fn element_mass_is_symmetric_positive_definite_and_carries_the_element_mass() {
    for e in odd_elements() {
        let m = e.mass();
        let total = e.density_kg_m3 * e.area_m2 * e.length_m;
        let mm = SMatrix::<f64, 6, 6>::from_fn(|i, j| m[i][j]);
        let asym = (mm - mm.transpose()).amax() / mm.amax();
        // The consistent mass matrix is symmetric (∫ρφᵀφ dV).
        assert!(asym < 1e-15, "mass matrix not symmetric: {asym:e}");
        let eig = mm.symmetric_eigenvalues();
        let (lo, hi) = (eig.min(), eig.max());
        println!(
            "L = {}: mass eigenvalues in [{lo:.4e}, {hi:.4e}], element mass {total:.6}",
            e.length_m
        );
        // Positive definite: kinetic energy ½ẋᵀMẋ > 0 for every non-zero nodal velocity.
        assert!(
            lo > 0.0 && mm.cholesky().is_some(),
            "mass matrix not positive definite (λmin = {lo:e})"
        );
        for dirs in [[0usize, 3], [1, 4]] {
            let sum: f64 = dirs
                .iter()
                .flat_map(|&i| dirs.iter().map(move |&j| (i, j)))
                .map(|(i, j)| m[i][j])
                .sum();
            // A unit translation (u or v at both nodes) has kinetic mass ρAL: translational block sums to the element mass.
            assert!(
                (sum - total).abs() < 1e-13 * total,
                "translational mass {sum} ≠ ρAL = {total}"
            );
        }
    }
}

#[test]
fn element_first_moment_integrates_the_shape_functions() {
    for e in odd_elements() {
        let (a, l) = (e.first_moment(), e.length_m);
        let m = e.density_kg_m3 * e.area_m2 * l;
        // ∫ρA·(1−ξ, ξ) dx = ρAL/2 each; ∫ρA·(Hermite N1, N2, N3, N4) dx = ρAL·(1/2, L/12, 1/2, −L/12).
        let want = [
            [m / 2.0, 0.0, 0.0, m / 2.0, 0.0, 0.0],
            [0.0, m / 2.0, m * l / 12.0, 0.0, m / 2.0, -m * l / 12.0],
        ];
        for r in 0..2 {
            for c in 0..6 {
                // First moment of mass (thesis eq. 3.3, A) of each shape function, closed form.
                assert!(
                    (a[r][c] - want[r][c]).abs() < 1e-13 * m * l.max(1.0),
                    "first moment [{r}][{c}] = {} ≠ {}",
                    a[r][c],
                    want[r][c]
                );
            }
        }
    }
}

#[test]
fn assembled_uniform_beam_mass_and_stiffness_are_consistent() {
    let mesh = uniform_mesh(ELEMENTS);
    let asm = mesh.assemble().expect("assembly");
    let n = mesh.n_dof();
    let total = DENSITY * AREA * LENGTH;
    // Unit axial translation of every node: rᵀMr = ρAL, K·r = 0.
    let (mut mu, mut kmax, mut kscale) = (0.0, 0.0f64, 0.0f64);
    for i in 0..n {
        for j in 0..n {
            if i % DOF_PER_NODE == 0 && j % DOF_PER_NODE == 0 {
                mu += asm.mass.get(i, j);
            }
            kscale = kscale.max(asm.stiffness.get(i, j).abs());
        }
        let f: f64 = (0..n)
            .filter(|j| j % DOF_PER_NODE == 0)
            .map(|j| asm.stiffness.get(i, j))
            .sum();
        kmax = kmax.max(f.abs());
    }
    // Assembled mass of a uniform beam: a rigid axial translation carries ρAL.
    assert!(
        (mu - total).abs() < 1e-12 * total,
        "assembled axial mass {mu} ≠ {total}"
    );
    assert!(
        (mesh.mass_kg() - total).abs() < 1e-12 * total,
        "BeamMesh::mass_kg {} ≠ {total}",
        mesh.mass_kg()
    );
    // A rigid axial translation of the assembled beam stores no strain energy.
    assert!(
        kmax < 1e-12 * kscale,
        "assembled K·(axial translation) = {kmax:e}"
    );
}
