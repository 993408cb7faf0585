//! Verification of the boom's structural model: section properties, mass, modes,
//! modal reduction and damping (thesis §3.2, §4.3, Appendix A; SPEC §2–3).

use crane_model::multibody::CraneModel;
use crane_model::data::crane::CraneData;
use crane_model::structure::fe::DOF_PER_NODE;
use crane_model::structure::modal::{MeshRefinement, ModalAnalysis, ModeKind, THESIS_BASIS};
use crane_model::data::section::boom_section_at;

mod common;
use common::{dims_at, hollow};

/// ∫f dx over [a, b] by composite Simpson with `n` (even) intervals.
fn simpson(a: f64, b: f64, n: usize, f: impl Fn(f64) -> f64) -> f64 {
    let h = (b - a) / n as f64;
    let mut s = f(a) + f(b);
    for i in 1..n {
        s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(a + i as f64 * h);
    }
    s * h / 3.0
}

fn analysis() -> ModalAnalysis<f64> {
    ModalAnalysis::<f64>::new(&CraneData::coles_mobile_930(), MeshRefinement::THESIS)
        .expect("boom modes")
}

#[test]
fn section_properties_at_a0_g_and_c_match_hand_computation() {
    let crane = CraneData::coles_mobile_930();
    let b = &crane.boom;
    // Hand values (python, shoelace formula on the 8 vertices, inner edges − 2t·tan22.5°):
    // A0 (e, c, f) = (453.33, 200, 120) mm, G = (160, 440, 120), C = (160, 206.67, 120), t = 20 mm.
    let literal = [
        (0.0, 0.037_607_716_600_406_07, 9.166_173_471_115_667e-4),
        (2.0, 0.045_074_516_600_406_18, 2.567_936_814_942_474_4e-3),
        (19.5, 0.026_408_116_600_406_08, 5.174_556_397_357_219e-4),
    ];
    for (x, a_hand, i_hand) in literal {
        let model = boom_section_at(b, x);
        let (a_mine, i_mine) = hollow(dims_at(b, x), b.wall_m);
        println!("x = {x:5.2} m: A = {:.12e} m² (hand {a_hand:.12e}), I = {:.12e} m⁴ (hand {i_hand:.12e})", model.area_m2, model.second_moment_m4);
        // Area of the hollow octagon equals the shoelace area computed in this test (and the python literal).
        assert!(
            (model.area_m2 - a_mine).abs() < 1e-12 * a_mine
                && (model.area_m2 - a_hand).abs() < 1e-12 * a_hand
        );
        // Second moment for in-plane bending equals the shoelace I_x (and the python literal).
        assert!(
            (model.second_moment_m4 - i_mine).abs() < 1e-12 * i_mine
                && (model.second_moment_m4 - i_hand).abs() < 1e-12 * i_hand
        );
    }
    // Inner outline: the height shrinks by exactly 2t (inset edges − 2t·tan 22.5° are a uniform wall t).
    let d = crane.boom.section_at_g;
    let inner = d.inset(b.wall_m);
    assert!((d.height_m() - inner.height_m() - 2.0 * b.wall_m).abs() < 1e-15);
    assert!((d.width_m() - inner.width_m() - 2.0 * b.wall_m).abs() < 1e-15);
    // Thin-wall check of the area: A ≈ t·(mid-line perimeter) (exact for a polygon with uniform wall).
    let mid = d.inset(b.wall_m / 2.0);
    let perimeter = 2.0 * (mid.e_m + mid.f_m) + 4.0 * mid.c_m;
    assert!((boom_section_at(b, 2.0).area_m2 - b.wall_m * perimeter).abs() < 1e-12);
}

#[test]
fn assembled_boom_mass_equals_density_times_integral_of_area() {
    let crane = CraneData::coles_mobile_930();
    let b = &crane.boom;
    let area = |x: f64| hollow(dims_at(b, x), b.wall_m).0;
    // A(x) is quadratic on each of A0–G and G–C, so Simpson per piece is exact.
    let (l, g) = (b.length_m(), b.foot_to_g_m);
    let mass = b.density_kg_m3 * (simpson(0.0, g, 200, area) + simpson(g, l, 2000, area));
    let first = b.density_kg_m3
        * (simpson(0.0, g, 200, |x| area(x) * x) + simpson(g, l, 2000, |x| area(x) * x));
    let an = analysis();
    let mesh_mass = an.mesh.mass_kg();
    let rel = (mesh_mass - mass).abs() / mass;
    println!("boom mass: mesh {mesh_mass:.9} kg, ρ∫A dx = {mass:.9} kg, rel {rel:.2e}");
    // Boom mass = ρ·∫A dx (the mesh uses each element's exact mean section, SPEC §3).
    assert!(rel < 1e-12, "boom mass off by {rel:e}");
    let modes = an.reduce(&THESIS_BASIS, 0.02).expect("reduce");
    // The reduced model carries the same mass (eq. 3.1).
    assert!((modes.mass_kg - mass).abs() < 1e-12 * mass);
    // Centre of mass: the mesh lumps each element's mass uniformly, so its centre is
    // Σ m_e·x_mid,e / m exactly; the continuous ρ∫A·x dx / m differs by O(h²) only.
    let mut lumped = 0.0;
    for k in 0..an.mesh.elements().len() {
        let (xa, xb) = (an.mesh.node_x(k), an.mesh.node_x(k + 1));
        lumped += b.density_kg_m3 * simpson(xa, xb, 2, area) * (xa + xb) / 2.0;
    }
    let (com, com_exact, com_mesh) = (an.centre_of_mass_m(), first / mass, lumped / mass);
    println!("centre of mass: model {com:.6} m, mesh Σm·x_mid {com_mesh:.6} m, continuous {com_exact:.6} m");
    // Centre of mass of the meshed boom (first moment A·e0 / m, eq. 3.3) equals Σ m_e·x_mid,e / m.
    assert!((com - com_mesh).abs() < 1e-12 * com_mesh);
    // …and is within 0.1 % of the continuous boom's (uniform-section elements 1.9 m long shift it by ~7 mm).
    assert!(
        (com - com_exact).abs() < 1e-3 * com_exact,
        "centre of mass {com} vs continuous {com_exact}"
    );
    // The rotary inertia about A0 of the reduced model (e0ᵀMe0, eq. 3.5) is the mesh's ∫ρA·x² dx
    // for uniform elements plus ρI·L per element (rotary part); compute it element by element.
    let mut inertia = 0.0;
    for k in 0..an.mesh.elements().len() {
        let e = an.mesh.elements()[k];
        let (xa, xb) = (an.mesh.node_x(k), an.mesh.node_x(k + 1));
        let m = e.density_kg_m3 * e.area_m2;
        inertia += m * (xb * xb * xb - xa * xa * xa) / 3.0;
    }
    println!(
        "inertia about A0: model {:.6} kg·m², Σ ρĀ∫x² dx = {inertia:.6} kg·m²",
        modes.inertia_rest
    );
    // e0 is an axial field (u = x), whose consistent axial mass reproduces ∫ρĀ x² dx exactly (linear shape functions).
    assert!((modes.inertia_rest - inertia).abs() < 1e-12 * inertia);
}

/// The retained thesis modes as mode indices of the analysis.
fn retained(an: &ModalAnalysis<f64>) -> [usize; 4] {
    THESIS_BASIS.map(|c| an.find(c).expect("thesis mode"))
}

#[test]
fn retained_modes_are_mass_orthonormal_and_diagonalize_stiffness() {
    let an = analysis();
    let n = an.mesh.n_dof();
    // All constrained modes, the four retained ones among them.
    let modes: Vec<usize> = (0..an.mode_count()).collect();
    let cols = retained(&an);
    let (mut err_m, mut err_k, mut err_m_all, mut err_k_all) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for &i in &modes {
        for &j in &modes {
            let (mut xm, mut xk) = (0.0, 0.0);
            for a in 0..n {
                let xa = an.shape(a, i);
                for b in 0..n {
                    xm += xa * an.mass.get(a, b) * an.shape(b, j);
                    xk += xa * an.stiffness.get(a, b) * an.shape(b, j);
                }
            }
            let dm = xm - if i == j { 1.0 } else { 0.0 };
            let wi = an.frequency_rad_s(i);
            let wj = an.frequency_rad_s(j);
            let dk = (xk - if i == j { wi * wi } else { 0.0 }) / (wi * wj);
            err_m_all += dm * dm;
            err_k_all = err_k_all.max(dk.abs());
            if cols.contains(&i) && cols.contains(&j) {
                err_m += dm * dm;
                err_k = err_k.max(dk.abs());
            }
        }
    }
    let (err_m, err_m_all) = (err_m.sqrt(), err_m_all.sqrt());
    println!("retained: ‖XᵀMX − I‖_F = {err_m:.2e}, max |XᵀKX − diag ω²|/(ωᵢωⱼ) = {err_k:.2e}");
    println!(
        "all {} modes: ‖XᵀMX − I‖_F = {err_m_all:.2e}, max rel K error = {err_k_all:.2e}",
        modes.len()
    );
    // Mass-normalized modes (χᵀMχ = I, so M_ηη = I in eq. 3.8): Frobenius error below 1e-9.
    assert!(
        err_m < 1e-9,
        "retained modes not mass-orthonormal: {err_m:e}"
    );
    // Modal stiffness χᵀKχ = diag(ω²) (eq. 2.52): every entry within 1e-9 of ωᵢωⱼ.
    assert!(err_k < 1e-9, "XᵀKX not diag(ω²): {err_k:e}");
    // The same for every constrained mode (the whole eigen-decomposition).
    assert!(err_m_all < 1e-9 && err_k_all < 1e-9);
    // Shapes vanish at the fixed dof (x, y at A0; v, θ at A: the thesis's boundary conditions).
    let lug = an.lug_node;
    for &k in &modes {
        for d in [0, 1, DOF_PER_NODE * lug + 1, DOF_PER_NODE * lug + 2] {
            assert_eq!(an.shape(d, k), 0.0);
        }
    }
}

/// Shares of a mode's Euclidean size in (axial, bending of A0–A, bending of A–C),
/// computed here from the shapes, independently of modal.rs's classifier.
fn shares(an: &ModalAnalysis<f64>, k: usize) -> (f64, f64, f64) {
    let (mut ax, mut left, mut right) = (0.0, 0.0, 0.0);
    for d in 0..an.mesh.n_dof() {
        let x = an.shape(d, k) * an.shape(d, k);
        if d % DOF_PER_NODE == 0 {
            ax += x;
        } else if d / DOF_PER_NODE <= an.lug_node {
            left += x;
        } else {
            right += x;
        }
    }
    let t = ax + left + right;
    (ax / t, left / t, right / t)
}

#[test]
fn thesis_basis_is_longitudinal_bending_foot_and_two_bending_tip_modes() {
    let an = analysis();
    let cols = retained(&an);
    let want = [
        (1, "longitudinal"),
        (2, "bending A0-A"),
        (3, "bending A-C"),
        (3, "bending A-C"),
    ];
    for (i, (&k, (which, label))) in cols.iter().zip(want.iter()).enumerate() {
        let (ax, left, right) = shares(&an, k);
        println!("retained {i}: mode {k}, ω = {:.4} rad/s, {label}: shares axial {ax:.2e}, A0–A {left:.2e}, A–C {right:.2e}", an.frequency_rad_s(k));
        let pure = match which {
            1 => ax,
            2 => left,
            _ => right,
        };
        // The mode lives entirely in one part/direction (the straight boom decouples axial and bending; the clamp at A splits A0–A from A–C).
        assert!(
            pure > 1.0 - 1e-12,
            "retained mode {i} is not pure {label}: {ax:e} {left:e} {right:e}"
        );
        assert_eq!(an.kind(k).label(), *label);
    }
    // Ordinals: the two A–C modes are the first and second of their kind, and nothing
    // of a retained kind lies below the chosen one (first longitudinal, first A0–A bending).
    for (choice, &k) in THESIS_BASIS.iter().zip(cols.iter()) {
        let below = (0..k).filter(|&j| an.kind(j) == choice.kind).count();
        assert_eq!(below, choice.ordinal);
    }
    // The lowest modes of the constrained boom are the A–C cantilever bending modes
    // (the overhang A–C is 13.7 m long and slender), so the first retained bending of A–C is mode 0.
    assert_eq!(cols[2], 0);
    assert_eq!(an.kind(0), ModeKind::BendingLugToTip);
    // Order of magnitude of the first A–C bending: a uniform cantilever of the overhang with the
    // section at its middle gives 1.875²/L²·√(EI/ρA); the taper stiffens the root, so the FE value is higher, within 2×.
    let b = CraneData::coles_mobile_930().boom;
    let l_over = b.length_m() - b.foot_to_lug_m;
    let (a_mid, i_mid) = hollow(dims_at(&b, b.foot_to_lug_m + l_over / 2.0), b.wall_m);
    let w_uniform = 1.875_104f64.powi(2) / (l_over * l_over)
        * (b.youngs_modulus_pa * i_mid / (b.density_kg_m3 * a_mid)).sqrt();
    let w0 = an.frequency_rad_s(0);
    println!(
        "first A–C bending: FE {w0:.3} rad/s, uniform-cantilever estimate {w_uniform:.3} rad/s"
    );
    assert!(w0 > w_uniform && w0 < 2.0 * w_uniform);
}

/// Measured (this machine): ω of the first A–C bending 26.170 rad/s in f32 against
/// 25.275 in f64 (3.5e-2); second A–C bending 1.3e-3; longitudinal 2.6e-5; A0–A 1.9e-6.
/// Not a test-design problem: rounding the f64-assembled K and M to f32 and solving in
/// f64 already moves ω₁ by 7.9e-4 (K's ω²max/ω²min ≈ 1.7e7), and the f32 Cholesky(M) +
/// Jacobi solve (absolute eigenvalue error ~ ε·λmax ≈ 650 rad²/s² against λ₁ = 639)
/// adds the rest. The f32 model must take its modes from the f64 analysis (BoomModes::cast).
#[test]
// The structural analysis runs in f64 and is shipped to the f32 controller as
// constants (`CraneModel::build`, `thesis_modes::THESIS_MODES_F32`): an f32
// eigen-solve cannot hold K, whose eigenvalues span 1.7e7 (measured: ω₁ 3.5 % off).
fn f32_and_f64_give_the_same_retained_frequencies() {
    let crane = CraneData::coles_mobile_930();
    let m64 = ModalAnalysis::<f64>::new(&crane, MeshRefinement::THESIS)
        .expect("f64 modes")
        .reduce(&THESIS_BASIS, 0.02)
        .expect("reduce f64");
    let built = CraneModel::<f32, 4>::build(&crane, MeshRefinement::THESIS, &THESIS_BASIS).expect("f32 model");
    for (name, m32) in [("CraneModel::<f32>::build", built.modes), ("THESIS_MODES_F32", crane_model::loads::thesis_modes::THESIS_MODES_F32)] {
        let mut worst = 0.0f64;
        for k in 0..4 {
            let (w64, w32) = (m64.omega_rad_s[k], m32.omega_rad_s[k] as f64);
            worst = worst.max((w32 - w64).abs() / w64);
            assert_eq!(m32.kinds[k], m64.kinds[k]);
        }
        // The f32 (MCU) model and the f64 (host) analysis have the same retained ω within 1e-4.
        assert!(worst < 1e-4, "{name}: f32 retained frequencies differ by {worst:e}");
    }
}

#[test]
fn rayleigh_damping_gives_two_percent_at_the_two_lowest_retained_modes() {
    let an = analysis();
    let modes = an.reduce(&THESIS_BASIS, 0.02).expect("reduce");
    let mut order: Vec<usize> = (0..4).collect();
    order.sort_by(|&a, &b| modes.omega_rad_s[a].total_cmp(&modes.omega_rad_s[b]));
    for (rank, &k) in order.iter().enumerate() {
        let w = modes.omega_rad_s[k];
        let zeta = modes.damping[k] / (2.0 * w);
        println!("ω = {w:9.4} rad/s: ζ = {zeta:.6}");
        // Modal damping χᵀCχ = α + βω² with C = αM + βK (eq. 2.54).
        assert!(
            (modes.damping[k] - (modes.rayleigh_alpha + modes.rayleigh_beta * w * w)).abs()
                < 1e-12 * modes.damping[k]
        );
        if rank < 2 {
            // ζ = 2 % exactly at the two lowest retained frequencies (eqs. 2.55–2.56, thesis §4.3).
            assert!((zeta - 0.02).abs() < 1e-12, "ζ = {zeta} at ω = {w}");
        } else {
            // Rayleigh damping grows above the upper anchor frequency: ζ > 2 % there.
            assert!(zeta > 0.02);
        }
    }
    // Both coefficients positive (a physically dissipative C).
    assert!(modes.rayleigh_alpha > 0.0 && modes.rayleigh_beta > 0.0);
}

#[test]
fn retained_frequencies_converge_with_mesh_refinement() {
    let crane = CraneData::coles_mobile_930();
    let coarse = ModalAnalysis::<f64>::new(&crane, MeshRefinement::THESIS).expect("12 elements");
    let fine = ModalAnalysis::<f64>::new(
        &crane,
        MeshRefinement {
            elements_foot_to_g: 4,
            elements_g_to_lug: 4,
        },
    )
    .expect("finer mesh");
    println!(
        "meshes: {} and {} elements",
        coarse.mesh.elements().len(),
        fine.mesh.elements().len()
    );
    for c in THESIS_BASIS {
        let (w12, wf) = (
            coarse.frequency_rad_s(coarse.find(c).unwrap()),
            fine.frequency_rad_s(fine.find(c).unwrap()),
        );
        let rel = (w12 - wf).abs() / wf;
        println!(
            "{} #{}: 12 el {w12:.4}, fine {wf:.4} rad/s, rel {rel:.2e}",
            c.kind.label(),
            c.ordinal
        );
        // The thesis's 12 elements resolve each retained frequency within 2 % of the refined mesh.
        assert!(rel < 0.02);
    }
}
