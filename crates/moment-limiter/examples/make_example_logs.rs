//! Writes the example logs of `examples/logs/` with the rigid stand-in model
//! (until `crane-sim synth` exists). Run from the workspace root:
//! `cargo run -p moment-limiter --example make_example_logs`.

#[path = "../tests/common/mod.rs"]
mod common;

use std::fmt::Write as _;

use common::Manoeuvre;

const FRICTION_UP_N: f64 = 12_000.0;
const FRICTION_DOWN_N: f64 = 8_000.0;

fn manoeuvre(load_kg: f64, from: f64, to: f64, seed: u32) -> Manoeuvre {
    let mut m = Manoeuvre::new(load_kg, from, to, 10.0);
    m.rate_hz = 50.0;
    m.friction_up_n = FRICTION_UP_N;
    m.friction_down_n = FRICTION_DOWN_N;
    m.seed = seed;
    m
}

/// CSV text; `edit` may change the p1 field of a row (index, text).
fn csv(title: &str, m: &Manoeuvre, edit: &dyn Fn(usize, f64, String) -> String) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# {title}");
    let _ = writeln!(
        s,
        "# rigid stand-in model, {} kg, {}° -> {}° in {} s, 50 Hz, friction up {} N / down {} N",
        m.load_kg, m.from_deg, m.to_deg, m.move_s, FRICTION_UP_N, FRICTION_DOWN_N
    );
    s.push_str("t_s,p1_bar,p2_bar,boom_angle_deg,true_load_kg\n");
    for (k, f) in m.frames().iter().enumerate() {
        let p1 = edit(k, f.t_s, format!("{:.2}", f.p1_bar));
        let _ = writeln!(
            s,
            "{:.2},{p1},{:.2},{:.2},{}",
            f.t_s, f.p2_bar, f.boom_angle_deg, m.load_kg
        );
    }
    s
}

fn main() -> std::io::Result<()> {
    let dir = std::path::Path::new("examples/logs");
    std::fs::create_dir_all(dir)?;
    let keep = |_: usize, _: f64, p1: String| p1;
    let files = [
        (
            "unloaded_up.csv",
            csv(
                "unloaded boom up (for calibrate)",
                &manoeuvre(0.0, 40.0, 80.0, 11),
                &keep,
            ),
        ),
        (
            "unloaded_down.csv",
            csv(
                "unloaded boom down (for calibrate)",
                &manoeuvre(0.0, 80.0, 40.0, 12),
                &keep,
            ),
        ),
        (
            "safe_lift.csv",
            csv(
                "safe lift: 3000 kg raised 40 -> 80 deg",
                &manoeuvre(3000.0, 40.0, 80.0, 13),
                &keep,
            ),
        ),
        (
            "overload_lowering.csv",
            csv(
                "overload while lowering: 8000 kg lowered 75 -> 40 deg",
                &manoeuvre(8000.0, 75.0, 40.0, 14),
                &keep,
            ),
        ),
        (
            "wire_break.csv",
            csv(
                "wire break: safe lift, p1 loop broken at t = 6.00 s (0 mA reads -50 bar)",
                &manoeuvre(3000.0, 40.0, 80.0, 15),
                &|_, t, p1| {
                    if t >= 6.0 - 1e-9 {
                        "-50.00".to_string()
                    } else {
                        p1
                    }
                },
            ),
        ),
        (
            "malformed.csv",
            csv(
                "malformed: the p1_bar field of the row at t = 2.00 s is not a number",
                &manoeuvre(3000.0, 40.0, 80.0, 16),
                &|k, _, p1| if k == 100 { format!("{p1}x") } else { p1 },
            ),
        ),
    ];
    for (name, text) in files {
        std::fs::write(dir.join(name), text)?;
    }
    Ok(())
}
