//! Central differences of a model's rates: the numeric Jacobians that tests hold a model's
//! proved Jacobians to, computed in one place.

/// ∂f/∂x and ∂f/∂u of `rates` at (`x`, `u`) by central differences, each entry's step
/// `step(its value)`: (f(v + h) − f(v − h)) / 2h, column by column.
pub fn central_jacobians<const N: usize, const M: usize>(
    rates: impl Fn(&[f64; N], &[f64; M]) -> [f64; N],
    (x, u): (&[f64; N], &[f64; M]),
    step: impl Fn(f64) -> f64,
) -> ([[f64; N]; N], [[f64; M]; N]) {
    let mut by_state = [[0.0; N]; N];
    for j in 0..N {
        let h = step(x[j]);
        let (mut up, mut down) = (*x, *x);
        up[j] += h;
        down[j] -= h;
        let (fu, fd) = (rates(&up, u), rates(&down, u));
        for i in 0..N {
            by_state[i][j] = (fu[i] - fd[i]) / (2.0 * h);
        }
    }
    let mut by_input = [[0.0; M]; N];
    for j in 0..M {
        let h = step(u[j]);
        let (mut up, mut down) = (*u, *u);
        up[j] += h;
        down[j] -= h;
        let (fu, fd) = (rates(x, &up), rates(x, &down));
        for i in 0..N {
            by_input[i][j] = (fu[i] - fd[i]) / (2.0 * h);
        }
    }
    (by_state, by_input)
}

/// Asserts that each row of `proved` (a Jacobian by `wrt`, `x` or `u`) equals `numeric` to
/// `tolerance` of the row's largest proved entry (at least 1), naming the entry (`∂f3/∂x1`)
/// that does not.
pub fn assert_rows_agree<const N: usize, const C: usize>(
    proved: &[[f64; C]; N],
    numeric: &[[f64; C]; N],
    wrt: &str,
    tolerance: f64,
) {
    for (row, (proved, numeric)) in proved.iter().zip(numeric).enumerate() {
        let scale = proved.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
        for (column, (exact, difference)) in proved.iter().zip(numeric).enumerate() {
            assert!(
                (difference - exact).abs() < tolerance * scale,
                "∂f{row}/∂{wrt}{column}: {difference} vs {exact}"
            );
        }
    }
}
