//! `crane-sim simulate` (not written yet).

/// Arguments of `crane-sim simulate`.
#[derive(clap::Args, Debug)]
pub struct SimulateArgs {}

/// Runs the subcommand; returns the exit code.
pub fn run(_args: SimulateArgs) -> anyhow::Result<u8> {
    anyhow::bail!("`crane-sim simulate` is not implemented yet")
}
