//! `crane-sim report` (not written yet).

/// Arguments of `crane-sim report`.
#[derive(clap::Args, Debug)]
pub struct ReportArgs {}

/// Runs the subcommand; returns the exit code.
pub fn run(_args: ReportArgs) -> anyhow::Result<u8> {
    anyhow::bail!("`crane-sim report` is not implemented yet")
}
