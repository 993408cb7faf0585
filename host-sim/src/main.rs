//! `crane-sim`: the desktop tool of the load moment limiter.
fn main() {}
