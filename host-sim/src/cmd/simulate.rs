//! `crane-sim simulate`: one boom maneuver (SPEC §5): a thesis case, any luffing
//! move, a lift-off or a maneuver file, with the thesis or the held rope.

use crate::model::thesis_model;
use crate::plot::{write_figure, Panel, Series, PALETTE};
use anyhow::{bail, Context, Result};
use crane_model::data::profile::RampShape;
use crane_model::multibody::rope::RopeChoice;
use crane_model::sim::simulation::{
    thesis_cases, Direction, InitialState, Maneuver, Program, Sample, Segment, SimulationOptions,
};
use crate::maneuver_file;
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
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
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

/// Rope mode on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum RopeArg {
    /// Paid out to keep the load 1 m above the ground (thesis assumption vi).
    Thesis,
    /// Constant hanging length, the winch braked (SPEC §3).
    Held,
}

/// The maneuver on the command line, shared by `simulate` and `synth`.
#[derive(clap::Args, Debug, Clone)]
pub struct ManeuverArgs {
    /// A thesis case by name (see `simulate --list`); the rope, hold and lift-off flags still apply.
    #[arg(long)]
    pub case: Option<String>,
    /// A session of segments (hold, luff, lift-off) from a TOML or JSON file (docs/maneuvers.md).
    #[arg(long, conflicts_with_all = ["case", "from_deg", "to_deg"])]
    pub maneuver: Option<PathBuf>,
    /// Hook load W (kg).
    #[arg(long, default_value_t = 3300.0)]
    pub load_kg: f64,
    /// Duration of the motion (s): 30 or 10 for the thesis moves, any ≥ 2 s with --from-deg/--to-deg.
    #[arg(long, default_value_t = 30.0)]
    pub duration: f64,
    /// Velocity profile of the piston.
    #[arg(long, value_enum, default_value = "cycloidal")]
    pub profile: ProfileArg,
    /// Boom up (40° → 80°) or down (80° → 40°) (the thesis moves; ignored with --from-deg).
    #[arg(long, value_enum, default_value = "up")]
    pub direction: DirectionArg,
    /// Start angle of a luffing move (deg); alone (without --to-deg): stay there for --duration.
    #[arg(long)]
    pub from_deg: Option<f64>,
    /// End angle of a luffing move (deg).
    #[arg(long, requires = "from_deg")]
    pub to_deg: Option<f64>,
    /// Acceleration and deceleration ramps (s); default 1.5 s for moves ≥ 20 s, 1 s from 10 s, a tenth below.
    #[arg(long)]
    pub ramp_s: Option<f64>,
    /// Time at rest before the move (s).
    #[arg(long, default_value_t = 0.0)]
    pub hold_before_s: f64,
    /// Time at rest after the move (s); default 0.3 s (the listing's).
    #[arg(long)]
    pub hold_after_s: Option<f64>,
    /// Rope: `thesis` (paid out, load kept 1 m up) or `held` (constant length).
    #[arg(long, value_enum)]
    pub rope: Option<RopeArg>,
    /// Hanging length of the held rope (m); default: the load 1 m above the ground at the start.
    #[arg(long)]
    pub rope_length_m: Option<f64>,
    /// Lift the load off the ground at the start angle first, over this many seconds (the hook load rises from 0 to W).
    #[arg(long)]
    pub lift_off_s: Option<f64>,
}

/// Arguments of `crane-sim simulate`.
#[derive(clap::Args, Debug)]
pub struct SimulateArgs {
    /// The maneuver.
    #[command(flatten)]
    pub maneuver: ManeuverArgs,
    /// List the twelve thesis cases and exit.
    #[arg(long)]
    pub list: bool,
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
pub const CSV_HEADER: &str = "t_s,boom_angle_deg,piston_force_n,node3_defl_m,node8_defl_m,node13_defl_m,jack_reaction_n,swing_deg,constraint_violation,rope_tension_n,hook_load_kg";

/// One CSV row.
pub fn csv_row(s: &Sample<f64>) -> String {
    format!(
        "{:.4},{:.6},{:.3},{:.6e},{:.6e},{:.6e},{:.3},{:.6},{:.3e},{:.3},{:.3}",
        s.t_s,
        s.boom_angle_rad.to_degrees(),
        s.reactions.piston_force_n,
        s.deflection_m[0],
        s.deflection_m[1],
        s.deflection_m[2],
        s.reactions.jack_reaction_n,
        s.swing_rad.to_degrees(),
        s.constraint_violation,
        s.rope_tension_n,
        s.hook_load_kg
    )
}

/// The rope the command line asks for, if it asks.
pub fn rope_choice(args: &ManeuverArgs) -> Result<Option<RopeChoice>> {
    let name = match (args.rope, args.rope_length_m) {
        (None, None) => return Ok(None),
        (Some(RopeArg::Thesis), _) => "thesis",
        (Some(RopeArg::Held), _) | (None, Some(_)) => "held",
    };
    Ok(Some(maneuver_file::rope(Some(name), args.rope_length_m)?))
}

/// Resolves a single luffing move (thesis case, thesis flags or --from-deg/--to-deg)
/// from the arguments, without rope, holds or lift-off.
pub fn maneuver(args: &ManeuverArgs) -> Result<(String, Maneuver)> {
    if let Some(name) = &args.case {
        return thesis_cases()
            .into_iter()
            .find(|(n, _)| n == name)
            .map(|(n, m)| (n.to_string(), m))
            .with_context(|| format!("unknown case '{name}'; `crane-sim simulate --list` shows the twelve thesis cases"));
    }
    let shape = match args.profile {
        ProfileArg::Linear => RampShape::Linear,
        ProfileArg::Cycloidal => RampShape::Cycloidal,
    };
    if !(args.duration >= 2.0 && args.duration <= 3600.0) {
        bail!("--duration must be in [2, 3600] s, got {}", args.duration);
    }
    let ramp = args.ramp_s.unwrap_or_else(|| maneuver_file::default_ramp_s(args.duration));
    let thesis_duration = args.duration == 30.0 || args.duration == 10.0;
    let (title, m) = match (args.from_deg, args.to_deg) {
        (Some(a), Some(b)) => (
            format!("{} kg, {a}° → {b}° in {} s, {:?}, ramps {ramp} s", args.load_kg, args.duration, shape),
            Maneuver::luff(args.load_kg, a, b, args.duration, ramp, shape),
        ),
        (Some(_), None) => bail!("--from-deg without --to-deg holds the boom still: use it with --lift-off-s or a maneuver file"),
        _ => {
            let direction = match args.direction {
                DirectionArg::Up => Direction::Up,
                DirectionArg::Down => Direction::Down,
            };
            let title = format!("{} kg, {} s, {:?}, {:?}", args.load_kg, args.duration, shape, direction);
            let m = if thesis_duration && args.ramp_s.is_none() {
                Maneuver::thesis(args.load_kg, args.duration, shape, direction)
            } else {
                let (a, b) = if direction == Direction::Up { (40.0, 80.0) } else { (80.0, 40.0) };
                Maneuver::luff(args.load_kg, a, b, args.duration, ramp, shape).map(|m| Maneuver { settle_s: 0.3, ..m })
            };
            (title, m)
        }
    };
    Ok((title, m.map_err(|e| anyhow::anyhow!("{e}"))?))
}

/// The whole program of the arguments: a maneuver file, or the luffing move with
/// its holds, rope and lift-off. Returns a title, the program and the move's
/// hook load.
pub fn program(args: &ManeuverArgs) -> Result<(String, Program)> {
    let rope = rope_choice(args)?;
    if let Some(path) = &args.maneuver {
        let file = maneuver_file::ManeuverFile::read(path)?;
        let p = file.program(rope).with_context(|| format!("in maneuver file {}", path.display()))?;
        return Ok((format!("maneuver {}", path.display()), p));
    }
    if !(args.hold_before_s >= 0.0 && args.hold_before_s <= 3600.0) {
        bail!("--hold-before-s must be in [0, 3600] s");
    }
    if let Some(h) = args.hold_after_s {
        if !(0.0..=3600.0).contains(&h) {
            bail!("--hold-after-s must be in [0, 3600] s");
        }
    }
    let ctx = |e: crane_model::ModelError| anyhow::anyhow!("{e}");
    // At rest at one angle (a lift-off, no luff).
    if let (Some(a), None, None) = (args.from_deg, args.to_deg, &args.case) {
        let lift = args.lift_off_s.context("--from-deg without --to-deg holds the boom still: give --lift-off-s (or --to-deg)")?;
        let mut p = Program::new(a, 0.0, rope.unwrap_or(RopeChoice::Thesis)).map_err(ctx)?;
        if args.hold_before_s > 0.0 {
            p.push(Segment::Hold { duration_s: args.hold_before_s }).map_err(ctx)?;
        }
        p.push(Segment::LiftOff { duration_s: lift, load_kg: args.load_kg }).map_err(ctx)?;
        p.push(Segment::Hold { duration_s: args.hold_after_s.unwrap_or(args.duration) }).map_err(ctx)?;
        return Ok((format!("lift-off of {} kg at {a}° over {lift} s", args.load_kg), p));
    }
    let (mut title, mut m) = maneuver(args)?;
    if let Some(r) = rope {
        m.rope = r;
    }
    m.hold_before_s = args.hold_before_s;
    if let Some(h) = args.hold_after_s {
        m.settle_s = h;
    }
    let mut p = m.program().map_err(ctx)?;
    if let Some(lift) = args.lift_off_s {
        let mut q = Program::new(p.start_deg, 0.0, p.rope).map_err(ctx)?;
        q.push(Segment::LiftOff { duration_s: lift, load_kg: m.load_kg }).map_err(ctx)?;
        for s in p.segments() {
            q.push(*s).map_err(ctx)?;
        }
        p = q;
        title += &format!(", lifted off over {lift} s first");
    }
    if let RopeChoice::Held { length_m } = p.rope {
        match length_m {
            Some(l) => title += &format!(", held rope {l} m"),
            None => title += ", held rope (load 1 m up at the start)",
        }
    }
    Ok((title, p))
}

/// Runs a program and collects its samples.
pub fn run_program(
    p: &Program,
    options: &SimulationOptions,
) -> Result<(Vec<Sample<f64>>, crane_model::sim::simulation::RunSummary<f64>)> {
    let model = thesis_model()?;
    let mut samples = Vec::new();
    let summary = model
        .simulate_program(p, options, |s| {
            samples.push(*s);
            true
        })
        .map_err(|e| anyhow::anyhow!("simulation failed: {e}"))?;
    Ok((samples, summary))
}

/// Runs a maneuver and collects its samples.
pub fn run_maneuver(
    m: &Maneuver,
    options: &SimulationOptions,
) -> Result<(Vec<Sample<f64>>, crane_model::sim::simulation::RunSummary<f64>)> {
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
    let (title, program) = program(&args.maneuver)?;
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
    let (samples, summary) = run_program(&program, &options)?;
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
        program.duration_s() / elapsed.as_secs_f64()
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
