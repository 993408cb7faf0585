//! `crane-sim calibrate` (not written yet).

/// Arguments of `crane-sim calibrate`.
#[derive(clap::Args, Debug)]
pub struct CalibrateArgs {}

/// Runs the subcommand; returns the exit code.
pub fn run(_args: CalibrateArgs) -> anyhow::Result<u8> {
    anyhow::bail!("`crane-sim calibrate` is not implemented yet")
}
