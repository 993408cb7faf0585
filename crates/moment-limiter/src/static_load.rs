//! The static hook mass whatever the rope does (SPEC §4 item 8): a bank of
//! rope hypotheses, and the one that keeps the load constant.
//!
//! ## The force a hanging load puts on the cylinder
//!
//! With the load a point mass W on the rope, the rope pulls the tip with
//! W·(g − a_L) (a_L the load's acceleration), i.e. vertically W·(g + a_Ly)
//! and horizontally W·(g + a_Ly)·tan φ (φ the rope angle from the vertical,
//! positive outward). Moved to the piston through the model's load slope,
//!
//! F − F_0(θ) − J(θ)·θ̈ − friction = F_W(θ, W)·(1 + h·a_Ly/g + tan θ·tan φ),
//!
//! where F_0 + F_W(θ, W) is the model's piston force at rest (quadratic in W,
//! [`crane_model::loads::load_model::Quadratic`]) and J·θ̈ the boom's own inertia
//! ([`crate::load_estimate`]). Two things the limiter cannot measure decide
//! the factor:
//!
//! - **h, how the rope is worked.** Held (the winch braked, what a crane does
//!   while luffing): the load rides with the tip, h = 1, and its vertical
//!   acceleration is the tip's, a_Ly = L·(cos θ·θ̈ − sin θ·θ̇²) (rigid boom; in
//!   a 10 s move the start ramp reaches 1–2.4 m/s², 10–24 % of the load's
//!   weight). Paid out to keep the load at its clearance (the thesis's
//!   assumption vi): the load does not move vertically, h = 0.
//! - **l, the hanging length**, which sets the swing: φ follows the tip's
//!   motion as a pendulum of length l ([`crate::swing`],
//!   [`crate::held_pendulum`]), period 2π·√(l/g): 3.5 s at 3 m, 9 s at 20 m. Held,
//!   l is any constant from 3 m to the tip height; paid out, l is the tip
//!   height less the clearance and changes with θ.
//!
//! ## The bank
//!
//! [`HYPOTHESES`] hypotheses run side by side: the paid-out rope (h = 0,
//! l(θ)), and held ropes (h = 1) of [`HELD_LENGTHS_M`] (a geometric grid from
//! 3 m to 22.6 m, ratio 1.25: neighbouring pendulum frequencies differ by
//! 12 %). Each has its large-angle pendulum, all driven by the same measured
//! (lag-compensated, filtered) boom motion (not by the noise of a still
//! boom: [`SWING_DEADBAND_RAD_S`]), and each solves the load equation
//! above for its own W_k. Every W_k sees the same force, so a real change of
//! the load (a lift-off, a load added) moves all of them at once and at
//! once: nothing here delays it. What separates them is the wrong factor: a
//! hypothesis with the wrong h or l turns the ramp's inertia or the swing
//! into a W_k that varies with the motion, the right one into a constant.
//!
//! **The answer: the lowest static mass any rope explains, held by its
//! average.** No hypothesis is chosen from the data: the rule depends only
//! on the W_k, each of which rises with the measured force, so a heavier
//! load never reads lower (a choice made from the spread of the W_k flips
//! with the load and broke that). The bank reports
//!
//! W = max(W_fast, W_slow),  W_fast = S(min_k W_k),  W_slow = min_k W̄_k,
//!
//! S one first-order stage at [`FAST_SMOOTHING_HZ`] against the load's
//! bounce, W̄_k the W_k of hypothesis k through [`SLOW_STAGES`] first-order stages
//! of time constant [`SLOW_TAU_S`] (restarted at W_k whenever hypothesis k
//! becomes possible again). Why both:
//!
//! - a wrong rope reads the load *low* as often as high; the true rope (or
//!   its neighbour on the grid) reads it right, so the minimum over the
//!   bank never reads the ride-up, the bounce of the swing or the swing of
//!   the wrong length as load: **no hypothesis of the bank can make a false
//!   OVERLOAD** that the true rope would not make;
//! - W_fast reacts to a heavier load at once (every W_k sees the force),
//!   but in motion it reads low by the spread of the hypotheses' factors
//!   (their swings drift out of phase: up to tan θ·Δφ);
//! - W̄_k averages each hypothesis over its swings (a swing of any period
//!   pulls the tip out and in alike: its mean is the static weight), so
//!   min_k W̄_k is the static mass less a few per cent for the hypothesis
//!   whose error is lowest on average. It holds the weighing through a move,
//!   so a load never reads lower in motion than the bank's averaged
//!   weighing; it follows a lighter load (a load set down) over
//!   [`SLOW_TAU_S`]·[`SLOW_STAGES`]. While every hypothesis's factor
//!   agrees within [`AGREEMENT`] with the boom still (no swing predicted;
//!   in motion the factors may cross without agreeing; every possible rope
//!   must weigh, as one alone always agrees with itself), or the
//!   boom has not luffed since the bank started (a lift-off before the first
//!   move), all ropes read the same W and the
//!   averages are set to W_fast, so a move starts from the full weighing
//!   rather than from an average still climbing after a lift-off (a fast
//!   lowering from 80° otherwise started at 0.6 of the load). The averages
//!   are raised to W_fast at once but lowered only at their own pace,
//!   W̄_k ← max(W̄_k, W_fast): the angle sensor lags the force, so at the
//!   start of a move the force's dip (the boom's J·θ̈ and the load's
//!   ride-down, 6 % for 0.3 s before the rate is seen) would otherwise become
//!   the weighing the move starts from (motion band p5 0.93 lowering from
//!   80°). A hypothesis that cannot weigh (below) starts its average afresh
//!   when it can again (a frozen one resumed with a stale weighing: 0.97 of
//!   the load), from max(W_k, W_slow of the last cycle): a rope that
//!   becomes possible as the tip rises has not followed the true swing, and
//!   its W_k of that instant (0.71 of the load with a 3 m rope at 55°) is no
//!   weighing; in the min it cannot raise W_slow above the ropes already
//!   weighing. Unless it was the lowest of them: a rope whose average was
//!   W_slow when it stopped weighing in motion starts again at W_slow. With
//!   the other averages higher, its start is the new W_slow: lowering 80.8° →
//!   8.2° in 9 s on a 4.2 m rope, the 3.75 m rope restarted at its W_k of
//!   1.09 × the load, W_slow jumped from 0.98 to 1.09 in one cycle, and the
//!   limiter cut at true u 0.900 (campaign seed 8 #1724; now no cut, the
//!   true u peaks at 0.967; seed 10 #6948 from 0.898 to 0.972). Capping every
//!   restart at 2 % or 5 % above W_slow instead lowered the thesis world's
//!   10 s lowerings (est/true down to 0.985, or a cut after u = 1 where it
//!   came 0.16 s before); this touches only the rope that was the weighing,
//!   and they do not change. **A load added at rest that nothing weighed**
//!   is the exception: when a move starts from a held weighing (below) that
//!   W_fast passed by [`load_jump::JUMP`] at rest, that weighing may be the
//!   old load's (no rope followed the swing, and the period was not yet
//!   known), and every rope restarts at max(W_k, W_slow) for that move. 60 %
//!   of rated made 100 % 3 s after a raise to 80° on an 8.9 m rope and
//!   lowered at once past the rated radius was cut at true u 1.245–1.249
//!   while the restart held the old load, instead of 1.128–1.133 (`host-sim`
//!   test `a_lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop_*`;
//!   since the swing's midrange weighs it, below, within the bounds).
//!   In such a move the averages also take up W_fast, W̄_k ← max(W̄_k,
//!   W_fast), whenever every possible rope weighs: restarted no lower than
//!   the old load, they otherwise climbed to the new one at their own pace
//!   only, and W_fast, the lowest rope's reading, dips with the ropes' swings
//!   out of phase (to 0.53 of the load at 51°, lowering from 80° on the
//!   8.9 m rope). Lowered 2–4 s
//!   after the take-up, before anything weighed the load at rest, those
//!   lowerings were cut up to true u 1.164; then 1.105. In such a move the
//!   swing's midrange begun at rest goes on following into a lowering for
//!   [`MIDRANGE_CARRY_S`] (below, "Settled after a move: a load added,
//!   weighed by its swing"): now up to 1.082 (the known gap in
//!   `a_lowering_2_to_10_s_after_a_load_added_at_rest_*`: where W_fast at
//!   rest never passed the old weighing, nothing doubts it). Once the
//!   swing's midrange or the mean over one swing period weighs the load at
//!   rest, the rest's peak of W_fast is forgotten: the load is weighed, and a
//!   peak above that weighing is the swing's crest, not a load nothing
//!   weighed. Doubting it, a lowering begun 10 s after the take-up on a 3 m
//!   rope held W_fast's crest at 68° (1.17 × the load) and was cut at true u
//!   0.873; now from 0.963 (and 8 s after from 0.933, where it was 0.904;
//!   `a_lowering_8_or_10_s_after_a_load_added_at_rest_*`).
//!   At rest a hypothesis that cannot weigh keeps its average and votes with
//!   it (the load swings on; its weighing from the move is the best it has).
//!
//! A held rope longer than the tip is high (the load would be below ground)
//! is impossible: such hypotheses are left out while the boom is that low.
//! Where a hypothesis's factor falls below [`MIN_LOAD_FACTOR`] (a short rope
//! swung inward at a steep boom: at 80° tan θ = 5.7, and a 3 m rope stopped
//! from a 10 s move swings 14°, so the load's pull on the cylinder nearly
//! vanishes), the force cannot weigh the load (every error is divided by
//! the factor): that hypothesis is left out of W_fast; in motion it is left
//! out of W_slow too and its average restarts when it can weigh again, at
//! rest its average is kept and votes. Which hypotheses take part depends on
//! the boom's motion only, never on the force. When none can weigh, the load
//! is taken hanging straight and still (factor 1), but never lower than the
//! last W_slow, the bank's weighing from before every rope became unusable
//! (a 9 s lowering from 84° on a 5.6 m held rope left no rope weighing for
//! 2 s; the factor-1 reading went to −0.55 of the load, the averages then
//! restarted from it and read 0.57 of the load when the true utilization
//! passed 1.05: a missed overload); at rest after a move no lower than the
//! move's weighing either (below).
//!
//! ## In motion: the averages move only while every rope can weigh
//!
//! A rope whose factor is unusable is left out of W_fast, but it may be the
//! true one: the ropes left read the swing of the wrong length, and their
//! lowest average is not the weighing (lowering from 82° at 10 °/s on a
//! 4.1 m rope the short ropes cannot weigh for seconds, and the others'
//! averages fell to 0.76 of the load: an overload cut at true u 1.09;
//! from 85° they rose to 1.5 × the load). So in motion, while a possible
//! rope cannot weigh, every average and W_slow itself stand (the load does
//! not change in the air), and they move again when every possible rope
//! weighs. A heavier load in motion is W_fast's, the lowest rope's reading,
//! which at a steep boom in a fast move reads the ropes' spread swings low
//! (0.69 of a load taken up mid-raise at 60° in 10 s), and the follower of
//! a load added in motion's ([`crate::load_rise`]): in a steady luff, a
//! rise that every rope sees and the consistent ropes confirm for 0.4 s
//! multiplies every average (and the weighing that stands) by the
//! consistent ropes' lowest rise over what they read a second before it,
//! never past what they read now. Before it, such a load was cut only
//! once a 10 s raise stopped (5.8 s after its take-up) and a lowering with
//! 90 % added was cut at true u 1.27 (`host-sim` test
//! `a_load_added_in_motion_known_gap`, whose doc gives today's figures).
//! The rescale of a load added at rest ([`crate::load_jump`]), a ratio to
//! the averages, run in motion was tried and not kept: it read a light load
//! at 1.395 × itself (campaign seed 1 #8831), and with the consistent ropes
//! voting it rescaled where the averages held a kept or old weighing
//! below the force (after a logger's dropout, between an inched lowering's
//! steps) and cut early, from true u 0.833; a rise over the ropes' own
//! readings does not see a weighing the averages missed.
//! At rest, while a possible rope has no average (it could not weigh as
//! the move ended), W_slow does not rise above the bank's weighing either.
//! The ropes never agree while the boom creeps (its rate over
//! [`SETTLED_RAD_S`]): its force may still carry the seals' sliding
//! friction.
//!
//! ## The seals' breakaway: the averages without it
//!
//! A raise starts with the seals' up-friction in the force before the
//! angle shows the boom rising ([`crate::breakaway`]). Raised to W_fast at
//! once, the averages took it up and held it into the raise, where the
//! sliding friction was out of the force but not out of them (1.087 × the
//! load, campaign seed 12 #7607). So while the breakaway is taken out of
//! the force (`seals_hold`), the averages are set to W_fast, both ways.
//!
//! ## Power-up: the filters' start-up is no luff
//!
//! The filters start settled on their first sample, and that sample's noise
//! reads as a rate while they converge: up to 0.5 °/s for half a second with
//! 0.05° of angle noise. For the first
//! [`crate::load_estimate::CREEP_AFTER_START_S`] the bank therefore drives no
//! pendulum with it and counts no luff. Before this, the start-up counted as
//! a luff (over [`MOVING_RAD_S`]). At 79° its phantom swing then kept the
//! ropes from agreeing, so a lift-off that followed never raised the averages
//! to W_fast. A lowering past the rated radius right after it started from
//! half the load and was cut at true u 1.11 (`host-sim` test
//! `a_lowering_right_after_a_lift_off_behind_a_noisy_angle_sensor_*`, found
//! by `crane-sim campaign --wide --seed 3`, #4653).
//!
//! **The first samples.** The filters start at the first reading, and the
//! bank's averages are raised to W_fast at once but lowered only at their
//! pace: they kept the first sample's noise for seconds. At a steep boom
//! the load moves the force little (at 84° its arm is a tenth of the boom),
//! so a pressure's noise weighs a lot: 7.7 t switched on at 84° behind
//! 0.85 bar of pressure noise read u 0.92 at the first sample for a true
//! 0.77 (0.81 with the ×1.05 reading), and WARNING for 6.5 s; with 0.13° of
//! angle noise too, OVERLOAD (`crane-sim campaign --wide --seed 6`, #538).
//! So the force filters start from the mean of their samples so far
//! ([`crate::filter::LowPass::starting_from_the_mean`]), and for the first
//! [`FIRST_SAMPLES_S`] the stage S and the averages follow W_fast both
//! ways. That case now reads 0.82 from 0.1 s on (0.88 after 0.01 s), no
//! WARNING. Neither delays a heavier load: the filters' weights on later
//! samples only grow, and the averages follow W_fast up at once as before.
//!
//! Forgetting the swing once the filters had converged left the phantom in
//! W_fast and the averages: the reading fell to 0.71 × the load at 84.6°
//! (campaign seed 1 #1830). A move begun within that second is seen only from
//! its end. A move under way at power-up is the power-up check's
//! ([`crate::cycle`]): FAULT until the boom stops.
//!
//! ## At rest after a move: the move's weighing held
//!
//! After a move stops, nothing in the bank damps the predicted swings: at a
//! steep boom a short rope's swing makes the force useless for weighing. At
//! 80° (tan θ = 5.7) a 3 m rope stopped from a 10 s raise swings 15°, its
//! factor 1 + tan θ·tan φ runs from −0.5 to 2.5, the true force nearly
//! vanishes twice a period, and any hypothesis slightly out of phase reads
//! from −1.3 to 1.5 × the load (band at rest p5 0.075 before). So when a
//! move of at least [`MOVE_FOR_HOLD_S`] ends, the bank keeps its last
//! reading in motion, W_hold, and reports at rest
//!
//! W = max(W_now, W_hold) while the force cannot weigh,  W = W_now otherwise,
//!
//! W_now = max(W_fast, W_slow) as above, where the force cannot weigh when a
//! possible rope's factor is unusable (below [`MIN_LOAD_FACTOR`]) or the
//! possible ropes' factors spread by more than [`UNUSABLE_SPREAD`],
//! f_max > (1 + 0.25)·f_min. W_hold is dropped when the boom moves again,
//! when all ropes agree (the averages are W_fast again), and
//! [`REST_HOLD_S`] after the stop; a fault of the force keeps it (it only
//! ever raises the reading). The hold never lowers the reading, so it
//! delays no overload; a load set down while the force cannot weigh reads
//! high until the spread falls or the hold ends (the limiter errs toward
//! cutting).
//!
//! ## At rest after a move: the stop's bounce
//!
//! A stop sets a hanging load bouncing on its rope and the boom (1–2 Hz,
//! the rope's stretch and the boom's bending, which no hypothesis models:
//! every rope reads it alike). W_fast's one stage at [`FAST_SMOOTHING_HZ`]
//! passes a 1.6 Hz bounce at 0.4 of its size, and a 10.9–12.6 s lowering
//! stopped at 10° on a 3–4 m rope rang on at up to ±14 % of the force: its
//! crests read 1.058–1.065 × the load (1.11–1.12 with the ×1.05 reading),
//! and loads of 0.896–0.908 of rated were cut 1–2 s after the stop, early
//! (campaign seed 11 #3433, seed 19 #2801). So for [`BOUNCE_WINDOW_S`]
//! after a loaded move stops, W_fast and the still force's stage (below,
//! "A still boom") are read through a second stage like the first, which
//! passes that bounce at 0.16: the two read at most u 0.994 and 0.962. No lift-off is delayed: a load leaves
//! the ground with the boom still and the hook empty before, and after an
//! empty-hook move the window does not open. A load added to a hanging
//! load within 2.5 s of the stop is read through the second stage: taken up
//! 1 s after the stop (`host-sim` test
//! `a_load_added_one_second_after_a_stop_known_gap`), one 110 % case of 16
//! is cut 1.68 s after its take-up instead of 1.46 s, the others as without
//! it. That test found the load added so soon after a stop seen late
//! whether or not the window is there (up to 3.75 s): no rope of the bank
//! reads the fresh swing consistently yet, so the common jump has no voters
//! ([`crate::load_jump`]).
//!
//! ## A still boom: the force without the sensor's lag
//!
//! The force goes through the angle sensor's lag (a first-order stage of
//! 0.1–0.3 s, [`crate::cycle::Limiter`] "Time alignment") so that force
//! and angle stand for the same instant in motion. A still boom has no use
//! for it: its angle is the same 0.3 s earlier. On a 0.3 s sensor the lag
//! delayed a lift-off's cut by 0.3–0.45 s: 110 % of rated taken up in 1 s
//! was cut 1.16–1.20 s after it left the ground (0.87–0.92 s on a 0.111 s
//! sensor). So while every rope agrees (the boom still, not creeping, and
//! no swing predicted, the condition under which the averages are set to
//! W_fast) the bank also reads the load W_still that the force through the
//! filter alone, without the lag, gives (factor f_max: every factor is
//! within [`AGREEMENT`] of it), through a stage like W_fast's, and reports
//!
//! W = max(W_now, S(W_still)).
//!
//! It only raises the reading, and only while the boom is still. A move
//! starts in the unlagged force up to one sensor lag before the angle
//! shows it, but the gate closes as soon as the filtered rate passes
//! [`SETTLED_RAD_S`] (0.05 °/s): on a 0.3 s sensor 0.04 s into a 21 °/s²
//! start (a 0.5 s ramp to 10 °/s), when the four-stage force filter has
//! passed about 10⁻⁴ of the start's inertia. The stage S keeps the load's
//! bounce out: a lift-off snatched in 0.15 s bounces at 1.7 Hz by ±68 % of
//! the load, and S(W_still) read 90 % of rated at most 1.046 × (0.990
//! with the ×1.05 reading) against 1.035 × through the lag. Measured with
//! `crane-sim synth --from-deg A --lift-off-s T` at 20°, 45°, 70° and 80°,
//! 110 % of rated, on a 0.111 s or a 0.3 s sensor alike: cut 0.54–0.57 s
//! after leaving the ground for T = 2 s, 0.74–0.80 s for 1 s, 0.91–0.96 s
//! for 0.5 s, 1.02–1.07 s for 0.3 s (a snatch; 0.15 s takes p1 past its
//! range, a FAULT, at 20°). Before, on the 0.3 s sensor: 0.88–0.92 s,
//! 1.16–1.20 s, 1.33–1.38 s and 1.37–1.46 s. On the held ropes a snatch in
//! 0.3 s was cut up to 1.12 s after, and is now within 0.98 s: a load
//! rising from an empty hook is read through one stage fewer (below, "A
//! lift-off: one stage fewer").
//!
//! ## A lift-off: the boom's give swings the load
//!
//! Taking a load up bends the boom, and its tip moves out by
//! c·g·W·cos θ·sin θ (c the tip's compliance across the boom, as for the
//! give below; [`crate::swing::SwingGeometry::tip_shift_m`]). Taken up
//! faster than the load can follow on its rope, the load is left inward of
//! the tip and swings. 9 t snatched in 0.3 s at 80° on a 3 m rope moves the
//! tip 4.6 cm in the simulator and swings the load ±0.8°, and at
//! tan 80° = 5.7 its outward crest pulls 8 % more. The boom angle never
//! moved, so no rope of the bank swung: they agreed, the crest read as load
//! and the averages held it. 90 % of rated was an OVERLOAD in all 16 noise
//! draws taken up in 0.3 s and in 8 of 16 in 0.5 s (highest estimated u
//! 1.0035; `host-sim` test `ninety_percent_lifted_on_a_3_m_rope_at_80_degrees_*`).
//!
//! So before any move, a lift-off is followed from an empty hook (the force
//! at factor 1 within [`load_jump::MIN_AVERAGE_KG`] of nothing, the boom
//! still, for [`EMPTY_BEFORE_LIFT_S`]): each cycle the load the force reads
//! at factor 1 rises, the tip moves out by the shift's growth, and every
//! pendulum turns in by it over its length ([`HeldRopes::shift_tip`]: the
//! load keeps its place and its velocity). The following ends when that
//! load falls to [`LIFT_FOLLOWED_TO`] of its highest: the take-up is over,
//! and the bounce and the swing move the force, not the hook load. (A swing
//! whose pull nearly vanishes at its troughs, switched on at a steep boom,
//! passes through nothing for a moment only: armed on that, the rise after
//! a trough kicked the ropes, and a case of `power_up_with_the_load_swinging_*`
//! changed.) A take-up slower than the swing leaves less swing, and the
//! pendulums, integrating the same shifts, predict less. Which rope follows
//! the true swing is left to the bank as always: the lowest reading wins,
//! so at the outward crest the rope that swings with the load reads it flat
//! and the others higher, and in the inward half swing the least inward
//! rope reads lowest, as every rope read before.
//!
//! Measured (`host-sim` tests, f64 and f32, through the still force's four
//! filter stages, before "A lift-off: one stage fewer" below): 90 % on the
//! 3 m rope at 80° read at most u 0.949 taken up in 0.3 s to 2 s, no
//! OVERLOAD in any of 64 draws; 110 % snatched in 0.3 s was cut 0.99–1.12 s
//! after it left the ground (1.00–1.14 s without following the give), in
//! 0.5 s at most 1.03 s (1.05 s), in 1 s or 2 s at most 0.84 s (0.86 s).
//! Where the force has no such swing (a boom
//! that does not give, or a long true rope), the shorter ropes' swings are
//! wrong and the lowest reading is lower, by at most the give of the load
//! over the shortest rope (tan θ·shift/(3 m + give): 8.7 % for 10 t at 80°),
//! and only while the averages, held at the weighing, are not higher: a
//! load lifted at once in such a world is weighed within [0.98, 1.02] of
//! itself 1 s after (`a_load_set_down_stops_the_ropes_swinging`), and
//! against an ideal bounce with no give (`lift_off_against_an_ideal_bounce_*`)
//! 110 % is cut no later than before.
//!
//! Not after a move: there a load added at rest has its own rules (below),
//! and the bank's pendulums already swing. The lift's swing is carried into
//! the move that follows, as the load carries it. In `crane-sim campaign`
//! (lift-offs taken up in 2–6 s, then luffs of 8–60 s) that moved 1 612 of
//! the first 60 000 scenarios' first cuts, 1 560 later (by up to 1.2 s, at
//! true u 0.95–0.96, none late), and made one more early cut in 80 000
//! `--wide` ones (seed 3 #6668: 90.5 % lifted, raised to 83.9° behind a
//! 0.11° noisy angle, highest estimated u 0.9998 before and 1.0065 now, cut
//! at true u 0.905). Resetting the ropes at the luff's start instead read
//! that case at 1.083.
//!
//! ## A lift-off: one stage fewer
//!
//! A load taken up fast was cut late by the filters that keep its bounce
//! out: snatched in 0.3 s, 110 % of rated 0.99–1.12 s after it left the
//! ground (the four 1.2 Hz stages of the still force cross 0.866 of the
//! step 0.68 s after the take-up ends, the stage S adds 0.31 s, the
//! debounce 0.05 s), and taken up in 0.5 s on a 3 m rope at 80° 1.03 s
//! after. So before any move, within [`FAST_LIFT_S`] of the hook's last
//! empty reading, the still force is read through three of the four stages
//! ([`crate::filter::LowPass::last_stage_lead`]: the third stage's output,
//! exactly the filter with one stage fewer, with no state of its own). That
//! takes 0.13 s out of the delay and passes a 1.7 Hz bounce at 0.19 of its
//! size instead of 0.11.
//!
//! The window is short because a step and its bounce arrive at different
//! times. The hook reads empty (through the lagged four-stage force) until
//! about 0.45 s into a fast take-up, and a take-up of 0.5 s or less is cut
//! 0.85–0.95 s after that; the first crest of a snatch's bounce reaches the
//! still force's stage S about 1.5 s after it. With a window of 2 s the
//! crest was read through three stages too: 90 % snatched in 0.1–0.2 s was
//! an OVERLOAD in 3–8 of 15 `crane-sim synth` lift-offs at 20°–80° (every
//! rope mode; highest estimated u 1.024), where through four stages it read
//! at most 0.992. With 1.2 s it reads at most 0.999 there, and the cuts of
//! take-ups from 0.3 s to 1 s are as with 2 s.
//!
//! Measured (`host-sim` tests, f64 and f32): snatched in 0.3 s, 110 % is cut
//! at most 0.98 s after it leaves the ground, in 0.5 s at most 0.88 s; 90 %
//! is no OVERLOAD and reads at most u 0.970 (as through four stages), on
//! the 3 m rope at 80° 0.951 (0.949). Snatched in 0.1–0.2 s, 110 % was still
//! cut up to 1.14 s after (1.22 s through four stages; within 0.87 s since
//! the mean of its ring is read, below), and 90 % snatched
//! in 0.1 s at 20° was an OVERLOAD in 4 of 40 cases (u 1.005; 0.990 through
//! four stages): the first crest of so fast a snatch comes through within
//! the window (none since the reading is held to the ring's mean, "A
//! lift-off: no higher than its ring"; `lift_off_snatched_in_0_02_to_0_2_s_*`). Against an
//! ideal bounce (`lift_off_snatched_against_an_ideal_bounce_*`) 110 % is
//! cut within 0.99 s (1.08 s through four stages), and 90 % behind a 1 Hz
//! bounce, whose first crest pulls up to twice the load, was an OVERLOAD in
//! 10 of 12 cases (8 through four stages; 8 since the ring's cap, below):
//! within a second no filter tells that bounce from a load 20 % heavier.
//!
//! The window also leaves out what the fourth stage is kept for elsewhere:
//! through three stages everywhere, a raise begun as a lift-off taken up in
//! 5 s ends read u 1.008 (campaign seed 12 #7607, the seals' up-friction in
//! the force before the angle shows the raise, [`crate::breakaway`]), and a
//! stop's bounce after a lowering to 10° was cut early (seed 11 #3433); both
//! read as before.
//!
//! ## A lift-off: read at once until it bounces
//!
//! The stage S is there against the bounce a fast take-up sets off (the
//! rope's stretch and the boom's bending ring at 1–2 Hz, the first crest up
//! to twice the load). Where the take-up sets off none, S only delays: in
//! the second formulation's world (`host-sim`'s rigid mechanism by
//! Lagrange's equation: no boom bending, no rope stretch), 110 % of rated
//! put on the hook in 0.02–0.1 s was cut 1.01–1.02 s after it left the
//! ground, over the second the lift-off test allows. Three filter stages
//! and S cross 0.866 of a step (what cuts 110 % with the ×1.05 reading)
//! 0.97 s after it; the debounce adds 0.05 s.
//!
//! A bounce shows itself before it reaches the reading: its first crest
//! turns within half a bounce period (0.25–0.5 s) and comes through the
//! still force's three stages about 0.4 s later. So while a load rises
//! from an empty hook (the window of "one stage fewer"), the limiter gives
//! the bank the still force's first filter stage f₁ (the filter with one
//! stage, [`crate::filter::LowPass::first_stage`]: a turn of the force shows
//! there first), and [`StaticLoadBank::watch_lift`] keeps its lowest value
//! while the hook read empty, f_base, and its highest since, f_peak. The
//! lift-off **bounces** once
//!
//! f_peak − f₁ ≥ [`LIFT_TURN`]·(f_peak − f_base),
//!
//! and until it does, the still force's load w is read through a stage at
//! [`LIFT_STAGE_HZ`] besides S, the higher of the two counting:
//!
//! W_still = max(S(w), S_1.4(w)) until the bounce, S(w) from then on
//! (until the hook reads empty again).
//!
//! It only raises the reading, in that window, before the force has
//! turned. A force that rises and stays has no bounce to keep out; one
//! that turns has been read through S from its first turn on, before its
//! crest came through the three stages (`tests::a_lift_off_is_read_at_once_until_it_bounces`:
//! 3 t at once behind the limiter's filter is read at 0.866 of itself 0.77
//! s after, 0.95 s through S; ringing at 1.5 Hz from twice the load, its
//! bounce is seen 0.49 s after and the reading's highest is S's).
//!
//! Measured (`host-sim` tests, f64 and f32): in the second formulation's
//! world, 110 % taken up in 0.02 s or 0.1 s at 10°–80° is cut at most
//! 0.84 s after it leaves the ground, 90 % reads at most u 0.945 (test
//! `a_load_on_the_hook_at_once_is_cut_within_1_s_where_nothing_bounces_*`).
//! In the simulator's world a fast take-up bounces on the boom's bending:
//! snatched in 0.1–0.3 s, the lift-offs read and cut as before, and 90 %
//! on the 3 m rope at 80° reads at most u 0.9504 (f32 0.9511, was 0.9506).
//! Slower take-ups may set off a bounce too small to turn the force by 5 %;
//! they are cut sooner (the paid-out rope taken up in 1 s behind a 0.3 s
//! angle sensor: 0.44–0.48 s after leaving the ground, was 0.59–0.64 s;
//! the slowest of every rope taken up in 1–2 s at 10°–80° is 0.68–0.69 s,
//! as before), and behind an ideal bounce of 2 Hz that small, 90 % taken
//! up in 0.5 s reads up to 0.013 higher (0.952 at 80°, was 0.939; the
//! highest behind 1.5–2 Hz in 0.5 s, 0.964, and behind 1–2 Hz in 0.8–2 s,
//! 0.977, are unchanged).
//! Switched on 3 s after a raise to 80° with the 3 m rope swinging, a case
//! already cut for its swing (the known gap "switched on while the load
//! swings"), the reading's highest rose from 3.04 to 3.09 × the load and its
//! OVERLOAD from 11.3 s to 11.4 s: the swing's force falls to nothing at
//! its troughs, so the hook reads empty and the window opens.
//! Why 1.4 Hz, not no stage at all: through the three filter stages alone
//! the rigid world's lift-offs were cut within 0.70 s, but on the 3 m rope
//! at 80° a take-up in 0.3 s sets off less than that turn (the boom's give
//! swings the load instead of bouncing it), and 90 % read u 0.9634; through
//! a 2 Hz stage 0.9559 and 0.79 s, through 1 Hz 0.9504 and 0.91 s. In
//! `crane-sim campaign --seed 1` nothing counted changes; the highest
//! estimated u of 480 scenarios with loads under 700 kg (hooks that read
//! nearly empty, true u at most 0.17) rises by at most 0.016.
//!
//! ## A lift-off: the mean of its ring
//!
//! Once a lift-off bounces, the stage S reads its ring at 0.7 Hz, and a
//! snatch rings hard: taken up in 0.1 s on the simulator's boom at 35°, the
//! force rings at 1.4 Hz from nearly the empty hook's force to twice the
//! load, and S carried its troughs into the reading for a second. 110 %
//! snatched in 0.1–0.2 s was cut up to 1.14 s after it left the ground (the
//! 3 m rope at 35° and 80°), over the second the lift-off test allows.
//!
//! Three turning points of a ring give its mean long before a filter has
//! averaged it out. A lightly damped ring decays geometrically: turning
//! points x₀, x₁, x₂ in a row lie at m + A, m − rA, m + r²A about its mean
//! m (or mirrored), so (x₀ − m)(x₂ − m) = (x₁ − m)², and whatever r,
//!
//! m = x₁ + d₀·d₂/(d₀ + d₂),  dᵢ = xᵢ − x₁
//!
//! (Aitken's Δ² extrapolation). A load put on at once rings from the empty
//! hook's force as from a turning point, so that force is the first x₀; a
//! take-up over time rings less than a step, and from the empty hook m
//! then reads low. So once a lift-off bounces, [`StaticLoadBank::watch_lift`]
//! follows the still force's first filter stage f₁ from turning point to
//! turning point: one is passed once f₁ has come back from it by
//! [`LIFT_TURN`] of the lift's rise to its first crest (as the first crest
//! is found), and each gives the ring's mean (`ring_mean`)
//!
//! f_ring = min(m, x₁ + d₂/2),
//!
//! bounded by the midrange of the last two turning points: where the ring
//! is not geometric (a slack rope, the filter's own transient) the lower of
//! two readings, never a crest. f₁ lags the force and shrinks its ring (to
//! 0.65 of it at 1.4 Hz) alike at every turning point, which leaves the mean
//! and the decay as they are. The latest f_ring counts: while the lift
//! window of "one stage fewer" is open,
//!
//! W_still = max(…, W(f_ring)),
//!
//! the load f_ring stands for at the still force's factor. It only raises
//! the reading, and no more than to a level the force has swung about.
//!
//! Measured (`host-sim` field tests, f64 and f32 alike; the unit tests
//! `a_ring_has_the_mean_of_three_turning_points` and
//! `a_lift_off_is_weighed_by_its_ring`): in the simulator's world, 110 %
//! snatched in 0.1–0.2 s is cut at most 0.87 s after it leaves the ground
//! (was 1.14 s), taken up in 0.3 s 0.97 s (0.98 s), in 0.5 s 0.76 s
//! (0.87 s), in 1–2 s 0.63 s (0.68 s); behind an ideal 1.5–2 Hz bounce
//! taken up in 0.3–0.5 s, 0.74 s (0.99 s). On the 3 m rope at 80° the
//! ring is fast (3.3 Hz) and f₁'s first wiggle in the rise counts as its
//! first turning point: its means read 0.63, 0.75, 0.90, 0.94, 0.97 and
//! 0.99 of the load as f₁ catches up, and 110 % snatched in 0.1 s is cut
//! 0.66 s after it leaves the ground (was 1.07 s). No reading of 90 %
//! moved where it is highest: on the 3 m rope at 80° at most u 0.9504 as
//! before, behind an ideal 1.5–2 Hz bounce 0.992; single cases rose by up
//! to 0.016 (behind a 2 Hz bounce at 80°, 0.943 → 0.959). 90 % snatched in
//! 0.1 s at 20° was still an OVERLOAD in 4 of 40 cases (u 1.005), 1.3 s
//! after it left the ground, where S carried the ring's second crest (the
//! ring's means read it at 0.905 and 0.992 of the load before that), until
//! the next section.
//!
//! ## A lift-off: no higher than its ring
//!
//! The ring's mean only raised the reading, and the stage S still carried
//! the ring's crests into it: S passes a 1.4 Hz ring at about an eighth of
//! its swing after the filter's stages, and the first crests swing by up to
//! the load. 90 % of rated snatched in 0.1 s at 20° read u 1.005 1.3 s
//! after it left the ground, where the ring's means had read it at 0.905
//! and 0.992 of the load; on a boom 30 % softer than the model (its ring
//! slower, 1.2 Hz, and lighter damped) up to u 1.070, and the crests came
//! after the lift window, through the averages W_fast feeds.
//!
//! A ring that decays has each turning point between the two before it,
//! and its mean is what the hook weighs. So once a lift-off has a ring's
//! mean, [`StaticLoadBank::watch_lift`] goes on following its turning
//! points after the lift window too, and while the ring **decays**,
//!
//! W_fast ← min(W_fast, (1 + [`RING_CAP`])·W(f_top)),
//! W_still ← min(W_still, (1 + [`RING_CAP`])·W(f_top)),
//!
//! with f_top the highest of the ring's means so far (a ramp's first mean
//! reads low, the later ones right; the highest is the least that can hold
//! a heavier load down). The cap holds until one of:
//!
//! - the first stage f₁ passes the turning point before the last by more
//!   than a turn ([`LIFT_TURN`] of the rise): no decaying ring does that,
//!   a load that changed does, and the cap ends at once;
//! - no turning point has been passed for [`RING_QUIET_S`] (the ring has
//!   died to under a turn, and S's share of it to about 1 % of the load);
//! - the boom moves, or the hook reads empty.
//!
//! It lowers a reading, so what it costs is a heavier load's wait: a load
//! added within a ring that swings wider than the addition is held to the
//! cap until a turning point gives a mean with it. 90 % snatched in 0.1 s
//! at 20° and then taken to 110 % 1 s later is cut 0.76 s after the second
//! take-up ends (0.20 s before, from the 90 % reading already near the
//! cut); 1.5–3 s later, within 0.69 s (`host-sim` test
//! `loads_added_to_ringing_lift_offs_are_cut_*`; with neither the envelope
//! nor the quiet second ending the cap, a load added there was cut 4.15 s
//! after). No lift-off's cut moved (below).
//! `tests::a_lift_offs_ring_is_read_no_higher_than_its_mean`: behind the
//! limiter's filter, a lightly damped 1.5 Hz ring reads at most 1.027 of
//! the load (1.073 through S alone), and a ringing tonne added at 4 s or
//! 5 s is seen no later than without the cap.
//!
//! Measured (`host-sim` field tests, f64 and f32 alike; the whole suite run
//! before and after, every printed figure compared): 90 % snatched in
//! 0.02–0.2 s reads at most u 0.985, no OVERLOAD (it was an OVERLOAD in 4
//! of 40 cases in 0.1 s at 20°, u 1.005, and in 6 of 40 in 0.02 s, u
//! 1.008). On a boom 10 % softer than the model, none (16 of 40 in 0.1 s,
//! u 1.024); 30 % softer, none in 0.3 s (24 of 40, u 1.029) and 2 of 40 in
//! 0.1 s (18 of 40, u 1.070), on the 3 m rope at 65°, where the ring rides
//! on the swing the boom's give starts and leaves the envelope. With the
//! boom's damping 0.3 of the model's, none (12 of 40). Behind an ideal 1 Hz
//! bounce 90 % is an OVERLOAD in 8 of 12 cases (10), behind 1.5–2 Hz it
//! reads at most 0.977 (0.992). No cut of 110 % moved anywhere in the
//! suite, and nothing else printed changed. In `crane-sim campaign`
//! (seeds 1, 12 and 18, and `--wide` seed 1) the summaries are identical.
//!
//! ## A load added while a lift-off rings: a lift-off again
//!
//! The lift window, the stage at [`LIFT_STAGE_HZ`] and the ring's mean serve
//! a load rising from an empty hook. A load added before any move to one
//! that hangs, while its lift-off still rings, rose through the four filter
//! stages and the stage S: 50 % of rated snatched in 0.1 s on the 3 m rope
//! at 80° and taken to 110 % in 0.1 s 3 s later (the force ringing at
//! 3.2 Hz from 99 to 116 kN before that take-up, from 110 to 260 kN after)
//! was cut 1.20 s after the take-up ended.
//!
//! The ring's follower sees such a load first: f₁ passes the crest before
//! its last trough by more than a turn, which no decaying ring does. Once
//! the lift window has closed, that break is read as a lift-off from the
//! trough the force rose from: the trough is f_base (a turning point, as the
//! empty hook's force is to a step), the window of one stage fewer opens
//! again for [`FAST_LIFT_S`] (`rise_s`), the stage at [`LIFT_STAGE_HZ`]
//! reads until the new load bounces, and its ring's means follow from there
//! (the last mean of the old ring stays the floor until a new one comes,
//! and the new ring caps the reading as the first did). Each of these only
//! raises the reading while the load rises, as for a lift-off from an empty
//! hook.
//!
//! Within the lift window a break is the lift-off itself still rising, or
//! its ring riding on the swing that the boom's give starts (the 3 m rope
//! at 65°): read as a lift-off again there, 110 % snatched at 65° was cut
//! 1.04 s after it left the ground (0.91 s) and 90 % was an OVERLOAD in 4
//! of 40 cases. So there a break only ends the cap, as before, and a load
//! added to that ring later is read as before.
//!
//! A load added to one that hangs steadily is the next section's.
//!
//! Measured (`host-sim` field tests, f64 and f32 alike; the whole suite run
//! before and after, every printed figure compared: only these changed):
//! loads added to ringing lift-offs (`loads_added_to_ringing_lift_offs_are_cut_*`)
//! are cut at most 1.14 s after the take-up ends (1.20 s), 0.97 s outside
//! the known gap (1.00 s); 90 % is never cut. `tests::a_load_added_to_a_ringing_lift_off_is_read_as_a_lift_off`:
//! 3 t ringing at 1.5 Hz and 1.5 t more added 1.5–3 s later are read at
//! 0.95 of the 4.5 t 0.66–1.06 s after it is added, 0.10–0.61 s sooner than
//! with the watch neutralized.
//!
//! ## A load added to one hanging steadily: a lift-off again
//!
//! A load added before any move to one that no longer rings rose through
//! the four filter stages and the stage S: 50 % of rated taken to 110 % in
//! 0.1 s at 65°–80°, 5 s or 12 s after its lift-off, was cut 1.01–1.11 s
//! after its take-up ended (11 of 72 cases; the longest on the 3 m rope at
//! 80° after a lift-off taken up in 2 s).
//!
//! So while no lift-off is watched, the watch (`watch_steady`) keeps
//! the band of f₁ (the still force's first filter stage, N): its low f_lo
//! and high f_hi, as long as
//!
//! f_hi − f_lo ≤ [`STEADY_BAND`]·(f_lo − F_0),
//!
//! F_0 the empty hook's force (`at_zero` of the still load equation), so
//! f_lo − F_0 the load's part. Once it has held for [`STEADY_S`] (and the
//! filters have started, [`crate::load_estimate::CREEP_AFTER_START_S`]),
//! the load hangs **steadily** and the band's top stays where it is; a rise
//!
//! f₁ > f_hi + [`STEADY_RISE`]·(f_lo − F_0) + F_up(f₁)
//!
//! (F_up the seals' up-friction by the calibration's law, which a raise's
//! start puts in the force before the angle shows it, [`crate::breakaway`])
//! is read as a lift-off from f_lo, as the break of a ring is (above): the
//! window of one stage fewer, the stage at [`LIFT_STAGE_HZ`] until the new
//! load bounces, its ring's means. Not at once: only if the boom is still
//! not seen moving [`STEADY_CONFIRM_S`] later (the watch follows the new
//! load's peak and bounce meanwhile, so that its reading starts where it
//! would have). Every filter it reads runs always, so the wait only starts
//! the faster reading 0.3 s later, where it stands as it would have.
//!
//! Why those bounds (each measured on the whole field suite):
//!
//! - **The rise, 30 % over the band's top.** A winch started hard pulls a
//!   fifth more for a quarter second (`host-sim` test
//!   `hard_hoist_starts_and_stops_*`); half again over that stays clear of
//!   it. Read from a rise of 10 % above the recent average (tried), 90 %
//!   hoisted hard with the boom still was cut in 8 of 9 cases (6 of 9).
//!   `tests::a_load_added_to_a_steadily_hanging_one_is_read_as_a_lift_off`
//!   holds a pull of a fifth for a quarter second no lift-off.
//! - **The band, 20 % wide; its top kept once steady.** A load swinging on
//!   a long rope after its lift-off rings by some per cent for long: with a
//!   10 % band (and the rise counted from its low), 50 % taken to 110 %
//!   12 s after its snatch at 65° on the thesis's and the longest rope was
//!   never steady, and cut 1.01 s after. A top that went on widening would
//!   let a rise through the band first: it would take 50 % above the low,
//!   not 30 % above the top, to be read as a lift-off.
//! - **The wait, 0.3 s.** A raise's start lifts the force as much before
//!   the angle shows it: the boom and the load accelerate (10° → 50° in
//!   10 s, linear, a 1 s ramp: 34 % of the load's part 0.25 s into the
//!   ramp, the boom still "settled" by its filtered rate). Read as a
//!   lift-off at once, 85 % of rated raised from 10°–30° in 10 s (`host-sim`
//!   test `no_false_overload_at_85_percent_over_other_ranges`) read up to
//!   u 0.945 where it read 0.90 (the tried 30 % over a 10 % band: up to
//!   0.947 in `no_false_overload_at_85_percent_*`). The boom is seen moving
//!   0.05–0.1 s after such a rise behind the simulator's angle sensor, and
//!   0.16 s after behind one that lags 0.3 s (the campaign's slowest): with
//!   a wait of 0.15 s, 1.6 t raised from 10° there read 1.52 × itself for
//!   a sample (`crane-sim campaign --seed 1 --only 1022`, estimated u 0.71
//!   at a true 0.47). With 0.3 s, every campaign scenario of seed 1 reads
//!   as before but five hooks of 0.5 t, up to 0.0013 of rated higher.
//! - **The seals' F_up on top.** Of a light load's part of the force the
//!   seals' friction is a large share: 30 % of rated raised 40° → 80° in
//!   10 s read up to u 0.330 where it read 0.316 without it in the rise.
//! - **Not while the seals' breakaway is held** ([`crate::breakaway`]: the
//!   angle already shows the boom rising, before the direction detector
//!   calls it a raise). A rise read then is the raise's start, and the
//!   limiter drops it ([`StaticLoadBank::raise_starts`]): the breakaway,
//!   taken out of f₁ in one step, looked like the new load's bounce and
//!   then like a ring breaking upward, which opens the lift window at once.
//!   1.4 t raised 7° → 54° in 17 s, begun 2 s after power-up, read 1.55 ×
//!   itself for a sample (estimated u 0.645 at a true 0.416; `crane-sim
//!   campaign --seed 1 --only 6956`, with the seals' release learned by
//!   the calibration, 0.1 s then, 0.2 s now: the breakaway was held 0.4 s into the raise;
//!   with the default 0.5 s the seals had not released by then, and it was
//!   not). Now as before, u 0.450.
//!
//! Measured (`host-sim` field tests, f64 and f32 alike; the whole suite
//! run before and after, every printed figure compared): loads added 5 s or
//! 12 s after their lift-off (`loads_added_to_hanging_loads_are_cut_*`) are
//! cut within the second but in one case of 72: 1.02 s after, on the 3 m
//! rope at 65° 5 s after its snatch, whose ring rides on the swing the
//! boom's give starts (nearly half the load's pull peak to peak) and is
//! never steady (the next section's).
//! Outside 65°–80° taken up in 0.1 s, within 0.83 s (0.94 s); 90 % never.
//! The only other figure that moved: 90 % lifted 12 s after an empty-hook
//! raise on the thesis's rope, an OVERLOAD already
//! (`a_load_lifted_long_after_an_empty_hook_move_known_gap`: the ropes hang
//! still and its swing's crest reads as a rise), reads at least 1.011 of
//! itself 3–6 s after (1.008). `crane-sim campaign` (10 000 scenarios):
//! seeds 1, 12 and 18 and `--wide` summarize as before.
//!
//! ## A load added to one that rings on: a rise over all it did
//!
//! The steady band asks a load to hold f₁ within 20 % of its part for a
//! second. On the 3 m rope at 65°, 50 % of rated snatched in 0.1 s rings on
//! at 2.5 Hz for seconds, f₁ between 165 and 299 kN (the empty hook's
//! 73 kN): the ring rides on the swing the boom's give starts, grows over
//! its first crests (so the ring's follower lets it go within the lift
//! window) and is never steady. 110 % added to it in 0.1 s 1.5–5 s after
//! the snatch rose through the four filter stages and the stage S, and was
//! cut 1.01–1.14 s after its take-up ended (5 cases of the field suite).
//!
//! So from a lift-off's first crest on, before any move, the watch also
//! keeps the **span** of f₁ (`widen_span`): its lowest s_lo and its highest
//! s_hi since. A crest over s_hi joins the span only once f₁ has come back
//! from it by ½·[`STEADY_RISE`]·(s_lo − F_0), half the margin below (or
//! into the span): a rise that goes on, ringing as it rises, is measured
//! against the top before it. Once the
//! span is [`STEADY_S`] old, a rise
//!
//! f₁ > s_hi + [`STEADY_RISE`]·(s_lo − F_0) + F_up(f₁)
//!
//! is read as a lift-off from s_lo, as a rise out of the steady band is,
//! after the same wait ([`STEADY_CONFIRM_S`]). The span holds the
//! lift-off's highest crest since its first, which no decaying ring passes
//! again; the margin over it is the steady band's (a winch started hard,
//! a raise's start, the seals). It starts at the first crest, not when
//! the lift window closes: from there, a load added 1.5 s after its snatch
//! would find a span 0.3 s old.
//!
//! A crest joins the span once f₁ has come back by half the margin, not at
//! once: joined at the first sample f₁ fell (tried), the field suite read
//! as now, but 3 t added to 3 t that rang on (the test below), the new
//! ring against the old, stalled on its way up, set the top there and was
//! seen 0.04 s sooner than without the watch. Joined once f₁ was halfway
//! back to the old top (tried), 60 % snatched at 20° and taken to 90 % 1 s
//! later was cut in 2 of its 6 cases (f64).
//!
//! Measured (`host-sim` field tests, f64 and f32 alike; the whole suite
//! run before and after, every printed figure compared: only these
//! changed): loads added to ringing lift-offs
//! (`loads_added_to_ringing_lift_offs_are_cut_*`) are cut within the second
//! but in one case: 1.05 s after (1.05 s before), 90 % of rated snatched on
//! the 3 m rope at 80° and taken to 110 % 3 s later, a rise of a fifth of
//! the load that no margin over a winch's pull can tell; outside 65°–80°
//! taken up in 0.1 s, within 0.90 s (0.97 s). Loads added to loads hanging
//! steadily (`loads_added_to_hanging_loads_are_cut_*`) are all cut within
//! 0.73 s (1.02 s); 90 % is never cut. `tests::a_load_added_to_one_that_rings_on_is_read_as_a_lift_off`:
//! 3 t ringing on at 1.5 Hz, its amplitude growing over the first crests,
//! and 3 t more added 3 s or 5 s after its lift-off are read at 0.95 of the
//! 6 t 1.06 s and 0.92 s after they are added (1.20 s and 1.26 s without
//! the watch); the ring alone is never read as a lift-off. `crane-sim
//! campaign` (10 000 scenarios): seeds 1, 12 and 18 and `--wide` count the
//! same missed, early, late and false OVERLOADs, and the bands move in the
//! sixth decimal; on seed 1 three hooks of 0.55–2.5 t read up to 0.0097 of
//! rated higher (#9566: 0.95 t taken up in 5.9 s and raised 51° → 57° in
//! 21 s reads u 0.153 at most at a true 0.126, 0.143 before: a slow
//! raise's start read as a lift-off).
//! `tests::a_load_added_to_a_steadily_hanging_one_is_read_as_a_lift_off`:
//! 3 t more added to 3 t hanging steadily is read at 0.95 of the 6 t 0.83 s
//! after, 1.27–1.29 s through the four stages.
//!
//! ## At rest after a move: the force without the lag
//!
//! After a move the ropes' swings disagree, but the boom is just as still,
//! and the lag only delays what the force shows. The pendulums are driven
//! by the lagged angle, and a pendulum is linear in its drive: each swings
//! as the true one would, seen through the sensor's first-order lag τ (at
//! the swing's ω, amplitude 1/√(1 + ω²τ²) and phase −atan(ωτ): 0.93 and
//! 21° for a 6 m rope behind a 0.3 s sensor). (1 + τ·d/dt) undoes that:
//! with the tip still, φ + τ·φ̇ and φ̇ − τ·(g/l)·sin φ
//! ([`crate::held_pendulum`]). So at rest after a move, once the boom has
//! settled (the rate within [`SETTLED_RAD_S`], where the pendulums are no
//! longer driven either: [`SWING_DEADBAND_RAD_S`]), every
//! hypothesis solves the force without the lag with the factor of its swing
//! so led, and W_fast, the averages, the hold and the load-added rescale
//! below go on as before with those W_k. A load added at rest (40° → 60°,
//! held ropes of 5.95–14.8 m, 110 % taken up in 0.5 s, crane 10 of the
//! campaign) was cut 1.18–1.24 s after its take-up behind a 0.3 s sensor
//! and 0.93–0.98 s behind the 0.111 s default; now 0.84–0.88 s and
//! 0.81–0.86 s. (Turning each swing forward by ωτ instead restored the
//! phase only: the ropes read 7 % too little swing, and the 5.95 m rope
//! lost its consistency.)
//!
//! ## At rest after a move: a load added, seen at once
//!
//! W_now follows a heavier load only at the averages' pace while the wrong
//! ropes swing on, and the hold does not rise with it. So at rest after a
//! move (of at least [`MOVE_FOR_HOLD_S`]) each hypothesis also keeps its
//! fast reading S_k(W_k), its ratio to its own average ρ_k = S_k(W_k)/W̄_k
//! and how far that ratio strays from 1, D_k ([`crate::load_jump`]). The
//! true rope's W_k is constant while the load is, and a change of the load
//! multiplies every W_k at once; so the consistent ropes (D_k near the
//! lowest) vote, their lowest ratio ρ is no more than the load's, and from
//! ρ ≥ 1.1 on, for 2 s, every average and the held weighing are multiplied
//! by ρ > 1 and the held weighing is raised to the voters' lowest S_k(W_k):
//!
//! W̄_k ← ρ·W̄_k,  W_hold ← max(ρ·W_hold, min_voters S_k(W_k)),
//! W_slow,stop ← ρ·W_slow,stop.
//!
//! It only raises. It needs a rope of the bank that follows the true swing
//! (D_k ≤ 0.03): on the grid or near it, or a swing small enough; a short
//! rope stopped at 80° (at 60°, see the next section) or a rope between the
//! grid's lengths at 80° has none, and a load added there is followed at the
//! averages' pace as before (`host-sim` test
//! `a_load_added_at_rest_after_a_move_known_gap`).
//!
//! **A load added, held.** The rescale's weighing is held as long as a
//! move's: each rescale starts the [`REST_HOLD_S`] of the hold (and of the
//! provisional reading, below) again. Held only until 20 s after the
//! stop, a load added 14 s after a raise to 70° or 80° on the paid-out rope
//! (9–25 m long, a swing of 6–10 s) was cut 0.8 s after its take-up and
//! released at the hold's end, at a true u of 1.10: the lowest average had
//! sunk to 0.79 of the new load, and the mean over one swing period weighed
//! it only 8 s later (`host-sim` test
//! `a_load_added_at_rest_on_the_paid_out_rope_*`). Within 20 s of the take-up
//! that mean is found (P·4/3 and a second of confirmation, 14.3 s at the
//! bank's longest period) and is the weighing from then on.
//!
//! **A load lifted after a move with the hook empty.** The averages weighed
//! the empty hook (under [`load_jump::MIN_AVERAGE_KG`]), so there is no
//! ratio to rescale by, and the load swings on as the hook did (the
//! simulator's load inherits the hook's swing): the averages climbed from
//! nothing at their own pace, and a 110 % load, cut as it left the ground,
//! read 0.38–0.81 of itself 5 s later (WARNING again: the paid-out rope
//! after 20° → 70° and 40° → 56°). So at rest after a move whose last
//! weighing was under that mass, every average is kept at or above W_fast,
//! as while the ropes agree (W̄_k ← max(W̄_k, W_fast)), and the rescale is
//! off. W_fast is the lowest any rope reads, and the bank reports it anyway:
//! this holds the reading's crests at the averages' pace, it never raises
//! them. Now 0.92–1.06 of the load 3–6 s after it leaves the ground
//! (`host-sim` test `a_load_lifted_after_an_empty_hook_move_*`). Where every
//! rope of the bank reads high at the swing's crest (20° → 70° on a 6 m
//! rope, between the grid's 5.9 m and 7.3 m: 7 % high), W_fast itself
//! reads 90 % of rated as an OVERLOAD, with or without this
//! (`a_load_lifted_after_an_empty_hook_move_known_gap`).
//!
//! ## At rest after a move: the boom's give
//!
//! A rope on the grid follows the true swing only if its period is the
//! load's, and the loaded boom gives: the load swings as on a rope longer
//! by c·sin²θ·g·W ([`crate::held_pendulum`], "The boom's give"; 0.1 m for
//! 3.2 t at 60° on the COLES 930). Settled, every pendulum of the bank is
//! lengthened by the give of the move's weighing (the load it swings with;
//! a load added is seen within about a second, before a period off by a
//! few per cent turns into phase). A 3 m rope stopped at 60° then keeps a
//! consistent rope: 110 % added 14 s after the stop is cut 0.99 s after
//! the take-up (1.38 s with rigid pendulums) and 90 % is no OVERLOAD (0.95 s
//! of OVERLOAD at a true 0.90 before); added 3 s after, with the seals'
//! friction 0.96 s (1.93 s; with constant friction still 1.93 s). The give
//! is the boom's bending alone; a real crane's cylinder, pins and chassis
//! add to it, never take from it, and on the bank's own ropes a load added
//! at rest is seen within 1 s on a boom that gives 1 to 2.5 times the
//! model's (rigid pendulums: a rigid boom to 1.5 times; test
//! `a_load_added_at_rest_is_seen_on_a_boom_that_gives_up_to_twice_the_models`).
//! Not in motion (see the pendulum module) and not with the reading of the
//! moment: that follows the swing after a load is added, and with it a
//! 110 % load lifted after an empty-hook raise to 70° on the paid-out rope
//! read 0.897 of itself 5.9 s after the lift instead of 0.916.
//!
//! ## Settled after a move: the mean over one swing period
//!
//! The ropes predict the swing from the boom's motion; where none follows
//! it, their readings follow the swing, not the load. Settled, the force
//! itself weighs the load once it repeats: its mean over one swing period
//! is the force of the load hanging still, whatever the rope
//! ([`crate::period_mean`], which finds the period). While the ropes
//! disagree and the force still repeats, that mean is the weighing;
//! otherwise it, and a load added to a steady swing read from the force's
//! ratio to one period earlier, are floors under the bank's reading. A
//! 110 % load added 3 s after a raise to 80° on a 6 m rope, never held cut
//! before, is cut from 8.5 s after the take-up; added 14 s after, from 2.7 s
//! (`host-sim` test `a_load_added_where_no_rope_follows_the_swing_*`).
//!
//! ## Settled after a move: a load added, weighed by its swing
//!
//! The mean over one swing period weighs a load added at rest only once the
//! step is older than P·4/3 and a second ([`crate::period_mean`], "When the
//! load changes"): 9 s on an 8.9 m rope, 10.6 s on a 13 m one. Until then,
//! where no rope of the bank follows the swing, the reading is the held
//! weighing of the old load and the ropes' crests. So once W_fast passes the
//! held weighing by [`load_jump::JUMP`] at rest after a move (the ropes
//! disagreeing, within [`REST_HOLD_S`]), the bank follows the force at
//! factor 1 and reads the midrange of its last crest and trough that turned
//! ([`crate::swing_midrange`]): the pull at the two turning points of a
//! swing of amplitude φ₀ averages to W·cos²φ₀, the load or a little less,
//! whatever the rope. It is a floor under the reading and under the
//! averages the next move starts from, until the mean over a period weighs,
//! the ropes agree, the boom moves or the hold ends. It needs half a swing
//! to a period and two thirds after the following begins, and a turn: 110 %
//! added where no rope follows is cut at most 8.6 s after its take-up
//! instead of 12.0 s (`host-sim` test
//! `a_load_added_at_rest_where_no_rope_follows_is_cut_within_9_s_*`), on
//! the paid-out rope 3 s after a raise at most 10.3 s after instead of
//! 14.3 s (6.1 s since the calibration learns the seals' release after a
//! raise, [`crate::seal_release`];
//! `…_soon_after_a_raise_is_cut_within_6_5_s_*`), 90 % never an
//! OVERLOAD. W_fast passes the held weighing late, though (it is the lowest
//! rope's reading, through a stage): on an 8.9 m rope at 80° the following
//! began 1.15 s before the new load's first crest, and the midrange of it
//! and the next trough is read about 5.8 s after the take-up began, 0.2 s
//! before a lowering begun 5 s after the 1 s take-up: cut within the bounds
//! (`a_lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop_*`; 1.13
//! before [`crate::swing_midrange::HALF_SWING_S`] was 1.0 s).
//!
//! **Into the move.** A lowering begun before the trough after that crest
//! started from the old load's weighing (the move ends the rest's
//! following) and was cut up to true u 1.105, 4 s after the take-up on the
//! 3 m and the 8.9 m ropes rated at 45°: the move's averages climbed to the
//! new load only 9 s into it. So a lowering that doubts its start (above,
//! "A load added at rest that nothing weighed") goes on following for
//! [`MIDRANGE_CARRY_S`], longer than half the longest rope's period: W₁ is
//! the load the force reads at factor 1 at the moving boom's angle, put back
//! into the rest's force by the rest's F_0 + F_W(W) (the pull's units must
//! not change with the angle: the load's arm grows by three quarters from
//! 80° to 72°), and
//! the midrange of the rest's crest and the trough in the move is a floor
//! under the reading and the averages as at rest. A lowering's start only
//! deepens the trough (the load sinks with the tip), so the floor errs low;
//! a raise's lifts it, and a raise brings the load in: it ends the
//! following as before.
//! Those lowerings are now cut from true u 0.952–0.980; begun 2–3 s after
//! the take-up, where W_fast had not passed the old weighing at rest and
//! nothing doubts it, still up to 1.082
//! (`a_lowering_2_to_10_s_after_a_load_added_at_rest_known_gap`). The
//! midrange alone does not doubt a weighing: followed from every loaded
//! stop, it read a 6 m rope's new load there, but between the steps of an
//! inched lowering on a rope as long as the tip is high it read 1.4 × the
//! load (W₁'s ring at 0.45 Hz stayed above the load through a 4 s pause),
//! and four of those lowerings were cut from true u 0.804.
//!
//! ## Settled, but for the angle's noise
//!
//! Settled is the filtered rate within [`SETTLED_RAD_S`] (0.05 °/s), and a
//! noisy pendulum takes a still boom's rate over it now and then: behind
//! three times synth's noise (0.09°) for 0.07–0.25 s about every second.
//! What follows the force over seconds at rest goes on through such an
//! excursion for up to [`UNSETTLED_GRACE_S`]: the mean over one swing
//! period and the swing's midrange (each excursion started them again, and
//! neither ever weighed), the force and the pendulums without the sensor's
//! lag, the give that lengthens the pendulums (each excursion switched them
//! to their other reading and back), and the provisional overload. A creep,
//! which lasts, starts them again after that, as before; the ropes never
//! agree while the rate is over [`SETTLED_RAD_S`], so a creep's sliding
//! friction stays out of the averages at once. Before, behind 0.06–0.09°
//! of noise, 110 % added at rest where no rope follows (the 13 m rope at
//! 80°) was left uncut for 18.3 s instead of 8.6 s, and 90 % on the 3 m
//! rope at 60° was an OVERLOAD at true u 0.900 10–17 s after its take-up
//! (`host-sim` test
//! `a_load_added_at_rest_where_no_rope_follows_behind_angle_noise_*`).
//! Going on with the followers alone and not with the lag and the give
//! made four such OVERLOADs at 0.09° instead of two. Behind synth's own
//! noise (0.03°) the excursions are rarer, and a load added at rest where a
//! rope follows the swing is cut 0.03–0.04 s sooner than before (40° → 60°
//! on the 5.95 m rope: 0.88 s after its take-up, now 0.84 s).
//!
//! ## Switched on while the load swings
//!
//! The ropes swing with the moves the bank has seen. Switched on while the
//! load swings (a power cut or a watchdog reset right after a move; a
//! fault that broke the angle, [`StaticLoadBank::reset`]; a limiter
//! switched on in motion that has seen the boom stop), it has seen none:
//! every rope hangs still, they agree, and the swing reads as load. 85 % of
//! rated after a 10 s move read 1.2–1.5 × the load at 40° and up to 3.1 ×
//! at 80°, an OVERLOAD for 18–30 s of a 30 s rest on the 3 m and 10 m held
//! ropes (`host-sim` test `power_up_with_the_load_swinging_*`).
//!
//! Whatever swings the load, the force over one of its periods averages to
//! the load hanging still ([`crate::period_mean`]). So the mean runs at rest
//! before any move too, and there, while it is found, the force still
//! repeats it ([`PeriodMean::steady`]) and it swings by more than a steady
//! bin may change either side of the mean ([`PeriodMean::swings`]: 3 % of
//! the load's part and 1 kN; a swing the readings of the moment would show),
//! it **is** the weighing although the ropes agree: no rope predicts a
//! swing, so none is right. The averages are set to it (not only raised:
//! they hold the crests the agreeing ropes raised them to), so a move
//! starts from it. Before any move it is no floor and the period mean's
//! step ([`PeriodMean::step_n`]) is not read, so a still load lifted at
//! power-up is weighed as before: the mean needs a repeating swing, and a
//! load taken up, a step of the force, ends it at once (the readings of the
//! moment, which follow the force without delay, count again). From 12 s
//! after power-up those cases read 1.037–1.049 × the load at p5,
//! 1.038–1.078 at p95, no OVERLOAD. Until the mean is found (P·4/3 and 1 s
//! of confirmation: 5.6 s on a 3 m rope, 9.4 s on a 10 m one) the crests
//! still read as load: OVERLOAD for 4.8–10.6 s. On a 3 m rope at 80° the
//! swing's inward pull takes p1 under its range at every trough, each
//! FAULT starts the mean again, and it never weighs
//! (`power_up_with_the_load_swinging_known_gap`).
//!
//! ## At rest after a move: an overload stands
//!
//! Until the mean over a period is found, a load swinging at rest where no
//! rope of the bank follows it is read through the ropes' swings, high at
//! their crests and low between: a 110 % load added 3 s after a raise was
//! cut at a crest and released at the next low, and held cut only once the
//! mean was found (5.6 s after the take-up on a 3 m rope at 60°, 8.6 s on a
//! 6 m rope at 80°). The crest is no false reading of an added load (every
//! rope reads the force that grew); the low is. So the bank marks its
//! reading [`StaticLoad::provisional`] while, within [`REST_HOLD_S`] of a
//! move of at least [`MOVE_FOR_HOLD_S`], the boom is settled, the ropes
//! disagree and no mean is the weighing; the limiter lets such a reading
//! set an OVERLOAD but not clear it
//! ([`crate::state_machine::CycleInput::Provisional`]). The cut then holds
//! from the first OVERLOAD (1.9 s and 4.5 s there). It clears once the ropes
//! agree, the mean weighs, the boom moves or [`REST_HOLD_S`] has passed; a
//! false OVERLOAD at a crest lasts that much longer (90 % lifted on a 6 m
//! rope after an empty-hook raise to 70°: 5.3 s instead of 2.9 s).
//!
//! ## The averages carry the rest's weighing into the next move
//!
//! At rest after a move the reading is the held weighing or the mean over
//! one swing period, but the averages W̄_k go on taking in the W_k of ropes
//! that read the swing wrong, and sink: after 20 s at 80° on a 3 m rope to
//! 0.64 of the load, while the reading stood at 1.035. A move then started
//! from them (the hold and the mean end with the rest): lowering 80° → 20°
//! right after, the load read 0.67 of itself, overloads were cut at true u
//! 1.055–1.064, and six released their OVERLOAD at a true u over 1.05
//! (`host-sim` test `a_lowering_after_a_raise_and_a_rest_*`, 48 cases). So
//! while the mean over one swing period is the weighing, every average is
//! raised to it, and when the boom starts moving while the last move's
//! weighing is still held, every average and W_slow are raised to W_slow as
//! it stood at that move's stop: a move starts from no less than the rest's
//! weighing. Both only raise (a load set down is followed as before, at the
//! averages' pace, or at once after [`EMPTY_HOOK_S`] of an empty hook), and
//! neither changes a reading at rest. Now those lowerings read no less than
//! 0.985 of the load and are cut at true u 0.83–1.01 (the 3 m rope 3 s
//! after its stop at 80° cuts early, as before; the 8.9 m rope after 20 s at
//! rest at 0.907, before 1/1.1, where it was 0.920 with the sunk averages).
//! The cost was in a lowering inched in short steps, where the averages that
//! sank in a pause had read the last move high: it was cut early in 10 of 64
//! cases (true u 0.804–0.908) instead of 7; re-measured after the later
//! changes, 3 of 64 (0.883–0.908, `inched_lowering_known_gap`). Raised to the
//! held weighing instead of W_slow at the stop, 12 were. No
//! inched lowering is cut late (`an_inched_lowering_is_cut_*`). The
//! rescale of a load added at rest (below, "At rest after a move: a load
//! added, seen at once") multiplies W_slow at the stop by its ρ as it does
//! the averages and the held weighing: the next move starts from the new
//! load. Until it did, a lowering begun 7 s after 60 % of rated became
//! 100 % (3 s after a raise to 80° on the paid-out rope, seal friction)
//! started from the averages, which had sunk at rest to 0.93 of the new
//! load, and was cut at true u 1.063; now from 1.023
//! (`a_lowering_2_to_10_s_after_a_load_added_at_rest_*`). A load
//! added at rest and read from the force's ratio to one period earlier
//! (the period mean's step) is taken up by the averages too, as the
//! rescale's is: lowered 80° → 20° after 60 % of rated became 100 % 14 s
//! after the stop, the 8.9 m rope was cut at true u 1.079–1.085, the
//! lowering starting from the old load's averages; now within the bounds
//! (`a_lowering_after_a_load_added_at_rest_*`). Added 3 s after the stop,
//! before the period is known, where no rope follows the swing, the swing's
//! midrange weighs it 5 s after its take-up (above), not sooner: lowered
//! 2–3 s after the take-up, ropes that nothing doubts are cut up to true u
//! 1.082 (4 s after, 1.105 before the midrange went on into such a move,
//! 1.164 before it took up W_fast, above); and
//! lowered 6–7 s after, several ropes are cut early, from 0.887
//! (`a_lowering_2_to_10_s_after_a_load_added_at_rest_known_gap`).
//!
//! ## A load set down: the ropes hang still again
//!
//! The pendulums are undamped, which is right while a load hangs: it swings
//! on. A load set on the ground swings no more, and one lifted from it
//! leaves the ground hanging still under the tip. The bank kept the swings
//! of every move before, and over a working shift (a load lifted at 40°,
//! raised to 70°, lowered, set down, again and again) each cycle's moves
//! added their swings to the last ones': the highest reading of a cycle at
//! a true u of 0.60 ranged 0.59–0.91, a cycle read 0.60 of its load at rest
//! at 70°, and after four cycles a 110 % load lifted at 40° was cut 7.6 s
//! after it left the ground and read 0.83 of itself (after 24 h in f32 it
//! was never cut; `host-sim` test `a_shift_of_work_*`). So once the boom
//! has been still for [`EMPTY_HOOK_S`] with the force under an empty
//! hook's, F − F_0 < F_W'·[`load_jump::MIN_AVERAGE_KG`] (the load at factor
//! 1 under 500 kg), every rope hangs still and the bank weighs as after
//! power-up: the ropes agree, the averages follow W_fast, nothing is held
//! and the period's mean weighs only a swing that repeats (see "Switched on
//! while the load swings"), so the next lift-off is weighed as the first
//! (now the same sample after 24 h as switched on, 0.77 s after it leaves
//! the ground). A swinging load never reads that light for that long: its
//! pull dips under an empty hook's for less than half a period (4.7 s at
//! 22 m), and on the bank's own ropes at 60° and 80°, 3 t for 1.2 s at most
//! (test `a_swinging_load_is_never_taken_for_an_empty_hook`). An empty
//! hook's swing pulls nothing on the cylinder, so nothing is lost while it
//! is empty. A load hung on a hook that still swings (the simulator's lift
//! after an empty-hook move, whose load inherits the massless hook's swing)
//! within [`EMPTY_HOOK_S`] of the stop is followed as before; lifted later,
//! the ropes hang still, its swing's crests read as load, and 90 % of rated
//! cuts (`host-sim` test
//! `a_load_lifted_long_after_an_empty_hook_move_known_gap`; before, 110 %
//! after a raise to 70° read 0.74 of itself there and was never cut).
//!
//! The cost per cycle: [`HYPOTHESES`] pendulums (one 10 ms sub-step at
//! 100 Hz each), as many solutions of a quadratic, four filter stages and
//! one division (the ratio ρ_k); at rest after a move as many factors of
//! the led swings (a sine and cosine polynomial each); settled, the period
//! mean's share of its search (before any move too); no heap, fixed loops.

use crane_model::loads::load_model::Quadratic;
use crane_model::Real;

use crate::held_pendulum::{BoomTip, HeldRopes, PaidOutRope};
use crate::filter::stage_gain;
use crate::load_rise::{Reading, RiseFollower};
use crate::load_jump::{self, Consistency};
use crate::period_mean::PeriodMean;
use crate::swing_midrange::SwingMidrange;
use crate::swing::SwingGeometry;

/// Boom rate under which the ropes' pendulums are not driven (rad/s;
/// 0.05 °/s). The pendulums are undamped, and the acceleration of a still
/// boom is the angle sensor's noise (its filtered rate stays under
/// 0.03 °/s at 0.035° of noise): driven by it, their swings grew like a
/// random walk. After an hour at rest at 80° the lowest rope read 0.83 of
/// the load, and a 110 % lift-off then read 7–11 % lower than at power-up
/// (test `long_uptime`; WARNING, not OVERLOAD, 1 s after it left the
/// ground, in a synthesized log); at 85° five
/// seconds of noise read a lift-off 3.4 % low, and it was cut 1.26 s after
/// leaving the ground. Beyond it the pendulums get the rate less the
/// deadband and the full acceleration (the deadband's derivative): a move
/// loses 0.05 °/s of its start and of its stop, 2–5 % of the swing of a
/// 1–3 °/s move.
pub const SWING_DEADBAND_RAD_S: f64 = 0.05 * core::f64::consts::PI / 180.0;

/// Hanging lengths of the held-rope hypotheses (m).
pub const HELD_LENGTHS_M: [f64; 10] = [
    3.0, 3.75, 4.6875, 5.859, 7.324, 9.155, 11.444, 14.305, 17.881, 22.352,
];

/// Number of hypotheses: the paid-out rope and the held lengths.
pub const HYPOTHESES: usize = 1 + HELD_LENGTHS_M.len();

/// How long after the bank starts the stage S and the averages follow the
/// lowest reading W_fast both ways (s). The force filter starts from the
/// mean of its samples so far ([`crate::filter::LowPass::starting_from_the_mean`]),
/// whose noise falls as 1/√n; the averages, raised to W_fast but lowered
/// only at their pace, kept the first sample's noise for seconds (see the
/// module doc, "Power-up"). Short: a move that starts this soon after
/// power-up and passes the power-up check (under 0.2° in 0.3 s) dips the
/// force by little in it.
pub const FIRST_SAMPLES_S: f64 = 0.1;

/// Time constant of each stage of the slow average W̄_k (s): longer than
/// the swing of the longest rope (9.5 s period at 22 m) over 2π.
pub const SLOW_TAU_S: f64 = 3.0;

/// Number of first-order stages of the slow average.
pub const SLOW_STAGES: usize = 2;

/// The hypotheses agree when their factors are within this fraction of each
/// other (a still boom with no swing predicted): the averages are then set to
/// W_fast.
pub const AGREEMENT: f64 = 0.005;

/// Boom rate above which the bank counts the boom as having luffed (rad/s,
/// 0.15 °/s: the limiter's start-of-motion threshold). Before the first
/// luff no hypothesis has a swing of its own (what the pendulums would show
/// then is the angle's noise, which at 80° spread the factors by over 1 %
/// before [`SWING_DEADBAND_RAD_S`]), so all agree.
pub const MOVING_RAD_S: f64 = 0.15 * core::f64::consts::PI / 180.0;

/// Boom rate (rad/s, 0.05 °/s: the limiter's stop threshold) above which
/// the ropes never agree: a boom creeping under [`MOVING_RAD_S`] carries the
/// seals' sliding friction in its force until the limiter sees it move
/// ([`crate::load_estimate::DirectionThresholds::creep_s`]), and the
/// averages must not take that for the weighing (raising at 0.13 °/s, they
/// did: 1.055 × the load, OVERLOAD at true u 0.898).
pub const SETTLED_RAD_S: f64 = 0.05 * core::f64::consts::PI / 180.0;

/// How long a still boom's filtered rate may stay over [`SETTLED_RAD_S`]
/// and the boom still count as settled for what follows the force over
/// seconds at rest (s): the mean over one period, the swing's midrange, the
/// force and the pendulums without the sensor's lag, the give, the
/// provisional overload (see the module doc, "Settled, but for the angle's
/// noise"). Three times synth's angle noise (0.09°) takes the rate over
/// 0.05 °/s for 0.07–0.25 s about every second; a creep lasts longer. The
/// ropes' agreement keeps to [`SETTLED_RAD_S`] itself.
pub const UNSETTLED_GRACE_S: f64 = 0.5;

// A settled boom is still and does not drive the pendulums: the lag can be
// undone from their free swings only then (see "At rest after a move: the
// force without the lag").
const _: () = assert!(SETTLED_RAD_S <= SWING_DEADBAND_RAD_S && SETTLED_RAD_S <= MOVING_RAD_S);

/// Cut-off of the one first-order stage W_fast goes through (Hz): the
/// load's bounce on the boom (1–2 Hz near rated load in a held rope, ±25 %
/// of the load's pull after a 10 s move stops) passes the force filter at
/// 0.06–0.35 and this stage at 0.33–0.57; it delays a lift-off by 0.23 s.
pub const FAST_SMOOTHING_HZ: f64 = 0.7;

/// How long after a loaded move stops W_fast and the still force's stage go
/// through a second [`FAST_SMOOTHING_HZ`] stage (s): the stop sets the load
/// bouncing on its rope at 1–2 Hz, and one stage passed its crests at up to
/// 1.065 × the load (see the module doc, "At rest after a move: the stop's
/// bounce"). Shorter than the 3 s after a stop at which a load added at rest
/// is first looked for in the tests, and long enough for the bounce to ring
/// down to what one stage keeps below the ×1.1 of an early cut.
pub const BOUNCE_WINDOW_S: f64 = 2.5;

/// Longest time the weighing of a move, or of a load added at rest, is
/// held at rest (s): two swings of the longest rope of the bank (9.5 s at
/// 22 m). See [`StaticLoadBank::update`].
pub const REST_HOLD_S: f64 = 20.0;

/// How long into a lowering that doubts its start (see the module doc, "A
/// load added at rest that nothing weighed") the swing's midrange begun at rest
/// goes on following (s): longer than half the longest rope's period (4.7 s
/// at 22 m), within which the trough after the crest the rest saw comes.
pub const MIDRANGE_CARRY_S: f64 = 5.0;

/// Spread of the possible ropes' factors (f_max/f_min − 1) beyond which the
/// force cannot weigh the load at rest and the move's weighing is held.
pub const UNUSABLE_SPREAD: f64 = 0.25;

/// Shortest motion after which the bank holds the move's weighing at rest
/// (s): a flicker of the rate at rest is no move.
pub const MOVE_FOR_HOLD_S: f64 = 1.0;

/// How long the boom must be still and the hook light (the force at factor
/// 1 under [`load_jump::MIN_AVERAGE_KG`]) before the ropes hang still again
/// and the bank weighs as after power-up (s; see the module doc, "A load
/// set down"): longer than half the longest rope's period (4.7 s at 22 m),
/// the longest a swinging load's pull can stay that low.
pub const EMPTY_HOOK_S: f64 = 6.0;

/// A lift-off is followed until the load falls below this share of the
/// highest it reached (see [`StaticLoadBank`]'s module doc, "A lift-off:
/// the boom's give swings the load"): the take-up is over, and what moves
/// the force now is the bounce or the swing, not the hook load.
pub const LIFT_FOLLOWED_TO: f64 = 0.98;

/// How long after the hook last read empty (the force at factor 1 under
/// [`load_jump::MIN_AVERAGE_KG`], the boom still) the still force's load is
/// read through one filter stage fewer, before any move (s; see the module
/// doc, "A lift-off: one stage fewer"): a take-up of 0.5 s or less is cut
/// 0.85–0.95 s after that reading, and the first crest of a snatch's bounce
/// comes through about 1.5 s after it. Slower take-ups, and a raise begun as
/// one ends, read as before.
pub const FAST_LIFT_S: f64 = 1.2;

/// How long the hook must have hung empty (the force at factor 1 within
/// [`load_jump::MIN_AVERAGE_KG`] of nothing, the boom still) before a rising
/// load is followed as a lift-off (s): a swing whose pull nearly vanishes
/// at its troughs (at a steep boom) passes through nothing for a moment
/// only, and is no lift-off.
pub const EMPTY_BEFORE_LIFT_S: f64 = 1.0;

/// A lift-off bounces once the still force's first filter stage has turned
/// down from its highest by this fraction of its rise from the empty hook
/// (see the module doc, "A lift-off: read at once until it bounces"), and
/// each later turning point of its ring is passed once the force has come
/// back from it by as much ("A lift-off: the mean of its ring").
pub const LIFT_TURN: f64 = 0.05;

/// Until a lift-off bounces, the still force's load is read through a
/// stage at this frequency (Hz) instead of [`FAST_SMOOTHING_HZ`]'s (see
/// the module doc, "A lift-off: read at once until it bounces").
pub const LIFT_STAGE_HZ: f64 = 1.4;

/// While a lift-off's ring decays, W_fast and the still force's load are
/// read no higher than the load of the ring's highest mean times 1 + this
/// (see the module doc, "A lift-off: no higher than its ring").
pub const RING_CAP: f64 = 0.03;

/// A lift-off's ring has died once no turning point has been passed for
/// this long (s): twice the half period of a 1 Hz ring.
pub const RING_QUIET_S: f64 = 1.0;

/// A load hangs steadily once the still force's first filter stage has
/// stayed within [`STEADY_BAND`] of the load's force for this long (s).
pub const STEADY_S: f64 = 1.0;

/// The band a steadily hanging load's force stays within, as a fraction of
/// the load's part of the force.
pub const STEADY_BAND: f64 = 0.2;

/// A rise out of a steady band by this fraction of the load's part of the
/// force is read as a lift-off: half again over the fifth more a winch
/// started hard pulls (see the module doc).
pub const STEADY_RISE: f64 = 0.3;

/// How long the boom must stay still after such a rise before it is read
/// as a lift-off (s): a raise's start lifts the force as much before the
/// angle shows it, 0.16 s later behind an angle sensor that lags 0.3 s.
pub const STEADY_CONFIRM_S: f64 = 0.3;

/// Smallest factor 1 + h·a_Ly/g + tan θ·tan φ at which a hypothesis weighs
/// the load (below it, it is left out of W_fast; see the module doc).
pub const MIN_LOAD_FACTOR: f64 = 0.5;

/// The model's terms of one cycle, as [`StaticLoadBank::update`] takes them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadTerms<T> {
    /// The model's piston force at rest at the force's boom angle, as a
    /// function of W (N).
    pub at_rest: Quadratic<T>,
    /// The measured force less offsets, friction and the boom's inertia
    /// J·θ̈ (N): what F_0 + F_W·factor must equal.
    pub force_n: T,
    /// The same without the angle sensor's lag (N; `None` when there is
    /// none to give): read while the boom is still and every rope agrees
    /// (see the module doc).
    pub force_still_n: Option<T>,
    /// A raise's start, seen ([`crate::breakaway`]): the seals' part of
    /// the force's rise at rest is out of `force_n`, and the averages are
    /// set to the weighing without it.
    pub seals_hold: bool,
    /// Boom angle at the force's instant (rad).
    pub angle_rad: T,
}

/// Every rope's factor with the sensor's lag undone
/// ([`StaticLoadBank::led_factors`]).
#[derive(Debug, Clone, Copy, PartialEq)]
struct LedFactors<T> {
    held: [T; HELD_LENGTHS_M.len()],
    paid_out: T,
}

/// One hypothesis: which rope, and its slow average.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Hypothesis<T> {
    /// A held rope's index in the bank's [`HeldRopes`]; `None` for the
    /// paid-out rope, whose swing is the bank's `paid_out`.
    held: Option<usize>,
    /// The stages of the slow average W̄_k (kg); `None` while the
    /// hypothesis cannot weigh.
    slow_kg: Option<[T; SLOW_STAGES]>,
    /// Its consistency with a constant load ([`crate::load_jump`]).
    jump: Consistency<T>,
    /// Its average was the bank's weighing W_slow (the lowest) when it
    /// stopped weighing in motion: it starts again at W_slow (see the
    /// module doc).
    was_lowest: bool,
}

/// The bank of rope hypotheses (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticLoadBank<T> {
    geometry: SwingGeometry<T>,
    hypotheses: [Hypothesis<T>; HYPOTHESES],
    /// The held ropes' pendulums, advanced together.
    ropes: HeldRopes<T, { HELD_LENGTHS_M.len() }>,
    /// The paid-out rope's pendulum.
    paid_out: PaidOutRope<T>,
    dt_s: T,
    /// The smoothing stage of W_fast; `None` until the first load.
    fast_stage: Option<T>,
    /// The same stage on the load the force without the sensor's lag
    /// reads; `None` without that force.
    still_stage: Option<T>,
    /// The second stages of W_fast and of the still force's load, read for
    /// [`BOUNCE_WINDOW_S`] after a loaded move stops.
    bounce_stages: (Option<T>, Option<T>),
    /// Time left in the stop's bounce window (s; see [`BOUNCE_WINDOW_S`]).
    bounce_s: T,
    /// The boom has luffed since the bank started: swings may differ.
    moved: bool,
    /// The boom's rate at the last advance is below [`MOVING_RAD_S`].
    still: bool,
    /// The boom's rate at the last advance is below [`SETTLED_RAD_S`].
    settled: bool,
    /// How long the boom's rate has stayed over [`SETTLED_RAD_S`] without
    /// a break (s); see [`UNSETTLED_GRACE_S`].
    unsettled_s: T,
    /// At the last advance the boom was still and its rate over
    /// [`SETTLED_RAD_S`] for no longer than [`UNSETTLED_GRACE_S`]: the rest's
    /// followers of the swing go on.
    calm: bool,
    /// How long the boom has been moving without a pause (s).
    moving_s: T,
    /// How long the boom has been still (s), counted again from each
    /// rescale of a load added at rest (its weighing is held as long as a
    /// move's).
    still_s: T,
    /// The last load reported in motion (kg): the move's weighing, whose
    /// give lengthens the pendulums at rest (see "At rest after a move: the
    /// boom's give" in the module doc).
    last_kg: Option<T>,
    /// The move's weighing held at rest (kg); see [`REST_HOLD_S`].
    hold_kg: Option<T>,
    /// W_slow when the last move stopped (kg): where the next one starts
    /// while [`Self::hold_kg`] stands.
    slow_at_stop: Option<T>,
    /// W_slow of the last cycle (kg), where averages that start begin.
    slow_kg: Option<T>,
    /// W_slow from before the force was interrupted (kg): where the
    /// averages start again while the restarted filters settle (see
    /// [`Self::restart_averages`]); dropped once the bank weighs again.
    kept_kg: Option<T>,
    /// Time left to follow a load added at rest (s; see [`crate::load_jump`]).
    follow_s: T,
    /// A load added in motion, followed as it rises ([`crate::load_rise`]).
    rise: RiseFollower<T, HYPOTHESES>,
    /// At rest after a move of at least [`MOVE_FOR_HOLD_S`]: where a load
    /// added is looked for ([`crate::load_jump`]).
    after_move: bool,
    /// The move that ended carried (nearly) no load: its last weighing was
    /// under [`load_jump::MIN_AVERAGE_KG`] (see the module doc).
    light_at_stop: bool,
    /// How long the boom has been still with the force reading a light hook
    /// at factor 1 (s; see [`EMPTY_HOOK_S`]), or, below 0, how long since it
    /// last did (see [`FAST_LIFT_S`]; from power-up, as if long ago).
    light_s: T,
    /// The angle sensor's lag (s), by which the force without it leads the
    /// pendulums (see the module doc).
    lead_s: T,
    /// The mean force over one swing period while the boom is settled after
    /// a move ([`crate::period_mean`]).
    period_mean: PeriodMean<T>,
    /// Time advanced since the last [`update`](Self::update) (s): more than
    /// one step when the chain bridged a gap in the readings, whose force is
    /// no reading the period's mean may take.
    advanced_s: T,
    /// Time the bank has advanced since it started (s), counted up to the
    /// filters' start-up, [`crate::load_estimate::CREEP_AFTER_START_S`]
    /// (see the module doc, "Power-up").
    started_s: T,
    /// At the last [`update`](Self::update) every possible rope weighed and
    /// their factors agreed within [`AGREEMENT`]: no swing predicted.
    factors_agree: bool,
    /// At the last update the force swung (see [`Self::force_swings`]).
    force_swings: bool,
    /// The highest W_fast at rest since the last move stopped, or since the
    /// swing's midrange or the period's mean last weighed the load (kg): a
    /// load added there that nothing weighed shows in it.
    rest_peak_kg: Option<T>,
    /// This move started from a held weighing that W_fast at rest had
    /// passed by [`load_jump::JUMP`]: the rope that was the weighing
    /// restarts as any other, and the averages take up W_fast while every
    /// rope weighs (see the module doc, "A load added at rest that nothing
    /// weighed").
    weighing_doubted: bool,
    /// The load the force read at factor 1 at the last
    /// [`update`](Self::update) (kg).
    hanging_kg: Option<T>,
    /// The swing's midrange since a load was added at rest
    /// ([`crate::swing_midrange`]).
    midrange: SwingMidrange<T>,
    /// The force at rest as a function of W where the midrange was last
    /// followed at rest: a lowering that doubts its start goes on following
    /// in its units.
    midrange_terms: Option<Quadratic<T>>,
    /// The boom's filtered rate was negative at the last
    /// [`advance`](Self::advance): it is lowered, if it moves.
    falling: bool,
    /// While a lift-off before any move is followed, the highest load it
    /// has reached (kg), whose give the pendulums have taken (see the
    /// module doc, "A lift-off: the boom's give swings the load").
    lifting_kg: Option<T>,
    /// How long the boom has been still with the force at factor 1 within
    /// [`load_jump::MIN_AVERAGE_KG`] of nothing (s): an empty hook.
    empty_s: T,
    /// A lift-off's bounce (see the module doc, "A lift-off: read at once
    /// until it bounces"): the still force's first filter stage (N) at its
    /// lowest while the hook read empty, at its highest since, and whether
    /// it has turned down by [`LIFT_TURN`] of its rise.
    lift_base_n: Option<T>,
    lift_peak_n: Option<T>,
    lift_bounced: bool,
    /// Once a lift-off bounces, the bounce's last two turning points of the
    /// still force's first filter stage (N; the first is the empty hook's),
    /// the extreme since (the next turning point, once the force has turned
    /// from it), and the mean it rings about from the last three (N; see
    /// the module doc, "A lift-off: the mean of its ring").
    lift_turns_n: Option<(T, T)>,
    lift_run_n: Option<T>,
    lift_ring_n: Option<T>,
    /// The ring's highest mean so far (N), how long since its last turning
    /// point (s), and whether it has left the envelope of its last two
    /// turning points (a decaying ring never does; see the module doc, "A
    /// lift-off: no higher than its ring").
    lift_ring_top_n: Option<T>,
    lift_ring_quiet_s: T,
    lift_ring_broken: bool,
    /// The still force's load through the stage at [`LIFT_STAGE_HZ`] (kg),
    /// read until a lift-off bounces; it runs always, so it is settled when
    /// read.
    lift_stage: Option<T>,
    /// How long since a lift-off's ring broke upward, a load added to the
    /// one hanging, after its lift window (s, up to [`FAST_LIFT_S`]; see the
    /// module doc, "A load added while a lift-off rings: a lift-off again"),
    /// or since a steady load rose by [`STEADY_RISE`] less
    /// [`STEADY_CONFIRM_S`] (below 0 while the boom must stay still).
    rise_s: T,
    /// How long the still force's first stage has stayed within
    /// [`STEADY_BAND`] before any move (s), and how long it has been above
    /// that band since (s; see [`Self::watch_steady`]).
    steady_s: T,
    above_s: T,
    /// The lowest and highest of the still force's first stage since a
    /// lift-off's first crest, before any move (N), and for how long (s,
    /// up to [`STEADY_S`]; 0: no span); see the module doc, "A load added
    /// to one that rings on: a rise over all it did".
    span_lo_n: T,
    span_hi_n: T,
    span_s: T,
    /// The crest a rise over the span's top has reached, kept out of the
    /// span until the force comes back from it (N).
    span_crest_n: T,
    /// The force of the empty hook at the last update (N; `at_zero` of the
    /// still load equation).
    empty_hook_n: Option<T>,
}

/// The bank's answer of one cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticLoad<T> {
    /// The static hook mass (kg): max(W_fast, W_slow).
    pub load_kg: T,
    /// The lowest load any possible hypothesis reads now (kg).
    pub fast_kg: T,
    /// The lowest slow average (kg); `None` before any average runs.
    pub slow_kg: Option<T>,
    /// Settled within [`REST_HOLD_S`] of a move, the ropes disagreeing and
    /// no mean over one swing period found: the reading may follow the
    /// swing rather than the load, so an OVERLOAD it gives is not cleared
    /// on it (see the module doc, "At rest after a move: an overload
    /// stands").
    pub provisional: bool,
}

impl<T: Real> StaticLoadBank<T> {
    /// A bank with the load hanging still in every hypothesis.
    pub fn new(geometry: SwingGeometry<T>) -> Self {
        let make = |k: usize| {
            let held = k.checked_sub(1);
            Hypothesis { held, slow_kg: None, jump: Consistency::new(), was_lowest: false }
        };
        Self {
            geometry,
            hypotheses: core::array::from_fn(make),
            ropes: HeldRopes::new(HELD_LENGTHS_M.map(T::lit), geometry.gravity_m_s2),
            paid_out: PaidOutRope::new(geometry.gravity_m_s2),
            dt_s: T::lit(0.0),
            fast_stage: None,
            still_stage: None,
            bounce_stages: (None, None),
            bounce_s: T::lit(0.0),
            moved: false,
            still: true,
            settled: true,
            unsettled_s: T::lit(0.0),
            calm: true,
            moving_s: T::lit(0.0),
            still_s: T::lit(0.0),
            last_kg: None,
            hold_kg: None,
            slow_at_stop: None,
            slow_kg: None,
            kept_kg: None,
            follow_s: T::lit(0.0),
            rise: RiseFollower::new(),
            after_move: false,
            light_at_stop: false,
            light_s: T::lit(-FAST_LIFT_S),
            lead_s: T::lit(0.0),
            period_mean: PeriodMean::new(),
            advanced_s: T::lit(0.0),
            started_s: T::lit(0.0),
            factors_agree: true,
            force_swings: false,
            rest_peak_kg: None,
            weighing_doubted: false,
            hanging_kg: None,
            midrange: SwingMidrange::new(),
            midrange_terms: None,
            falling: false,
            lifting_kg: None,
            empty_s: T::lit(0.0),
            lift_base_n: None,
            lift_peak_n: None,
            lift_bounced: false,
            lift_turns_n: None,
            lift_run_n: None,
            lift_ring_n: None,
            lift_ring_top_n: None,
            lift_ring_quiet_s: T::lit(0.0),
            lift_ring_broken: false,
            lift_stage: None,
            rise_s: T::lit(FAST_LIFT_S),
            steady_s: T::lit(0.0),
            above_s: T::lit(0.0),
            span_lo_n: T::lit(0.0),
            span_hi_n: T::lit(0.0),
            span_s: T::lit(0.0),
            span_crest_n: T::lit(0.0),
            empty_hook_n: None,
        }
    }

    /// The same bank that, at rest after a move, reads the force without the
    /// angle sensor's lag `lead_s` (s) against its pendulums' swings with the
    /// lag undone (see the module doc).
    pub fn with_lead_s(mut self, lead_s: T) -> Self {
        let lead_s = if lead_s.is_finite() && lead_s > T::lit(0.0) { lead_s } else { T::lit(0.0) };
        self.lead_s = lead_s;
        self
    }

    /// Forgets the averages, keeps the swing (after a fault interrupted the
    /// force: the load swings on) and the move's weighing held at rest (it
    /// only ever raises the reading: a load added over the gap is read by
    /// the force as before). The bank's weighing from before the gap is
    /// kept too: the averages start again from it, as a rope that weighs
    /// again starts from W_slow (the load does not change in the air; a
    /// heavier one is W_fast's, and a lighter one is followed at the
    /// averages' pace). Started from the settled filters' W_k alone, the
    /// averages took up the ropes that read a lowering's swing low: after
    /// a 2 s logger dropout, 15 of the 15 s lowerings past the rated radius
    /// were still NORMAL or WARNING at true u 1.05 (`host-sim` test
    /// `a_dropout_in_a_lowering_keeps_the_bounds_*`).
    // Never inlined (runs on a restart only): its inlined copies took
    // 0.28 KB more of the board's 64 KiB flash than one function.
    #[inline(never)]
    pub fn restart_averages(&mut self) {
        // The first call of a restart keeps the weighing; the later ones,
        // while the filters settle, keep that one.
        self.kept_kg = self.kept_kg.or(self.slow_kg);
        for h in self.hypotheses.iter_mut() {
            h.slow_kg = None;
            h.jump = Consistency::new();
        }
        self.rise.clear();
        self.fast_stage = None;
        self.still_stage = None;
        self.bounce_stages = (None, None);
        self.slow_kg = None;
        self.follow_s = T::lit(0.0);
        self.period_mean.clear();
        self.midrange.clear();
    }

    /// Starts again as a bank switched on at rest: every rope hangs still,
    /// nothing is held and the averages start afresh (after a limiter
    /// switched on in motion has seen the boom stop,
    /// [`crate::cycle::power_up`]). The same as [`Self::reset`] but for the
    /// boom's present motion, which it keeps, in a fifth of the flash.
    pub fn start_at_rest(&mut self) {
        self.hang_still();
        self.restart_averages();
        self.kept_kg = None;
        self.hold_kg = None;
        self.slow_at_stop = None;
        self.last_kg = None;
        self.after_move = false;
        self.light_at_stop = false;
    }

    /// Every rope's load hanging still, as in a bank that has not seen the
    /// boom luff: the ropes agree again (a hook left empty, or a limiter
    /// switched on in motion that has seen the boom stop).
    fn hang_still(&mut self) {
        self.moved = false;
        self.ropes.still();
        self.paid_out.still();
    }

    /// How far the tip moved out since the last advance under a lift-off
    /// before any move (m; see the module doc, "A lift-off: the boom's give
    /// swings the load"), with the boom `settled` at (sin θ, cos θ) = `trig`,
    /// `dt_s` after the last advance. A lift-off is followed from an empty
    /// hook (the force at factor 1 within [`load_jump::MIN_AVERAGE_KG`] of
    /// nothing for [`EMPTY_BEFORE_LIFT_S`]) while the load rises, and no
    /// longer once it falls to [`LIFT_FOLLOWED_TO`] of its highest.
    fn lift_shift_m(&mut self, trig: (T, T), settled: bool, dt_s: T) -> T {
        let zero = T::lit(0.0);
        let near_zero = self.hanging_kg.is_some_and(|w| w.abs() < T::lit(load_jump::MIN_AVERAGE_KG));
        self.empty_s = if near_zero && self.still && dt_s.is_finite() { self.empty_s + dt_s.max(zero) } else { zero };
        let w = match self.hanging_kg {
            Some(w) if settled && !self.moved => w,
            _ => {
                self.lifting_kg = None;
                return zero;
            }
        };
        if near_zero {
            // Armed only on a hook that has hung empty: a swing's trough
            // passes through nothing too, and no lift-off follows it.
            self.lifting_kg = (self.empty_s >= T::lit(EMPTY_BEFORE_LIFT_S)).then(|| w.max(zero));
            return zero;
        }
        match self.lifting_kg {
            Some(top) if w > top => {
                self.lifting_kg = Some(w);
                self.geometry.tip_shift_m(trig, w) - self.geometry.tip_shift_m(trig, top)
            }
            Some(top) if w < top * T::lit(LIFT_FOLLOWED_TO) => {
                self.lifting_kg = None;
                zero
            }
            _ => zero,
        }
    }

    /// The ropes disagreed at the last update: they predict a swing, whose
    /// factor needs the force and the pendulums at one instant.
    pub fn swing_predicted(&self) -> bool {
        !self.factors_agree
    }

    /// The force repeats a swing ([`crate::period_mean`]): it rises and
    /// falls with the load's swing, and no seals' breakaway is read in it
    /// ([`crate::breakaway`]).
    pub fn force_swings(&self) -> bool {
        self.force_swings
    }

    /// A load is rising from an empty hook before any move: within
    /// [`FAST_LIFT_S`] of the hook's last empty reading, or of a lift-off's
    /// ring breaking upward after that, or of a steady load's rise (a load
    /// added; see the module doc, "A load added while a lift-off rings: a
    /// lift-off again" and "A load added to one hanging steadily: a lift-off
    /// again"), the still force is read through one filter stage fewer (see
    /// the module doc, "A lift-off: one stage fewer").
    pub fn lifting(&self) -> bool {
        !self.moved && (self.light_s > T::lit(-FAST_LIFT_S) || self.rise_s >= T::lit(0.0) && self.rise_s < T::lit(FAST_LIFT_S))
    }

    /// Watches a lift-off for its bounce, given the still force's first
    /// filter stage (N; see the module doc, "A lift-off: read at once until
    /// it bounces"), and a load hanging steadily, or ringing on, for a
    /// rise, given also the seals' up-friction at that force (N; "A load
    /// added to one hanging steadily: a lift-off again" and "A load added to
    /// one that rings on: a rise over all it did"). Call once a cycle before
    /// [`Self::update`].
    pub fn watch_lift(&mut self, first_stage_n: Option<T>, up_friction_n: T) {
        let Some(f) = first_stage_n else { return };
        self.rise_s = (self.rise_s + self.dt_s).min(T::lit(FAST_LIFT_S));
        if self.light_s > T::lit(0.0) {
            // The hook reads empty: the force a lift rises from, its lowest
            // over this empty spell (a spell after a lift starts afresh).
            self.lift_base_n = Some(match (self.lift_peak_n, self.lift_base_n) {
                (None, Some(b)) => b.min(f),
                _ => f,
            });
            self.lift_peak_n = None;
            self.lift_bounced = false;
            self.forget_ring();
            self.span_s = T::lit(0.0);
        } else if self.lifting() || self.ring_caps() || !self.moved && self.rise_s < T::lit(0.0) {
            // The peak stops at the bounce's first crest.
            let peak = match self.lift_peak_n {
                Some(p) if self.lift_bounced => p,
                p => p.map_or(f, |p| p.max(f)),
            };
            self.lift_peak_n = Some(peak);
            // A force that never rose above the empty hook's (peak ≤ base)
            // counts as turned: read through the stage against the bounce,
            // as before this watch.
            if let Some(base) = self.lift_base_n {
                let bounced = peak - f >= T::lit(LIFT_TURN) * (peak - base);
                if bounced && !self.lift_bounced && peak > base {
                    self.lift_turns_n = Some((base, peak));
                }
                self.lift_bounced |= bounced;
            }
            // A ring that breaks upward after the lift window: a load added,
            // read as a lift-off from the trough it rose from (see the
            // module doc, "A load added while a lift-off rings: a lift-off
            // again"). Within the window the lift-off may still be rising.
            let lifting = self.lifting();
            if let Some(trough) = self.follow_ring(f).filter(|_| !lifting) {
                let mean = self.lift_ring_n;
                self.forget_ring();
                self.lift_ring_n = mean;
                self.lift_off_again(trough, f, T::lit(0.0));
            }
        } else {
            self.forget_ring();
            self.watch_steady(f, up_friction_n);
        }
        // The span runs from a lift-off's first crest (a lift-off read
        // again above has not bounced yet), before any move.
        if self.lift_bounced && !self.moved {
            self.widen_span(f);
        }
    }

    /// The seals' breakaway is held ([`crate::breakaway`]): the angle shows
    /// the boom rising before the direction detector calls it a raise. A
    /// rise of the force then is the raise's start (the seals' friction and
    /// the boom's J·θ̈), not a load added: a lift-off read from such a rise
    /// before any move is dropped, and the watch of the force starts again
    /// (see the module doc, "A load added to one hanging steadily: a
    /// lift-off again"). A lift from an empty hook is watched on. Call
    /// before [`Self::watch_lift`].
    pub fn raise_starts(&mut self) {
        if self.moved || self.rise_s >= T::lit(FAST_LIFT_S) || self.light_s > T::lit(-FAST_LIFT_S) {
            return;
        }
        self.rise_s = T::lit(FAST_LIFT_S);
        self.lift_base_n = None;
        self.lift_peak_n = None;
        self.lift_bounced = false;
        self.forget_ring();
        self.steady_s = T::lit(0.0);
        self.span_s = T::lit(0.0);
    }

    /// Watches a load that hangs steadily before any move, given the still
    /// force's first filter stage `f` and the seals' up-friction at it
    /// (N): its band, kept in
    /// `lift_base_n`/`lift_peak_n` while no lift-off is watched, and a rise
    /// out of it, or out of the span since the lift-off's first crest, read
    /// as a lift-off from that band's or span's low (see the module doc, "A
    /// load added to one hanging steadily: a lift-off again" and "A load
    /// added to one that rings on: a rise over all it did").
    fn watch_steady(&mut self, f: T, up_friction_n: T) {
        let (Some(empty), false) = (self.empty_hook_n, self.moved) else {
            self.lift_base_n = None;
            self.lift_peak_n = None;
            self.span_s = T::lit(0.0);
            return;
        };
        let (Some(lo), Some(hi)) = (self.lift_base_n, self.lift_peak_n) else {
            self.start_steady(f);
            return;
        };
        let started = self.started_s >= T::lit(crate::load_estimate::CREEP_AFTER_START_S);
        let steady = started && self.steady_s >= T::lit(STEADY_S) && lo > empty;
        // Once steady, the band's top stays where the steady spell put it:
        // a rise widens it no more.
        let (lo_now, hi_now) = (lo.min(f), if steady { hi } else { hi.max(f) });
        let rises_over = |lo: T, hi: T| lo > empty && f > hi + (lo - empty) * T::lit(STEADY_RISE) + up_friction_n;
        // A rise out of the steady band is read from its low; one over all
        // the force did since the lift-off's first crest, from that span's.
        let base = if steady && rises_over(lo, hi) {
            Some(lo)
        } else {
            (started && self.span_s >= T::lit(STEADY_S) && rises_over(self.span_lo_n, self.span_hi_n)).then_some(self.span_lo_n)
        };
        if let Some(base) = base {
            self.lift_off_again(base, f, T::lit(-STEADY_CONFIRM_S));
            self.steady_s = T::lit(0.0);
        } else if f <= hi_now && hi_now - lo_now <= (lo_now - empty) * T::lit(STEADY_BAND) {
            self.lift_base_n = Some(lo_now);
            self.lift_peak_n = Some(hi_now);
            self.steady_s += self.dt_s;
            self.above_s = T::lit(0.0);
        } else if steady && f > hi && self.above_s < T::lit(STEADY_S) {
            // Above the band for a moment after a steady spell: the band's
            // low is kept for a rise that may go on.
            self.above_s += self.dt_s;
        } else {
            self.start_steady(f);
        }
    }

    /// Reads a load added to the one hanging as a lift-off from the force
    /// `base_n` it rose from, the still force's first stage now `f` (N):
    /// the lift window's clock set to `rise_s` (0 opens it, below 0 is the
    /// wait before it; see the module doc, "A load added while a lift-off
    /// rings: a lift-off again" and "A load added to one hanging steadily:
    /// a lift-off again").
    fn lift_off_again(&mut self, base_n: T, f: T, rise_s: T) {
        self.span_s = T::lit(0.0);
        self.lift_base_n = Some(base_n);
        self.lift_peak_n = Some(f);
        self.lift_bounced = false;
        self.rise_s = rise_s;
    }

    /// Widens the span of the still force's first stage `f` (N) since a
    /// lift-off's first crest (started afresh when `span_s` is 0).
    fn widen_span(&mut self, f: T) {
        if self.span_s <= T::lit(0.0) {
            (self.span_lo_n, self.span_hi_n, self.span_crest_n) = (f, f, f);
        }
        self.span_lo_n = self.span_lo_n.min(f);
        // A crest over the top widens the span once the force has come
        // back from it by half the margin of a rise read as a lift-off, or
        // into the span: a rise that goes on, however it rings, is measured
        // against the top before it.
        let part = self.span_lo_n - self.empty_hook_n.unwrap_or(self.span_lo_n);
        self.span_crest_n = self.span_crest_n.max(f);
        if f <= self.span_hi_n || f < self.span_crest_n - part.max(T::lit(0.0)) * T::lit(0.5 * STEADY_RISE) {
            self.span_hi_n = self.span_crest_n;
        }
        // Held at the age it must reach: a clock that ran on for days
        // would stop adding a cycle's step in f32.
        self.span_s = (self.span_s + self.dt_s).min(T::lit(STEADY_S));
    }

    /// Starts a steady band at the still force's first stage `f` (N).
    fn start_steady(&mut self, f: T) {
        self.lift_base_n = Some(f);
        self.lift_peak_n = Some(f);
        self.steady_s = T::lit(0.0);
        self.above_s = T::lit(0.0);
    }

    /// Forgets a lift-off's ring: its turning points and its mean.
    fn forget_ring(&mut self) {
        self.lift_turns_n = None;
        self.lift_run_n = None;
        self.lift_ring_n = None;
        self.lift_ring_top_n = None;
        self.lift_ring_quiet_s = T::lit(0.0);
        self.lift_ring_broken = false;
    }

    /// A lift-off's ring decays, with a mean to read it by: W_fast and the
    /// still force's load are read no higher than that mean allows (see the
    /// module doc, "A lift-off: no higher than its ring").
    fn ring_caps(&self) -> bool {
        !self.moved && !self.lift_ring_broken && self.lift_ring_top_n.is_some() && self.lift_ring_quiet_s <= T::lit(RING_QUIET_S)
    }

    /// Follows a bouncing lift-off's turning points in the first filter
    /// stage `f` (N): a turning point is passed once the force has come
    /// back from it by [`LIFT_TURN`] of the lift's rise to its first crest,
    /// as the first crest was, and each gives the ring's mean from the last
    /// three (see the module doc, "A lift-off: the mean of its ring").
    /// Returns the trough the force rose from when it passes the crest
    /// before that trough by more than a turn (the ring broke upward: a load
    /// added).
    fn follow_ring(&mut self, f: T) -> Option<T> {
        let (Some((before, last)), Some(base), Some(crest)) = (self.lift_turns_n, self.lift_base_n, self.lift_peak_n) else { return None };
        let turn = T::lit(LIFT_TURN) * (crest - base);
        // Falling from a crest, the next turning point is a trough.
        let falling = last > before;
        let run = self.lift_run_n.map_or(f, |r| if falling { r.min(f) } else { r.max(f) });
        self.lift_run_n = Some(run);
        // A decaying ring turns within its last two turning points: one
        // past the turning point before the last, by more than a turn, is
        // a load that changed.
        let broken_up = !falling && run > before + turn;
        self.lift_ring_broken |= broken_up || (falling && run < before - turn);
        self.lift_ring_quiet_s += self.dt_s;
        if (f - run).abs() >= turn {
            if let Some(m) = ring_mean(before, last, run) {
                self.lift_ring_n = Some(m);
                self.lift_ring_top_n = Some(self.lift_ring_top_n.map_or(m, |top| top.max(m)));
            }
            self.lift_ring_quiet_s = T::lit(0.0);
            self.lift_turns_n = Some((last, run));
            self.lift_run_n = None;
        }
        broken_up.then_some(last)
    }

    /// Forgets swing and averages (after a sensor fault broke the angle).
    pub fn reset(&mut self) {
        *self = Self::new(self.geometry).with_lead_s(self.lead_s);
    }

    /// Advances every rope's pendulum to the boom angle `angle_rad`, rate
    /// and acceleration (at the force's instant), `dt_s` after the previous
    /// call; returns the paid-out rope's tan φ (a diagnostic).
    pub fn advance(&mut self, angle_rad: T, rate_rad_s: T, accel_rad_s2: T, dt_s: T) -> T {
        // The pendulums move with the boom, not with the sensor's noise
        // (see SWING_DEADBAND_RAD_S).
        let r0 = T::lit(SWING_DEADBAND_RAD_S);
        // The filters' start-up drives no pendulum and is no luff (see the
        // module doc, "Power-up").
        let starting = self.started_s < T::lit(crate::load_estimate::CREEP_AFTER_START_S);
        let (drive_rate, drive_accel) = if starting {
            (T::lit(0.0), T::lit(0.0))
        } else if rate_rad_s > r0 {
            (rate_rad_s - r0, accel_rad_s2)
        } else if rate_rad_s < -r0 {
            (rate_rad_s + r0, accel_rad_s2)
        } else {
            (T::lit(0.0), T::lit(0.0))
        };
        // An empty hook swings no load: after EMPTY_HOOK_S of a still boom
        // and a light hook the ropes hang still, as at power-up (see the
        // module doc).
        if self.moved && self.light_s >= T::lit(EMPTY_HOOK_S) {
            self.hang_still();
        }
        let trig = angle_rad.sin_cos_own();
        let tip = BoomTip::new(trig, self.geometry.boom_length_m, drive_rate, drive_accel, dt_s);
        self.dt_s = if dt_s.is_finite() && dt_s > T::lit(0.0) {
            dt_s
        } else {
            T::lit(0.0)
        };
        let still = starting || rate_rad_s.abs() <= T::lit(MOVING_RAD_S);
        self.rise.luff(!still, accel_rad_s2, self.dt_s);
        self.falling = rate_rad_s < T::lit(0.0);
        let settled = rate_rad_s.abs() <= T::lit(SETTLED_RAD_S);
        self.unsettled_s = if settled { T::lit(0.0) } else { self.unsettled_s + self.dt_s };
        // Settled but for the angle noise's brief excursions (see
        // UNSETTLED_GRACE_S): the give and a lift-off's shift of the tip
        // come and go with the boom, not with the noise.
        let calm = still && self.unsettled_s <= T::lit(UNSETTLED_GRACE_S);
        // At rest the loaded pendulums swing longer by the boom's give (see
        // the module doc).
        let give = match (calm, self.last_kg) {
            (true, Some(w)) => self.geometry.give_m(trig.0, w),
            _ => T::lit(0.0),
        };
        self.ropes.set_give(give);
        let paid_out_m = self.geometry.paid_out_length_m(angle_rad) + give;
        let shift = self.lift_shift_m(trig, calm && !starting, dt_s);
        if shift > T::lit(0.0) {
            self.ropes.shift_tip(shift);
            self.paid_out.shift_tip(shift, paid_out_m);
        }
        self.ropes.update(&tip);
        self.paid_out.update(&tip, paid_out_m);
        self.advanced_s += self.dt_s;
        if starting {
            self.started_s += self.dt_s;
        }
        self.settled = settled;
        self.calm = calm;
        if still {
            // A move ends: its last weighing is held (see `update`).
            if !self.still && self.moving_s >= T::lit(MOVE_FOR_HOLD_S) {
                self.hold_kg = self.last_kg;
                self.slow_at_stop = self.slow_kg;
                self.after_move = true;
                self.light_at_stop = self.last_kg.is_none_or(|w| w < T::lit(load_jump::MIN_AVERAGE_KG));
                self.still_s = T::lit(0.0);
                self.rest_peak_kg = None;
                // An empty hook does not bounce, and a load lifted after
                // it must be seen as at any other time.
                self.bounce_s = if self.light_at_stop { T::lit(0.0) } else { T::lit(BOUNCE_WINDOW_S) };
            }
            self.bounce_s = (self.bounce_s - self.dt_s).max(T::lit(0.0));
            self.moving_s = T::lit(0.0);
            self.still_s += self.dt_s;
            if self.still_s > T::lit(REST_HOLD_S) {
                self.hold_kg = None;
            }
        } else {
            if self.still {
                // Did W_fast at rest pass the weighing this move starts from?
                let jump = T::lit(1.0 + load_jump::JUMP);
                self.weighing_doubted = matches!((self.rest_peak_kg, self.hold_kg), (Some(p), Some(h)) if p >= h * jump);
            }
            // A move starts no lower than the averages stood when the last
            // one stopped, while its weighing is held (see the module doc,
            // "The averages carry the rest's weighing into the next move").
            if let (Some(_), Some(w)) = (self.hold_kg, self.slow_at_stop) {
                self.raise_averages(w);
                self.slow_kg = self.slow_kg.map(|s| s.max(w));
            }
            self.moved = true;
            self.bounce_s = T::lit(0.0);
            self.moving_s += self.dt_s;
            self.hold_kg = None;
            self.after_move = false;
            self.light_at_stop = false;
        }
        self.still = still;
        self.paid_out.tan_swing()
    }

    /// Raises every running average to at least `w` (kg). One copy for both
    /// callers, and a loop the compiler does not unroll (its count hidden
    /// from it): inlined and unrolled, the two took 1.2 KiB of the board's
    /// flash.
    #[inline(never)]
    fn raise_averages(&mut self, w: T) {
        let (mut k, n) = (0, core::hint::black_box(HYPOTHESES));
        while k < n {
            if let Some(st) = self.hypotheses.get_mut(k).and_then(|h| h.slow_kg.as_mut()) {
                for x in st.iter_mut() {
                    if *x < w {
                        *x = w;
                    }
                }
            }
            k += 1;
        }
    }

    /// Sets every average, and W_slow, to `w` (kg): the mean over one swing
    /// period weighs a swing no rope predicts.
    #[inline(never)]
    fn set_averages(&mut self, w: T) {
        for h in self.hypotheses.iter_mut() {
            h.slow_kg = Some([w; SLOW_STAGES]);
        }
        self.slow_kg = Some(w);
    }

    /// The factor of possible hypothesis `h`, if it can weigh (see the
    /// module doc): motion only, never the force.
    fn factor(&self, h: &Hypothesis<T>, led: Option<&LedFactors<T>>) -> Option<T> {
        let factor = match (h.held, led) {
            (Some(i), None) => self.ropes.factor(i)?,
            (None, None) => self.paid_out.factor(),
            (Some(i), Some(l)) => *l.held.get(i)?,
            (None, Some(l)) => l.paid_out,
        };
        (factor.is_finite() && factor >= T::lit(MIN_LOAD_FACTOR)).then_some(factor)
    }

    /// Every rope's factor with [`Self::with_lead_s`]'s lag undone, the boom
    /// still at `angle_rad`.
    fn led_factors(&self, angle_rad: T) -> LedFactors<T> {
        let (s, c) = angle_rad.sin_cos_own();
        let tan_angle = s / c;
        LedFactors {
            held: self.ropes.led_factors(self.lead_s, tan_angle),
            paid_out: self.paid_out.led_factor(self.geometry.paid_out_length_m(angle_rad) + self.ropes.give_m(), self.lead_s, tan_angle),
        }
    }

    /// Whether hypothesis `h` is possible at all with the tip `tip_height_m`
    /// high: a held rope longer than the tip is high would hold its load
    /// below ground.
    fn possible(&self, h: &Hypothesis<T>, tip_height_m: T) -> bool {
        match h.held {
            Some(i) => self.ropes.length_m(i).is_some_and(|l| l <= tip_height_m),
            None => true,
        }
    }

    /// A load added at rest after a move ([`crate::load_jump`]): the common
    /// ratio ρ of the consistent ropes; from ρ ≥ 1 + JUMP on, for
    /// FOLLOW_S, every slow average and the held weighing multiplied by
    /// ρ > 1. Then each weighing hypothesis's inconsistency takes its ratio.
    fn follow_jump(&mut self, factors: &[Option<T>; HYPOTHESES], agree: bool, settle: T) {
        // ρ_k of every hypothesis that weighs, once (one division each),
        // and the most consistent one's D_k, which sets the bar the others
        // must meet to vote.
        let mut ratios: [Option<T>; HYPOTHESES] = [None; HYPOTHESES];
        let mut best: Option<T> = None;
        for ((slot, h), factor) in ratios.iter_mut().zip(self.hypotheses.iter()).zip(factors.iter()) {
            if factor.is_some() {
                *slot = h.slow_kg.and_then(|st| st.last().copied()).and_then(|avg| h.jump.ratio(avg));
                let d = h.jump.inconsistency();
                best = Some(best.map_or(d, |m: T| m.min(d)));
            }
        }
        // After a light move the averages follow W_fast up instead (see
        // the module doc): a ratio to an average raised moments ago is no
        // ratio to a weighing.
        // Nor in the stop's bounce window after a move whose load added was
        // followed in motion ([`crate::load_rise`]): the averages hold it,
        // and the stop's bounce on the rope rises as a load added would.
        let bouncing_after_rise = self.bounce_s > T::lit(0.0) && self.rise.followed_in_move();
        let at_rest = self.still && self.after_move && !agree && !self.light_at_stop && !bouncing_after_rise;
        let mut scale = T::lit(1.0);
        if at_rest {
            let bar = best.map_or(T::lit(0.0), load_jump::bar);
            // ρ, the voters' lowest reading S_k(W_k) and their lowest rise
            // S_k(W_k) − W̄_k (kg).
            let (mut rho, mut reading, mut rise): (Option<T>, Option<T>, Option<T>) = (None, None, None);
            for (h, r) in self.hypotheses.iter().zip(ratios.iter()) {
                let average = h.slow_kg.and_then(|st| st.last().copied()).filter(|&avg| avg >= T::lit(load_jump::MIN_AVERAGE_KG));
                if let (true, Some(avg), Some(r), Some(s)) = (h.jump.inconsistency() <= bar, average, *r, h.jump.fast_kg()) {
                    rho = Some(rho.map_or(r, |m: T| m.min(r)));
                    reading = Some(reading.map_or(s, |m: T| m.min(s)));
                    let d = s - avg;
                    rise = Some(rise.map_or(d, |m: T| m.min(d)));
                }
            }
            if let (Some(r), Some(s), Some(d)) = (rho, reading, rise) {
                if r >= T::lit(1.0 + load_jump::JUMP) && d >= T::lit(load_jump::MIN_JUMP_KG) {
                    self.follow_s = T::lit(load_jump::FOLLOW_S);
                    // The new load's weighing is held as long as a move's
                    // (see the module doc, "A load added, held").
                    self.still_s = T::lit(0.0);
                }
                if self.follow_s > T::lit(0.0) {
                    // Raise only: ρ ≤ 1 leaves everything as it is; at most
                    // MAX_STEP a cycle (a guard: S_k's stage rises by less).
                    scale = r.max(T::lit(1.0)).min(T::lit(load_jump::MAX_STEP));
                    // The voters read the new load directly: the held
                    // weighing (of the move, read ×0.96–1.0 of the old load)
                    // is raised to their reading, after its rescale (their
                    // reading has the new load in it already).
                    let held = self.hold_kg.map_or(s, |w| (w * scale).max(s));
                    self.hold_kg = Some(held);
                    // The next move starts from the new load (see the
                    // module doc, "The averages carry the rest's weighing
                    // into the next move").
                    self.slow_at_stop = self.slow_at_stop.map(|w| w * scale);
                }
                self.follow_s = (self.follow_s - self.dt_s).max(T::lit(0.0));
            }
        } else {
            self.follow_s = T::lit(0.0);
        }
        // The rescale (scale = 1 when none: a multiplication by one costs
        // less flash than a second loop), after which every ρ_k is ρ_k/scale.
        let inverse = T::lit(1.0) / scale;
        for (h, r) in self.hypotheses.iter_mut().zip(ratios.iter()) {
            if let Some(st) = h.slow_kg.as_mut() {
                for x in st.iter_mut() {
                    *x *= scale;
                }
            }
            if let Some(r) = *r {
                h.jump.settle(r * inverse, settle);
            }
        }
    }

    /// A load added in motion ([`crate::load_rise`]): every slow average
    /// multiplied by the follower's factor of this cycle (1 when none), which
    /// it returns.
    fn follow_rise(&mut self, factors: &[Option<T>; HYPOTHESES]) -> T {
        let mut readings: [Option<Reading<T>>; HYPOTHESES] = [None; HYPOTHESES];
        for ((slot, h), f) in readings.iter_mut().zip(self.hypotheses.iter()).zip(factors.iter()) {
            *slot = match (f, h.jump.fast_kg()) {
                (Some(_), Some(s)) => Some(Reading { fast_kg: s, average_kg: h.slow_kg.and_then(|st| st.last().copied()), inconsistency: h.jump.inconsistency() }),
                _ => None,
            };
        }
        let scale = self.rise.update(&readings, self.slow_kg, self.dt_s);
        if scale != T::lit(1.0) {
            for h in self.hypotheses.iter_mut() {
                if let Some(st) = h.slow_kg.as_mut() {
                    for x in st.iter_mut() {
                        *x *= scale;
                    }
                }
            }
        }
        scale
    }

    /// The load of this cycle (after [`advance`](Self::advance)); `None` when
    /// the force gives no load on the model's rising branch (not observable).
    // Not inlined: the controller's cycle calls it once, and inlined into the
    // cycle it took 568 B more of the board's 64 KiB of flash (and no fewer
    // instructions: 8 583 a cycle at most, 8 797 inlined).
    #[inline(never)]
    pub fn update(&mut self, terms: &LoadTerms<T>) -> Option<StaticLoad<T>> {
        // How long the hook has read empty with the boom still: the next
        // advance stills the ropes after EMPTY_HOOK_S (see the module doc).
        let light = self.still && terms.force_n - terms.at_rest.at_zero < terms.at_rest.per_kg * T::lit(load_jump::MIN_AVERAGE_KG);
        self.light_s = if light { self.light_s.max(T::lit(0.0)) + self.dt_s } else { (self.light_s.min(T::lit(0.0)) - self.dt_s).max(T::lit(-FAST_LIFT_S)) };
        let tip_height = self.geometry.tip_height_m(terms.angle_rad);
        self.empty_hook_n = Some(terms.at_rest.at_zero);
        // Gains 1 − e^(−dt/τ) of the slow stages, the fast ones (W_fast's
        // and each hypothesis's S_k) and the inconsistency's.
        let alpha = stage_gain(self.dt_s / T::lit(SLOW_TAU_S));
        let gain = stage_gain(self.dt_s * T::two_pi() * T::lit(FAST_SMOOTHING_HZ));
        let settle = stage_gain(self.dt_s / T::lit(load_jump::CONSISTENCY_TAU_S));
        // The factors first: which hypotheses weigh, and how far apart they
        // are (motion only).
        // At rest after a move, the force without the sensor's lag and the
        // pendulums' swings with the lag undone (see the module doc); settled
        // but for the noise (see UNSETTLED_GRACE_S), the boom is still and
        // drives no pendulum.
        let led = match terms.force_still_n {
            Some(f) if self.moved && self.calm && self.lead_s > T::lit(0.0) => Some((f, self.led_factors(terms.angle_rad))),
            _ => None,
        };
        let (force, led) = match led {
            Some((f, l)) => (f, Some(l)),
            None => (terms.force_n, None),
        };
        self.hanging_kg = terms.at_rest.solve(force);
        let mut factors = [None; HYPOTHESES];
        let (mut f_lo, mut f_hi): (Option<T>, Option<T>) = (None, None);
        // Every possible rope (one whose load would be above ground) weighs:
        // agreement among fewer says nothing (one alone always agrees).
        let mut all_weigh = true;
        let mut possible = [false; HYPOTHESES];
        for ((slot, h), p) in factors.iter_mut().zip(self.hypotheses.iter()).zip(possible.iter_mut()) {
            if !self.possible(h, tip_height) {
                continue;
            }
            *p = true;
            *slot = self.factor(h, led.as_ref());
            match *slot {
                Some(f) => {
                    f_lo = Some(f_lo.map_or(f, |l: T| l.min(f)));
                    f_hi = Some(f_hi.map_or(f, |h: T| h.max(f)));
                }
                None => all_weigh = false,
            }
        }
        // Every possible rope weighs and their factors are within `spread`
        // of each other.
        let within = |spread: f64| {
            all_weigh && matches!((f_lo, f_hi), (Some(lo), Some(hi)) if hi <= lo * T::lit(1.0 + spread))
        };
        self.factors_agree = within(AGREEMENT);
        let agree = self.settled && (!self.moved || self.still && self.factors_agree);
        let mut fast: Option<T> = None;
        let still = self.still;
        // In motion the averages move only while every possible rope weighs:
        // a rope that cannot (a short one swung hard at a steep boom) is
        // the true one as often as not, and the ropes left read the wrong
        // factor. Lowering from 82° at 10 °/s on a 4.1 m rope, the averages
        // of the ropes left fell to 0.76 of the load and the overload was
        // cut at true u 1.09 (campaign #9090); held, they keep the weighing
        // from before (the load does not change in motion; a heavier one
        // is W_fast's).
        let averaging = still || all_weigh;
        // After a restart the averages start from the weighing kept over
        // it (see `restart_averages`) until the bank weighs again: each
        // restart while the filters settle empties W_slow once more.
        let prev_slow = match self.slow_kg {
            Some(w) => {
                self.kept_kg = None;
                Some(w)
            }
            None => self.kept_kg,
        };
        let doubted = self.weighing_doubted;
        for (k, (h, factor)) in self.hypotheses.iter_mut().zip(factors.iter()).enumerate() {
            let Some(f) = *factor else {
                // Cannot weigh now. In motion its average starts afresh when
                // it can (the rope moved on meanwhile); at rest it is kept.
                if !still {
                    let last = h.slow_kg.and_then(|st| st.last().copied());
                    h.was_lowest |= matches!((last, prev_slow), (Some(a), Some(p)) if a <= p);
                    h.slow_kg = None;
                    h.jump = Consistency::new();
                    // Its reading starts afresh too: no rise over it.
                    self.rise.forget(k);
                }
                continue;
            };
            let w = terms.at_rest.scale_load_part(f).solve(force)?;
            fast = Some(fast.map_or(w, |m: T| m.min(w)));
            // A hypothesis that starts weighing (or starts again) starts no
            // lower than the bank's weighing of the last cycle: a rope that
            // becomes possible as the tip rises has not followed the true
            // swing, and its W_k of one instant (0.71 of the load with a 3 m
            // rope at 55°) is no weighing. It starts at its own W_k when
            // that is higher: in the min it cannot lower W_slow, and in
            // motion it takes part only once every rope weighs (see
            // `averaging`), when the ropes already weighing are in the min
            // too. (Started at the bank's weighing instead, the short ropes
            // that become usable lowering from 80° averaged their low
            // readings down to 0.92 of the load.)
            // The rope whose average was the weighing when it stopped
            // weighing starts again at the weighing, not at its W_k of one
            // instant: it was the lowest, and with the others higher its
            // start would be W_slow at once (see the module doc). Not when
            // that weighing may be an old load's.
            let start = prev_slow.map_or(w, |p| if h.was_lowest && !still && !doubted { p } else { p.max(w) });
            h.was_lowest = false;
            let mut stages = h.slow_kg.unwrap_or([start; SLOW_STAGES]);
            if h.jump.fast_kg().is_none() {
                // Its first ratio against the average it starts, or takes
                // up again, with.
                h.jump = Consistency::starting(w, stages.last().copied().unwrap_or(start));
            }
            h.jump.smooth(w, gain);
            if averaging {
                let mut input = w;
                for st in stages.iter_mut() {
                    *st += alpha * (input - *st);
                    input = *st;
                }
            }
            h.slow_kg = Some(stages);
        }
        // A load lifted after a move with the hook empty: the averages
        // are no lower than W_fast (see the module doc).
        let light_raise = still && self.after_move && self.light_at_stop && fast.is_some();
        let fast = match fast {
            Some(f) => f,
            // No hypothesis can weigh: the load hanging straight and still.
            None => terms.at_rest.solve(force)?,
        };
        // One stage against the bounce. Not over the first
        // [`FIRST_SAMPLES_S`], whose force is the mean of its samples so far
        // (see the module doc, "Power-up").
        let first = self.started_s < T::lit(FIRST_SAMPLES_S);
        let fast = stage(fast, self.fast_stage, gain, first);
        self.fast_stage = Some(fast);
        // Right after a loaded move stops, a second stage against the
        // stop's bounce (see the module doc); it runs always, so it is
        // settled when read.
        let bouncing = self.bounce_s > T::lit(0.0);
        let bounce_fast = stage(fast, self.bounce_stages.0, gain, first);
        self.bounce_stages.0 = Some(bounce_fast);
        let fast = if bouncing { bounce_fast } else { fast };
        // A lift-off's ring that decays: no higher than its highest mean
        // allows (see the module doc, "A lift-off: no higher than its ring").
        let still_at_rest = terms.at_rest.scale_load_part(f_hi.unwrap_or(T::lit(1.0)));
        let cap_kg = self.lift_ring_top_n.filter(|_| self.ring_caps()).and_then(|f| still_at_rest.solve(f)).map(|w| w * T::lit(1.0 + RING_CAP));
        let fast = cap_kg.map_or(fast, |c| fast.min(c));
        if still && self.after_move {
            self.rest_peak_kg = Some(self.rest_peak_kg.map_or(fast, |p| p.max(fast)));
        }
        // A load added in motion: the averages rise with it, and so does the
        // weighing that stands while a possible rope cannot weigh.
        let rise = self.follow_rise(&factors);
        let prev_slow = prev_slow.map(|p| p * rise);
        self.follow_jump(&factors, agree, settle);
        // A move that doubts the weighing it started from: while every
        // rope weighs, the averages, restarted at the old load, take up
        // W_fast (raised only; in motion only the ropes that weigh have
        // one).
        if doubted && !still && all_weigh {
            self.raise_averages(fast);
        }
        // While every rope agrees, the weighing is W_fast itself: the
        // averages start the next move from it (a lift-off is in them at once).
        // Only the hypotheses that weigh now vote: a frozen average is a
        // weighing from before the rope became impossible.
        let mut slow: Option<T> = None;
        // At rest, a possible rope without an average (it could not weigh
        // at the end of the move): maybe the true one.
        let mut unweighed = false;
        for ((h, factor), &possible) in self.hypotheses.iter_mut().zip(factors.iter()).zip(possible.iter()) {
            if first {
                // Both ways: no move has started to dip the force (see the
                // module doc, "Power-up").
                h.slow_kg = Some([fast; SLOW_STAGES]);
            } else if agree || light_raise {
                // Raised to W_fast at once (a lift-off), lowered only at the
                // averages' pace: the force leads the lagging angle at the
                // start of a move (its J·θ̈ and ride-down read as a dip of
                // 6 % over 0.3 s before the rate is seen) and that dip is no
                // weighing to start the move from. Set to it while the seals'
                // breakaway is taken out of the force: the averages took
                // its rise up before the angle showed the raise.
                let stages = match h.slow_kg {
                    Some(st) if !terms.seals_hold => st.map(|x| x.max(fast)),
                    _ => [fast; SLOW_STAGES],
                };
                h.slow_kg = Some(stages);
            }
            let last = h.slow_kg.and_then(|st| st.last().copied());
            if let (true, Some(last)) = (factor.is_some() || still, last) {
                slow = Some(slow.map_or(last, |m: T| m.min(last)));
            }
            unweighed |= still && possible && last.is_none();
        }
        // At rest after a move, the move's last weighing is held while the
        // ropes disagree (see the module doc): the swing of a short rope at
        // a steep boom makes the force unusable for weighing.
        if agree {
            self.hold_kg = None;
        }
        // In motion while a possible rope cannot weigh, the bank's weighing
        // stands as the averages do (the lowest of the ropes left is not
        // the weighing: the true rope may be the one that left); and when
        // no rope weighs, the last weighing stands until one can weigh
        // again, and the averages that then start begin from it.
        let slow = if averaging { slow.or(prev_slow) } else { prev_slow.or(slow) };
        // At rest, while a possible rope has no average, W_slow does not
        // rise above the bank's weighing: the lowest of the other ropes'
        // averages is not the weighing when the true rope is the one
        // missing (it stood for it at 1.017 × the load after a raise to 80°).
        let slow = match (slow, prev_slow) {
            (Some(s), Some(p)) if unweighed => Some(s.min(p)),
            _ => slow,
        };
        self.slow_kg = slow;
        let now = slow.map_or(fast, |s| s.max(fast));
        // The force cannot weigh while a possible rope cannot or the ropes'
        // factors spread by more than [`UNUSABLE_SPREAD`].
        let unusable = !within(UNUSABLE_SPREAD);
        let load_kg = match self.hold_kg {
            Some(h) if unusable => h.max(now),
            _ => now,
        };
        // A still boom with every rope agreeing: the force without the
        // sensor's lag reads a heavier load one lag sooner (see the module
        // doc); its stage runs always, so it is settled when it is read.
        let still_now = terms.force_still_n.and_then(|f| still_at_rest.solve(f));
        self.still_stage = still_now.map(|w| stage(w, self.still_stage, gain, first));
        let still_kg = self.still_stage.map(|w| {
            let bounce_still = stage(w, self.bounce_stages.1, gain, first);
            self.bounce_stages.1 = Some(bounce_still);
            if bouncing { bounce_still } else { w }
        });
        // A lift-off that has not bounced: the still force's load through
        // the faster stage too (see the module doc, "A lift-off: read at
        // once until it bounces").
        let lift_gain = stage_gain(self.dt_s * T::two_pi() * T::lit(LIFT_STAGE_HZ));
        self.lift_stage = still_now.map(|w| stage(w, self.lift_stage, lift_gain, first));
        let still_kg = match (still_kg, self.lift_stage) {
            (Some(s), Some(w)) if self.lifting() && self.lift_base_n.is_some() && !self.lift_bounced => Some(s.max(w)),
            (s, _) => s,
        };
        // A bouncing lift-off: the mean its ring swings about (see the module doc,
        // "A lift-off: the mean of its ring").
        let still_kg = match (still_kg, self.lift_ring_n.filter(|_| self.lifting())) {
            (Some(s), Some(f)) => Some(still_at_rest.solve(f).map_or(s, |r| s.max(r))),
            (s, _) => s,
        };
        // While it decays, no higher than its highest mean allows.
        let still_kg = match (still_kg, cap_kg) {
            (Some(s), Some(c)) => Some(s.min(c)),
            (s, _) => s,
        };
        let load_kg = match (agree, still_kg) {
            (true, Some(w)) => load_kg.max(w),
            _ => load_kg,
        };
        // Settled after a move, the mean force over one swing period weighs
        // the load whatever the rope ([`crate::period_mean`]). While the
        // ropes disagree and the force still repeats it is the weighing (the
        // bank's ropes read the swing of the wrong period high and low);
        // otherwise a floor: it raises the reading, never lowers it.
        let advanced = core::mem::replace(&mut self.advanced_s, T::lit(0.0));
        let period_kg = if self.calm {
            // Over a bridged gap the whole time advanced is one step, which
            // the mean refuses (it starts again).
            self.period_mean.push(force, terms.at_rest.at_zero, advanced).and_then(|f| terms.at_rest.solve(f))
        } else {
            self.period_mean.clear();
            None
        };
        // A change of the load from a steady swing, read at once from the
        // force's ratio to one period earlier: raises only. After a move.
        let step_kg = self.period_mean.step_n().filter(|_| self.moved).and_then(|f| terms.at_rest.solve(f));
        // Before any move the ropes hang still and agree: a swing the force
        // repeats is one none of them predicts (see the module doc,
        // "Switched on while the load swings").
        self.force_swings = self.period_mean.swings(terms.at_rest.at_zero);
        let unseen_swing = !self.moved && self.force_swings;
        let mean_weighs = period_kg.is_some() && (!agree || unseen_swing) && self.period_mean.steady(terms.at_rest.at_zero);
        let load_kg = match period_kg {
            Some(w) if mean_weighs => {
                if unseen_swing {
                    // The ropes' averages hold the swing's crests: the next
                    // move starts from the mean instead.
                    self.set_averages(w);
                } else {
                    // The weighing at rest is the one the next move starts
                    // from (see the module doc, "The averages carry the
                    // rest's weighing into the next move").
                    self.raise_averages(w);
                }
                w
            }
            Some(w) if self.moved => load_kg.max(w),
            _ => load_kg,
        };
        // Settled after a move, within the hold, the ropes disagreeing: the
        // reading may follow the swing rather than the load.
        let swinging_at_rest = self.after_move && self.calm && self.still_s <= T::lit(REST_HOLD_S) && !agree;
        let provisional = swinging_at_rest && !mean_weighs;
        let load_kg = match step_kg {
            Some(w) => {
                // A load added, read from the swing: the averages take it
                // up, as the rescale's (see the module doc, "The averages
                // carry the rest's weighing into the next move").
                self.raise_averages(w);
                load_kg.max(w)
            }
            None => load_kg,
        };
        // A load added at rest while it swings: the swing's midrange, once
        // it has turned at a crest and a trough, is a floor under the
        // reading and the averages the next move starts from (see
        // [`crate::swing_midrange`]). A lowering that doubts its start goes
        // on following for MIDRANGE_CARRY_S, the load W₁ reads at factor 1 put
        // back into the rest's force, so that a crest seen at rest pairs
        // with the trough after it (see the module doc, "A load added at
        // rest that nothing weighed").
        let resting = swinging_at_rest && !self.light_at_stop;
        let added = matches!(self.hold_kg, Some(h) if fast >= h * T::lit(1.0 + load_jump::JUMP));
        let carry = !still && self.falling && self.weighing_doubted && self.midrange.following() && self.moving_s <= T::lit(MIDRANGE_CARRY_S);
        let mid_kg = if resting && (added || self.midrange.following()) {
            self.midrange_terms = Some(terms.at_rest);
            self.midrange.push(force - terms.at_rest.at_zero, self.dt_s, gain).and_then(|f| terms.at_rest.solve(f + terms.at_rest.at_zero))
        } else if let (true, Some(q), Some(w)) = (carry, self.midrange_terms, terms.at_rest.solve(force)) {
            self.midrange.push(q.at(w) - q.at_zero, self.dt_s, gain).and_then(|f| q.solve(f + q.at_zero))
        } else {
            self.midrange.clear();
            None
        };
        let load_kg = match mid_kg {
            Some(w) if !mean_weighs => {
                self.raise_averages(w);
                load_kg.max(w)
            }
            _ => load_kg,
        };
        // Weighed at rest: a peak of W_fast above it is the swing's crest.
        if mean_weighs || mid_kg.is_some() {
            self.rest_peak_kg = None;
        }
        if !self.still {
            self.last_kg = Some(load_kg);
        }
        Some(StaticLoad {
            load_kg,
            fast_kg: fast,
            slow_kg: slow,
            provisional,
        })
    }
}

/// The mean a ring's three consecutive turning points `x0`, `x1`, `x2`
/// swing about (see the module doc, "A lift-off: the mean of its ring"):
/// the lower of the mean of a ring that decays geometrically, x₁ +
/// d₀·d₂/(d₀ + d₂) (dᵢ = xᵢ − x₁; Aitken's Δ²), and the midrange of the
/// last two, x₁ + d₂/2. `None` unless x₁ is a crest or a trough between
/// the other two.
fn ring_mean<T: Real>(x0: T, x1: T, x2: T) -> Option<T> {
    let (d0, d2) = (x0 - x1, x2 - x1);
    let turned = (d0 > T::lit(0.0) && d2 > T::lit(0.0)) || (d0 < T::lit(0.0) && d2 < T::lit(0.0));
    turned.then(|| x1 + (d0 * d2 / (d0 + d2)).min(d2 * T::lit(0.5)))
}

/// One cycle of a first-order smoothing stage of gain `gain` on `input`,
/// from its last output `last`: the new output. The stage starts at `input`
/// when it has none, and follows it unsmoothed over the first samples
/// (`first`; see the module doc, "Power-up").
pub(crate) fn stage<T: Real>(input: T, last: Option<T>, gain: T, first: bool) -> T {
    match last {
        Some(y) if !first => y + gain * (input - y),
        _ => input,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A model of slope 10 N/kg and 100 kN at zero load.
    fn at_rest() -> Quadratic<f64> {
        Quadratic {
            at_zero: 100_000.0,
            per_kg: 10.0,
            per_kg2: 0.0,
        }
    }

    #[test]
    fn a_held_load_riding_with_the_tip_is_not_read_as_load() {
        // The boom at 40° accelerates at 0.1 rad/s² from rest for 1 s, then
        // turns at constant rate: a held 3 t load pulls W·(1 + a_Ly/g).
        let g = SwingGeometry::<f64>::coles_930();
        let mut bank = StaticLoadBank::new(g);
        let (mut th, mut rate) = (40f64.to_radians(), 0.0);
        let dt = 0.01;
        let mut worst: f64 = 0.0;
        for k in 0..500 {
            let acc = if (100..200).contains(&k) { 0.1 } else { 0.0 };
            rate += acc * dt;
            th += rate * dt;
            bank.advance(th, rate, acc, dt);
            // The truth: a held rope of 7.324 m (hypothesis 5), its swing too.
            let truth = bank.ropes.factor(4).unwrap();
            let force = 100_000.0 + 10.0 * 3000.0 * truth;
            let est = bank
                .update(&LoadTerms {
                    at_rest: at_rest(),
                    force_n: force,
                    force_still_n: None,
                    seals_hold: false,
                    angle_rad: th,
                })
                .unwrap();
            worst = worst.max((est.load_kg / 3000.0 - 1.0).abs());
        }
        println!("worst {worst}");
        assert!(worst < 0.03, "{worst}"); // 15 % uncorrected; 2.1 % measured (switching between neighbouring lengths)
    }

    /// A loaded move stops at 10° and the load bounces at 1.6 Hz by ±14 % of
    /// its pull (campaign seed 19 #2801): for [`BOUNCE_WINDOW_S`] the
    /// reading goes through two stages, after it through one. Measured: the
    /// crests read at most 1.023 × the load in the window and 1.056 after it
    /// (1.057 in the window too with one stage).
    #[test]
    fn a_stops_bounce_goes_through_a_second_stage() {
        let mut bank = StaticLoadBank::new(SwingGeometry::<f64>::coles_930());
        let dt = 0.01;
        let (mut th, w) = (14f64.to_radians(), 3000.0);
        let (mut inside, mut after): (f64, f64) = (0.0, 0.0);
        for k in 0..800 {
            // 2 s still, 2 s lowering at 2 °/s, then at rest.
            let rate = if (200..400).contains(&k) { -2f64.to_radians() } else { 0.0 };
            th += rate * dt;
            bank.advance(th, rate, 0.0, dt);
            let since_stop = (k as f64 - 400.0) * dt;
            // The bounce builds up as the stop's deceleration passes.
            let bounce = if since_stop >= 0.0 {
                0.14 * (1.0 - (-since_stop / 0.3).exp()) * (2.0 * core::f64::consts::PI * 1.6 * since_stop).sin()
            } else {
                0.0
            };
            let est = bank
                .update(&LoadTerms {
                    at_rest: at_rest(),
                    force_n: 100_000.0 + 10.0 * w * (1.0 + bounce),
                    force_still_n: None,
                    seals_hold: false,
                    angle_rad: th,
                })
                .unwrap();
            let r = est.load_kg / w;
            if (0.5..BOUNCE_WINDOW_S).contains(&since_stop) {
                inside = inside.max(r);
            } else if since_stop > BOUNCE_WINDOW_S + 0.5 {
                after = after.max(r);
            }
        }
        println!("bounce crest in the window {inside:.4}, after it {after:.4}");
        // One stage passes 1.6 Hz at 0.40 of its size, two at 0.16.
        assert!(inside < 1.03, "{inside}");
        assert!(after > 1.045, "{after}");
    }

    /// A load rising from an empty hook before any move is a lift-off, read
    /// through one filter stage fewer for [`FAST_LIFT_S`] after the hook last
    /// read empty (see the module doc, "A lift-off: one stage fewer"); not a
    /// load hanging at power-up, nor one lifted after a move until the hook
    /// has hung empty for [`EMPTY_HOOK_S`] and the ropes hang still again.
    #[test]
    fn a_lift_off_is_only_a_load_rising_from_an_empty_hook_before_any_move() {
        let th = 50f64.to_radians();
        let dt = 0.01;
        // The boom's rate, the load (kg) over the run, and whether the bank
        // says it lifts, cycle by cycle.
        let run = |rate: &dyn Fn(usize) -> f64, load: &dyn Fn(usize) -> f64, n: usize| -> Vec<bool> {
            let mut bank = StaticLoadBank::new(SwingGeometry::<f64>::coles_930());
            let mut angle = th;
            (0..n)
                .map(|k| {
                    angle += rate(k) * dt;
                    bank.advance(angle, rate(k), 0.0, dt);
                    let terms = LoadTerms { at_rest: at_rest(), force_n: 100_000.0 + 10.0 * load(k), force_still_n: None, seals_hold: false, angle_rad: angle };
                    bank.update(&terms);
                    bank.lifting()
                })
                .collect()
        };
        let lift = |k: usize| if k < 300 { 0.0 } else { (f64::from(k as u32 - 300) * 100.0).min(3000.0) };
        // Empty for 3 s, then 3 t taken up in 0.3 s: the window runs from
        // the last empty reading (400 kg, cycle 304) for FAST_LIFT_S.
        let lifting = run(&|_| 0.0, &lift, 800);
        let last = lifting.iter().rposition(|&l| l).unwrap();
        assert!(lifting[..=last].iter().all(|&l| l), "{lifting:?}");
        assert_eq!(last, 304 + (FAST_LIFT_S / dt).round() as usize - 1, "{last}");
        // A load hanging at power-up is no lift-off.
        assert!(run(&|_| 0.0, &|_| 3000.0, 400).iter().all(|&l| !l));
        // Nor a load lifted right after an empty-hook move (1 s at 2 °/s)...
        let moved = |k: usize| if (100..200).contains(&k) { 2f64.to_radians() } else { 0.0 };
        let after_move = |k: usize| if k < 500 { 0.0 } else { 3000.0 };
        assert!(run(&moved, &after_move, 800)[200..].iter().all(|&l| !l));
        // ... until the hook has hung empty for EMPTY_HOOK_S after it.
        let long_after = |k: usize| if k < 1000 { 0.0 } else { 3000.0 };
        let lifting = run(&moved, &long_after, 1100);
        assert!(!lifting[300] && lifting[900] && lifting[1050], "{:?}", &lifting[850..]);
    }

    /// A lift-off bounces once the still force's first filter stage turns
    /// down by a twentieth of its rise (`watch_lift`), and until then its
    /// load is read through the faster stage: 3 t put on an empty hook at
    /// once, before any move, through the limiter's force filter (four
    /// 1.2 Hz stages; the still force through three while a load rises).
    #[test]
    fn a_lift_off_is_read_at_once_until_it_bounces() {
        let dt = 0.01;
        // The load over the run (kg); the bank's reading and whether the
        // lift-off has bounced, cycle by cycle; `watched`: whether the bank
        // is given the first stage (without it, the stage against the
        // bounce throughout).
        let run_watched = |load: &dyn Fn(f64) -> f64, watched: bool| -> Vec<(f64, bool)> { lift_off_cycles(load, watched).iter().map(|c| (c.load_kg, c.bounced)).collect() };
        let run = |load: &dyn Fn(f64) -> f64| run_watched(load, true);
        // Empty for 3 s, then the load at once.
        let step = |t: f64| if t < 3.0 { 0.0 } else { 3000.0 };
        // Its bounce: twice the load at the first crest, ringing at 1.5 Hz.
        let bounce = |t: f64| ringing(t, 1.0);
        // Turning down by 4 % of its rise: no bounce.
        let turn = |t: f64| if t < 3.0 { 0.0 } else if t < 3.5 { 3000.0 } else { 2880.0 };
        let (stepped, bounced, turned) = (run(&step), run(&bounce), run(&turn));
        // When the reading first reaches 0.866 of the load (what cuts 110 %
        // with the ×1.05 reading), s after the step: measured 0.77 s, and
        // 0.95 s through the stage against the bounce.
        let first = |r: &[(f64, bool)]| r.iter().position(|&(w, _)| w >= 0.866 * 3000.0).map(|k| k as f64 * dt - 3.0);
        let (seen, seen_unwatched) = (first(&stepped).unwrap(), first(&run_watched(&step, false)).unwrap());
        assert!(seen <= 0.8 && seen_unwatched >= seen + 0.15 && stepped.iter().all(|&(_, b)| !b), "seen {seen:.2} s after the step, {seen_unwatched:.2} s unwatched");
        assert!(!turned.iter().any(|&(_, b)| b));
        // The bounce's first crest turns 0.33 s after the step, and shows in
        // the first stage 0.49 s after it; from then on the stage against
        // the bounce alone, and the faster stage has read no more of the
        // crest than that stage reads (the crests come through the three
        // stages later still).
        let at = bounced.iter().position(|&(_, b)| b).map(|k| k as f64 * dt - 3.0).unwrap();
        let highest = |r: &[(f64, bool)]| r.iter().map(|&(w, _)| w).fold(0.0, f64::max);
        let unwatched = run_watched(&bounce, false);
        assert!((0.33..0.55).contains(&at), "bounced {at:.2} s after the step");
        assert!(highest(&bounced) <= highest(&unwatched) * 1.001, "{:.0} kg against {:.0} kg", highest(&bounced), highest(&unwatched));
    }

    /// A ring that decays geometrically, by `r` from one turning point to
    /// the next, has the mean `ring_mean` gives from any three of them in a
    /// row, crest or trough in the middle, whatever its damping; the
    /// midrange of two reads it off by up to r(1 − r)/2 of the swing before
    /// (high from a crest to a trough). A lift-off taken up over time rings
    /// less than a step: from the empty hook through its first crest and
    /// trough, the mean reads low, never high.
    #[test]
    fn a_ring_has_the_mean_of_three_turning_points() {
        for r in [0.3f64, 0.5, 0.72, 0.9, 0.97, 1.0] {
            for a in [-2.0f64, 0.7] {
                // Turning points 1 + a·(−r)^n about the mean 1.
                let x = |n: i32| 1.0 + a * (-r).powi(n);
                for n in 0..4 {
                    let m = ring_mean(x(n), x(n + 1), x(n + 2)).unwrap();
                    // Ending at a crest, the midrange of the last two is
                    // the lower: low by r(1 − r)/2 of the first's amplitude.
                    let low = if x(n + 2) > x(n + 1) { r * (1.0 - r) / 2.0 * (x(n) - 1.0).abs() } else { 0.0 };
                    assert!((m - (1.0 - low)).abs() < 1e-12, "r {r}, a {a}, n {n}: {m}");
                }
            }
            // From a crest 1 + r to the trough 1 − r², the midrange is high.
            assert!(((1.0 + r + 1.0 - r * r) / 2.0 - 1.0 - r * (1.0 - r) / 2.0).abs() < 1e-12);
        }
        // Rung by k of a step's ring (a ramp's sinc; the filter's stage),
        // from the empty hook at 0.
        for k in [0.2f64, 0.5, 0.65, 0.9] {
            for r in [0.5f64, 0.9, 0.97] {
                let m = ring_mean(0.0, 1.0 + k * r, 1.0 - k * r * r).unwrap();
                assert!(m <= 1.0 && m > 0.85, "k {k} r {r}: {m}");
            }
        }
        // No turning point in the middle, no mean.
        assert_eq!(ring_mean(0.0f64, 1.0, 2.0), None);
        assert_eq!(ring_mean(1.0f64, 1.0, 0.5), None);
    }

    /// A lift-off's ring weighs it before the filters have averaged the
    /// bounce (`watch_lift`; module doc, "A lift-off: the mean of its
    /// ring"): 3 t put on an empty hook through the limiter's force filter,
    /// ringing at 1.5 Hz, lightly (as the simulator's boom) or heavily
    /// damped, at once or taken up in 0.2 s. The first mean is found within
    /// 0.85 s of the take-up's end and reads at least 0.85 of the load; no
    /// mean reads more than 1.005 of it (measured: 0.72–0.83 s, 0.895–0.931
    /// of the load, the later means up to 1.000). The heavy ring's first
    /// crest and trough alone (their midrange) read it 10 % high.
    #[test]
    fn a_lift_off_is_weighed_by_its_ring() {
        // Every mean found (of the load) and when (s after the step).
        let run = |load: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
            let mut means: Vec<(f64, f64)> = Vec::new();
            for c in lift_off_cycles(load, true) {
                if let Some(w) = c.ring_kg {
                    if means.last().is_none_or(|&(m, _)| m != w / 3000.0) {
                        means.push((w / 3000.0, c.t - 3.0));
                    }
                }
            }
            means
        };
        let (light, heavy) = (|t| ringing(t, 0.1), |t| ringing(t, 1.0));
        // Name, take-up (s), the load over time.
        type Case<'a> = (&'a str, f64, &'a dyn Fn(f64) -> f64);
        let cases: [Case; 4] = [
            ("light, at once", 0.0, &light),
            ("heavy, at once", 0.0, &heavy),
            ("light, in 0.2 s", 0.2, &|t: f64| ramped_ring(t - 3.0, 0.2, 0.1)),
            ("heavy, in 0.2 s", 0.2, &|t: f64| ramped_ring(t - 3.0, 0.2, 1.0)),
        ];
        for (name, take_up, load) in cases {
            let means = run(load);
            let (first, at) = means.first().copied().unwrap_or((f64::NAN, f64::NAN));
            let highest = means.iter().map(|&(m, _)| m).fold(0.0, f64::max);
            assert!(first >= 0.85 && at - take_up <= 0.85 && highest <= 1.005, "{name}: {means:.3?}");
        }
        // A load that rises and stays (no ring) gives no mean.
        assert!(run(&|t: f64| if t < 3.0 { 0.0 } else { 3000.0 }).is_empty());
    }

    /// While a lift-off's ring decays, the reading stays within [`RING_CAP`]
    /// of the ring's highest mean (module doc, "A lift-off: no higher than
    /// its ring"): 3 t put on the hook at once behind the limiter's filter,
    /// ringing at 1.5 Hz lightly damped, is read at most 1.035 of itself
    /// (measured 1.027), where the stage against the bounce alone carries its
    /// crests to 1.073 (decaying at 0.1/s) and 1.053 (0.3/s). And a load
    /// added while it rings, 1 t ringing as it goes on at 4 s or 5 s, is
    /// seen at 0.95 of the new load no later than without the cap.
    #[test]
    fn a_lift_offs_ring_is_read_no_higher_than_its_mean() {
        let highest = |c: &[LiftCycle]| c.iter().filter(|c| c.t >= 3.0).map(|c| c.load_kg).fold(0.0, f64::max);
        for (decay, uncapped) in [(0.1, 1.07), (0.3, 1.05)] {
            let (watched, unwatched) = (lift_off_cycles(&|t| ringing(t, decay), true), lift_off_cycles(&|t| ringing(t, decay), false));
            let (w, u) = (highest(&watched) / 3000.0, highest(&unwatched) / 3000.0);
            assert!(w <= 1.035 && u >= uncapped, "decay {decay}: read up to {w:.3} of the load, {u:.3} without the watch");
            for at in [4.0, 5.0] {
                let load = |t: f64| ringing(t, decay) + if t < at { 0.0 } else { ringing(t - at + 3.0, decay) / 3.0 };
                let seen = |c: &[LiftCycle]| c.iter().find(|c| c.t >= at && c.load_kg >= 0.95 * 4000.0).map(|c| c.t - at);
                let (w, u) = (seen(&lift_off_cycles(&load, true)), seen(&lift_off_cycles(&load, false)));
                assert!(w.is_some() && w <= u, "decay {decay}, added at {at} s: seen {w:?} s after, {u:?} s without the watch");
            }
        }
    }

    /// A load added while a lift-off's ring decays, once the lift window
    /// has closed, is read as a lift-off from the trough it rose from (module
    /// doc, "A load added while a lift-off rings: a lift-off again"): 3 t
    /// put on at once ringing at 1.5 Hz, 1.5 t more ringing as it goes on
    /// 1.5 s, 2 s or 3 s later, is read at 0.95 of the 4.5 t at least 0.09 s
    /// sooner than through the four filter stages and the stage against the
    /// bounce (measured 0.10–0.61 s sooner: 0.66–1.06 s after, where the
    /// watch that reads it so is neutralized 1.05–1.27 s), and no higher
    /// than 1.03 of it (1.027; 1.042 without).
    #[test]
    fn a_load_added_to_a_ringing_lift_off_is_read_as_a_lift_off() {
        for decay in [0.1, 0.3] {
            for at in [4.5, 5.0, 6.0] {
                let load = |t: f64| ringing(t, decay) + if t < at { 0.0 } else { ringing(t - at + 3.0, decay) / 2.0 };
                let a = added_load(&load, at, 4500.0, 900);
                assert!(a.seen_s + 0.09 <= a.unwatched_s && a.highest <= 1.03, "decay {decay}, added at {at} s: seen {:.2} s after ({:.2} s without the watch), read up to {:.3}", a.seen_s, a.unwatched_s, a.highest);
            }
        }
    }

    /// A load added to one that hangs steadily before any move is read as a
    /// lift-off from the steady force (module doc, "A load added to one
    /// hanging steadily: a lift-off again"): 3 t lifted at once, ringing at
    /// 1.5 Hz and decaying at 1/s, with 3 t more added 5 s or 7 s later
    /// ringing as it goes on, is read at 0.95 of the 6 t at least 0.09 s
    /// sooner than through the four filter stages and the stage against the
    /// bounce (measured: 0.83 s after, 1.27–1.29 s without the watch), and
    /// no higher than 1.03 of it (1.000). A winch started hard, the rope
    /// pulling a fifth more for a quarter second, is no lift-off, nor is a
    /// raise's start whose force rises as much but whose boom is seen
    /// moving within [`STEADY_CONFIRM_S`] (one seen moving later is).
    #[test]
    fn a_load_added_to_a_steadily_hanging_one_is_read_as_a_lift_off() {
        for at in [8.0, 10.0] {
            let load = |t: f64| ringing(t, 1.0) + if t < at { 0.0 } else { ringing(t - at + 3.0, 1.0) };
            let a = added_load(&load, at, 6000.0, 1200);
            assert!(a.seen_s + 0.09 <= a.unwatched_s && a.highest <= 1.03, "added at {at} s: seen {:.2} s after ({:.2} s without the watch), read up to {:.3}", a.seen_s, a.unwatched_s, a.highest);
        }
        let winch = |t: f64| ringing(t, 1.0) * if (10.0..10.25).contains(&t) { 1.2 } else { 1.0 };
        assert!(lift_off_cycles_for(&winch, true, 1200).iter().all(|c| !c.lifting || c.t < 10.0), "a winch's pull read as a lift-off");
        // A raise's start: the force 60 % up over a second from 10 s (f₁
        // passes the band's top by 30 % at 10.64 s). The boom seen moving
        // (over MOVING_RAD_S) 0.25 s later, within STEADY_CONFIRM_S, is no
        // lift-off; seen 0.45 s later, it is one from 10.94 s.
        let raise = |t: f64| ringing(t, 1.0) * (1.0 + 0.6 * (t - 10.0).clamp(0.0, 1.0));
        for (seen_at, read) in [(10.89, false), (11.09, true)] {
            let moving = move |t: f64| if t >= seen_at { 2.0 * MOVING_RAD_S } else { 0.0 };
            let lifting = lift_off_cycles_raising(&raise, &moving, true, 1200, f64::INFINITY).iter().any(|c| c.lifting && c.t >= 10.0);
            assert_eq!(lifting, read, "the boom seen moving at {seen_at} s");
        }
        // The same raise seen moving at 11.09 s, with the seals' breakaway
        // held from 10.7 s (the angle shows the boom rising before the
        // direction detector calls it a raise, crate::breakaway): no
        // lift-off; held only from 11.0 s, after the lift window opened
        // at 10.94 s, still one.
        let moving = |t: f64| if t >= 11.09 { 2.0 * MOVING_RAD_S } else { 0.0 };
        for (held_from, read) in [(10.7, false), (11.0, true)] {
            let lifting = lift_off_cycles_raising(&raise, &moving, true, 1200, held_from).iter().any(|c| c.lifting && c.t >= 10.0);
            assert_eq!(lifting, read, "the seals held from {held_from} s");
        }
    }

    /// A load that rings on after its lift-off, never hanging steadily
    /// (its ring grows over the first crests, as when it rides on the
    /// swing the boom's give starts, then decays by a tenth a second): a
    /// load added to it rises over all the force did since the lift-off's
    /// first crest and is read as a lift-off; the ring alone never is.
    #[test]
    fn a_load_added_to_one_that_rings_on_is_read_as_a_lift_off() {
        let rings_on = |t: f64| {
            let s = t - 3.0;
            let amplitude = 0.6 * (1.0 - 0.5 * (-2.0 * s).exp()) * (-0.1 * s).exp();
            if s < 0.0 { 0.0 } else { 3000.0 * (1.0 - (std::f64::consts::TAU * 1.5 * s).cos() * amplitude) }
        };
        let window_ends = 3.0 + FAST_LIFT_S + 0.5;
        assert!(lift_off_cycles_for(&rings_on, true, 1200).iter().all(|c| !c.lifting || c.t < window_ends), "the ring read as a lift-off");
        for at in [6.0, 8.0] {
            let load = |t: f64| rings_on(t) + if t < at { 0.0 } else { ringing(t - at + 3.0, 1.0) };
            let a = added_load(&load, at, 6000.0, 1200);
            println!("added at {at} s: seen {:.2} s after ({:.2} s without the watch), read up to {:.3}", a.seen_s, a.unwatched_s, a.highest);
            assert!(a.lifting && a.seen_s + 0.09 <= a.unwatched_s && a.highest <= 1.03, "added at {at} s: read as a lift-off {}, seen {:.2} s after ({:.2} s without the watch), read up to {:.3}", a.lifting, a.seen_s, a.unwatched_s, a.highest);
        }
    }

    /// How the bank reads a load added at `at` s to the hook's `load` (kg
    /// at t s), `total_kg` on the hook with it, over `cycles` cycles
    /// ([`lift_off_cycles_for`]).
    struct AddedLoad {
        /// When the reading first reaches 0.95 of `total_kg` (s after `at`;
        /// infinite if never), with the watch and without it.
        seen_s: f64,
        unwatched_s: f64,
        /// The highest reading from `at` on, of `total_kg` (with the watch).
        highest: f64,
        /// Whether the bank reads a lift-off from `at` on (with the watch).
        lifting: bool,
    }

    fn added_load(load: &dyn Fn(f64) -> f64, at: f64, total_kg: f64, cycles: u16) -> AddedLoad {
        let seen = |c: &[LiftCycle]| c.iter().find(|c| c.t >= at && c.load_kg >= 0.95 * total_kg).map_or(f64::INFINITY, |c| c.t - at);
        let (w, u) = (lift_off_cycles_for(load, true, cycles), lift_off_cycles_for(load, false, cycles));
        AddedLoad {
            seen_s: seen(&w),
            unwatched_s: seen(&u),
            highest: w.iter().filter(|c| c.t >= at).map(|c| c.load_kg).fold(0.0, f64::max) / total_kg,
            lifting: w.iter().any(|c| c.lifting && c.t >= at),
        }
    }

    /// One cycle of [`lift_off_cycles`]: its time (s), the bank's reading
    /// (kg), whether the lift-off has bounced, its ring's mean (kg) and
    /// whether the bank reads a lift-off.
    struct LiftCycle {
        t: f64,
        load_kg: f64,
        bounced: bool,
        ring_kg: Option<f64>,
        lifting: bool,
    }

    /// The hook load `load` (kg at t s) through the limiter's force filter
    /// (four 1.2 Hz stages; the still force through three while a load
    /// rises) into the bank at 50°, boom still, 600 cycles of 10 ms;
    /// `watched`: whether the bank is given the first stage (without it,
    /// the stage against the bounce throughout, and no ring).
    fn lift_off_cycles(load: &dyn Fn(f64) -> f64, watched: bool) -> Vec<LiftCycle> {
        lift_off_cycles_for(load, watched, 600)
    }

    /// [`lift_off_cycles`] over `cycles` cycles.
    fn lift_off_cycles_for(load: &dyn Fn(f64) -> f64, watched: bool, cycles: u16) -> Vec<LiftCycle> {
        lift_off_cycles_raising(load, &|_| 0.0, watched, cycles, f64::INFINITY)
    }

    /// [`lift_off_cycles_for`] with the boom raised from 50° at `rate`
    /// (rad/s at t s, as the limiter's filtered rate gives it).
    /// From `held_from` s on, the seals' breakaway is held (the limiter calls
    /// [`StaticLoadBank::raise_starts`]).
    fn lift_off_cycles_raising(load: &dyn Fn(f64) -> f64, rate: &dyn Fn(f64) -> f64, watched: bool, cycles: u16, held_from: f64) -> Vec<LiftCycle> {
        use crate::filter::LowPass;
        let mut th = 50f64.to_radians();
        let dt = 0.01;
        let mut bank = StaticLoadBank::new(SwingGeometry::<f64>::coles_930());
        let mut filter = LowPass::new(1.2, 4);
        (0..cycles)
            .map(|k| {
                let t = f64::from(k) * dt;
                let force = filter.update(100_000.0 + 10.0 * load(t), dt);
                th += rate(t) * dt;
                bank.advance(th, rate(t), 0.0, dt);
                if t >= held_from {
                    bank.raise_starts();
                }
                if watched {
                    bank.watch_lift(filter.first_stage(), 0.0);
                }
                let still = if bank.lifting() { force + filter.last_stage_lead() } else { force };
                let terms = LoadTerms { at_rest: at_rest(), force_n: force, force_still_n: Some(still), seals_hold: false, angle_rad: th };
                let load_kg = bank.update(&terms).map_or(f64::NAN, |l| l.load_kg);
                LiftCycle { t, load_kg, bounced: bank.lift_bounced, ring_kg: bank.lift_ring_n.and_then(|f| at_rest().solve(f)), lifting: bank.lifting() }
            })
            .collect()
    }

    /// 3 t put on the hook at t = 3 s, ringing at 1.5 Hz from the empty hook
    /// to twice the load, its amplitude decaying at `decay_per_s`: the load
    /// on the hook (kg) at `t`.
    fn ringing(t: f64, decay_per_s: f64) -> f64 {
        if t < 3.0 {
            0.0
        } else {
            3000.0 * (1.0 - (std::f64::consts::TAU * 1.5 * (t - 3.0)).cos() * (-decay_per_s * (t - 3.0)).exp())
        }
    }

    /// 3 t taken up over `take_up` s from `s` = 0 on a mass-spring that rings
    /// at 1.5 Hz with its amplitude decaying at `decay_per_s`: the load on
    /// the hook (kg) at `s`.
    fn ramped_ring(s: f64, take_up: f64, decay_per_s: f64) -> f64 {
        let w = std::f64::consts::TAU * 1.5;
        // A ramp's response is the mean of the step's, 1 − cos(ωs)·e^(−as),
        // over the ramp: `step` is its integral from 0 to s.
        let a = decay_per_s;
        let step = |s: f64| if s <= 0.0 { 0.0 } else { s - ((-a * s).exp() * (w * (w * s).sin() - a * (w * s).cos()) + a) / (a * a + w * w) };
        3000.0 * (step(s) - step(s - take_up)) / take_up
    }

    #[test]
    fn a_heavier_load_is_seen_through_one_stage_and_never_overshoots() {
        let mut bank = StaticLoadBank::new(SwingGeometry::<f64>::coles_930());
        let th = 50f64.to_radians();
        let tau = 1.0 / (2.0 * core::f64::consts::PI * FAST_SMOOTHING_HZ);
        for k in 0..300 {
            bank.advance(th, 0.0, 0.0, 0.01);
            let w = if k < 200 { 3000.0 } else { 4000.0 };
            let est = bank
                .update(&LoadTerms {
                    at_rest: at_rest(),
                    force_n: 100_000.0 + 10.0 * w,
                    force_still_n: None,
                    seals_hold: false,
                    angle_rad: th,
                })
                .unwrap();
            assert!(est.load_kg <= w + 1e-9, "{k}: {}", est.load_kg);
            if k < 200 {
                assert!((est.load_kg - w).abs() < 1e-9);
            } else {
                // At least the first-order step response of the stage.
                let t = f64::from(k - 199) * 0.01;
                let floor = 3000.0 + 1000.0 * (1.0 - (-t / tau).exp());
                assert!(est.load_kg >= floor - 1.0, "{k}: {} < {floor}", est.load_kg);
            }
        }
    }

    /// Before any move the averages are raised to W_fast at once and
    /// lowered at their own pace; while the seals' breakaway is taken out of
    /// the force they are set to W_fast, so the rise they took up before the
    /// angle showed the raise is not carried into it.
    #[test]
    fn a_breakaway_sets_the_averages_to_the_weighing() {
        let mut bank = StaticLoadBank::new(SwingGeometry::<f64>::coles_930());
        let th = 50f64.to_radians();
        let mut step = |w: f64, seals_hold: bool| {
            bank.advance(th, 0.0, 0.0, 0.01);
            let terms = LoadTerms { at_rest: at_rest(), force_n: 100_000.0 + 10.0 * w, force_still_n: None, seals_hold, angle_rad: th };
            bank.update(&terms).unwrap()
        };
        for _ in 0..200 {
            step(3000.0, false);
        }
        // The friction's rise, read as 150 kg more, before the angle shows it.
        for _ in 0..100 {
            step(3150.0, false);
        }
        let raised = step(3000.0, false);
        assert!(raised.slow_kg.is_some_and(|s| s > 3140.0), "{raised:?}");
        // Taken out: the averages are the weighing again.
        let held = step(3000.0, true);
        assert!(held.slow_kg.is_some_and(|s| (s - held.fast_kg).abs() < 1e-9 && s < 3150.0), "{held:?}");
    }
}

#[cfg(test)]
mod rest_tests {
    use super::*;

    fn at_rest() -> Quadratic<f64> {
        Quadratic {
            at_zero: 100_000.0,
            per_kg: 10.0,
            per_kg2: 0.0,
        }
    }

    /// The boom of a 10 s-like move from `from` to `to` degrees (accelerate
    /// 1 s, turn at constant rate to 9 s, decelerate 1 s, then rest),
    /// sampled every `dt` s for `steps` steps: (t, θ, rate, acceleration).
    fn raise(from: f64, to: f64, dt: f64, steps: u32) -> impl Iterator<Item = (f64, f64, f64, f64)> {
        // Ramps of 1 s and 8 s at constant rate: rate = span / 9.
        let rate_max = (to - from).to_radians() / 9.0;
        let (mut th, mut rate) = (from.to_radians(), 0.0);
        (0..steps).map(move |k| {
            let t = f64::from(k) * dt;
            let acc = if (1.0..2.0).contains(&t) {
                rate_max
            } else if (9.0..10.0).contains(&t) {
                -rate_max
            } else {
                0.0
            };
            rate += acc * dt;
            if t >= 10.0 {
                rate = 0.0;
            }
            th += rate * dt;
            (t, th, rate, acc)
        })
    }

    /// A 10 s-like raise from `from` to `to` degrees (accelerate 1 s, turn,
    /// decelerate 1 s), then rest; the truth a held rope `truth` of the bank,
    /// its load `w0` and from `add_at` s on `w1`. Returns (t, estimate, true
    /// load) per cycle.
    fn run(from: f64, to: f64, truth: usize, w0: f64, w1: f64, add_at: f64) -> Vec<(f64, f64, f64)> {
        run_in(from, to, truth, w0, w1, add_at, None)
    }

    /// [`run`] with the truth its own pendulum when `world_give` is
    /// `Some(scale)`: rigid in the move, lengthened at rest by `scale` times
    /// the model's give under the true load (see
    /// [`late_where_the_boom_gives`]).
    fn run_in(from: f64, to: f64, truth: usize, w0: f64, w1: f64, add_at: f64, world_give: Option<f64>) -> Vec<(f64, f64, f64)> {
        let g = SwingGeometry::<f64>::coles_930();
        let mut world = HeldRopes::new([HELD_LENGTHS_M[truth]], g.gravity_m_s2);
        let mut bank = StaticLoadBank::new(g);
        let dt = 0.01;
        let mut out = Vec::new();
        for (t, th, rate, acc) in raise(from, to, dt, 2000) {
            bank.advance(th, rate, acc, dt);
            let w = if t >= add_at { w1 } else { w0 };
            let f = match world_give {
                None => bank.ropes.factor(truth).unwrap(),
                Some(scale) => {
                    world.set_give(if t >= 10.0 { scale * g.give_m(th.sin(), w) } else { 0.0 });
                    world.update(&BoomTip::new(th.sin_cos(), g.boom_length_m, rate, acc, dt));
                    world.factor(0).unwrap()
                }
            };
            let est = bank
                .update(&LoadTerms {
                    at_rest: at_rest(),
                    force_n: 100_000.0 + 10.0 * w * f,
                    force_still_n: None,
                    seals_hold: false,
                    angle_rad: th,
                })
                .unwrap();
            out.push((t, est.load_kg, w));
        }
        out
    }

    /// A still boom's rate over [`SETTLED_RAD_S`] for less than
    /// [`UNSETTLED_GRACE_S`] (angle noise) leaves the rest settled for what
    /// follows the force over seconds; for longer (a creep), not.
    #[test]
    fn the_rest_stays_settled_through_a_noise_excursion_but_not_through_a_creep() {
        let mut bank = StaticLoadBank::new(SwingGeometry::<f64>::coles_930());
        let (th, dt) = (1.0, 0.01);
        // Between the settled (0.05 °/s) and the moving (0.15 °/s) rates.
        let over = 0.1f64.to_radians();
        for _ in 0..150 {
            bank.advance(th, 0.0, 0.0, dt);
        }
        assert!(bank.calm);
        for _ in 0..25 {
            bank.advance(th, over, 0.0, dt);
        }
        assert!(bank.calm && !bank.settled, "a 0.25 s excursion");
        bank.advance(th, 0.0, 0.0, dt);
        for _ in 0..51 {
            bank.advance(th, -over, 0.0, dt);
        }
        assert!(!bank.calm && bank.still, "a 0.51 s creep");
        bank.advance(th, 0.0, 0.0, dt);
        assert!(bank.calm);
    }

    /// 3 t → 4 t added 3 s after each move of
    /// [`a_load_added_at_rest_after_a_move_is_seen_within_one_second`] on
    /// every possible held rope, in a world whose boom gives `scale` times
    /// the model's give at rest (the truth its own pendulum, lengthened by
    /// `scale`·c·sin²θ·g·W of the true load): the cases (move, rope, time to
    /// ≥ 97.5 %) not seen within 1 s.
    fn late_where_the_boom_gives(scale: f64) -> Vec<(f64, f64, f64, Option<f64>)> {
        let g = SwingGeometry::<f64>::coles_930();
        let mut late = Vec::new();
        for (from, to) in [(40.0, 60.0), (60.0, 40.0), (40.0, 80.0)] {
            for (truth, length) in HELD_LENGTHS_M.iter().enumerate() {
                if *length > g.tip_height_m(f64::to_radians(to)) {
                    continue;
                }
                let pts = run_in(from, to, truth, 3000.0, 4000.0, 13.0, Some(scale));
                let seen = pts.iter().find(|p| p.0 >= 13.0 && p.1 >= 3900.0).map(|p| p.0 - 13.0);
                if seen.is_none_or(|s| s > 1.0) {
                    late.push((from, to, *length, seen));
                }
            }
        }
        late
    }

    /// The bank lengthens its pendulums at rest by the model's give (the
    /// boom's bending alone); a real crane's cylinder, pins and chassis give
    /// more, never less. Asserted: a load added at rest is seen within 1 s
    /// on a boom that gives as the model's and up to twice as much. Measured
    /// (`..._measured`): within 1 s from 1 to 2.5 times; at 0.75 times and
    /// on a rigid boom the 3 m rope stopped at 80° is seen after 1.9 s (the
    /// 4.7 m one after 2.1 s rigid), at 3 times after 3.1 s. With rigid
    /// pendulums in the bank the window was a rigid boom to 1.5 times the
    /// model's give: at twice, the 3 m and 5.9 m ropes stopped at 80° were
    /// seen after 3.0 s and 4.75 s (this test failed).
    #[test]
    fn a_load_added_at_rest_is_seen_on_a_boom_that_gives_up_to_twice_the_models() {
        for scale in [1.0, 1.5, 2.0] {
            let late = late_where_the_boom_gives(scale);
            assert!(late.is_empty(), "give x{scale}: {late:?}");
        }
    }

    #[test]
    #[ignore = "measurement: a load added at rest against how much the boom gives"]
    fn a_load_added_at_rest_against_the_booms_give_measured() {
        for scale in [0.0, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0] {
            println!("boom giving {scale} times the model's: not seen within 1 s {:?}", late_where_the_boom_gives(scale));
        }
    }

    #[test]
    fn at_rest_after_a_raise_to_80_degrees_the_short_rope_does_not_collapse_the_weighing() {
        for (truth, length) in HELD_LENGTHS_M.iter().enumerate() {
            let pts = run(40.0, 80.0, truth, 3000.0, 3000.0, 99.0);
            let low = pts.iter().filter(|p| p.0 >= 11.0 && p.0 < 13.0).map(|p| p.1 / p.2).fold(f64::INFINITY, f64::min);
            println!("rope {length} m: lowest at rest 1-3 s after stopping {low:.3}");
            assert!(low > 0.95, "rope {truth}: {low}");
        }
    }

    #[test]
    fn a_load_added_at_rest_after_a_move_is_seen_within_one_second() {
        // 3 t -> 4 t, 3 s after a 10 s-like move stops, the load still
        // swinging: seen (>= 97.5 %) within 1 s for every held rope of the
        // bank that the boom can hold at rest (a rope longer than the tip is
        // high would hold its load below ground: no hypothesis of the bank
        // is possible there, and such a crane cannot exist; printed only).
        // Before the common-jump rescale (crate::load_jump): 1.4-6 s or not
        // within 7 s for most lengths.
        let g = SwingGeometry::<f64>::coles_930();
        let mut late = Vec::new();
        for (from, to) in [(40.0, 60.0), (60.0, 40.0), (40.0, 80.0)] {
            for (truth, length) in HELD_LENGTHS_M.iter().enumerate() {
                let pts = run(from, to, truth, 3000.0, 4000.0, 13.0);
                let seen = pts.iter().find(|p| p.0 >= 13.0 && p.1 >= 3900.0).map(|p| p.0 - 13.0);
                // Never above the load, before or after.
                let over = pts.iter().map(|p| p.1 / p.2).fold(0.0, f64::max);
                let possible = *length <= g.tip_height_m(f64::to_radians(to));
                println!("{from}->{to} rope {length} m{}: 4 t seen after {seen:?} s, highest {over:.3}", if possible { "" } else { " (impossible at rest)" });
                if possible && (seen.is_none_or(|s| s > 1.0) || over > 1.01) {
                    late.push((from, to, truth, seen, over));
                }
            }
        }
        assert!(late.is_empty(), "{late:?}");
    }

    /// Per cycle: time (s), estimate (kg), true load (kg), force (N).
    type Trace = Vec<(f64, f64, f64, f64)>;

    /// A raise from 40° to `to` degrees with `w0` kg on held rope `truth`
    /// of the bank (the truth its own pendulum), then at rest: `set_down`
    /// s after the start the load lands (the force of an empty hook; a load
    /// on the ground swings no more), and from `lift` s on `w1` kg hangs
    /// still under the tip. Returns the bank and its [`Trace`].
    fn set_down_and_lift(to: f64, truth: usize, w0: f64, set_down: f64, lift: f64, w1: f64) -> (StaticLoadBank<f64>, Trace) {
        let g = SwingGeometry::<f64>::coles_930();
        let mut world = HeldRopes::new([HELD_LENGTHS_M[truth]], g.gravity_m_s2);
        let mut bank = StaticLoadBank::new(g);
        let dt = 0.01;
        let mut out = Vec::new();
        for (t, th, rate, acc) in raise(40.0, to, dt, 6000) {
            bank.advance(th, rate, acc, dt);
            world.update(&BoomTip::new(th.sin_cos(), g.boom_length_m, rate, acc, dt));
            let (w, f) = if t < set_down { (w0, world.factor(0).unwrap()) } else if t < lift { (0.0, 1.0) } else { (w1, 1.0) };
            let terms = LoadTerms { at_rest: at_rest(), force_n: 100_000.0 + 10.0 * w * f, force_still_n: None, seals_hold: false, angle_rad: th };
            out.push((t, bank.update(&terms).unwrap().load_kg, w, terms.force_n));
        }
        (bank, out)
    }

    /// A load set down at rest and another lifted, or a load lifted after a
    /// move with the hook empty (a rigger steadies the hook; the load leaves
    /// the ground hanging still): once the hook has been empty for
    /// [`EMPTY_HOOK_S`], every rope of the bank hangs still, and a load
    /// lifted then is weighed as at power-up, within [0.98, 1.02] of
    /// itself 1 s after it is taken up (0.988–1.000), on every rope. Before,
    /// the ropes swung on from the move, and the lift on the 3 m rope after
    /// a raise to 60° read 0.839 of itself. The lift, taken up at once,
    /// swings each rope by no more than the tip's give leaves its load
    /// inward ("A lift-off: the boom's give swings the load"): this world
    /// has no give, and the weighing holds anyway.
    #[test]
    fn a_load_set_down_stops_the_ropes_swinging() {
        for (to, w0) in [(60.0, 3000.0), (80.0, 3000.0), (60.0, 0.0), (80.0, 0.0)] {
            for truth in 0..HELD_LENGTHS_M.len() {
                let (bank, out) = set_down_and_lift(to, truth, w0, 20.0, 30.0, 4000.0);
                let g = SwingGeometry::<f64>::coles_930();
                // The tip's shift under the load the bank reads hanging, at
                // the angle `raise` stops at (8/9 of the span: it turns at
                // `rate_max` for 8 s in all).
                let end = (40.0 + (to - 40.0) * 8.0 / 9.0).to_radians();
                let shift = g.tip_shift_m(end.sin_cos(), bank.hanging_kg.unwrap_or(f64::NAN));
                for (i, l) in HELD_LENGTHS_M.iter().enumerate() {
                    // The move's swing (up to 15° on the 3 m rope at 80°)
                    // is gone; what swings is the lift's give, the load left
                    // inward of the tip by its shift.
                    let kick = shift / l;
                    let swing = bank.ropes.tan_swing(i).unwrap_or(f64::NAN).abs();
                    assert!(swing <= kick * 1.001, "to {to}, {w0} kg, truth {truth}: rope {i} swings by tan φ {swing:.5}, the lift's give {kick:.5}");
                }
                let paid_out_kick = shift / g.paid_out_length_m(end);
                assert!(bank.paid_out.tan_swing().abs() <= paid_out_kick * 1.001, "to {to}, {w0} kg, truth {truth}: the paid-out rope swings");
                let late = out.iter().filter(|q| q.0 >= 31.0);
                let (lo, hi) = late.fold((f64::INFINITY, 0.0f64), |(lo, hi), &(_, e, w, _)| (lo.min(e / w), hi.max(e / w)));
                assert!(lo >= 0.98 && hi <= 1.02, "to {to}, {w0} kg, truth {truth}: estimate/true {lo:.3}..{hi:.3} from 1 s after the lift");
            }
        }
    }

    /// A load that swings at rest is never taken for an empty hook, however
    /// low its pull dips: 3 t on every rope of the bank, 50 s at rest after
    /// a raise to 60° or 80° (at 80° the 3 m rope swings 15°, and its pull
    /// on the cylinder nearly vanishes twice a period): the bank's ropes
    /// swing on to the end, and the longest the pull stays under an empty
    /// hook's is under half of [`EMPTY_HOOK_S`].
    #[test]
    fn a_swinging_load_is_never_taken_for_an_empty_hook() {
        let light_n = 100_000.0 + 10.0 * load_jump::MIN_AVERAGE_KG;
        let mut longest = 0.0f64;
        for to in [60.0, 80.0] {
            for truth in 0..HELD_LENGTHS_M.len() {
                let (bank, out) = set_down_and_lift(to, truth, 3000.0, f64::INFINITY, f64::INFINITY, 0.0);
                assert!(bank.moved, "to {to}, truth {truth}: the ropes were stilled");
                let mut run = 0.0f64;
                for &(t, _, _, force) in &out {
                    run = if t >= 10.0 && force < light_n { run + 0.01 } else { 0.0 };
                    longest = longest.max(run);
                }
            }
        }
        assert!(longest > 0.0 && longest < EMPTY_HOOK_S / 2.0, "the pull stayed under an empty hook's for {longest:.2} s");
    }
}
