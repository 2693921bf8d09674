//! eom's catalog models as a user's crate calls them, against the peer bench's way, in the same
//! process: `spatial_full_euler` and `spatial_full_quaternion` on the peer bench's body (diag(2,
//! 3, 4) turned, 5 kg) over 1024 states of its ranges (forward speed 5–40 m/s, side and
//! vertical ±5 m/s, rates ±1.5 rad/s, roll and heading in [−π, π), pitch within ±80°, force
//! ±100 N, moment ±10 N·m), nine rounds, the contenders' order turned each round.
//!
//! - **peer**: a never-inlined function returning the rates, called through a `fn` pointer the
//!   optimiser cannot see, every output read with its own volatile load (`peer/benches/peer.rs`);
//! - **user**: `fn call(k, s, u, out) { *out = rhs(k, s, u) }`, never inlined, called directly,
//!   the outputs summed with `out.iter().sum()`.

use eom::InertiaTensor;
use eom::models::{FromBody, generated};
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use std::hint::black_box;
use std::time::Instant;

type Euler = generated::spatial_full_euler::Coefficients<f64>;
type Quaternion = generated::spatial_full_quaternion::Coefficients<f64>;

#[inline(never)]
fn call(k: &Euler, s: &[f64; 12], u: &[f64; 6], out: &mut [f64; 12]) {
    *out = generated::spatial_full_euler::rhs(k, s, u)
}

#[inline(never)]
fn call_quaternion(k: &Quaternion, s: &[f64; 13], u: &[f64; 6], out: &mut [f64; 13]) {
    *out = generated::spatial_full_quaternion::rhs(k, s, u)
}

#[inline(never)]
fn by_value(k: &Euler, s: &[f64; 12], u: &[f64; 6]) -> [f64; 12] {
    generated::spatial_full_euler::rhs(k, s, u)
}

#[inline(never)]
fn by_value_quaternion(k: &Quaternion, s: &[f64; 13], u: &[f64; 6]) -> [f64; 13] {
    generated::spatial_full_quaternion::rhs(k, s, u)
}

/// The peer bench's draws: splitmix64, uniform from the top 53 bits.
struct SplitMix64(u64);

impl SplitMix64 {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        lo + (hi - lo) * (((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// The sum of the entries, each read with its own volatile load, as the peer bench reads them.
fn total<const N: usize>(out: &[f64; N]) -> f64 {
    // SAFETY: each `x` is a valid, aligned reference to an initialised f64.
    out.iter()
        .map(|x| unsafe { std::ptr::read_volatile(x) })
        .sum()
}

type States = (Vec<[f64; 12]>, Vec<[f64; 13]>, Vec<[f64; 6]>);

fn draw() -> States {
    let (mut euler, mut quaternion, mut inputs) = (Vec::new(), Vec::new(), Vec::new());
    let mut rng = SplitMix64(0x5EED_4E0F_2026);
    let pi = std::f64::consts::PI;
    for _ in 0..1024 {
        let mut s = [0.0; 12];
        s[0] = rng.uniform(5.0, 40.0);
        s[1] = rng.uniform(-5.0, 5.0);
        s[2] = rng.uniform(-5.0, 5.0);
        s[3..6].iter_mut().for_each(|x| *x = rng.uniform(-1.5, 1.5));
        s[6..9]
            .iter_mut()
            .for_each(|x| *x = rng.uniform(-1000.0, 1000.0));
        s[9] = rng.uniform(-pi, pi);
        s[10] = rng.uniform(-80f64.to_radians(), 80f64.to_radians());
        s[11] = rng.uniform(-pi, pi);
        let q = UnitQuaternion::from_euler_angles(s[9], s[10], s[11]);
        let mut sq = [0.0; 13];
        sq[..9].copy_from_slice(&s[..9]);
        sq[9..].copy_from_slice(&[q.w, q.i, q.j, q.k]);
        let mut u = [0.0; 6];
        u[..3]
            .iter_mut()
            .for_each(|x| *x = rng.uniform(-100.0, 100.0));
        u[3..]
            .iter_mut()
            .for_each(|x| *x = rng.uniform(-10.0, 10.0));
        euler.push(s);
        quaternion.push(sq);
        inputs.push(u);
    }
    (euler, quaternion, inputs)
}

fn main() {
    let turn = Rotation3::from_euler_angles(0.3, -0.2, 0.5).into_inner();
    let tensor = turn * Matrix3::from_diagonal(&Vector3::new(2.0, 3.0, 4.0)) * turn.transpose();
    let Ok(inertia) = InertiaTensor::from_matrix(tensor) else {
        eprintln!("the body's tensor is not physical");
        std::process::exit(1);
    };
    let k = Euler::new(&generated::spatial_full_euler::Parameters::from_body(
        5.0, &inertia,
    ));
    let kq = Quaternion::new(&generated::spatial_full_quaternion::Parameters::from_body(
        5.0, &inertia,
    ));
    let (euler, quaternion, inputs) = draw();
    let calls = 2_000_000;
    let mut ns = vec![Vec::new(); 4];
    let mut sum = 0.0;
    for round in 0..9 {
        for c in (0..4).map(|c| (c + round) % 4) {
            let clock = Instant::now();
            let (f, fq) = (
                black_box(by_value as fn(_, _, _) -> _),
                black_box(by_value_quaternion as fn(_, _, _) -> _),
            );
            let (mut out, mut out_q) = ([0.0; 12], [0.0; 13]);
            for i in 0..calls {
                let j = i % 1024;
                sum += match c {
                    0 => total(&f(&k, &euler[j], &inputs[j])),
                    1 => {
                        call(&k, &euler[j], &inputs[j], &mut out);
                        out.iter().sum::<f64>()
                    }
                    2 => total(&fq(&kq, &quaternion[j], &inputs[j])),
                    _ => {
                        call_quaternion(&kq, &quaternion[j], &inputs[j], &mut out_q);
                        out_q.iter().sum::<f64>()
                    }
                };
            }
            ns[c].push(clock.elapsed().as_secs_f64() / calls as f64 * 1e9);
        }
    }
    let names = [
        "full Euler, peer",
        "full Euler, user",
        "full quaternion, peer",
        "full quaternion, user",
    ];
    for (name, mut times) in names.iter().zip(ns) {
        times.sort_by(f64::total_cmp);
        println!(
            "{name}: median {:.1} ns per call (range {:.1}–{:.1})",
            times[4], times[0], times[8]
        );
    }
    black_box(sum);
}
