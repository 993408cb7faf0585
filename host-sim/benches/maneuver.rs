//! The thesis's reference maneuver at its resolution (12 elements, 4 modes):
//! 3300 kg, 30 s, cycloidal, boom up, with a sample (multipliers, reactions,
//! deflections) every 10 ms. Target: median ≤ 20 ms (1500× faster than real time).
//! Also with the held rope, and with the piston force alone (`Outputs::PistonForce`,
//! what log synthesis and the campaign use), and that with the fast Newton iteration.
// criterion_group! generates an undocumented function.
#![allow(missing_docs)]
use criterion::{criterion_group, criterion_main, Criterion};
use crane_model::sim::integrator::NewtonStart;
use crane_model::structure::modal::{MeshRefinement, THESIS_BASIS};
use crane_model::multibody::ThesisModel;
use crane_model::data::profile::RampShape;
use crane_model::multibody::rope::RopeChoice;
use crane_model::sim::simulation::{Direction, Maneuver, Outputs, SimulationOptions};
use crane_model::CraneData;
use std::hint::black_box;

fn maneuver(c: &mut Criterion) {
    let model = ThesisModel::<f64>::build(&CraneData::coles_mobile_930(), MeshRefinement::THESIS, &THESIS_BASIS).expect("model");
    let m = Maneuver::thesis(3300.0, 30.0, RampShape::Cycloidal, Direction::Up).expect("maneuver");
    let options = SimulationOptions::for_type::<f64>();
    c.bench_function("thesis_30s_3300kg_cycloidal_up", |b| {
        b.iter(|| {
            let mut peak = 0.0f64;
            let summary = model
                .simulate(black_box(&m), &options, |s| {
                    peak = peak.max(s.reactions.piston_force_n);
                    true
                })
                .expect("simulation");
            black_box((peak, summary))
        })
    });
    let held = Maneuver { rope: RopeChoice::Held { length_m: None }, ..m };
    c.bench_function("thesis_30s_3300kg_cycloidal_up_held_rope", |b| {
        b.iter(|| black_box(model.simulate(black_box(&held), &options, |_| true).expect("simulation")))
    });
    let light = SimulationOptions { outputs: Outputs::PistonForce, ..options };
    c.bench_function("thesis_30s_3300kg_cycloidal_up_piston_force_only", |b| {
        b.iter(|| black_box(model.simulate(black_box(&m), &light, |_| true).expect("simulation")))
    });
    c.bench_function("thesis_30s_3300kg_cycloidal_up_held_rope_piston_force_only", |b| {
        b.iter(|| black_box(model.simulate(black_box(&held), &light, |_| true).expect("simulation")))
    });
    // What log synthesis and the campaign run: the held rope, the piston force
    // alone and the fast Newton iteration.
    let fast = SimulationOptions { newton_start: NewtonStart::Extrapolated, ..light };
    c.bench_function("thesis_30s_3300kg_cycloidal_up_held_rope_piston_force_only_fast_newton", |b| {
        b.iter(|| black_box(model.simulate(black_box(&held), &fast, |_| true).expect("simulation")))
    });
    let m32 = ThesisModel::<f32>::build(&CraneData::coles_mobile_930(), MeshRefinement::THESIS, &THESIS_BASIS).expect("model");
    let options32 = SimulationOptions::for_type::<f32>();
    c.bench_function("thesis_30s_3300kg_cycloidal_up_f32", |b| {
        b.iter(|| black_box(m32.simulate(black_box(&m), &options32, |_| true).expect("simulation")))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30);
    targets = maneuver
}
criterion_main!(benches);
