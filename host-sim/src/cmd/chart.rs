//! `crane-sim chart` (not written yet).

/// Arguments of `crane-sim chart`.
#[derive(clap::Args, Debug)]
pub struct ChartArgs {}

/// Runs the subcommand; returns the exit code.
pub fn run(_args: ChartArgs) -> anyhow::Result<u8> {
    anyhow::bail!("`crane-sim chart` is not implemented yet")
}
