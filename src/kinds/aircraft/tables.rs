//! Lookup tables in one and two arguments: linear (bilinear) interpolation between
//! breakpoints, and past the ends the end segment extended, as Stevens & Lewis's code looks
//! up every F-16 table (the segment's index is clamped, its fraction is not).
//!
//! A lookup returns its value and its slopes: the segment's, which is what the model's
//! Jacobians read through the chain rule (at a breakpoint, the segment above it, as the
//! lookup itself takes it).

use thiserror::Error;

/// Why a table cannot be used, naming the table.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TableError {
    /// Fewer than two breakpoints.
    #[error("`{table}`: {axis} needs at least two breakpoints, found {found}")]
    TooFewBreakpoints {
        /// The table.
        table: String,
        /// Which argument's breakpoints.
        axis: String,
        /// How many there are.
        found: usize,
    },
    /// Breakpoints that are not finite and strictly increasing.
    #[error(
        "`{table}`: {axis} must be finite and strictly increasing, but breakpoint {index} is \
         {value} after {previous}"
    )]
    NotIncreasing {
        /// The table.
        table: String,
        /// Which argument's breakpoints.
        axis: String,
        /// The index of the breakpoint that is not above its predecessor.
        index: usize,
        /// Its value.
        value: f64,
        /// Its predecessor's.
        previous: f64,
    },
    /// A value that is not finite, or a row of the wrong length.
    #[error("`{table}`: {what}")]
    Values {
        /// The table.
        table: String,
        /// What is wrong.
        what: String,
    },
}

/// The breakpoints of one argument: finite, strictly increasing, at least two.
#[derive(Debug, Clone, PartialEq)]
pub struct Breakpoints(Vec<f64>);

impl Breakpoints {
    /// Checks `points` for the table `table`'s argument `axis`.
    pub fn new(table: &str, axis: &str, points: Vec<f64>) -> Result<Self, TableError> {
        if points.len() < 2 {
            return Err(TableError::TooFewBreakpoints {
                table: table.into(),
                axis: axis.into(),
                found: points.len(),
            });
        }
        if let Some(first) = points.first().filter(|x| !x.is_finite()) {
            return Err(TableError::NotIncreasing {
                table: table.into(),
                axis: axis.into(),
                index: 0,
                value: *first,
                previous: f64::NEG_INFINITY,
            });
        }
        for (index, pair) in points.windows(2).enumerate() {
            if pair[1].partial_cmp(&pair[0]) != Some(std::cmp::Ordering::Greater)
                || !pair[1].is_finite()
            {
                return Err(TableError::NotIncreasing {
                    table: table.into(),
                    axis: axis.into(),
                    index: index + 1,
                    value: pair[1],
                    previous: pair[0],
                });
            }
        }
        Ok(Breakpoints(points))
    }

    /// The points.
    pub fn points(&self) -> &[f64] {
        &self.0
    }

    /// The segment `x` falls in (the first or the last past the ends) and its fraction there,
    /// below 0 or above 1 past the ends.
    fn segment(&self, x: f64) -> Segment {
        let points = &self.0;
        let last = points.len() - 2;
        let k = points[1..=last].partition_point(|&p| p <= x);
        let width = points[k + 1] - points[k];
        Segment {
            index: k,
            fraction: (x - points[k]) / width,
            width,
        }
    }
}

#[derive(Debug, Clone, Copy)]
struct Segment {
    index: usize,
    fraction: f64,
    width: f64,
}

/// A value and its slope in the argument.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lookup1 {
    /// The interpolated value.
    pub value: f64,
    /// d(value)/dx on the segment.
    pub slope: f64,
}

/// A value and its slopes in both arguments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lookup2 {
    /// The interpolated value.
    pub value: f64,
    /// ∂(value)/∂x on the cell.
    pub by_x: f64,
    /// ∂(value)/∂y on the cell.
    pub by_y: f64,
}

/// A table of one argument.
#[derive(Debug, Clone, PartialEq)]
pub struct Table1 {
    x: Breakpoints,
    values: Vec<f64>,
}

impl Table1 {
    /// `values[i]` at `x[i]`, checked for `table`.
    pub fn new(table: &str, x: Breakpoints, values: Vec<f64>) -> Result<Self, TableError> {
        if values.len() != x.0.len() {
            return Err(TableError::Values {
                table: table.into(),
                what: format!("{} values for {} breakpoints", values.len(), x.0.len()),
            });
        }
        finite(table, &values)?;
        Ok(Table1 { x, values })
    }

    /// The value at `x` and its slope.
    pub fn at(&self, x: f64) -> Lookup1 {
        let s = self.x.segment(x);
        let (low, high) = (self.values[s.index], self.values[s.index + 1]);
        Lookup1 {
            value: low + s.fraction * (high - low),
            slope: (high - low) / s.width,
        }
    }
}

/// A table of two arguments, `values[i][j]` at `x[i]`, `y[j]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Table2 {
    x: Breakpoints,
    y: Breakpoints,
    values: Vec<Vec<f64>>,
}

impl Table2 {
    /// `values[i][j]` at `x[i]`, `y[j]`, checked for `table`.
    pub fn new(
        table: &str,
        x: Breakpoints,
        y: Breakpoints,
        values: Vec<Vec<f64>>,
    ) -> Result<Self, TableError> {
        if values.len() != x.0.len() {
            return Err(TableError::Values {
                table: table.into(),
                what: format!("{} rows for {} breakpoints", values.len(), x.0.len()),
            });
        }
        for (i, row) in values.iter().enumerate() {
            if row.len() != y.0.len() {
                return Err(TableError::Values {
                    table: table.into(),
                    what: format!(
                        "row {i} has {} values for {} breakpoints",
                        row.len(),
                        y.0.len()
                    ),
                });
            }
            finite(table, row)?;
        }
        Ok(Table2 { x, y, values })
    }

    /// The first and last breakpoints of x, then of y: where the table holds data.
    pub fn extent(&self) -> [(f64, f64); 2] {
        let ends = |points: &[f64]| (points[0], points[points.len() - 1]);
        [ends(self.x.points()), ends(self.y.points())]
    }

    /// The value at (`x`, `y`) and its slopes: interpolated in x on the two rows' columns,
    /// then in y, as the source writes it.
    pub fn at(&self, x: f64, y: f64) -> Lookup2 {
        let (s, t) = (self.x.segment(x), self.y.segment(y));
        let (k, m) = (s.index, t.index);
        let v = &self.values;
        let low = v[k][m] + s.fraction * (v[k + 1][m] - v[k][m]);
        let high = v[k][m + 1] + s.fraction * (v[k + 1][m + 1] - v[k][m + 1]);
        let low_by_x = (v[k + 1][m] - v[k][m]) / s.width;
        let high_by_x = (v[k + 1][m + 1] - v[k][m + 1]) / s.width;
        Lookup2 {
            value: low + t.fraction * (high - low),
            by_x: low_by_x + t.fraction * (high_by_x - low_by_x),
            by_y: (high - low) / t.width,
        }
    }
}

fn finite(table: &str, values: &[f64]) -> Result<(), TableError> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(i) => Err(TableError::Values {
            table: table.into(),
            what: format!("value {i} is {}", values[i]),
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(p: &[f64]) -> Breakpoints {
        Breakpoints::new("t", "x", p.to_vec()).unwrap()
    }

    #[test]
    fn a_lookup_interpolates_inside_and_extends_the_end_segments_outside() {
        let table = Table1::new("t", points(&[0.0, 1.0, 3.0]), vec![1.0, 3.0, 4.0]).unwrap();
        assert_eq!(
            table.at(0.5),
            Lookup1 {
                value: 2.0,
                slope: 2.0
            }
        );
        assert_eq!(
            table.at(2.0),
            Lookup1 {
                value: 3.5,
                slope: 0.5
            }
        );
        // Past the ends the end segments go on: below 0 with slope 2, above 3 with 0.5.
        assert_eq!(
            table.at(-1.0),
            Lookup1 {
                value: -1.0,
                slope: 2.0
            }
        );
        assert_eq!(
            table.at(5.0),
            Lookup1 {
                value: 5.0,
                slope: 0.5
            }
        );
        // At a breakpoint, the segment above it.
        assert_eq!(table.at(1.0).slope, 0.5);
    }

    #[test]
    fn a_bilinear_lookup_has_the_slopes_of_its_cell() {
        // v = 1 + 2x + 3y + xy on a grid is reproduced exactly by bilinear interpolation.
        let (xs, ys) = ([0.0, 1.0, 2.0], [0.0, 2.0, 5.0]);
        let f = |x: f64, y: f64| 1.0 + 2.0 * x + 3.0 * y + x * y;
        let values = xs
            .iter()
            .map(|&x| ys.iter().map(|&y| f(x, y)).collect())
            .collect();
        let table = Table2::new("t", points(&xs), points(&ys), values).unwrap();
        for (x, y) in [(0.5, 1.0), (1.5, 4.0), (-1.0, 7.0), (3.0, -2.0)] {
            let at = table.at(x, y);
            assert!((at.value - f(x, y)).abs() < 1e-12, "{x} {y}");
            assert!((at.by_x - (2.0 + y)).abs() < 1e-12);
            assert!((at.by_y - (3.0 + x)).abs() < 1e-12);
        }
    }

    #[test]
    fn breakpoints_that_do_not_increase_are_named() {
        let refused = Breakpoints::new("Cx", "alpha_deg", vec![0.0, 5.0, 5.0]).unwrap_err();
        assert_eq!(
            refused.to_string(),
            "`Cx`: alpha_deg must be finite and strictly increasing, but breakpoint 2 is 5 after 5"
        );
        assert!(Breakpoints::new("Cx", "alpha_deg", vec![0.0, f64::NAN]).is_err());
        assert!(Breakpoints::new("Cx", "alpha_deg", vec![0.0]).is_err());
        let short = Table1::new("Cz", points(&[0.0, 1.0]), vec![1.0]).unwrap_err();
        assert_eq!(short.to_string(), "`Cz`: 1 values for 2 breakpoints");
    }
}
