//! `crane-sim simulate`: one boom maneuver of the thesis (SPEC §5).

use crate::model::thesis_model;
use crate::plot::{write_figure, Panel, Series, PALETTE};
use anyhow::{bail, Context, Result};
use crane_model::profile::RampShape;
use crane_model::simulation::{
    thesis_cases, Direction, InitialState, Maneuver, Sample, SimulationOptions,
};
use std::io::Write;
use std::path::PathBuf;

/// Ramp shape on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum ProfileArg {
    /// Linear acceleration and deceleration (eq. 3.48).
    Linear,
    /// Cycloidal acceleration and deceleration (eq. 3.47).
    Cycloidal,
}

/// Direction on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum DirectionArg {
    /// 40° → 80°.
    Up,
    /// 80° → 40°.
    Down,
}

/// Initial state on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum InitialArg {
    /// Static deflection projected in the energy norm (the reduced model's equilibrium).
    Equilibrium,
    /// The listing's Euclidean least-squares projection.
    Listing,
}

/// Arguments of `crane-sim simulate`.
#[derive(clap::Args, Debug)]
pub struct SimulateArgs {
    /// A thesis case by name (see --list); overrides the four flags below.
    #[arg(long)]
    pub case: Option<String>,
    /// List the twelve thesis cases and exit.
    #[arg(long)]
    pub list: bool,
    /// Hook load W (kg).
    #[arg(long, default_value_t = 3300.0)]
    pub load_kg: f64,
    /// Duration of the motion: 30 or 10 (s).
    #[arg(long, default_value_t = 30.0)]
    pub duration: f64,
    /// Velocity profile of the piston.
    #[arg(long, value_enum, default_value = "cycloidal")]
    pub profile: ProfileArg,
    /// Boom up (40° → 80°) or down (80° → 40°).
    #[arg(long, value_enum, default_value = "up")]
    pub direction: DirectionArg,
    /// Time step (ms).
    #[arg(long, default_value_t = 2.0)]
    pub step_ms: f64,
    /// Output every this many steps.
    #[arg(long, default_value_t = 5)]
    pub output_every: usize,
    /// How the run starts.
    #[arg(long, value_enum, default_value = "equilibrium")]
    pub initial: InitialArg,
    /// Write the samples as CSV.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Draw piston force, deflections and F_A against boom angle: PNG if FILE
    /// ends in .png, SVG if it ends in .svg.
    #[arg(long)]
    pub plot: Option<PathBuf>,
}

/// The CSV header (SPEC §5 columns first).
pub const CSV_HEADER: &str = "t_s,boom_angle_deg,piston_force_n,node3_defl_m,node8_defl_m,node13_defl_m,jack_reaction_n,swing_deg,constraint_violation";

/// One CSV row.
pub fn csv_row(s: &Sample<f64>) -> String {
    format!(
        "{:.4},{:.6},{:.3},{:.6e},{:.6e},{:.6e},{:.3},{:.6},{:.3e}",
        s.t_s,
        s.boom_angle_rad.to_degrees(),
        s.reactions.piston_force_n,
        s.deflection_m[0],
        s.deflection_m[1],
        s.deflection_m[2],
        s.reactions.jack_reaction_n,
        s.swing_rad.to_degrees(),
        s.constraint_violation
    )
}

/// Resolves the maneuver from the arguments.
pub fn maneuver(args: &SimulateArgs) -> Result<(String, Maneuver)> {
    if let Some(name) = &args.case {
        return thesis_cases()
            .into_iter()
            .find(|(n, _)| n == name)
            .map(|(n, m)| (n.to_string(), m))
            .with_context(|| format!("unknown case '{name}'; `crane-sim simulate --list` shows the twelve thesis cases"));
    }
    if args.duration != 30.0 && args.duration != 10.0 {
        bail!("--duration must be 30 or 10 (s), got {}", args.duration);
    }
    let shape = match args.profile {
        ProfileArg::Linear => RampShape::Linear,
        ProfileArg::Cycloidal => RampShape::Cycloidal,
    };
    let direction = match args.direction {
        DirectionArg::Up => Direction::Up,
        DirectionArg::Down => Direction::Down,
    };
    let m = Maneuver::thesis(args.load_kg, args.duration, shape, direction)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    Ok((
        format!(
            "{} kg, {} s, {:?}, {:?}",
            args.load_kg, args.duration, shape, direction
        ),
        m,
    ))
}

/// Runs a maneuver and collects its samples.
pub fn run_maneuver(
    m: &Maneuver,
    options: &SimulationOptions,
) -> Result<(Vec<Sample<f64>>, crane_model::simulation::RunSummary<f64>)> {
    let model = thesis_model()?;
    let mut samples = Vec::new();
    let summary = model
        .simulate(m, options, |s| {
            samples.push(*s);
            true
        })
        .map_err(|e| anyhow::anyhow!("simulation failed: {e}"))?;
    Ok((samples, summary))
}

/// Draws the thesis's figures for a run (piston force, deflections, F_A
/// against boom angle), SVG or PNG by the file's extension. Node 3 (between
/// A0 and A, tens of µm) has its own panel in µm: on the tip's millimetre
/// axis it would be a flat line.
pub fn plot_run(path: &std::path::Path, title: &str, samples: &[Sample<f64>]) -> Result<()> {
    let series = |f: &dyn Fn(&Sample<f64>) -> f64| -> Vec<(f64, f64)> {
        samples.iter().map(|s| (s.boom_angle_rad.to_degrees(), f(s))).collect()
    };
    let force = series(&|s| s.reactions.piston_force_n / 1e3);
    let d3 = series(&|s| s.deflection_m[0] * 1e6);
    let d8 = series(&|s| s.deflection_m[1] * 1e3);
    let d13 = series(&|s| s.deflection_m[2] * 1e3);
    let fa = series(&|s| s.reactions.jack_reaction_n / 1e3);
    let t1 = format!("Piston force vs boom angle — {title}");
    let t2 = format!("Transverse deflection of nodes 8 and 13 (tip) — {title}");
    let t3 = format!("Transverse deflection of node 3 (between A0 and A) — {title}");
    let t4 = format!("Rear-jack reaction F_A (eq. 4.2) — {title}");
    write_figure(
        path,
        &[
            Panel::new(&t1, "boom angle θ1 (deg)", "piston force (kN)", vec![Series::line("piston force F (eq. 4.1)", &force)]),
            Panel::new(
                &t2,
                "boom angle θ1 (deg)",
                "deflection (mm)",
                vec![Series::line("node 8", &d8).color(PALETTE[1]), Series::line("node 13 (tip C)", &d13).color(PALETTE[2])],
            ),
            Panel::new(&t3, "boom angle θ1 (deg)", "deflection (µm)", vec![Series::line("node 3", &d3).color(PALETTE[0])]),
            Panel::new(&t4, "boom angle θ1 (deg)", "F_A (kN)", vec![Series::line("F_A (crane tips at 0)", &fa).color(PALETTE[3])]),
        ],
    )
}

/// Runs the subcommand; returns the exit code.
pub fn run(args: SimulateArgs) -> Result<u8> {
    if args.list {
        let mut out = crate::stdout::stdout();
        for (name, _) in thesis_cases() {
            writeln!(out, "{name}")?;
        }
        out.flush()?;
        return Ok(0);
    }
    let (title, m) = maneuver(&args)?;
    if !(args.step_ms > 0.0 && args.step_ms <= 100.0) || args.output_every == 0 {
        bail!("--step-ms must be in (0, 100] and --output-every ≥ 1");
    }
    let mut options = SimulationOptions::for_type::<f64>();
    options.step_s = args.step_ms * 1e-3;
    options.output_every = args.output_every;
    options.initial = match args.initial {
        InitialArg::Equilibrium => InitialState::Equilibrium,
        InitialArg::Listing => InitialState::ListingProjection,
    };
    let started = std::time::Instant::now();
    let (samples, summary) = run_maneuver(&m, &options)?;
    let elapsed = started.elapsed();
    if let Some(path) = &args.out {
        let mut f = std::io::BufWriter::new(
            std::fs::File::create(path)
                .with_context(|| format!("cannot create {}", path.display()))?,
        );
        writeln!(f, "{CSV_HEADER}")?;
        for s in &samples {
            writeln!(f, "{}", csv_row(s))?;
        }
        f.flush()?;
    }
    if let Some(path) = &args.plot {
        plot_run(path, &title, &samples)?;
    }
    let peak = samples
        .iter()
        .map(|s| s.reactions.piston_force_n)
        .fold(f64::MIN, f64::max);
    let min_fa = samples
        .iter()
        .map(|s| s.reactions.jack_reaction_n)
        .fold(f64::MAX, f64::min);
    let max_tip = samples
        .iter()
        .map(|s| s.deflection_m[2].abs())
        .fold(0.0, f64::max);
    let mut out = crate::stdout::stdout();
    writeln!(out, "maneuver          {title}")?;
    writeln!(
        out,
        "integrator        Newmark average acceleration, h = {} ms, {} steps, {} evaluations",
        args.step_ms, summary.steps, summary.evaluations
    )?;
    writeln!(
        out,
        "wall time         {:.1} ms ({:.0}x faster than real time)",
        elapsed.as_secs_f64() * 1e3,
        m.end_s() / elapsed.as_secs_f64()
    )?;
    writeln!(out, "peak piston force {:.1} kN", peak / 1e3)?;
    writeln!(out, "max |tip defl.|   {:.2} mm", max_tip * 1e3)?;
    writeln!(
        out,
        "min F_A           {:.1} kN{}",
        min_fa / 1e3,
        if min_fa <= 0.0 { "  (TIPS)" } else { "" }
    )?;
    writeln!(
        out,
        "max |constraint|  {:.2e}",
        summary.max_constraint_violation
    )?;
    out.flush()?;
    Ok(0)
}
