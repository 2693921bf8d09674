//! The dense output of DOP853: Hairer's seventh-order continuous extension (`CONTD8`), which
//! needs three more stages per step (14–16) on top of the thirteen of the step itself.
//!
//! Over a step from tₙ to tₙ + h, with θ = (t − tₙ)/h and θ₁ = 1 − θ,
//! y(θ) = r₁ + θ(r₂ + θ₁(r₃ + θ(r₄ + θ₁(r₅ + θ(r₆ + θ₁(r₇ + θ r₈)))))), where r₁ = yₙ,
//! r₂ = yₙ₊₁ − yₙ, r₃ = h k₁ − r₂, r₄ = r₂ − h k₁₃ − r₃, and r₅…r₈ are h Σ dᵢⱼ kⱼ over the
//! sixteen stages. The coefficients are Hairer's published constants; the tests check the row
//! sums of the extra stages and the accuracy of the interpolant.

use nalgebra::{RealField, SVector};

use super::adaptive::{AcceptedStep, combine};
use super::{OdeSystem, lit};

/// The rows aᵢⱼ of the extra stages 14–16 over stages 1–15 (Hairer's `dop853.f`; stage 13
/// is f(tₙ₊₁, yₙ₊₁)).
const A_DENSE: [&[f64]; 3] = [
    &[
        0.056167502283047954,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.25350021021662483,
        -0.2462390374708025,
        -0.12419142326381637,
        0.15329179827876568,
        0.00820105229563469,
        0.007567897660545699,
        -0.008298,
    ],
    &[
        0.03183464816350214,
        0.0,
        0.0,
        0.0,
        0.0,
        0.028300909672366776,
        0.053541988307438566,
        -0.05492374857139099,
        0.0,
        0.0,
        -0.00010834732869724932,
        0.0003825710908356584,
        -0.00034046500868740456,
        0.1413124436746325,
    ],
    &[
        -0.42889630158379194,
        0.0,
        0.0,
        0.0,
        0.0,
        -4.697621415361164,
        7.683421196062599,
        4.06898981839711,
        0.3567271874552811,
        0.0,
        0.0,
        0.0,
        -0.0013990241651590145,
        2.9475147891527724,
        -9.15095847217987,
    ],
];
/// The nodes of stages 14–16.
const C_DENSE: [f64; 3] = [0.1, 0.2, 0.7777777777777778];
/// The weights of the dense-output coefficients r₅…r₈ over stages 1–16.
const D: [[f64; 16]; 4] = [
    [
        -8.428938276109013,
        0.0,
        0.0,
        0.0,
        0.0,
        0.5667149535193777,
        -3.0689499459498917,
        2.38466765651207,
        2.117034582445028,
        -0.871391583777973,
        2.2404374302607883,
        0.6315787787694688,
        -0.08899033645133331,
        18.148505520854727,
        -9.194632392478356,
        -4.436036387594894,
    ],
    [
        10.427508642579134,
        0.0,
        0.0,
        0.0,
        0.0,
        242.28349177525817,
        165.20045171727028,
        -374.5467547226902,
        -22.113666853125306,
        7.733432668472264,
        -30.674084731089398,
        -9.332130526430229,
        15.697238121770845,
        -31.139403219565178,
        -9.35292435884448,
        35.81684148639408,
    ],
    [
        19.985053242002433,
        0.0,
        0.0,
        0.0,
        0.0,
        -387.0373087493518,
        -189.17813819516758,
        527.8081592054236,
        -11.57390253995963,
        6.8812326946963,
        -1.0006050966910838,
        0.7777137798053443,
        -2.778205752353508,
        -60.19669523126412,
        84.32040550667716,
        11.99229113618279,
    ],
    [
        -25.69393346270375,
        0.0,
        0.0,
        0.0,
        0.0,
        -154.18974869023643,
        -231.5293791760455,
        357.6391179106141,
        93.40532418362432,
        -37.45832313645163,
        104.0996495089623,
        29.8402934266605,
        -43.53345659001114,
        96.32455395918828,
        -39.17726167561544,
        -149.72683625798564,
    ],
];

/// The continuous extension of one accepted DOP853 step, a polynomial of degree seven in θ.
#[derive(Debug, Clone, Copy)]
pub struct Dop853Interpolant<T: RealField + Copy, const N: usize> {
    t_old: T,
    h: T,
    r: [SVector<T, N>; 8],
}

impl<T: RealField + Copy, const N: usize> Dop853Interpolant<T, N> {
    /// The interpolated state at `t` (meant for `t` within the step; outside it extrapolates).
    pub fn eval(&self, t: T) -> SVector<T, N> {
        let theta = (t - self.t_old) / self.h;
        let theta1 = T::one() - theta;
        let [r1, r2, r3, r4, r5, r6, r7, r8] = &self.r;
        let tail = r5 + (r6 + (r7 + r8 * theta) * theta1) * theta;
        r1 + (r2 + (r3 + (r4 + tail * theta1) * theta) * theta1) * theta
    }
}

/// Builds the interpolant of an accepted step, evaluating stages 14–16 (three RHS calls).
pub(crate) fn interpolant<T, const N: usize, S>(
    system: &S,
    step: &AcceptedStep<'_, T, N, 12>,
) -> Dop853Interpolant<T, N>
where
    T: RealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    let (t, h, y) = (step.t_old, step.h, step.y_old);
    let mut k = [SVector::<T, N>::zeros(); 16];
    k[..12].copy_from_slice(step.k);
    k[12] = *step.k_new;
    for (s, row) in A_DENSE.iter().enumerate() {
        let ys = y + combine(row, &k) * h;
        system.rhs(t + h * lit(C_DENSE[s]), &ys, &mut k[13 + s]);
    }
    let r2 = step.y_new - y;
    let r3 = k[0] * h - r2;
    let r4 = r2 - k[12] * h - r3;
    let d = |i: usize| combine(&D[i], &k) * h;
    Dop853Interpolant {
        t_old: t,
        h,
        r: [*y, r2, r3, r4, d(0), d(1), d(2), d(3)],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extra_stage_rows_sum_to_their_nodes() {
        // 1e-13: coefficients up to ~10 in size, each rounded once to f64.
        for (row, c) in A_DENSE.iter().zip(C_DENSE) {
            assert!((row.iter().sum::<f64>() - c).abs() < 1e-13);
        }
    }

    #[test]
    fn interpolant_reproduces_both_ends_of_the_step() {
        let decay = |_t: f64, y: &SVector<f64, 1>, dy: &mut SVector<f64, 1>| *dy = -*y;
        let (y_old, y_new) = (
            SVector::<f64, 1>::new(1.0),
            SVector::<f64, 1>::new((-0.1f64).exp()),
        );
        let mut k = [SVector::<f64, 1>::zeros(); 12];
        k[0] = -y_old;
        let k13 = -y_new;
        let (t_old, h) = (0.0, 0.1);
        let step = AcceptedStep {
            t_old,
            h,
            y_old: &y_old,
            y_new: &y_new,
            k: &k,
            k_new: &k13,
        };
        let p = interpolant(&decay, &step);
        // 1e-15: the construction gives r₁ at θ = 0 and r₁ + r₂ at θ = 1 up to rounding.
        assert!((p.eval(0.0) - y_old).amax() < 1e-15);
        assert!((p.eval(0.1) - y_new).amax() < 1e-15);
    }
}
