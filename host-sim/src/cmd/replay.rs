//! `crane-sim replay` (not written yet).

/// Arguments of `crane-sim replay`.
#[derive(clap::Args, Debug)]
pub struct ReplayArgs {}

/// Runs the subcommand; returns the exit code.
pub fn run(_args: ReplayArgs) -> anyhow::Result<u8> {
    anyhow::bail!("`crane-sim replay` is not implemented yet")
}
