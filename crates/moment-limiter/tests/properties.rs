//! Property tests: monotonicity of the estimate and the overload hysteresis.

mod common;

use moment_limiter::clock::Ticks;
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::io::Frame;
use moment_limiter::testing::rigid_reference::RigidCrane;
use moment_limiter::state_machine::{CycleInput, LimiterState, StateMachine, Thresholds};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// More load (a higher piston-side pressure at every sample, with the same
    /// angles and rod-side pressures) never lowers the estimated utilization,
    /// at any sample. Holds because the filter's impulse response is never
    /// negative and the rating does not depend on the pressures.
    #[test]
    fn more_load_never_lowers_utilization(
        base_bar in 20.0..120.0f64,
        angle0 in 35.0..75.0f64,
        steps in prop::collection::vec((-0.3..0.3f64, -0.5..0.5f64, 0.0..20.0f64), 50..300),
    ) {
        let make = || Limiter::new(RigidCrane::coles_930(), LimiterConfig::standard()).unwrap();
        let (mut light, mut heavy) = (make(), make());
        let (mut p1, mut angle) = (base_bar, angle0);
        for (k, &(dp, da, extra)) in steps.iter().enumerate() {
            p1 = (p1 + dp).clamp(10.0, 150.0);
            angle = (angle + da * 0.1).clamp(30.0, 80.0);
            let t = Ticks::from_millis(k as u32 * 10);
            let f = Frame { t, p1_bar: p1, p2_bar: 5.0 + 0.01 * (k % 3) as f64, boom_angle_deg: angle };
            let a = light.step_frame(&f);
            let b = heavy.step_frame(&Frame { p1_bar: p1 + extra, ..f });
            if let (Some(a), Some(b)) = (a.estimate, b.estimate) {
                prop_assert!(b.utilization >= a.utilization - 1e-12,
                    "sample {}: {} < {}", k, b.utilization, a.utilization);
                prop_assert!(b.load_kg >= a.load_kg - 1e-9);
            }
        }
    }

    /// The state never goes from OVERLOAD to NORMAL directly, and after an
    /// OVERLOAD reaches WARNING or NORMAL (even through FAULT) only once the
    /// utilization has stayed below 0.95 for 0.5 s of consecutive good cycles.
    #[test]
    fn overload_is_left_only_through_the_hysteresis(
        inputs in prop::collection::vec(prop_oneof![
            8 => (0.5..1.2f64).prop_map(Some),
            1 => Just(None),
        ], 1..2000),
        run_lengths in prop::collection::vec(1usize..60, 1..50),
    ) {
        let th = Thresholds::<f64>::standard();
        let mut sm = StateMachine::new(th);
        let dt = 0.01;
        let mut prev = sm.state();
        let mut overload_latched = false;
        let mut below_count = 0usize; // consecutive good cycles with u < 0.95
        let mut hysteresis_passed = false; // since the last OVERLOAD cycle
        // Repeat each input for a run length so that debounces can elapse.
        let seq = inputs.iter().zip(run_lengths.iter().cycle())
            .flat_map(|(&u, &n)| core::iter::repeat_n(u, n));
        for u in seq {
            let input = match u { Some(u) => CycleInput::Utilization(u), None => CycleInput::Fault };
            if let Some(u) = u {
                below_count = if u < th.overload_exit { below_count + 1 } else { 0 };
            }
            let s = sm.update(dt, input);
            // n consecutive cycles span (n − 1)·dt.
            if below_count > 0 && (below_count as f64 - 1.0) * dt >= th.overload_exit_s - 1e-6 {
                hysteresis_passed = true;
            }
            prop_assert!(!(prev == LimiterState::Overload && s == LimiterState::Normal));
            if s == LimiterState::Overload {
                overload_latched = true;
                hysteresis_passed = false;
            }
            if overload_latched && matches!(s, LimiterState::Normal | LimiterState::Warning) {
                prop_assert!(hysteresis_passed, "left overload after {} cycles below", below_count);
                overload_latched = false;
            }
            prev = s;
        }
    }
}
