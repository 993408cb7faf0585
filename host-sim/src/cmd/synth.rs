//! `crane-sim synth` (not written yet).

/// Arguments of `crane-sim synth`.
#[derive(clap::Args, Debug)]
pub struct SynthArgs {}

/// Runs the subcommand; returns the exit code.
pub fn run(_args: SynthArgs) -> anyhow::Result<u8> {
    anyhow::bail!("`crane-sim synth` is not implemented yet")
}
