//! `crane-sim modes [--json]`: the boom's mass and modes (SPEC §5).

use crane_model::structure::modal::{MeshRefinement, ModalAnalysis, THESIS_BASIS};
use crane_model::CraneData;
use serde::Serialize;
use std::io::Write;

/// Arguments of `crane-sim modes`.
#[derive(clap::Args, Debug)]
pub struct ModesArgs {
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
    /// Elements between A0 and G (thesis: 2).
    #[arg(long, default_value_t = 2)]
    elements_foot_to_g: usize,
    /// Elements between G and A (thesis: 2, giving 12 elements in all).
    #[arg(long, default_value_t = 2)]
    elements_g_to_lug: usize,
}

#[derive(Serialize)]
struct ModeRow {
    kind: &'static str,
    omega_rad_s: f64,
    frequency_hz: f64,
}

#[derive(Serialize)]
struct ModesReport {
    elements: usize,
    boom_mass_kg: f64,
    centre_of_mass_from_a0_m: f64,
    rayleigh_alpha_per_s: f64,
    rayleigh_beta_s: f64,
    retained: Vec<ModeRow>,
    lowest_constrained: Vec<ModeRow>,
}

fn row(kind: &'static str, omega: f64) -> ModeRow {
    ModeRow {
        kind,
        omega_rad_s: omega,
        frequency_hz: omega / (2.0 * std::f64::consts::PI),
    }
}

/// One table of modes: number, kind, ω, f.
fn write_table(out: &mut impl Write, title: &str, rows: &[ModeRow]) -> std::io::Result<()> {
    writeln!(out, "\n{title}")?;
    writeln!(out, "  {:>2}  {:<14} {:>12} {:>10}", "#", "kind", "omega rad/s", "f Hz")?;
    for (i, m) in rows.iter().enumerate() {
        writeln!(out, "  {:>2}  {:<14} {:>12.3} {:>10.3}", i + 1, m.kind, m.omega_rad_s, m.frequency_hz)?;
    }
    Ok(())
}

/// Runs the subcommand; returns the exit code.
pub fn run(args: ModesArgs) -> anyhow::Result<u8> {
    let crane = CraneData::coles_mobile_930();
    let refinement = MeshRefinement {
        elements_foot_to_g: args.elements_foot_to_g,
        elements_g_to_lug: args.elements_g_to_lug,
    };
    let analysis = ModalAnalysis::<f64>::new(&crane, refinement)
        .map_err(|e| anyhow::anyhow!("modal analysis failed: {e}"))?;
    let modes = analysis
        .reduce(&THESIS_BASIS, crane.boom.damping_ratio)
        .map_err(|e| anyhow::anyhow!("mode selection failed: {e}"))?;
    let report = ModesReport {
        elements: analysis.mesh.elements().len(),
        boom_mass_kg: modes.mass_kg,
        centre_of_mass_from_a0_m: analysis.centre_of_mass_m(),
        rayleigh_alpha_per_s: modes.rayleigh_alpha,
        rayleigh_beta_s: modes.rayleigh_beta,
        retained: modes
            .kinds
            .iter()
            .zip(modes.omega_rad_s.iter())
            .map(|(k, &w)| row(k.label(), w))
            .collect(),
        lowest_constrained: (0..analysis.mode_count().min(10))
            .map(|k| row(analysis.kind(k).label(), analysis.frequency_rad_s(k)))
            .collect(),
    };
    // A closed stdout (`| head`) ends the output quietly; other write
    // errors are errors (`crate::stdout`).
    let mut out = crate::stdout::stdout();
    if args.json {
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
        out.flush()?;
        return Ok(0);
    }
    writeln!(out, "Boom (body 1) of the COLES Mobile 930, {} elements", report.elements)?;
    writeln!(out, "  mass                 {:10.2} kg", report.boom_mass_kg)?;
    writeln!(out, "  centre of mass       {:10.4} m from A0", report.centre_of_mass_from_a0_m)?;
    writeln!(
        out,
        "  Rayleigh damping     alpha = {:.5} 1/s, beta = {:.4e} s (zeta = 2 % at the two lowest retained modes)",
        report.rayleigh_alpha_per_s, report.rayleigh_beta_s
    )?;
    write_table(&mut out, "Retained modes (thesis basis)", &report.retained)?;
    write_table(&mut out, "Lowest constrained modes of the boom (A0 pinned, A clamped)", &report.lowest_constrained)?;
    out.flush()?;
    Ok(0)
}
