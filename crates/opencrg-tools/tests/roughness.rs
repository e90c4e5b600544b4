//! Roughness on profiles with known answers: a constant slope, sines against the quarter
//! car's steady-state response worked out in the frequency domain, profiles synthesised
//! with a known ISO 8608 density in classes A to E; and the same through roads.

use opencrg_core::synth::RoadSpec;
use opencrg_tools::{iri, psd, roughness};
use realfft::num_complex::Complex64;
use realfft::RealFftPlanner;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

/// (sprung - unsprung displacement) / profile displacement of the golden car at the
/// angular frequency `omega` (rad/s), from its two equations of motion.
fn travel_per_input(omega: f64) -> f64 {
    let s = Complex64::new(0.0, omega);
    let coupling = s * iri::C + iri::K2;
    let sprung_per_unsprung = coupling / (s * s + coupling);
    let unsprung_per_input = iri::K1 / (-coupling * sprung_per_unsprung + s * s * iri::MU + coupling + iri::K1);
    ((sprung_per_unsprung - 1.0) * unsprung_per_input).norm()
}

/// The steady-state IRI of `a · sin(2π x / wavelength)` sampled `dx` apart: the smoothed
/// slope's amplitude, through the car, rectified (mean |sin| = 2/π), with the factor of
/// the input held over each interval.
fn sine_iri(a: f64, wavelength: f64, dx: f64) -> f64 {
    let k = TAU / wavelength;
    let base = iri::base_samples(dx) as f64 * dx;
    let slope = 2.0 * a / base * (k * base / 2.0).sin().abs();
    let held = (k * dx / 2.0).sin() / (k * dx / 2.0);
    1000.0 * 2.0 / PI * travel_per_input(k * iri::SPEED) * slope * held
}

#[test]
fn a_constant_slope_has_no_roughness() {
    for dx in [0.01, 0.05, 0.25, 0.5] {
        let profile: Vec<f64> = (0..(200.0 / dx) as usize).map(|i| 0.02 * i as f64 * dx - 3.0).collect();
        let r = iri::response(&profile, dx).unwrap();
        assert!(r.iri() < 1e-9, "dx {dx}: {}", r.iri());
    }
}

#[test]
fn sines_give_the_steady_state_response() {
    let dx = 0.05;
    for wavelength in [1.0, 2.0, 5.0, 10.0, 20.0, 40.0] {
        let a = 0.005;
        let profile: Vec<f64> =
            (0..=(2000.0 / dx) as usize).map(|i| a * (TAU * i as f64 * dx / wavelength).sin()).collect();
        let r = iri::response(&profile, dx).unwrap();
        // From 500 m on the start has died away; 1000 m hold whole periods.
        let measured = r.iri_between(500.0, 1500.0).unwrap();
        let expected = sine_iri(a, wavelength, dx);
        assert!(
            (measured / expected - 1.0).abs() < 0.01,
            "wavelength {wavelength} m: {measured} against {expected} m/km"
        );
    }
}

#[test]
fn too_short_a_profile_names_what_is_missing() {
    let e = iri::response(&[0.0; 100], 0.1).unwrap_err().to_string();
    assert!(e.contains("too short") && e.contains("11 m"), "{e}");
}

/// A profile of `n` samples `dx` apart with the one-sided density
/// `gd_n0 · (n / 0.1)^-2` at every frequency of its transform, random phases.
fn iso_profile(gd_n0: f64, n: usize, dx: f64, seed: u64) -> Vec<f64> {
    let mut state = seed;
    let mut random = move || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let df = 1.0 / (n as f64 * dx);
    let inverse = RealFftPlanner::<f64>::new().plan_fft_inverse(n);
    let mut spectrum = inverse.make_input_vec();
    for (k, x) in spectrum.iter_mut().enumerate().take(n / 2).skip(1) {
        let f = k as f64 * df;
        let amplitude = (2.0 * gd_n0 * (f / psd::N0).powi(-2) * df).sqrt();
        *x = Complex64::from_polar(amplitude / 2.0, TAU * random());
    }
    let mut profile = inverse.make_output_vec();
    inverse.process(&mut spectrum, &mut profile).unwrap();
    profile
}

#[test]
fn synthesised_iso_profiles_get_their_class() {
    for (gd_n0, class) in [(16e-6, 'A'), (64e-6, 'B'), (256e-6, 'C'), (1024e-6, 'D'), (4096e-6, 'E')] {
        let profile = iso_profile(gd_n0, 1 << 15, 0.05, 11);
        let s = psd::spectrum(&profile, 0.05).unwrap();
        assert_eq!(s.class, class, "Gd(n0) {gd_n0}: {s:?}");
        assert!((s.gd_n0 / gd_n0 - 1.0).abs() < 0.25, "Gd(n0) {gd_n0}: fitted {}", s.gd_n0);
        assert!((s.w - 2.0).abs() < 0.2, "w {}", s.w);
        assert!(s.fitted.0 <= 0.025 && s.fitted.1 >= 2.8, "{:?}", s.fitted);
    }
}

/// A straight road whose every long section is `z` (`dx` apart).
fn road_of(z: Vec<f64>, dx: f64, nan_between: Option<(f64, f64)>) -> Arc<opencrg_core::Road> {
    let length = (z.len() - 1) as f64 * dx;
    let spec = RoadSpec::straight(length, 4.0, dx, 0.5).with_elevation(move |u, _| {
        let z = z[((u / dx).round() as usize).min(z.len() - 1)];
        match nan_between {
            Some((a, b)) if u >= a && u < b => f64::NAN,
            _ => z,
        }
    });
    Arc::new(spec.build().unwrap())
}

#[test]
fn roads_are_analysed_track_by_track() {
    let dx = 0.05;
    let profile = iso_profile(256e-6, 1 << 15, dx, 5);
    let road = road_of(profile.clone(), dx, None);
    let tracks = roughness::roughness(&road, &roughness::DEFAULT_TRACKS, 100.0).unwrap();
    assert_eq!(tracks.len(), 3);
    // Every long section is the profile: the road's tracks are the profile (in single
    // precision, as the grid keeps it).
    let alone = iri::response(&profile, dx).unwrap().iri();
    for t in &tracks {
        assert!((t.iri / alone - 1.0).abs() < 1e-4, "{} against {alone}", t.iri);
        assert_eq!(t.psd.class, 'C');
        assert_eq!(t.skipped, 0.0);
        let length = (profile.len() - 1) as f64 * dx;
        assert_eq!(t.segments.len(), (length / 100.0).ceil() as usize);
        assert!(t.segments.iter().all(|s| s.iri.is_some_and(|x| x > 0.0)));
        assert_eq!(t.segments.last().unwrap().u_end, length);
    }
}

#[test]
fn bad_tracks_and_gaps_are_reported() {
    let dx = 0.1;
    let road = road_of(iso_profile(64e-6, 1 << 13, dx, 3), dx, Some((300.0, 350.0)));
    let e = roughness::roughness(&road, &[2.5], 100.0).unwrap_err().to_string();
    assert!(e.contains("v = 2.5") && e.contains("outside"), "{e}");
    let t = &roughness::roughness(&road, &[0.0], 100.0).unwrap()[0];
    assert!((t.skipped - 50.0).abs() <= 2.0 * dx, "skipped {} m", t.skipped);
    // The segment inside the gap is still driven at its edges; none lacks an answer.
    assert!(t.segments.iter().all(|s| s.iri.is_some()));
    let short = road_of(vec![0.0; 50], dx, None);
    let e = roughness::roughness(&short, &[0.0], 100.0).unwrap_err().to_string();
    assert!(e.contains("too short") && e.contains("IRI"), "{e}");
}
