//! `crane-sim modes` (not written yet).

/// Arguments of `crane-sim modes`.
#[derive(clap::Args, Debug)]
pub struct ModesArgs {}

/// Runs the subcommand; returns the exit code.
pub fn run(_args: ModesArgs) -> anyhow::Result<u8> {
    anyhow::bail!("`crane-sim modes` is not implemented yet")
}
