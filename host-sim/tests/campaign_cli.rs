//! `crane-sim campaign` (issue 10, SPEC §5): reproducible from its seed, shards
//! that make up the whole campaign, and a small campaign that must not miss an
//! overload while luffing or at rest.
//!
//! The small campaign is the CI's copy of issue 11's: no missed overload (a
//! lift-off graded by its own rule, OVERLOAD within 1 s of the load leaving
//! the ground) and no early one; the false-OVERLOAD count and the lift-offs
//! that pass u = 1.05 while the hoist takes the load up are printed.
use std::process::Command;

fn campaign(args: &[&str]) -> (String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_crane-sim")).arg("campaign").args(args).output().expect("runs");
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    (String::from_utf8(out.stdout).expect("utf8"), String::from_utf8_lossy(&out.stderr).into_owned())
}

fn scenario_lines(json: &str) -> Vec<String> {
    json.lines().filter(|l| l.contains("\"type\":\"scenario\"")).map(str::to_owned).collect()
}

fn summary(json: &str) -> serde_json::Value {
    let last = json.lines().last().expect("summary line");
    let v: serde_json::Value = serde_json::from_str(last).expect("json");
    assert_eq!(v["type"], "summary");
    v
}

#[test]
fn same_seed_same_json_and_shards_make_up_the_campaign() {
    let args = ["--scenarios", "12", "--seed", "5", "--cranes", "3", "--json"];
    let (a, _) = campaign(&args);
    let (b, _) = campaign(&args);
    assert_eq!(a, b, "same seed, same JSON");
    let all = scenario_lines(&a);
    assert_eq!(all.len(), 12);
    let mut shards: Vec<String> = ["1/2", "2/2"].iter().flat_map(|s| scenario_lines(&campaign(&[&args[..], &["--shard", s]].concat()).0)).collect();
    let key = |l: &String| serde_json::from_str::<serde_json::Value>(l).expect("json")["index"].as_u64().expect("index");
    shards.sort_by_key(key);
    assert_eq!(shards, all, "shards 1/2 and 2/2 are the campaign");
    // Every scenario carries its seed and the synth command that re-makes it.
    for l in &all {
        let v: serde_json::Value = serde_json::from_str(l).expect("json");
        assert!(v["seed"].as_u64().is_some());
        assert!(v["synth"].as_str().expect("synth").starts_with("crane-sim synth --from-deg"));
    }
    let (c, _) = campaign(&["--scenarios", "12", "--seed", "6", "--cranes", "3", "--json"]);
    assert_ne!(scenario_lines(&c), all, "another seed, other scenarios");
}

#[test]
fn small_campaign_misses_no_overload_and_alarms_none_early() {
    let (json, err) = campaign(&["--scenarios", "200", "--seed", "1", "--json"]);
    let s = summary(&json);
    println!("{s}");
    println!("{err}");
    let n = |k: &str| s[k].as_u64().unwrap_or_else(|| panic!("{k}"));
    assert_eq!(n("scenarios"), 200);
    assert_eq!(n("failed_simulations"), 0);
    assert!(n("overload_scenarios") >= 15, "the distribution must contain overloads");
    println!(
        "missed overloads {} ({} in lift-offs), early {}, false OVERLOADs {} (reported, not asserted), lift-offs past u = 1.05 before the cut {} of {}",
        n("missed_overloads"),
        n("missed_in_lift_off"),
        n("early_overloads"),
        n("false_overloads"),
        n("lift_off_past_1_05_uncut"),
        n("lift_off_overloads")
    );
    assert_eq!(n("missed_overloads") - n("missed_in_lift_off"), 0, "an overload while luffing or at rest was missed");
    assert_eq!(n("missed_in_lift_off"), 0, "a lift-off was not cut within 1 s of the load leaving the ground");
    assert_eq!(n("early_overloads"), 0, "an OVERLOAD came before true u = 1/1.1");
    assert!(n("lift_off_overloads") >= 5, "the distribution must contain over-rated lift-offs");
    // Every group of the summary adds up to the whole.
    let groups = s["groups"].as_array().expect("groups");
    assert_eq!(groups.len(), 4);
    let sum = |k: &str| groups.iter().map(|g| g[k].as_u64().expect(k)).sum::<u64>();
    for k in ["scenarios", "missed_overloads", "early_overloads", "false_overloads", "late_overloads"] {
        assert_eq!(sum(k), n(k), "{k}");
    }
}

/// The cases the 10 000-scenario campaign (`--scenarios 10000 --seed 1`) graded
/// missed, early or false at some point, re-run alone with `--only` (drawn,
/// calibrated and graded as in the whole campaign):
/// - #8345 lowers a 4.3 t load in 9 s from 84° on a 5.6 m held rope: at the
///   steep start no rope hypothesis could weigh and the reading fell to
///   −2.4 t, and it still read 0.57 of the load when true u passed 1.05;
/// - #4152: a FAULT at a stop's pressure spike, after which the filters
///   restarted settled on the spike's value and OVERLOAD came at true u 0.84
///   (now a gap under 1 s pauses the signal chain);
/// - #4528 and #8272 (lowering 3 t to 5–6°): the stop's pressure spike
///   FAULTs for 0.2–0.25 s; taken as one long step, the gap put the boom's
///   whole deceleration into one sample of the filtered angle (220 °/s²) and
///   none after it while the force's rise came on, and the stop read 1.14 ×
///   the load: OVERLOAD at true u 0.906 and 0.873 (now the chain runs through
///   the gap on the straight line between its good samples);
/// - #572 (4.1 t lowered 85° → 10° at 7 °/s on a 3 m held rope) and #9090
///   (4.1 t, 82° → 7° at 10 °/s, 4.1 m): at the steep start the short ropes
///   cannot weigh; the ropes left read the wrong swing, and their averages
///   went to 1.5 × the load (#572: OVERLOAD at true u 0.60) or 0.76 of it
///   (#9090: cut at u 1.09); now the averages and the bank's weighing stand
///   in motion while a possible rope cannot weigh;
/// - #7297: an over-rated lift-off cut at u 1.12, a FAULT, then back to the
///   OVERLOAD latched before it: graded at its onset, not again;
/// - #1131, #2734, #3222, #3326: cranes whose angle sensor lags 0.29–0.30 s
///   (first-order; cranes 6, 11, 14), aligned for the default 0.111 s,
///   alarmed early (OVERLOAD below true u 1/1.1; #3222 at 0.884); the
///   calibration now learns the lag (0.275–0.286 s) and none alarms.
#[test]
fn the_large_campaigns_hard_cases_are_neither_missed_nor_early() {
    let hard = ["8345", "572", "4152", "4528", "8272", "9090", "7297", "1131", "2734", "3222", "3326"];
    assert_none_missed_early_or_false(&only("1", &hard));
}

/// #2186 of the campaign with `--seed 2` (a lift-off at 9°, then a raise to
/// 81° on a held rope) alarmed at true u 0.902 before the bank's averages
/// stood while a short rope could not weigh.
#[test]
fn the_second_campaigns_raise_to_81_degrees_is_not_early() {
    assert_none_missed_early_or_false(&only("2", &["2186"]));
}

/// Booms creeping up under the 0.15 °/s start rate, after a lift-off: #9085
/// and #7769 of the campaign with `--seed 2` (3.2–4.6 t at 0.13–0.27 °/s,
/// seal friction) and #1868 of `--seed 3` (71° → 77° in 58 s). Taken as
/// still, their seals' sliding up-friction stayed in the force as load
/// (1.055–1.065 ×, OVERLOAD at true u 0.898–0.902). Now a rate over 0.05 °/s
/// for 0.25 s upward is a raise when the force stays within 10 % meanwhile
/// (a load taken up at rest shows the same rate with its force rising:
/// `field_limiter a_load_added_at_rest_after_a_move_known_gap`, whose cut it
/// delayed by 0.37 s without that condition).
#[test]
fn creeping_raises_are_not_early() {
    assert_none_missed_early_or_false(&only("2", &["9085", "7769"]));
    assert_none_missed_early_or_false(&only("3", &["1868"]));
}

/// Slow raises begun 2 s after a lift-off, on seals whose up-friction is
/// 4–7 % of the force (seal or constant friction, angle sensors lagging
/// 0.25–0.29 s): #6055 and #7607 of `--seed 12`, #4411 of `--seed 16`,
/// #8203 of `--seed 17`, #8429 of `--seed 18`, #4991 and #4238 of
/// `--seed 28`. The friction is in the force as the boom begins to creep,
/// about a second before the angle shows the raise, and the bank's
/// averages took it up: OVERLOAD at true u 0.901–0.909 (early), highest
/// estimated u 1.002–1.014. The seals' breakaway is now taken out once the
/// angle shows the boom rising (`moment_limiter::breakaway`): none is cut,
/// the highest estimated u 0.984–1.002.
#[test]
fn slow_raises_begun_as_a_lift_off_ends_are_not_early() {
    for (seed, indices) in [("12", &["6055", "7607"][..]), ("16", &["4411"]), ("17", &["8203"]), ("18", &["8429"]), ("28", &["4991", "4238"])] {
        let runs = only(seed, indices);
        assert_none_missed_early_or_false(&runs);
        for v in &runs {
            assert_eq!(v["overload_onsets"], 0, "{v}");
            println!("seed {seed} #{}: highest estimated u {}", v["index"], v["max_estimated_utilization"]);
        }
    }
}

/// #6036 of the campaign with `--seed 3`: a raise of a 3.1 m held rope from
/// 5.6° starts with a 0.6 s FAULT (p1 out of range). Taken as one long step
/// the gap read 1.21 × the load as it ended (OVERLOAD at true u 0.883); the
/// chain now runs through it on the straight line between the good samples,
/// one step per sample (with 8 steps of 75 ms the swing's drive was coarse
/// enough to read 1.10 × and alarm the same).
#[test]
fn a_fault_at_the_start_of_a_raise_is_bridged_without_an_early_alarm() {
    assert_none_missed_early_or_false(&only("3", &["6036"]));
}

/// #1724 of the campaign with `--seed 8` (a lift-off of 3.3 t at 80.8°, then
/// a lowering to 8.2° in 9 s on a 4.2 m held rope) and #6948 of `--seed 10`
/// (82.6° → 35.6° in 11 s on a 3–4 m rope). The 3.75 m rope's average, the
/// bank's weighing, was dropped while that rope could not weigh; when it
/// could again the average restarted at its W_k of that instant, 1.09 × the
/// load, above every other average, and the weighing jumped with it:
/// OVERLOAD at true u 0.8997 and 0.898 (early). A rope that was the weighing
/// now restarts at the weighing: #1724 is not cut (its true u peaks at
/// 0.967), #6948 is cut at 0.972.
#[test]
fn the_rope_that_was_the_weighing_restarts_at_it_in_a_fast_lowering() {
    let runs = only("8", &["1724"]);
    assert_none_missed_early_or_false(&runs);
    assert_eq!(runs[0]["overload_onsets"], 0, "{}", runs[0]);
    assert_none_missed_early_or_false(&only("10", &["6948"]));
}

/// #3433 of the campaign with `--seed 11` (3.1 t lowered 34.6° → 10.1° in
/// 12.6 s on a 3.0 m held rope, seal friction) and #2801 of `--seed 19`
/// (3.1 t, 70.8° → 10.4° in 10.9 s on a 4.0 m rope, whose stop takes p1
/// past its range for moments): the stop sets the load bouncing at about
/// 1.6 Hz, whose crests passed W_fast's one stage at 1.058–1.065 × the load
/// and were cut 1–2 s after the stop, at true u 0.908 and 0.896 (early;
/// highest estimated u 1.011 and 1.003). For 2.5 s after a loaded move stops
/// a second stage now keeps the bounce out
/// (`moment_limiter::static_load::BOUNCE_WINDOW_S`): neither is cut, their
/// highest estimated u 0.994 and 0.962.
#[test]
fn a_short_ropes_bounce_after_a_lowering_stops_at_10_degrees_is_not_early() {
    for (seed, index) in [("11", "3433"), ("19", "2801")] {
        let runs = only(seed, &[index]);
        assert_none_missed_early_or_false(&runs);
        assert_eq!(runs[0]["overload_onsets"], 0, "{}", runs[0]);
        println!("#{index}: highest estimated u {}", runs[0]["max_estimated_utilization"]);
    }
}

fn assert_none_missed_early_or_false(runs: &[serde_json::Value]) {
    for v in runs {
        assert_eq!(v["missed"], false, "#{} missed: {v}", v["index"]);
        assert_eq!(v["false_overload"], false, "#{} false OVERLOAD: {v}", v["index"]);
        assert_eq!(v["early"], false, "#{} early: {v}", v["index"]);
    }
}

/// #1611 of the campaign with `--seed 2`: a 3 t load lowered from 82° to
/// 7.5° in 15.6 s on the paid-out rope swings 24° when the boom stops. Its
/// rope's tension then varies by ±14 % twice per period, which the old
/// small-angle observer of the paid-out rope did not model: the reading
/// peaked at 1.08 × the load, 0.9998 of rated at true u 0.88, and the
/// change that stopped the noise driving the swings tipped it to OVERLOAD
/// (early). The paid-out rope is now the large-angle pendulum of the held
/// ropes with its length's terms (`moment_limiter::held_pendulum::PaidOutRope`).
#[test]
fn a_paid_out_ropes_large_swing_after_a_stop_is_not_read_as_load() {
    assert_none_missed_early_or_false(&only("2", &["1611"]));
}

/// Runs the scenarios `indices` of the 10 000-scenario campaign of `seed`
/// alone.
fn only(seed: &str, indices: &[&str]) -> Vec<serde_json::Value> {
    let mut args = vec!["--scenarios", "10000", "--seed", seed, "--json"];
    for i in indices {
        args.extend(["--only", i]);
    }
    let (json, _) = campaign(&args);
    assert_eq!(summary(&json)["scenarios"].as_u64(), Some(indices.len() as u64));
    let v: Vec<serde_json::Value> = scenario_lines(&json).iter().map(|l| serde_json::from_str(l).expect("json")).collect();
    for s in &v {
        println!(
            "#{} first OVERLOAD {} s at true u {}, fault {}, true u 1.0 at {} s, 1.05 at {} s, lift-off delay {} s",
            s["index"], s["first_overload_s"], s["min_u_at_overload_onset"], s["first_fault"], s["t_true_overload_s"], s["t_true_1_05_s"], s["lift_off_delay_s"]
        );
    }
    v
}

/// #2455 and #2967 of the campaign with `--seed 3` lift 10.9 t and 10.5 t
/// (rated 10 t) off at 80° and 85° over 2–3 s on crane 7 (seal friction, a
/// 0.25 s angle sensor). The rope bank's pendulums, driven by the angle
/// sensor's noise at rest (0.035°), spread the ropes' factors, and the
/// lowest rope read the load 3.4 % low at 85° (tan θ = 11): OVERLOAD came
/// 1.0–1.26 s after the load left the ground, at true u 1.05 and 1.09
/// (missed). A still boom no longer drives them
/// (`moment_limiter::static_load::SWING_DEADBAND_RAD_S`).
#[test]
fn the_third_campaigns_steep_lift_offs_are_cut_in_time() {
    let runs = only("3", &["2455", "2967"]);
    assert_none_missed_early_or_false(&runs);
    for v in &runs {
        assert!(v["lift_off_delay_s"].as_f64().is_some_and(|d| d <= 1.0), "#{} lift-off delay: {v}", v["index"]);
    }
}

/// `--wide` draws the cranes' sensors and seals from wider worlds and
/// changes nothing else: the same scenarios (moves, loads, ropes, noise
/// seeds) on the same cranes' friction laws; crane 0 stays the nominal one;
/// the other cranes' synth lines carry the wider settings; the summary says
/// which worlds it drew from.
#[test]
fn wider_worlds_change_only_the_cranes_sensors() {
    let args = ["--scenarios", "6", "--seed", "5", "--cranes", "3", "--json", "--step-ms", "5"];
    let (narrow, _) = campaign(&args);
    let (wide, _) = campaign(&[&args[..], &["--wide"]].concat());
    assert_eq!(summary(&narrow)["wide"], false);
    assert_eq!(summary(&wide)["wide"], true);
    assert_eq!(scenario_lines(&wide).len(), 6);
    let parse = |l: &String| serde_json::from_str::<serde_json::Value>(l).expect("json");
    for (a, b) in scenario_lines(&narrow).iter().map(parse).zip(scenario_lines(&wide).iter().map(parse)) {
        for key in ["from_deg", "to_deg", "duration_s", "load_kg", "rope", "rope_length_m", "lift_off_s", "noise_seed", "crane"] {
            assert_eq!(a[key], b[key], "{key}");
        }
        let (sa, sb) = (a["synth"].as_str().expect("synth"), b["synth"].as_str().expect("synth"));
        let law = |s: &str| s.split(" --standstill-release-s").next().unwrap_or("").split(" --friction-law").nth(1).unwrap_or("").to_string();
        assert_eq!(law(sa), law(sb), "the friction law is the crane's");
        if a["crane"] == 0 {
            assert_eq!(sa, sb, "crane 0 is the nominal crane");
        } else {
            assert!(!sa.contains("--friction-onset-deg-s") && sb.contains("--friction-onset-deg-s"), "{sa}\n{sb}");
        }
    }
}

/// A crane whose calibration is refused is named, not fatal: `--wide` seed 12
/// draws crane 10 with an angle sensor so noisy that the rate check faults on
/// half of its unloaded runs' samples and no steady boom-down sample is left.
/// Until this test, that ended the whole campaign with exit 1 and a Debug
/// dump (`crane 10: calibration: TooFewSamples { up: false, found: 0 }`), and
/// the other 15 cranes' scenarios were lost. Asserted: exit 0; the summary
/// names crane 10, why, and its scenarios, which are not run (a crane
/// `crane-sim calibrate` refuses is not put into service) and not graded;
/// every other scenario is; the warning names the crane on stderr.
#[test]
fn a_crane_the_calibration_refuses_is_named_and_the_others_are_graded() {
    let (json, err) = campaign(&["--scenarios", "40", "--seed", "12", "--wide", "--json", "--step-ms", "5"]);
    let s = summary(&json);
    let refused = s["uncalibrated_cranes"].as_array().expect("uncalibrated_cranes");
    assert_eq!(refused.len(), 1, "{s}");
    assert_eq!(refused[0]["crane"], 10);
    let why = refused[0]["error"].as_str().expect("error");
    assert!(why.contains("too few samples moving down") && why.contains("angle implausible rate of change"), "{why}");
    let not_run = s["scenarios_not_run"].as_u64().expect("scenarios_not_run");
    assert_eq!(refused[0]["scenarios"].as_u64(), Some(not_run));
    assert!(not_run >= 1, "crane 10 draws scenarios of the 40");
    let lines = scenario_lines(&json);
    assert_eq!(lines.len() as u64 + not_run, 40);
    assert_eq!(s["scenarios"].as_u64(), Some(40 - not_run));
    assert!(lines.iter().all(|l| !l.contains("\"crane\":10,")), "crane 10's scenarios are not graded");
    assert!(s["calibrations"].as_array().expect("calibrations").iter().all(|c| c["crane"] != 10));
    assert!(err.contains("warning: crane 10: calibration refused"), "{err}");
}
